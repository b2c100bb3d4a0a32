#include "post/PostProcessor.h"

#include "post/detail/ScriptSink.h"

#include <QCoreApplication>

#include <fstream>
#include <sstream>

namespace camwb::post {

namespace {

base::Status needApplication()
{
    if (!QCoreApplication::instance())
        return base::makeError("the post kernel needs a QCoreApplication (QJSEngine requires one)");
    return {};
}

}  // namespace

base::Result<PostProcessor> PostProcessor::load(const std::string& scriptPath)
{
    if (base::Status app = needApplication(); !app)
        return app.error();
    std::ifstream in(scriptPath, std::ios::binary);
    if (!in)
        return base::makeError("cannot read post script", scriptPath);
    std::ostringstream buffer;
    buffer << in.rdbuf();

    PostProcessor post;
    post.m_source = buffer.str();
    ScriptRun run(scriptPath, PostContext{});
    if (base::Status status = run.evaluate(post.m_source, post.m_info); !status)
        return status.error();
    return post;
}

base::Result<PostOutput> PostProcessor::run(const toolpath::Toolpath& toolpath, const PostContext& context) const
{
    if (base::Status app = needApplication(); !app)
        return app.error();
    ScriptRun run(m_info.filePath, context);
    PostInfo info;
    if (base::Status status = run.evaluate(m_source, info); !status)
        return status.error();
    return run.play(toolpath);
}

}  // namespace camwb::post
