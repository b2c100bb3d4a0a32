#include "gui/shell/Workbench.h"

#include "base/AtomicFile.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "document/JobSetup.h"
#include "document/ReferenceRemap.h"
#include "document/StockBlank.h"
#include "gui/shell/NewOperation.h"
#include "gui/shell/Prompter.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"
#include "sim/MotionPlan.h"

#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <optional>
#include <utility>

namespace camwb::gui {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Progress from a worker thread, delivered on the GUI thread; false (stop) once the workbench is
// closing.
occ::ProgressFn progressReporter(Workbench* workbench, const QString& what,
                                 std::shared_ptr<const std::atomic<bool>> closing)
{
    QPointer<Workbench> target(workbench);
    return [target, what, closing](double fraction) {
        const int percent = std::clamp(static_cast<int>(fraction * 100), 0, 100);
        QMetaObject::invokeMethod(
            target.data(),
            [target, percent, what] {
                if (target)
                    emit target->progress(percent, what);
            },
            Qt::QueuedConnection);
        return !closing->load();
    };
}

// The job's tools as a tool table: what T and D mean in a program posted from the job, so the
// inspector compensates the posted G41/G42 with the radius the CL was made for.
nc::ToolTable toolTableOf(const document::Job& job)
{
    nc::ToolTable table;
    for (const ops::ToolController& tc : job.tools)
        table.set({tc.tool.number, tc.tool.number, tc.tool.diameterMm, tc.tool.lengthMm, tc.tool.name});
    return table;
}

// Planned seconds of each operation of `program` on `machine` (by job index; -1: not in it), as
// the program information plans the whole program: the job tree shows them.
std::vector<double> plannedOperationSeconds(const toolpath::Toolpath& program, std::size_t operations,
                                            const kinematics::Machine& machine)
{
    sim::MoveOptions options;
    if (machine.kinematics.fiveAxis())
        options.chain = &machine.kinematics;
    const sim::MoveList moves = sim::buildMoves(program, options);
    std::vector<double> seconds(operations, -1.0);
    for (const auto& [operation, s] : sim::secondsPerOperation(program, moves, sim::planMotion(moves, machine)))
        if (operation >= 0 && operation < static_cast<int>(operations))
            seconds[static_cast<std::size_t>(operation)] = s;
    return seconds;
}

}  // namespace

// What a background compute brings back; empty optionals mean "unchanged".
namespace {

// What a blank stock's mesh was read for: its file and the origin it is moved by; empty for the
// other shapes.
std::string stockBlankKey(const document::Job& job)
{
    if (job.stock.shape != document::Stock::Shape::Blank)
        return {};
    const base::Vec3& o = job.origin;
    return job.stock.blankPath + "@" + std::to_string(o.x) + "," + std::to_string(o.y) + "," + std::to_string(o.z);
}

QString stockText(const document::Stock& stock)
{
    const base::Vec3 size = stock.max - stock.min;
    return Workbench::tr("%1 × %2 × %3 mm from (%4, %5, %6)")
        .arg(size.x, 0, 'g', 6)
        .arg(size.y, 0, 'g', 6)
        .arg(size.z, 0, 'g', 6)
        .arg(stock.min.x, 0, 'g', 6)
        .arg(stock.min.y, 0, 'g', 6)
        .arg(stock.min.z, 0, 'g', 6);
}

}  // namespace

