// Private: the post engine, what PostProcessor's load and runs do (ScriptEngine.cpp, over
// ScriptRun and QJSEngine). It lives in the engine library (libcamwb_post_engine.so), which the
// programs load with their first post (detail/EngineTable.h), so that the commands that post
// nothing start without Qt Qml's libraries.
#pragma once

#include "post/PostProcessor.h"

namespace camwb::post {

struct ScriptEngine {
    static base::Result<PostProcessor> load(const std::string& scriptPath, std::chrono::milliseconds scriptBudget);
    static base::Result<PostOutput> run(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                        const RunOptions& options);
    static base::Result<PostSummary> runToFile(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                               const RunOptions& options, const std::string& outputPath);
};

}  // namespace camwb::post
