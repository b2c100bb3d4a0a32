// The post engine (detail/ScriptEngine.h): loading and running a post script in its own QJSEngine.
#include "post/detail/ScriptEngine.h"

#include "toolpath/ProgramStats.h"

#include "base/AtomicFile.h"
#include "kinematics/LimitCheck.h"
#include "post/ProgramSummary.h"
#include "post/detail/ScriptRun.h"
#include "toolpath/ForwardingSink.h"
#include "toolpath/MachineSink.h"

#include <QCoreApplication>

#include <algorithm>
#include <clocale>
#include <filesystem>
#include <memory>
#include <string>

namespace camwb::post {

namespace fs = std::filesystem;

namespace {

// QJSEngine needs a core application. A program without one (camwb-cli links no Qt) gets it
// here, with the first post, for the rest of the process: it is never deleted, so that it
// outlives every engine. Qt sets the C library's locale from the environment as it makes one;
// the numeric part is put back, so that the program formats numbers after its first post as it
// did before it.
void ensureApplication()
{
    if (QCoreApplication::instance())
        return;
    static int argc = 1;
    static char name[] = "camwb";
    static char* argv[] = {name, nullptr};
    static QCoreApplication* const made = [] {
        const char* current = std::setlocale(LC_NUMERIC, nullptr);
        const std::string numeric = current != nullptr ? current : "C";
        auto* app = new QCoreApplication(argc, argv);
        std::setlocale(LC_NUMERIC, numeric.c_str());
        return app;
    }();
    (void)made;
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

base::Result<PostProcessor> ScriptEngine::load(const std::string& scriptPath, std::chrono::milliseconds scriptBudget)
{
    ensureApplication();
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

base::Result<PostOutput> ScriptEngine::run(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                           const RunOptions& options)
{
    ensureApplication();
    ScriptRun run(post.m_info.filePath, options.context, options.scriptBudget);
    if (base::Status status = prepare(run, post.m_info, post.m_source, options); !status)
        return status.error();
    base::Status status;
    PostOutput output;
    output.messages = playAndCollect(run, toolpath, options, status);
    if (!status)
        return status.error();
    output.lineOperation = run.writer().lineOperations();
    output.text = run.writer().takeText();
    for (CompanionWriter& file : run.companions())
        output.files.push_back({file.name, file.writer.takeText()});
    return output;
}

base::Result<PostSummary> ScriptEngine::runToFile(const PostProcessor& post, const toolpath::Toolpath& toolpath,
                                                  const RunOptions& options, const std::string& outputPath)
{
    ensureApplication();
    ScriptRun run(post.m_info.filePath, options.context, options.scriptBudget);
    if (base::Status status = prepare(run, post.m_info, post.m_source, options); !status)
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
    if (base::Status written = file.finishWriting(); !written)
        return written.error();
    // The companion files are in memory (a post copies a few subprograms); each gets its own
    // temporary file, and nothing is renamed before all of them are written.
    const fs::path folder = fs::path(outputPath).parent_path();
    std::vector<std::unique_ptr<base::AtomicFileWriter>> companions;
    for (CompanionWriter& companion : run.companions()) {
        const fs::path target = folder / companion.name;
        std::error_code ec;
        if (fs::equivalent(target, outputPath, ec) || target.filename() == fs::path(outputPath).filename())
            return base::makeError("the post's companion file " + companion.name + " would overwrite the output " +
                                       outputPath,
                                   post.m_info.filePath);
        auto writer = std::make_unique<base::AtomicFileWriter>(target.string());
        if (base::Status opened = writer->open(); !opened)
            return opened.error();
        writer->write(companion.writer.text());
        if (base::Status written = writer->finishWriting(); !written)
            return written.error();
        summary.companionPaths.push_back(target.string());
        companions.push_back(std::move(writer));
    }
    if (base::Status committed = file.commit(); !committed)
        return committed.error();
    for (std::size_t i = 0; i < companions.size(); ++i)
        if (base::Status committed = companions[i]->commit(); !committed)
            return base::makeError(committed.error().message + " (the output and the companion files before " +
                                       summary.companionPaths[i] + " were written)",
                                   summary.companionPaths[i]);
    summary.lines = run.writer().lineCount();
    summary.bytes = run.writer().byteCount();
    return summary;
}

}  // namespace camwb::post