struct Workbench::ComputeOutcome {
    std::optional<occ::Model> model;
    std::string modelPath;
    base::Vec3 modelOrigin;  // the job origin the model was moved by
    occ::DisplayMesh mesh;
    std::shared_ptr<const sim::TriangleMesh> stockBlank;  // read for `stockBlankKey`
    std::string stockBlankKey;
    // The job's stock as its model or blank gives it now, when that is not the stored one.
    std::optional<document::Stock> storedStock, resolvedStock;
    std::optional<toolpath::Toolpath> toolpath;
    std::optional<post::PostOutput> nc;
    std::string ncExtension;
    std::shared_ptr<const kinematics::Machine> machine;  // what the post checked the program against
    std::shared_ptr<const nc::ToolTable> tools;          // the job's tools, as the program was posted
    std::shared_ptr<const post::PostInfo> postInfo;      // the post it was posted with
    std::vector<base::Diagnostic> warnings;              // the operations' (left corners, helix fallbacks, ...)
    std::vector<std::string> errors;
    std::vector<document::OperationFailure> failures;  // every operation that cannot be made
    std::vector<double> operationSeconds;              // planned, by operation index
    bool modelFailed = false;                          // the job's model could not be read
    int generation = 0;
    std::optional<document::RemappedOperations> remap;  // import: the operations on the new model
};

Workbench::Workbench(QObject* parent) : QObject(parent)
{
    m_document.setChangedListener([this] {
        m_operationSeconds.clear();  // by the old indices; the compute this change starts fills them
        emit jobChanged();
        if (!m_suppressRecompute)
            startCompute();
    });
}

// Its background work is stopped and waited for: left running it would outlive the application
// (the post's script engine then aborts the process as it exits).
Workbench::~Workbench()
{
    m_closing->store(true);
    emit closing();
    for (QFutureWatcherBase* watcher : findChildren<QFutureWatcherBase*>(Qt::FindDirectChildrenOnly))
        watcher->waitForFinished();
}

QString Workbench::operationProblem(int index) const
{
    return index >= 0 && index < static_cast<int>(m_operationProblems.size())
               ? m_operationProblems[static_cast<std::size_t>(index)]
               : QString();
}

bool Workbench::openJob(const QString& path)
{
    auto job = document::loadJob(path.toStdString());
    if (!job) {
        fail(tr("Open job"), qs(job.error().toString()));
        return false;
    }
    setJob(std::move(job.value()), path);
    report(Severity::Note, tr("Opened job %1").arg(path));
    return true;
}

void Workbench::setJob(document::Job job, const QString& path)
{
    ++m_generation;  // a compute of the previous job still running is not applied
    m_suppressRecompute = true;
    m_document.reset(std::move(job), path.toStdString());
    m_suppressRecompute = false;
    // Nothing of the previous job may stay on screen or be computed on: its model, toolpath and
    // NC go now, not when (or if) this job's model has loaded.
    clearDerived();
    m_showComputeFailure = true;
    m_checkStoredStock = true;
    startCompute();
}

void Workbench::clearDerived()
{
    m_model = {};
    m_modelPath.clear();  // always read the model again: the file may have changed on disk
    m_mesh = {};
    m_stockBlank.reset();  // read again too
    m_stockBlankKey.clear();
    m_toolpath = {};
    m_nc.clear();
    m_programProblem.clear();
    m_modelProblem.clear();
    m_operationProblems.clear();
    m_operationSeconds.clear();
    emit modelChanged();
    emit stockBlankChanged();
    emit toolpathChanged();
    emit ncChanged();
    emit programStateChanged();
}

bool Workbench::saveJob(const QString& path)
{
    if (base::Status saved = m_document.saveAs(path.toStdString()); !saved) {
        fail(tr("Save job"), qs(saved.error().toString()));
        return false;
    }
    report(Severity::Note, tr("Saved job %1").arg(path));
    return true;
}

void Workbench::post()
{
    m_showComputeFailure = true;
    startCompute();
}

bool Workbench::ncSavable()
{
    if (m_busy) {
        // Every edit starts a compute at once: while it runs, the program is of the job before.
        fail(tr("Save NC program"), tr("The job is being computed; save the NC program when the post has finished."));
        return false;
    }
    if (!isProgramCurrent()) {
        fail(tr("Save NC program"),
             tr("The NC program is out of date and was not saved: %1\nFix the job and post it again.")
                 .arg(m_programProblem));
        return false;
    }
    if (m_nc.isEmpty()) {
        fail(tr("Save NC program"), tr("There is no NC program to save; post the job first."));
        return false;
    }
    return true;
}

