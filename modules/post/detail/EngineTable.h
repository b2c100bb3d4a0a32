// The post engine library's entry points (detail/ScriptEngine.h): its one exported C symbol
// returns this table.
#pragma once

#include "post/PostProcessor.h"

namespace camwb::post {

struct EngineTable {
    int abi = 0;  // kEngineAbi when library and program were built together
    base::Result<PostProcessor> (*load)(const std::string& scriptPath, std::chrono::milliseconds scriptBudget);
    base::Result<PostOutput> (*run)(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                    const RunOptions& options);
    base::Result<PostSummary> (*runToFile)(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                           const RunOptions& options, const std::string& outputPath);
};

// Raise whenever EngineTable or the types it passes (PostProcessor, RunOptions, the outputs,
// Toolpath) change.
inline constexpr int kEngineAbi = 1;
inline constexpr const char* kEngineEntryPoint = "camwb_post_engine_table";

}  // namespace camwb::post
