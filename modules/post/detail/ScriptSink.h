// Private: one post run in its own QJSEngine. Installs the kernel services, evaluates the post
// script, and plays a Toolpath through the script's handlers (a MachineSink), with the kernel's
// arc policy (pieces of at most `post.maxArcSweep` degrees, default 180) applied before onCircular.
#pragma once

#include "base/Result.h"
#include "post/PostProcessor.h"
#include "post/detail/ScriptBindings.h"
#include "toolpath/MachineSink.h"

#include <QJSEngine>
#include <QJSValue>

#include <map>
#include <memory>
#include <string>

namespace camwb::post {

class ScriptRun {
public:
    ScriptRun(std::string postFile, const PostContext& context);
    ~ScriptRun();

    // Evaluates the post source; reads `post` into info (id defaults to the file's base name).
    base::Status evaluate(const std::string& source, PostInfo& info);
    base::Result<PostOutput> play(const toolpath::Toolpath& toolpath);

private:
    friend class ScriptSink;
    // Calls handler `name` with args; false when the script failed (m_failure holds the error).
    bool call(const char* name, const QJSValueList& args, bool& handled);
    base::Error scriptError(const QJSValue& thrown, const std::string& where);

    std::string m_postFile;
    std::string m_postId;
    QJSEngine m_engine;
    std::unique_ptr<ScriptKernel> m_kernel;  // C++ ownership; destroyed before the engine
    QJSValue m_post;
    QJSValue m_trampoline;
    std::map<std::string, QJSValue> m_handlers;
    std::string m_where;  // record being handled, for error messages
    std::optional<base::Error> m_failure;
    double m_maxArcSweepDeg = 180;
};

}  // namespace camwb::post