bool Workbench::saveNc(const QString& path)
{
    if (!ncSavable())
        return false;
    if (base::Status written = base::writeFileAtomically(path.toStdString(), m_nc.toStdString()); !written) {
        fail(tr("Save NC program"), qs(written.error().toString()));
        return false;
    }
    report(Severity::Note, tr("Wrote NC program %1").arg(path));
    return true;
}

void Workbench::importModel(const QString& path)
{
    if (m_busy) {
        fail(tr("Import model"), tr("Busy; import the model again when the current work has finished."));
        emit modelImportFinished(false);
        return;
    }
    setBusy(true);
    const std::string file = QFileInfo(path).absoluteFilePath().toStdString();
    auto progress = progressReporter(this, tr("Importing %1").arg(QFileInfo(path).fileName()), m_closing);
    auto* watcher = new QFutureWatcher<std::shared_ptr<ComputeOutcome>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, file] {
        std::shared_ptr<ComputeOutcome> outcome = watcher->result();
        watcher->deleteLater();
        setBusy(false);
        finishImport(file, outcome);
    });
    document::Job target = job();  // the new model in the job's work coordinates
    target.modelPath = file;
    watcher->setFuture(QtConcurrent::run([target, progress, previous = m_model, operations = job().operations] {
        auto outcome = std::make_shared<ComputeOutcome>();
        auto model = document::loadJobModel(target, progress);
        if (!model) {
            outcome->errors.push_back(model.error().toString());
            return outcome;
        }
        outcome->mesh = model->mesh();
        outcome->remap = document::remapReferences(operations, previous, model.value());
        outcome->model = std::move(model.value());
        return outcome;
    }));
}

void Workbench::finishImport(const std::string& file, const std::shared_ptr<ComputeOutcome>& outcome)
{
    if (!outcome->model) {
        // The job stays exactly as it was.
        for (const std::string& e : outcome->errors)
            fail(tr("Import model"), qs(e));
        emit modelImportFinished(false);
        return;
    }
    const document::RemappedOperations& remap = *outcome->remap;
    const std::vector<document::Operation>& operations = job().operations;
    // What happens to operations whose references are not in the new model: asked, never silent.
    Prompter::Answer answer = Prompter::Answer::Accept;
    if (!remap.checked && !operations.empty()) {
        const Prompter::Question question{
            tr("Import model"),
            tr("The previous model is not loaded, so the references of the %n operation(s) cannot be checked "
               "against %1. Keep them with their face, edge and hole numbers (check each operation), or delete "
               "them?",
               nullptr, static_cast<int>(operations.size()))
                .arg(qs(file)),
            tr("Keep the operations"), tr("Delete the operations")};
        answer = m_prompter ? m_prompter->ask(question) : Prompter::Answer::Cancel;
    } else if (!remap.lost.empty()) {
        const Prompter::Question question{
            tr("Import model"),
            tr("These references of the operations are not in %1:\n%2\n\nKeep the operations without them "
               "(they are marked until you choose new geometry in their task panels), or delete the operations "
               "that lost references?")
                .arg(qs(file), qs(document::describeLost(remap.lost, operations))),
            tr("Keep the operations"), tr("Delete those operations")};
        answer = m_prompter ? m_prompter->ask(question) : Prompter::Answer::Cancel;
    }
    if (answer == Prompter::Answer::Cancel) {
        report(Severity::Note, tr("Import of %1 cancelled; the job is unchanged.").arg(qs(file)));
        emit modelImportFinished(false);
        return;
    }
    std::vector<document::Operation> kept = remap.operations;
    if (answer == Prompter::Answer::Discard) {
        std::vector<bool> drop(kept.size(), !remap.checked);
        for (const document::LostReference& l : remap.lost)
            drop[static_cast<std::size_t>(l.operation)] = true;
        std::vector<document::Operation> remaining;
        for (std::size_t i = 0; i < kept.size(); ++i)
            if (!drop[i])
                remaining.push_back(std::move(kept[i]));
        report(Severity::Note, tr("Deleted %n operation(s) that lost references.", nullptr,
                                  static_cast<int>(kept.size() - remaining.size())));
        kept = std::move(remaining);
    } else if (!remap.lost.empty()) {
        report(Severity::Warning, tr("Kept the operations; these references are not in the new model:\n%1")
                                      .arg(qs(document::describeLost(remap.lost, operations))));
    }

    m_model = std::move(*outcome->model);
    m_modelPath = file;
    m_modelOrigin = job().origin;
    m_mesh = std::move(outcome->mesh);
    m_modelProblem.clear();
    emit modelChanged();
    report(Severity::Note, tr("Imported %1 (%2 faces)").arg(qs(file)).arg(m_model.faceCount()));
    const base::Vec3 lo = m_model.boundsMin(), hi = m_model.boundsMax();
    const bool hadModel = !job().modelPath.empty();
    m_document.edit("Import model", [&](document::Job& j) {
        j.modelPath = file;
        if (!hadModel && !j.stock.fromModel) {
            j.stock.min = lo;
            j.stock.max = hi;
        }
        j.stock.resolve(lo, hi);  // a "from model" stock follows the new model
        j.operations = kept;
    });
    emit modelImportFinished(true);
}

