#include "gui/shell/SetupSheetActions.h"

#include "document/SetupSheet.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/Workbench.h"
#include "post/PostRegistry.h"
#include "sheet/SheetFiles.h"
#include "sheet/SheetPicture.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <memory>
#include <optional>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(SetupSheetActions)
};

// What the worker makes the sheet of: the job as it was when the user asked.
struct SheetInput {
    document::Job job;
    std::string jobPath;
    occ::Model model;
    occ::DisplayMesh mesh;
    toolpath::Toolpath program;
    QImage grabbed;
    QString html;
    std::vector<base::DataDir> postDirs;
    sheet::SheetUnit unit = sheet::SheetUnit::Millimetre;
};

// The staged sheet (not yet in place), or why there is none.
struct SheetOutcome {
    std::optional<sheet::StagedSheet> staged;
    QString error;  // empty when staged or cancelled
};

// The one sheet being made (at most one at a time).
struct SheetRun {
    std::shared_ptr<std::atomic<bool>> cancel;
    bool userCancelled = false;
    bool jobChanged = false;
    QPointer<QProgressDialog> dialog;
};

// Runs on the worker thread: collects (simulates), draws and writes the sheet into temporaries.
std::shared_ptr<SheetOutcome> makeSheet(const SheetInput& input, const std::atomic<bool>* cancel,
                                        const std::function<void(int)>& progress)
{
    auto outcome = std::make_shared<SheetOutcome>();
    document::SheetOptions options;
    options.postDirs = input.postDirs;
    options.cancel = cancel;
    options.progress = [&progress](double fraction) { progress(static_cast<int>(80 * fraction)); };
    auto sheet = document::collectSetupSheet(input.job, input.jobPath, input.model, input.program, options);
    if (cancel->load())
        return outcome;
    if (!sheet) {
        outcome->error = QString::fromStdString(sheet.error().toString());
        return outcome;
    }
    progress(85);
    const sheet::SheetPicture pictures(input.mesh, input.job.stock.box(), input.program);
    sheet::SheetOutput output;
    output.htmlPath = input.html.toStdString();
    output.unit = input.unit;
    const QFileInfo info(input.html);
    output.pdfPath = info.dir().filePath(info.completeBaseName() + QStringLiteral(".pdf")).toStdString();
    if (!input.grabbed.isNull())
        output.partPicture =
            input.grabbed.scaled(sheet::kPartWidth, sheet::kPartHeight, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    auto staged = sheet::stageSetupSheet(sheet.value(), pictures, output);
    if (!staged)
        outcome->error = QString::fromStdString(staged.error().toString());
    else
        outcome->staged.emplace(std::move(staged).value());
    progress(100);
    return outcome;
}

// On the GUI thread when the worker is done: the sheet goes into place only when still wanted.
void finishSheet(Workbench* workbench, Prompter& prompter, SheetRun& run, SheetOutcome& outcome, const QString& html)
{
    if (run.dialog)
        run.dialog->deleteLater();
    if (run.jobChanged) {
        emit workbench->message(Workbench::Severity::Warning,
                                Tr::tr("The job changed while the setup sheet was being made, so it was not "
                                       "written. Make it again when the program is current."));
        return;  // the staged files go with `outcome`
    }
    if (run.userCancelled) {
        emit workbench->message(Workbench::Severity::Note, Tr::tr("Setup sheet cancelled: nothing was written"));
        return;
    }
    QString error = outcome.error;
    if (error.isEmpty() && outcome.staged) {
        if (const base::Status committed = outcome.staged->commit(); !committed)
            error = QString::fromStdString(committed.error().toString());
    }
    if (!error.isEmpty())
        prompter.showError(Tr::tr("Setup sheet"), Tr::tr("The setup sheet was not written: %1").arg(error));
    else
        emit workbench->message(Workbench::Severity::Note, Tr::tr("Setup sheet written: %1").arg(html));
}

void startSheet(Workbench* workbench, QWidget* window, const std::shared_ptr<std::optional<SheetRun>>& current,
                const std::function<Prompter&()>& prompter, SheetInput input)
{
    SheetRun& run = current->emplace();
    run.cancel = std::make_shared<std::atomic<bool>>(false);
    auto* dialog = new QProgressDialog(Tr::tr("Making the setup sheet (simulating the program)…"), Tr::tr("Cancel"), 0,
                                       100, window);
    dialog->setObjectName(QStringLiteral("setupSheetProgress"));
    dialog->setWindowTitle(Tr::tr("Setup sheet"));
    dialog->setWindowModality(Qt::NonModal);  // the window stays usable; an edit discards the sheet
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(0);
    run.dialog = dialog;
    dialog->show();
    QObject::connect(dialog, &QProgressDialog::canceled, workbench, [current] {
        if (*current) {
            (*current)->userCancelled = true;
            (*current)->cancel->store(true);
        }
    });
    const QPointer<QProgressDialog> target(dialog);
    const auto progress = [target](int percent) {
        if (target.isNull())
            return;  // the window went (the worker is being cancelled)
        QMetaObject::invokeMethod(
            target,
            [target, percent] {
                if (target)
                    target->setValue(percent);
            },
            Qt::QueuedConnection);
    };
    const QString html = input.html;
    auto* watcher = new QFutureWatcher<std::shared_ptr<SheetOutcome>>(workbench);
    QObject::connect(watcher, &QFutureWatcherBase::finished, workbench, [workbench, prompter, current, watcher, html] {
        watcher->deleteLater();
        const std::shared_ptr<SheetOutcome> outcome = watcher->result();
        SheetRun run = std::move(**current);
        current->reset();
        finishSheet(workbench, prompter(), run, *outcome, html);
    });
    // The cancel flag lives as long as the worker (it is captured by value).
    watcher->setFuture(QtConcurrent::run([input = std::move(input), cancel = run.cancel, progress] {
        return makeSheet(input, cancel.get(), progress);
    }));
}

}  // namespace

