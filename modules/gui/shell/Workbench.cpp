#include "gui/shell/Workbench.h"

#include "base/AtomicFile.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "gui/shell/NewOperation.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"

#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <optional>

namespace camwb::gui {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Progress from a worker thread, delivered on the GUI thread.
occ::ProgressFn progressReporter(Workbench* workbench, const QString& what)
{
    QPointer<Workbench> target(workbench);
    return [target, what](double fraction) {
        const int percent = std::clamp(static_cast<int>(fraction * 100), 0, 100);
        QMetaObject::invokeMethod(
            target.data(),
            [target, percent, what] {
                if (target)
                    emit target->progress(percent, what);
            },
            Qt::QueuedConnection);
        return true;
    };
}

}  // namespace

// What a background compute brings back; empty optionals mean "unchanged".
struct Workbench::ComputeOutcome {
    std::optional<occ::Model> model;
    std::string modelPath;
    occ::DisplayMesh mesh;
    std::optional<toolpath::Toolpath> toolpath;
    std::optional<post::PostOutput> nc;
    std::string ncExtension;
    std::vector<base::Diagnostic> warnings;  // the operations' (left corners, helix fallbacks, ...)
    std::vector<std::string> errors;
};

Workbench::Workbench(QObject* parent) : QObject(parent)
{
    m_document.setChangedListener([this] {
        emit jobChanged();
        if (!m_suppressRecompute)
            startCompute();
    });
}

Workbench::~Workbench() = default;

bool Workbench::openJob(const QString& path)
{
    auto job = document::loadJob(path.toStdString());
    if (!job) {
        report(Severity::Error, qs(job.error().toString()));
        return false;
    }
    m_suppressRecompute = true;
    m_modelPath.clear();  // always read the model again: the file may have changed on disk
    m_document.reset(std::move(job.value()), path.toStdString());
    m_suppressRecompute = false;
    report(Severity::Note, tr("Opened job %1").arg(path));
    startCompute();
    return true;
}

bool Workbench::saveJob(const QString& path)
{
    if (base::Status saved = m_document.saveAs(path.toStdString()); !saved) {
        report(Severity::Error, qs(saved.error().toString()));
        return false;
    }
    report(Severity::Note, tr("Saved job %1").arg(path));
    return true;
}

void Workbench::post() { startCompute(); }

bool Workbench::saveNc(const QString& path)
{
    if (m_nc.isEmpty()) {
        report(Severity::Error, tr("There is no NC program to save; post the job first."));
        return false;
    }
    if (base::Status written = base::writeFileAtomically(path.toStdString(), m_nc.toStdString()); !written) {
        report(Severity::Error, qs(written.error().toString()));
        return false;
    }
    report(Severity::Note, tr("Wrote NC program %1").arg(path));
    return true;
}

void Workbench::importModel(const QString& path)
{
    if (m_busy) {
        report(Severity::Warning, tr("Busy; import the model again when the current work has finished."));
        emit modelImportFinished(false);
        return;
    }
    setBusy(true);
    const std::string file = QFileInfo(path).absoluteFilePath().toStdString();
    auto progress = progressReporter(this, tr("Importing %1").arg(QFileInfo(path).fileName()));
    auto* watcher = new QFutureWatcher<std::shared_ptr<ComputeOutcome>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, file] {
        std::shared_ptr<ComputeOutcome> outcome = watcher->result();
        watcher->deleteLater();
        setBusy(false);
        if (!outcome->model) {
            // The job stays exactly as it was.
            for (const std::string& e : outcome->errors)
                report(Severity::Error, qs(e));
            emit modelImportFinished(false);
            return;
        }
        m_model = std::move(*outcome->model);
        m_modelPath = file;
        m_mesh = std::move(outcome->mesh);
        emit modelChanged();
        report(Severity::Note, tr("Imported %1 (%2 faces)").arg(qs(file)).arg(m_model.faceCount()));
        const base::Vec3 lo = m_model.boundsMin(), hi = m_model.boundsMax();
        const bool hadModel = !job().modelPath.empty();
        m_document.edit("Import model", [&](document::Job& j) {
            j.modelPath = file;
            if (!hadModel)
                j.stock = {lo, hi};
            // Faces of another model mean nothing for this one.
            if (hadModel)
                j.operations.clear();
        });
        emit modelImportFinished(true);
    });
    watcher->setFuture(QtConcurrent::run([file, progress] {
        auto outcome = std::make_shared<ComputeOutcome>();
        auto model = occ::Model::load(file, progress);
        if (!model) {
            outcome->errors.push_back(model.error().toString());
            return outcome;
        }
        outcome->mesh = model->mesh();
        outcome->model = std::move(model.value());
        return outcome;
    }));
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
    if (document::serializeJob(edited) == document::serializeJob(job()))
        return;  // OK without a change: no empty undo step
    m_document.edit("Edit " + operation.name(), [&](document::Job& j) { j.operations[index] = operation; });
}