bool Workbench::addOperation(document::OperationKind kind, const std::vector<int>& selectedFaces)
{
    auto proposal = proposeOperation(kind, job(), m_model, selectedFaces);
    if (!proposal) {
        report(Severity::Error, qs(proposal.error().toString()));
        return false;
    }
    addOperation(proposal->operation, proposal->newTool);
    return true;
}

void Workbench::addOperation(const document::Operation& operation, const std::optional<ops::ToolController>& newTool)
{
    m_document.edit("New " + operation.name(), [&](document::Job& j) {
        if (newTool && j.tool(newTool->tool.number) == nullptr)
            j.tools.push_back(*newTool);
        j.operations.push_back(operation);
    });
}

void Workbench::updateOperation(int index, const document::Operation& operation)
{
    if (index < 0 || index >= static_cast<int>(job().operations.size()))
        return;
    document::Job edited = job();
    edited.operations[index] = operation;
    m_document.replace("Edit " + operation.name(), std::move(edited));  // OK without a change: no step
}

void Workbench::removeOperation(int index)
{
    if (index < 0 || index >= static_cast<int>(job().operations.size()))
        return;
    m_document.edit("Delete " + job().operations[index].name(),
                    [&](document::Job& j) { j.operations.erase(j.operations.begin() + index); });
}

void Workbench::moveOperation(int from, int to)
{
    const int count = static_cast<int>(job().operations.size());
    if (from < 0 || from >= count || to < 0 || to >= count || from == to)
        return;
    m_document.edit("Move " + job().operations[from].name(), [&](document::Job& j) {
        document::Operation moved = std::move(j.operations[from]);
        j.operations.erase(j.operations.begin() + from);
        j.operations.insert(j.operations.begin() + to, std::move(moved));
    });
}

void Workbench::setOperationEnabled(int index, bool enabled)
{
    if (index < 0 || index >= static_cast<int>(job().operations.size()) || job().operations[index].enabled == enabled)
        return;
    m_document.edit((enabled ? "Enable " : "Disable ") + job().operations[index].name(),
                    [&](document::Job& j) { j.operations[index].enabled = enabled; });
}

void Workbench::duplicateOperation(int index)
{
    if (index < 0 || index >= static_cast<int>(job().operations.size()))
        return;
    document::Operation copy = job().operations[index];
    copy.setName(copy.name() + " (copy)");
    m_document.edit("Duplicate " + job().operations[index].name(),
                    [&](document::Job& j) { j.operations.insert(j.operations.begin() + index + 1, copy); });
}

