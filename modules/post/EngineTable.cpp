// The post engine library's one exported symbol (detail/EngineTable.h).
#include "post/detail/EngineTable.h"

#include "post/detail/ScriptEngine.h"

extern "C" __attribute__((visibility("default"))) const camwb::post::EngineTable* camwb_post_engine_table()
{
    using camwb::post::ScriptEngine;
    static const camwb::post::EngineTable table{camwb::post::kEngineAbi, ScriptEngine::load, ScriptEngine::run,
                                                ScriptEngine::runToFile};
    return &table;
}
