// PostProcessor's load and runs, forwarded to the post engine (detail/ScriptEngine.h), which is
// loaded with the first post: Qt Qml and its libraries (a JavaScript engine, Qt Network) are
// loaded only by the commands that post.
#include "post/PostProcessor.h"

#include "base/PluginLibrary.h"
#include "post/detail/EngineTable.h"

namespace camwb::post {
namespace {

base::Result<const EngineTable*> engine()
{
    // Installed beside the program (`bin/../<libdir>/camwb/`), or where it was built.
    static const base::Result<const EngineTable*> loaded =
        base::loadPlugin<EngineTable>({"the post engine", "libcamwb_post_engine.so runs the post scripts",
                                       "CAMWB_POST_ENGINE", CAMWB_POST_ENGINE_FROM_BINDIR, CAMWB_POST_ENGINE_BUILT},
                                      kEngineEntryPoint, kEngineAbi);
    return loaded;
}

}  // namespace

base::Result<PostProcessor> PostProcessor::load(const std::string& scriptPath, std::chrono::milliseconds scriptBudget)
{
    const base::Result<const EngineTable*> loaded = engine();
    if (!loaded)
        return base::makeError(loaded.error().message, scriptPath);
    return loaded.value()->load(scriptPath, scriptBudget);
}

base::Result<PostOutput> PostProcessor::run(const toolpath::Toolpath& toolpath, const RunOptions& options) const
{
    const base::Result<const EngineTable*> loaded = engine();
    if (!loaded)
        return base::makeError(loaded.error().message, m_info.filePath);
    return loaded.value()->run(*this, toolpath, options);
}

base::Result<PostOutput> PostProcessor::run(const toolpath::Toolpath& toolpath, const PostContext& context) const
{
    RunOptions options;
    options.context = context;
    return run(toolpath, options);
}

base::Result<PostSummary> PostProcessor::runToFile(const toolpath::Toolpath& toolpath, const RunOptions& options,
                                                   const std::string& outputPath) const
{
    const base::Result<const EngineTable*> loaded = engine();
    if (!loaded)
        return base::makeError(loaded.error().message, m_info.filePath);
    return loaded.value()->runToFile(*this, toolpath, options, outputPath);
}

}  // namespace camwb::post