void Workbench::renameOperation(int index, const QString& name)
{
    const std::string text = name.trimmed().toStdString();
    if (index < 0 || index >= static_cast<int>(job().operations.size()) || text.empty() ||
        text == job().operations[index].name())
        return;
    m_document.edit("Rename " + job().operations[index].name(),
                    [&](document::Job& j) { j.operations[index].setName(text); });
}

double Workbench::operationSeconds(int index) const
{
    return index >= 0 && index < static_cast<int>(m_operationSeconds.size())
               ? m_operationSeconds[static_cast<std::size_t>(index)]
               : -1.0;
}

bool Workbench::setJobSetup(const document::Job& setup)
{
    document::Stock stock = setup.stock;
    if (!m_model.empty()) {
        // m_model is in the coordinates of m_modelOrigin; the stock is in those of setup.origin.
        const base::Vec3 shift = m_modelOrigin - setup.origin;
        stock.resolve(m_model.boundsMin() + shift, m_model.boundsMax() + shift);
    }
    document::Job edited = job();
    std::vector<QString> notes;
    // The panel's form already holds the values the (new) post takes; operations' own values
    // follow the post as Post Settings does (setPost), and what is dropped is reported.
    if (setup.postId != edited.postId &&
        !switchPostIn(edited, setup.postId, setup.machineId, setup.postProperties, notes))
        return false;
    edited.postProperties = setup.postProperties;
    document::moveOrigin(edited, setup.origin);  // the operations' height overrides stay on the part
    edited.stock = stock;
    edited.workOffset = setup.workOffset;
    edited.machineId = setup.machineId;
    edited.outputName = setup.outputName;
    edited.outputFolder = setup.outputFolder;
    if (!m_document.replace("Job setup", std::move(edited)))
        return true;  // no empty undo step
    for (const QString& note : notes)
        report(Severity::Warning, note);
    return true;
}

void Workbench::undo() { m_document.undo(); }
void Workbench::redo() { m_document.redo(); }