void registerSetupSheetActions(ActionRegistry& registry, const QString& menu, Workbench* workbench, QWidget* window,
                               std::function<Prompter&()> prompter, std::function<QImage()> grab)
{
    QAction* action = registry.add({"Cam.Job.SetupSheet",
                                    Tr::tr("Setup &Sheet…"),
                                    menu,
                                    {},
                                    false,
                                    false,
                                    Tr::tr("Write the setup sheet of the job for the operator: HTML and PDF")});
    auto current = std::make_shared<std::optional<SheetRun>>();
    // Any change to what the sheet shows makes the one being made out of date: it is stopped
    // and not written.
    const auto outOfDate = [current] {
        if (*current) {
            (*current)->jobChanged = true;
            (*current)->cancel->store(true);
        }
    };
    QObject::connect(workbench, &Workbench::jobChanged, workbench, outOfDate);
    QObject::connect(workbench, &Workbench::modelChanged, workbench, outOfDate);
    QObject::connect(workbench, &Workbench::toolpathChanged, workbench, outOfDate);
    // A window that goes stops the worker (it would otherwise run on, to be thrown away); the
    // workbench then waits for it.
    QObject::connect(workbench, &Workbench::closing, [current] {
        if (*current)
            (*current)->cancel->store(true);
    });
    QObject::connect(action, &QAction::triggered, workbench, [workbench, window, prompter, grab, current] {
        if (*current) {  // one at a time: show the one being made
            if ((*current)->dialog)
                (*current)->dialog->raise();
            return;
        }
        // The sheet shows the program as posted: not one that is out of date or being computed.
        if (!workbench->ncSavable())
            return;
        const QString base = QFileInfo(QString::fromStdString(workbench->document().path())).completeBaseName();
        const QString html = prompter().saveFileName(
            Tr::tr("Save setup sheet"), (base.isEmpty() ? QStringLiteral("job") : base) + QStringLiteral("-sheet.html"),
            Tr::tr("Setup sheets (*.html);;All files (*)"));
        if (html.isEmpty())
            return;
        SheetInput input;
        input.job = workbench->job();
        input.jobPath = workbench->document().path();
        if (input.jobPath.empty())
            input.jobPath = (input.job.name.empty() ? std::string("job") : input.job.name) + ".camwb";
        input.model = workbench->model();
        input.mesh = workbench->model().mesh();
        input.program = workbench->toolpath();
        input.grabbed = grab();
        input.html = html;
        input.postDirs = post::defaultPostDirs();
        // Lengths as the window shows them (the CLI's sheet stays in mm).
        input.unit = displayUnit() == LengthUnit::Inch ? sheet::SheetUnit::Inch : sheet::SheetUnit::Millimetre;
        startSheet(workbench, window, current, prompter, std::move(input));
    });
}

}  // namespace camwb::gui
