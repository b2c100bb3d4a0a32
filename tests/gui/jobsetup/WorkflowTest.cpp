// The job a newcomer builds in the window without touching a text file, from an empty job: import
// the example STEP, stock from the model's bounds + 2 mm, the work origin on the stock's top
// corner, machine and post chosen and a post property changed (Job Setup), a tool from the tool
// library, a pocket; posted, the NC equals the golden and what `camwb-cli run` makes of the saved
// job; then every step undone, one at a time, back to the empty job. Under Xvfb and offscreen.
// CAMWB_UPDATE_GOLDEN=1 writes the golden.
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/JobSetupPanel.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PostPropertiesForm.h"
#include "gui/tools/ToolActions.h"
#include "gui/tools/ToolLibraryDialog.h"
#include "gui/view3d/View3D.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

using camwb::gui::JobSetupPanel;
using camwb::gui::MainWindow;
using camwb::gui::Prompter;
using camwb::gui::ToolLibraryDialog;
using camwb::gui::Workbench;

namespace {

std::string jobText(MainWindow& window) { return camwb::document::serializeJob(window.workbench().job()); }

QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void waitIdle(MainWindow& window)
{
    QElapsedTimer waited;
    waited.start();
    while (window.workbench().isBusy() && waited.elapsed() < 120000)
        QTest::qWait(20);
    QVERIFY(!window.workbench().isBusy());
}

bool chooseText(QWidget* panel, const char* combo, const QString& text)
{
    auto* box = panel->findChild<QComboBox*>(QLatin1String(combo));
    const int index = box ? box->findText(text) : -1;
    if (index >= 0)
        box->setCurrentIndex(index);
    return index >= 0;
}

}  // namespace

class WorkflowTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QFile::remove(camwb::gui::userToolLibraryPath()); }

    void newcomerBuildsTheExampleJobInTheWindow()
    {
        QTemporaryDir dir;
        MainWindow window;
        auto owned = std::make_unique<ScriptedPrompter>();
        ScriptedPrompter* prompter = owned.get();
        window.setPrompter(std::move(owned));
        window.show();
        Workbench& wb = window.workbench();
        const std::string empty = jobText(window);
        std::vector<std::string> states{empty};  // the job after each step

        // 1. The model.
        QSignalSpy imported(&wb, &Workbench::modelImportFinished);
        prompter->files = {QStringLiteral(CAMWB_EXAMPLE_STEP)};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.count() > 0 || imported.wait(120000));
        QVERIFY(imported.last().first().toBool());
        waitIdle(window);
        states.push_back(jobText(window));

        // 2. Job setup: stock from the bounds + 2 mm, origin on its top front left corner, the
        // EMCO and its SINUMERIK post, block numbers in steps of 5.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Setup")));
        JobSetupPanel* panel = window.jobSetupPanel();
        QVERIFY(panel);
        panel->findChild<QComboBox*>(QStringLiteral("stockSize"))->setCurrentIndex(0);
        for (const char* axis : {"X", "Y", "Z"})
            for (const char* side : {"stockBelow", "stockAbove"}) {
                auto* spin = panel->findChild<QDoubleSpinBox*>(QLatin1String(side) + QLatin1String(axis));
                QVERIFY(spin);
                spin->setValue(2);
            }
        panel->findChild<QComboBox*>(QStringLiteral("originAnchor"))->setCurrentIndex(1);
        QVERIFY(chooseText(panel, "machine", QStringLiteral("emco-concept-mill-105")));
        QVERIFY(chooseText(panel, "post", QStringLiteral("sinumerik828d-emco")));
        auto* step = qobject_cast<QSpinBox*>(panel->postProperties()->editor("sequenceStep"));
        QVERIFY(step);
        step->setValue(5);
        QVERIFY(panel->findChild<QAbstractButton*>(QStringLiteral("okButton")));
        panel->findChild<QAbstractButton*>(QStringLiteral("okButton"))->click();
        QVERIFY(window.jobSetupPanel() == nullptr);
        QCOMPARE(wb.job().postProperties.at("sequenceStep"), std::string("5"));
        QCOMPARE(wb.job().machineId, std::string("emco-concept-mill-105"));
        waitIdle(window);
        states.push_back(jobText(window));

        // 3. A tool from the library (copied into the job).
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Tools.Library")));
        auto* library = window.findChild<ToolLibraryDialog*>();
        QVERIFY(library);
        int d6 = -1;
        for (std::size_t i = 0; i < library->library().tools.size(); ++i)
            if (library->library().tools[i].tool.name == "Flat end mill D6")
                d6 = static_cast<int>(i);
        QVERIFY(d6 >= 0);
        library->selectTools({d6});
        library->findChild<QPushButton*>(QStringLiteral("addToJob"))->click();
        QCOMPARE(int(wb.job().tools.size()), 1);
        library->findChild<QPushButton*>(QStringLiteral("closeLibrary"))->click();
        waitIdle(window);
        states.push_back(jobText(window));

        // 4. A pocket proposed from the model, with that tool.
        QVERIFY(window.newOperation(camwb::document::OperationKind::Pocket));
        QVERIFY(window.taskPanel());
        QVERIFY(window.taskPanel()->accept());
        QCOMPARE(int(wb.job().operations.size()), 1);
        QCOMPARE(wb.job().operations[0].toolNumber, wb.job().tools[0].tool.number);
        QCOMPARE(int(wb.job().tools.size()), 1);  // no default tool added beside the library's
        waitIdle(window);
        states.push_back(jobText(window));

        // Saved and posted: the golden, and what the command line makes of the saved job.
        const QString job = dir.filePath(QStringLiteral("workflow.camwb"));
        prompter->files = {job};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.SaveAs")));
        QVERIFY(QFile::exists(job));
        QSignalSpy posted(&wb, &Workbench::postFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Post")));
        QVERIFY(posted.wait(120000));
        QVERIFY(posted.last().first().toBool());
        waitIdle(window);
        QVERIFY2(wb.isProgramCurrent(), qPrintable(wb.programProblem()));
        const QByteArray nc = window.ncEditor()->text().toUtf8();
        QVERIFY(nc.contains("N15 "));  // the property reached the program
        const QString golden = QStringLiteral(CAMWB_WORKFLOW_GOLDEN);
        if (qEnvironmentVariableIsSet("CAMWB_UPDATE_GOLDEN")) {
            QFile out(golden);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(nc);
        }
        QCOMPARE(nc, readFile(golden));

        const QString cliOut = dir.filePath(QStringLiteral("cli.mpf"));
        QProcess cli;
        cli.start(QStringLiteral(CAMWB_CLI), {QStringLiteral("run"), job, QStringLiteral("-o"), cliOut});
        QVERIFY(cli.waitForFinished(120000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QCOMPARE(readFile(cliOut), nc);

        // Undo, one step at a time, back to the empty job.
        for (auto state = states.rbegin() + 1; state != states.rend(); ++state) {
            QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
            QCOMPARE(jobText(window), *state);
        }
        QVERIFY(!wb.document().undoStack().canUndo());
        QCOMPARE(jobText(window), empty);
        waitIdle(window);
    }

    // A job file cut off in the middle: a message naming the file and line, the job being edited
    // (with its unsaved edit) kept as it was, the broken file untouched.
    void corruptJobIsReportedAndLosesNothing()
    {
        QTemporaryDir dir;
        MainWindow window;
        auto owned = std::make_unique<ScriptedPrompter>();
        ScriptedPrompter* prompter = owned.get();
        window.setPrompter(std::move(owned));
        Workbench& wb = window.workbench();
        QSignalSpy imported(&wb, &Workbench::modelImportFinished);
        prompter->files = {QStringLiteral(CAMWB_EXAMPLE_STEP)};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.count() > 0 || imported.wait(120000));
        waitIdle(window);
        const std::string edited = jobText(window);
        QVERIFY(wb.document().isModified());

        const QString broken = dir.filePath(QStringLiteral("broken.camwb"));
        const QByteArray text = "{\n  \"format\": \"camwb-job\",\n  \"version\": 6,\n  \"name\": \"cut";
        {
            QFile file(broken);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(text);
        }
        prompter->answers = {Prompter::Answer::Discard};  // the unsaved edit: the open is asked about
        QVERIFY(!window.openJob(broken));
        QVERIFY2(!prompter->errors.isEmpty(), "no message");
        QVERIFY2(prompter->errors.last().contains(QStringLiteral("broken.camwb:4")),
                 qPrintable(prompter->errors.last()));
        QCOMPARE(jobText(window), edited);
        QVERIFY(wb.document().isModified());
        QCOMPARE(readFile(broken), text);
    }
};

int main(int argc, char** argv)
{
    // The programs' header: the same date and user for the window, the command line and the golden.
    qputenv("SOURCE_DATE_EPOCH", "1767225600");
    qputenv("CAMWB_USER", "golden");
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    WorkflowTest test;
    run.run(&test);
    return run.finish();
}

#include "WorkflowTest.moc"