void Workbench::startCompute()
{
    if (m_busy) {
        m_recomputePending = true;
        return;
    }
    setBusy(true);
    const document::Job job = this->job();
    const occ::Model model = m_model;
    // The model is held in work coordinates: a moved origin reloads it too.
    const bool reloadModel = job.modelPath != m_modelPath || !(job.origin == m_modelOrigin);
    auto progress = progressReporter(this, tr("Loading model"), m_closing);
    std::shared_ptr<const std::atomic<bool>> stop = m_closing;
    const std::string programName = QFileInfo(qs(m_document.path())).completeBaseName().toStdString();
    const int generation = m_generation;
    const std::string blankKey = stockBlankKey(job);
    const bool reloadBlank = !blankKey.empty() && (blankKey != m_stockBlankKey || !m_stockBlank);
    std::shared_ptr<const sim::TriangleMesh> blank = blankKey.empty() ? nullptr : m_stockBlank;
    const bool checkStoredStock = std::exchange(m_checkStoredStock, false);
    const std::string jobPath = m_document.path();

    auto* watcher = new QFutureWatcher<std::shared_ptr<ComputeOutcome>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        std::shared_ptr<ComputeOutcome> outcome = watcher->result();
        watcher->deleteLater();
        finishCompute(outcome);
    });
    watcher->setFuture(QtConcurrent::run([job, model, reloadModel, progress, programName, generation, blankKey,
                                          reloadBlank, blank, checkStoredStock, jobPath, stop] {
        auto outcome = std::make_shared<ComputeOutcome>();
        outcome->generation = generation;
        if (job.modelPath.empty() && document::jobNeedsModel(job))
            return outcome;  // a new job: nothing to compute yet (a lathe job's grooves need no model)
        occ::Model current = model;
        if (reloadModel) {
            auto loaded = document::loadJobModel(job, progress);
            if (!loaded) {
                outcome->modelFailed = true;
                outcome->errors.push_back(loaded.error().toString());
                return outcome;
            }
            current = std::move(loaded.value());
            outcome->mesh = current.mesh();
            outcome->model = current;
            outcome->modelPath = job.modelPath;
            outcome->modelOrigin = job.origin;
        }
        // A blank stock is its file's solid, read again when the file or the origin changes.
        std::shared_ptr<const sim::TriangleMesh> currentBlank = blank;
        if (reloadBlank) {
            auto loaded = document::loadStockBlank(job, jobPath);
            if (!loaded) {
                outcome->errors.push_back(loaded.error().toString());
                return outcome;
            }
            currentBlank = std::make_shared<const sim::TriangleMesh>(std::move(loaded.value()));
            outcome->stockBlank = currentBlank;
            outcome->stockBlankKey = blankKey;
        }
        // A "from model" stock follows the model as loaded, as camwb-cli's pipeline does; a blank
        // stock's box is its file's.
        document::Job resolved = job;
        document::resolveJobStock(resolved, current);
        if (currentBlank)
            document::resolveStockBlank(resolved.stock, *currentBlank);
        if (checkStoredStock && !(resolved.stock == job.stock)) {
            outcome->storedStock = job.stock;
            outcome->resolvedStock = resolved.stock;
        }
        document::ProgramReport report;
        report.allFailures = true;  // the job tree marks every operation that cannot be made
        auto program = document::computeProgram(resolved, current, ops::Progress{{}, stop.get()}, &report);
        outcome->warnings = std::move(report.warnings);
        outcome->failures = std::move(report.failures);
        if (!program) {
            for (const document::OperationFailure& f : outcome->failures)
                outcome->errors.push_back(f.message);
            if (outcome->failures.empty())
                outcome->errors.push_back(program.error().message);
            return outcome;
        }
        outcome->toolpath = program.value();
        if (stop->load())
            return outcome;  // the workbench is closing: nobody waits for the program
        auto post = document::loadJobPost(job, post::defaultPostDirs());
        if (!post) {
            outcome->errors.push_back(post.error().toString());
            return outcome;
        }
        outcome->ncExtension = post->info().extension;
        outcome->postInfo = std::make_shared<const post::PostInfo>(post->info());
        post::PostContext context = post::PostContext::fromEnvironment(programName);
        context.outputName = programName;  // Save NC File proposes the job's name
        auto options = document::jobRunOptions(resolved, post.value(), context, kinematics::defaultMachineDirs());
        if (!options) {
            outcome->errors.push_back(options.error().toString());
            return outcome;
        }
        if (options->machine)
            outcome->machine = std::make_shared<const kinematics::Machine>(*options->machine);
        outcome->operationSeconds =
            plannedOperationSeconds(program.value(), job.operations.size(),
                                    options->machine ? *options->machine : kinematics::defaultLimitsMachine());
        outcome->tools = std::make_shared<const nc::ToolTable>(toolTableOf(job));
        auto nc = post->run(program.value(), options.value());
        if (!nc) {
            outcome->errors.push_back(nc.error().toString());
            return outcome;
        }
        outcome->nc = std::move(nc.value());
        return outcome;
    }));
}

