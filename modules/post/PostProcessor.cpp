#include "post/PostProcessor.h"

#include "toolpath/ProgramStats.h"

#include "base/AtomicFile.h"
#include "kinematics/LimitCheck.h"
#include "post/ProgramSummary.h"
#include "post/detail/ScriptRun.h"
#include "toolpath/ForwardingSink.h"
#include "toolpath/MachineSink.h"

#include <QCoreApplication>

#include <algorithm>

namespace camwb::post {

namespace {

base::Status needApplication()
{
    if (!QCoreApplication::instance())
        return base::makeError("the post kernel needs a QCoreApplication (QJSEngine requires one)");
    return {};
}

// Sets up a run of `info`'s post with the options; the script is evaluated with the run's
// properties and machine, so that its top-level code sees them too.
base::Status prepare(ScriptRun& run, const PostInfo& info, const std::string& source, const RunOptions& options)
{
    auto properties = resolveProperties(info, options.properties);
    if (!properties)
        return properties.error();
    run.setProperties(properties.value());
    if (options.machine) {
        const kinematics::Machine& machine = *options.machine;
        if (!info.machines.empty() &&
            std::find(info.machines.begin(), info.machines.end(), machine.id) == info.machines.end()) {
            std::string accepted;
            for (const std::string& id : info.machines)
                accepted += (accepted.empty() ? "" : ", ") + id;
            return base::makeError("post " + info.id + " does not drive machine " + machine.id +
                                   " (it is written for: " + accepted + ")");
        }
        run.setMachine(machine);
    }
    run.setJob(options.job);
    PostInfo evaluated;
    return run.evaluate(source, evaluated);
}

std::vector<base::Diagnostic> playAndCollect(ScriptRun& run, const toolpath::Toolpath& toolpath,
                                             const RunOptions& options, base::Status& status)
{
    const ProgramSummary summary = summarizeProgram(toolpath);
    // machiningSeconds() in the script: the estimate costs a pass over the program, made only when asked.
    run.setMachiningTime([&toolpath, &options] {
        toolpath::StatsOptions stats;
        stats.rapidMmPerMin = kinematics::estimateRapidMmPerMin(options.machine ? &*options.machine : nullptr);
        return toolpath::programStats(toolpath, stats).totals.totalSeconds();
    });
    std::vector<base::Diagnostic> messages;
    if (options.machine) {
        toolpath::NullSink nowhere;
        kinematics::LimitCheck check(*options.machine, nowhere);
        toolpath::play(toolpath, check);
        messages = check.clDiagnostics();
    }
    status = run.play(toolpath, summary);
    std::vector<base::Diagnostic>& fromRun = run.messages();
    messages.insert(messages.end(), fromRun.begin(), fromRun.end());
    return messages;
}

}  // namespace

base::Result<PostProcessor> PostProcessor::load(const std::string& scriptPath, std::chrono::milliseconds scriptBudget)
{
    if (base::Status app = needApplication(); !app)
        return app.error();
    auto source = base::readTextFile(scriptPath);
    if (!source)
        return base::makeError("cannot read post script: " + source.error().message, scriptPath);

    PostProcessor post;
    post.m_source = std::move(source).value();
    ScriptRun run(scriptPath, PostContext{}, scriptBudget);
    if (base::Status status = run.evaluate(post.m_source, post.m_info); !status)
        return status.error();
    return post;
}

base::Result<PostOutput> PostProcessor::run(const toolpath::Toolpath& toolpath, const RunOptions& options) const
{
    if (base::Status app = needApplication(); !app)
        return app.error();
    ScriptRun run(m_info.filePath, options.context, options.scriptBudget);
    if (base::Status status = prepare(run, m_info, m_source, options); !status)
        return status.error();
    base::Status status;
    PostOutput output;
    output.messages = playAndCollect(run, toolpath, options, status);
    if (!status)
        return status.error();
    output.lineOperation = run.writer().lineOperations();
    output.text = run.writer().takeText();
    return output;
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
    if (base::Status app = needApplication(); !app)
        return app.error();
    ScriptRun run(m_info.filePath, options.context, options.scriptBudget);
    if (base::Status status = prepare(run, m_info, m_source, options); !status)
        return status.error();
    base::AtomicFileWriter file(outputPath);
    if (base::Status opened = file.open(); !opened)
        return opened.error();
    run.writer().streamTo([&file](std::string_view chunk) {
        file.write(chunk);
        return true;  // write failures surface at commit()
    });
    base::Status status;
    PostSummary summary;
    summary.messages = playAndCollect(run, toolpath, options, status);
    if (!status)
        return status.error();  // the writer's destructor removes the temporary file
    run.writer().finish();
    if (base::Status committed = file.commit(); !committed)
        return committed.error();
    summary.lines = run.writer().lineCount();
    summary.bytes = run.writer().byteCount();
    return summary;
}

}  // namespace camwb::post