void Workbench::removeOperation(int index)
{
    if (index < 0 || index >= static_cast<int>(job().operations.size()))
        return;
    m_document.edit("Delete " + job().operations[index].name(),
                    [&](document::Job& j) { j.operations.erase(j.operations.begin() + index); });
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
    const bool reloadModel = job.modelPath != m_modelPath;
    auto progress = progressReporter(this, tr("Loading model"));
    const std::string programName = QFileInfo(qs(m_document.path())).completeBaseName().toStdString();

    auto* watcher = new QFutureWatcher<std::shared_ptr<ComputeOutcome>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        std::shared_ptr<ComputeOutcome> outcome = watcher->result();
        watcher->deleteLater();
        finishCompute(outcome);
    });
    watcher->setFuture(QtConcurrent::run([job, model, reloadModel, progress, programName] {
        auto outcome = std::make_shared<ComputeOutcome>();
        if (job.modelPath.empty())
            return outcome;  // a new job: nothing to compute yet
        occ::Model current = model;
        if (reloadModel) {
            auto loaded = document::loadJobModel(job, progress);
            if (!loaded) {
                outcome->errors.push_back(loaded.error().toString());
                return outcome;
            }
            current = std::move(loaded.value());
            outcome->mesh = current.mesh();
            outcome->model = current;
            outcome->modelPath = job.modelPath;
        }
        document::ProgramReport report;
        auto program = document::computeProgram(job, current, {}, &report);
        outcome->warnings = std::move(report.warnings);
        if (!program) {
            outcome->errors.push_back(program.error().message);
            return outcome;
        }
        outcome->toolpath = program.value();
        auto post = document::loadJobPost(job, post::defaultPostDirs());
        if (!post) {
            outcome->errors.push_back(post.error().toString());
            return outcome;
        }
        outcome->ncExtension = post->info().extension;
        auto options = document::jobRunOptions(job, post.value(), post::PostContext::fromEnvironment(programName),
                                               kinematics::defaultMachineDirs());
        if (!options) {
            outcome->errors.push_back(options.error().toString());
            return outcome;
        }
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
    if (outcome->model) {
        m_model = std::move(*outcome->model);
        m_modelPath = outcome->modelPath;
        m_mesh = std::move(outcome->mesh);
        emit modelChanged();
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
        for (const base::Diagnostic& m : outcome->nc->messages)
            report(m.severity, qs(base::formatDiagnostic(m)));
        report(Severity::Note, tr("Posted %1 lines with %2").arg(m_nc.count('\n')).arg(qs(job().postId)));
        emit ncChanged();
    }
    for (const std::string& e : outcome->errors)
        report(Severity::Error, qs(e));
    setBusy(false);
    emit postFinished(outcome->errors.empty());
    if (m_recomputePending) {
        m_recomputePending = false;
        startCompute();
    }
}

void Workbench::setBusy(bool busy)
{
    if (m_busy == busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

void Workbench::report(Severity severity, const QString& text) { emit message(severity, text); }

}  // namespace camwb::gui