void Workbench::finishCompute(const std::shared_ptr<ComputeOutcome>& outcome)
{
    if (outcome->generation != m_generation) {
        // Computed for a job that is no longer open: the pending recompute is for this one.
        setBusy(false);
        if (std::exchange(m_recomputePending, false))
            startCompute();
        return;
    }
    if (outcome->modelFailed) {
        // The job's model cannot be read: nothing may be shown or computed from another one.
        m_model = {};
        m_modelPath.clear();
        m_mesh = {};
        m_toolpath = {};
        m_nc.clear();
        emit modelChanged();
        emit toolpathChanged();
        emit ncChanged();
    }
    if (outcome->model) {
        m_model = std::move(*outcome->model);
        m_modelPath = outcome->modelPath;
        m_modelOrigin = outcome->modelOrigin;
        m_mesh = std::move(outcome->mesh);
        emit modelChanged();
    }
    if (outcome->stockBlank) {
        m_stockBlank = outcome->stockBlank;
        m_stockBlankKey = outcome->stockBlankKey;
        emit stockBlankChanged();
    }
    if (outcome->toolpath) {
        m_toolpath = std::move(*outcome->toolpath);
        const toolpath::ToolpathStats stats = toolpath::statistics(m_toolpath);
        report(Severity::Note, tr("Toolpath: %1 lines, %2 arcs, %3 rapids")
                                   .arg(stats.lines)
                                   .arg(stats.arcs + stats.helices)
                                   .arg(stats.rapids));
        emit toolpathChanged();
    }
    for (const base::Diagnostic& w : outcome->warnings)
        report(w.severity, qs(w.message));
    if (outcome->nc) {
        m_nc = qs(outcome->nc->text);
        m_ncExtension = qs(outcome->ncExtension);
        m_machine = outcome->machine;
        m_tools = outcome->tools;
        m_postInfo = outcome->postInfo;
        for (const base::Diagnostic& m : outcome->nc->messages)
            report(m.severity, qs(base::formatDiagnostic(m)));
        report(Severity::Note, tr("Posted %1 lines with %2").arg(m_nc.count('\n')).arg(qs(job().postId)));
        emit ncChanged();
    }
    for (const std::string& e : outcome->errors)
        report(Severity::Error, qs(e));
    applyProblems(*outcome);
    if (std::exchange(m_showComputeFailure, false) && !outcome->errors.empty() && m_prompter != nullptr)
        m_prompter->showError(outcome->modelFailed ? tr("Open job") : tr("Post"), m_programProblem);  // reported above
    setBusy(false);
    // The stored stock box was resolved against a model or blank that has changed on disk since:
    // the job takes the box the files give now (the NC was computed from it already), said so.
    if (outcome->resolvedStock && job().stock == *outcome->storedStock) {
        report(Severity::Warning,
               tr("The stock stored in the job (%1) is not what its %2 gives now (%3): the "
                  "file changed since the job was saved. The job now uses the new stock.")
                   .arg(stockText(*outcome->storedStock),
                        outcome->resolvedStock->shape == document::Stock::Shape::Blank ? tr("blank file") : tr("model"),
                        stockText(*outcome->resolvedStock)));
        const document::Stock stock = *outcome->resolvedStock;
        m_document.edit("Stock follows its file", [&stock](document::Job& j) { j.stock = stock; });
    }
    emit postFinished(outcome->errors.empty());
    if (m_recomputePending) {
        m_recomputePending = false;
        startCompute();
    }
}

// What the window marks: the program out of date, each operation that cannot be made, the model.
void Workbench::applyProblems(const ComputeOutcome& outcome)
{
    QStringList errors;
    for (const std::string& e : outcome.errors)
        errors << qs(e);
    m_programProblem = errors.join(QLatin1Char('\n'));
    m_modelProblem = outcome.modelFailed ? m_programProblem : QString();
    m_operationProblems.assign(job().operations.size(), QString());
    m_operationSeconds = outcome.operationSeconds;
    for (QString& problem : m_operationProblems)
        problem = outcome.modelFailed ? tr("unresolved: the model is not loaded (%1)").arg(m_modelProblem) : QString();
    for (const document::OperationFailure& f : outcome.failures)
        if (f.operation >= 0 && f.operation < static_cast<int>(m_operationProblems.size()))
            m_operationProblems[static_cast<std::size_t>(f.operation)] = qs(f.message);
    emit programStateChanged();
}

void Workbench::setBusy(bool busy)
{
    if (m_busy == busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

void Workbench::report(Severity severity, const QString& text) { emit message(severity, text); }

void Workbench::fail(const QString& title, const QString& text)
{
    report(Severity::Error, text);
    if (m_prompter != nullptr)
        m_prompter->showError(title, text);
}

}  // namespace camwb::gui
