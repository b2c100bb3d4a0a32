// Drives the operation task panels on the real main window with the example job: each kind's
// panel previews, a change updates the preview, Cancel leaves the job byte-identical, OK is one
// undo step; the New… actions; cancelling a running pocket preview; the event loop's longest stall
// while a large pocket computes (printed, not asserted). Under Xvfb (GL) and offscreen (no GL).
#include "QtTestRun.h"
#include "Shots.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/NewOperation.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PreviewRunner.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"
#include "toolpath/ToolpathPolylines.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QLabel>
#include <QListWidget>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QThreadPool>
#include <QTimer>

#include <cmath>

using camwb::document::OperationKind;
using camwb::gui::MainWindow;
using camwb::gui::OperationPanel;
using camwb::gui::PreviewRunner;
using camwb::gui::Workbench;

namespace {

bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

std::string jobText(MainWindow& window) { return camwb::document::serializeJob(window.workbench().job()); }

int indexOfKind(MainWindow& window, OperationKind kind)
{
    const auto& ops = window.workbench().job().operations;
    for (std::size_t i = 0; i < ops.size(); ++i)
        if (ops[i].kind() == kind)
            return static_cast<int>(i);
    return -1;
}

// Waits for the preview that the last change requested (started after `spy` was made).
bool waitPreview(QSignalSpy& spy, int timeoutMs = 120000) { return spy.count() > 0 || spy.wait(timeoutMs); }

// The exact segment points of the preview shown in the view (empty without a preview).
std::vector<camwb::base::Vec3> previewPoints(MainWindow& window)
{
    const auto* polylines = window.view()->overlay().previewPolylines();
    return polylines ? polylines->points() : std::vector<camwb::base::Vec3>{};
}

QString counts(const camwb::ops::MotionCounts& c)
{
    return QStringLiteral("%1 lines %2 arcs %3 helices %4 cycles")
        .arg(c.lines)
        .arg(c.arcs)
        .arg(c.helices)
        .arg(c.cycles);
}

// A change of the kind's main parameter that changes the toolpath.
void changeParameter(OperationPanel& panel)
{
    auto halve = [&panel](const char* name, double fallback) {
        auto* box = panel.findChild<QDoubleSpinBox*>(QLatin1String(name));
        QVERIFY2(box, name);
        box->setValue(box->value() > 0 ? box->value() / 2 : fallback);
    };
    switch (panel.operation().kind()) {
    case OperationKind::Contour:
        halve("stepDownBox", 2.0);
        break;
    case OperationKind::Pocket:
        halve("stepoverPercentBox", 25.0);
        break;
    case OperationKind::Helix:
        halve("pitchBox", 0.5);
        break;
    case OperationKind::Drill: {
        auto* box = panel.findChild<QCheckBox*>(QStringLiteral("retractToClearanceCheck"));
        QVERIFY(box);
        box->toggle();
        break;
    }
    case OperationKind::Swarf: {
        auto* box = panel.findChild<QDoubleSpinBox*>(QStringLiteral("chordToleranceBox"));
        QVERIFY(box);
        box->setValue(box->value() / 10);  // halving may keep the points (the bisection's steps)
        break;
    }
    case OperationKind::Pocket3d:
        halve("stepDownBox", 1.0);
        break;
    case OperationKind::Waterline:
        halve("minSlopeBox", 15.0);  // more of the walls: the step-down follows the scallop anyway
        break;
    case OperationKind::Parallel:
        halve("stepoverBox", 0.5);
        break;
    case OperationKind::Groove:
        halve("infeedBox", 0.5);
        break;
    }
}

}  // namespace

class TaskPanelTest : public QObject {
    Q_OBJECT

private:
    static void openExample(MainWindow& window, const QString& job = QStringLiteral(CAMWB_EXAMPLE_JOB))
    {
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(job));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
    }

    static void waitIdle(MainWindow& window)
    {
        QElapsedTimer waited;
        waited.start();
        while (window.workbench().isBusy() && waited.elapsed() < 120000)
            QTest::qWait(20);
        QVERIFY(!window.workbench().isBusy());
    }

    // Opens operation `index`'s panel and waits for its first preview.
    static OperationPanel* openPanel(MainWindow& window, int index)
    {
        window.editOperation(index);
        OperationPanel* panel = window.taskPanel();
        if (panel == nullptr)
            return nullptr;
        QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
        if (!waitPreview(finished))
            return nullptr;
        return panel;
    }

private slots:
    void newOperationActionsAreRegistered()
    {
        MainWindow window;
        const QStringList ids = window.actions().ids();
        for (const char* id : {"Cam.Op.NewContour", "Cam.Op.NewPocket", "Cam.Op.NewHelix", "Cam.Op.NewDrill",
                               "Cam.Op.NewSwarf", "Cam.Op.NewPocket3d", "Cam.Op.NewWaterline", "Cam.Op.NewParallel",
                               "Cam.Op.NewGroove", "Cam.Op.NewProfile", "Cam.Op.Edit", "Cam.Op.Delete"})
            QVERIFY2(ids.contains(QLatin1String(id)), id);
    }

    // Each kind of the example jobs (the block; the mould for the 3D operations): preview, change,
    // Cancel (job identical), OK (one undo step).
    void eachPanelPreviewsCancelsAndApplies_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("job");
        const QString block = QStringLiteral(CAMWB_EXAMPLE_JOB), mould = QStringLiteral(CAMWB_MOULD_JOB);
        QTest::newRow("contour") << int(OperationKind::Contour) << block;
        QTest::newRow("pocket") << int(OperationKind::Pocket) << block;
        QTest::newRow("helix") << int(OperationKind::Helix) << block;
        QTest::newRow("drill") << int(OperationKind::Drill) << block;
        QTest::newRow("pocket3d") << int(OperationKind::Pocket3d) << mould;
        QTest::newRow("waterline") << int(OperationKind::Waterline) << mould;
        QTest::newRow("parallel") << int(OperationKind::Parallel) << mould;
    }
    void eachPanelPreviewsCancelsAndApplies()
    {
        QFETCH(int, kind);
        QFETCH(QString, job);
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window, job);
        const int index = indexOfKind(window, OperationKind(kind));
        QVERIFY2(index >= 0, "the example job has no operation of this kind");
        const std::string original = jobText(window);
        const std::size_t undoSteps = window.workbench().document().undoStack().count();

        OperationPanel* panel = openPanel(window, index);
        QVERIFY(panel);
        const auto first = panel->preview().lastOutcome();
        QVERIFY(first);
        qInfo("%s: %s | %s", camwb::document::kindName(OperationKind(kind)), qPrintable(counts(first->result.counts)),
              qPrintable(panel->statusText()));
        QVERIFY2(first->ok, qPrintable(QStringLiteral("the operation does not compute: ") + panel->statusText()));
        QVERIFY(window.view()->overlay().previewSegmentCount() > 0);
        const auto firstPoints = previewPoints(window);
        QVERIFY(panel->statusText().contains(QLatin1String("lines")));

        {
            QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
            changeParameter(*panel);
            QVERIFY(waitPreview(finished));
        }
        const auto changed = panel->preview().lastOutcome();
        QVERIFY(changed && changed != first);
        QVERIFY2(changed->ok, changed->error.c_str());
        QVERIFY(!previewPoints(window).empty());
        QVERIFY(previewPoints(window) != firstPoints);
        if (OperationKind(kind) != OperationKind::Drill)
            QVERIFY2(counts(first->result.counts) != counts(changed->result.counts),
                     qPrintable(counts(changed->result.counts)));
        QCOMPARE(jobText(window), original);  // nothing applied while editing

        panel->findChild<QAbstractButton*>(QStringLiteral("cancelButton"))->click();
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(window.view()->overlay().previewSegmentCount(), 0);
        QCOMPARE(jobText(window), original);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps);

        panel = openPanel(window, index);
        QVERIFY(panel);
        {
            QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
            changeParameter(*panel);
            QVERIFY(waitPreview(finished));
        }
        panel->findChild<QAbstractButton*>(QStringLiteral("okButton"))->click();
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        QVERIFY(jobText(window) != original);
        waitIdle(window);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        waitIdle(window);
    }

    // Destroying the window itself (not closing it: the close settles the panel first) while an
    // operation panel shows its preview, or computes a new one, or the job setup panel is open:
    // the panels go before the view's overlay and the workbench they refer to (this crashed).
    void destroyingTheWindowWithAnOpenPanel()
    {
        // Shown or never shown (the dock widgets are then destroyed in another order).
        for (int round = 0; round < 6; ++round) {
            auto* window = new MainWindow;
            if (round % 2 == 0) {
                window->show();
                QVERIFY(QTest::qWaitForWindowExposed(window));
            }
            openExample(*window);
            if (round / 2 == 2) {
                window->editJobSetup();
                QVERIFY(window->jobSetupPanel() != nullptr);
            } else {
                OperationPanel* panel = openPanel(*window, indexOfKind(*window, OperationKind::Pocket));
                QVERIFY(panel);
                QVERIFY(window->view()->overlay().previewSegmentCount() > 0);
                if (round / 2 == 1)
                    changeParameter(*panel);  // a preview being computed when the window goes
            }
            delete window;
        }
    }

    // New… from the model's defaults: the panel opens on an operation not yet in the job; OK adds
    // it (with its tool when the job had none suited) as one undo step.
    void newOperationsFromTheModel_data()
    {
        QTest::addColumn<QString>("action");
        QTest::addColumn<int>("kind");
        QTest::newRow("contour") << QStringLiteral("Cam.Op.NewContour") << int(OperationKind::Contour);
        QTest::newRow("pocket") << QStringLiteral("Cam.Op.NewPocket") << int(OperationKind::Pocket);
        QTest::newRow("helix") << QStringLiteral("Cam.Op.NewHelix") << int(OperationKind::Helix);
        QTest::newRow("drill") << QStringLiteral("Cam.Op.NewDrill") << int(OperationKind::Drill);
    }
    void newOperationsFromTheModel()
    {
        QFETCH(QString, action);
        QFETCH(int, kind);
        MainWindow window;
        openExample(window);
        const std::string original = jobText(window);
        const std::size_t operations = window.workbench().job().operations.size();
        QVERIFY(window.actions().trigger(action));
        OperationPanel* panel = window.taskPanel();
        QVERIFY2(panel != nullptr, "the example model offers nothing for this kind (see the report)");
        QCOMPARE(panel->operationIndex(), -1);
        QCOMPARE(int(panel->operation().kind()), kind);
        QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
        QVERIFY(waitPreview(finished));
        qInfo("%s: %s", qPrintable(action), qPrintable(panel->statusText()));
        QVERIFY(!panel->statusText().isEmpty());
        QCOMPARE(jobText(window), original);

        panel->accept();
        QCOMPARE(window.workbench().job().operations.size(), operations + 1);
        QCOMPARE(int(window.workbench().job().operations.back().kind()), kind);
        const auto* tool = window.workbench().job().tool(window.workbench().job().operations.back().toolNumber);
        QVERIFY(tool);
        QCOMPARE(tool->tool.kind == "drill", OperationKind(kind) == OperationKind::Drill);
        waitIdle(window);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        waitIdle(window);
    }

    // Faces picked in the view become the new operation's geometry.
    void pickedFacesBecomeTheGeometry()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        auto proposal =
            camwb::gui::proposeOperation(OperationKind::Pocket, window.workbench().job(), window.workbench().model());
        QVERIFY(proposal);
        const int floor = proposal->operation.geometry.faces.at(0);
        auto& overlay = window.view()->overlay();
        overlay.clickFace(floor, false);
        overlay.clickFace(floor, true);  // Ctrl+click again: removed
        QVERIFY(overlay.selectedFaces().empty());
        overlay.clickFace(floor, false);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewPocket")));
        QVERIFY(window.taskPanel());
        QCOMPARE(window.taskPanel()->operation().geometry.faces, std::vector<int>{floor});
        QVERIFY(overlay.selectedFaces().empty());  // taken
        window.taskPanel()->reject();
        if (withGl()) {
            // A click in the middle of the top view lands on a face of the block.
            window.view()->setViewPreset(camwb::gui::View3D::Preset::Top);
            window.view()->grabImage();
            const QPointF centre(window.view()->width() / 2.0, window.view()->height() / 2.0);
            QVERIFY(window.view()->pickFace(centre) > 0);
        }
        waitIdle(window);
    }

    // A long pocket preview stops on Cancel; the event loop keeps turning meanwhile (stall printed).
    void largePocketPreviewCancelsAndKeepsTheGuiResponsive()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        int index = indexOfKind(window, OperationKind::Pocket);
        if (index < 0) {
            QVERIFY(window.workbench().addOperation(OperationKind::Pocket));
            waitIdle(window);
            index = indexOfKind(window, OperationKind::Pocket);
        }
        OperationPanel* panel = openPanel(window, index);
        QVERIFY(panel);
        QVERIFY2(panel->preview().lastOutcome()->ok,
                 qPrintable(QStringLiteral("the pocket does not compute: ") + panel->statusText()));

        // Large: 0.02 mm stepover and 0.1 mm step-downs over the whole pocket.
        qint64 longestStall = 0;
        QElapsedTimer tick;
        QTimer ticker;
        ticker.setInterval(10);
        connect(&ticker, &QTimer::timeout, &window, [&] { longestStall = std::max(longestStall, tick.restart()); });
        QSignalSpy started(&panel->preview(), &PreviewRunner::started);
        QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
        QSignalSpy cancelled(&panel->preview(), &PreviewRunner::cancelled);
        panel->findChild<QDoubleSpinBox*>(QStringLiteral("stepoverMmBox"))->setValue(0.02);
        panel->findChild<QDoubleSpinBox*>(QStringLiteral("stepDownBox"))->setValue(0.1);
        QVERIFY(started.wait(10000));
        tick.start();
        ticker.start();
        QElapsedTimer clock;
        clock.start();
        // Measured to the end, or for 30 s when it takes longer (then that run is the one cancelled).
        const bool done = waitPreview(finished, 30000);
        const qint64 computeMs = clock.elapsed();
        ticker.stop();
        // Drawing the result is the one step on the GUI thread: one frame, timed apart.
        QElapsedTimer frame;
        frame.start();
        window.view()->grabImage();
        const qint64 frameMs = frame.elapsed();
        const auto outcome = panel->preview().lastOutcome();
        if (done)
            qInfo("large pocket preview: %lld ms, %s, %d display segments; longest event-loop stall while computing "
                  "%lld ms; first frame with it %lld ms",
                  computeMs, outcome->ok ? qPrintable(counts(outcome->result.counts)) : outcome->error.c_str(),
                  window.view()->overlay().previewSegmentCount(), longestStall, frameMs);
        else
            qInfo("large pocket preview still computing after %lld ms; longest event-loop stall %lld ms", computeMs,
                  longestStall);

        if (done) {  // again, to cancel it while it runs
            panel->findChild<QDoubleSpinBox*>(QStringLiteral("stepoverMmBox"))->setValue(0.015);
            QVERIFY(started.wait(10000));
        }
        // Cancelled right after it started: its result is delivered on this thread, which has not
        // turned its event loop since, so only a pocket that takes no time at all could be done.
        QVERIFY2(panel->preview().isRunning(), "the pocket finished before it could be cancelled");
        QElapsedTimer stopping;
        stopping.start();
        panel->findChild<QAbstractButton*>(QStringLiteral("cancelPreviewButton"))->click();
        QCOMPARE(cancelled.count(), 1);
        QVERIFY(!panel->preview().isRunning());
        QVERIFY(panel->statusText().contains(QLatin1String("cancelled")));
        QVERIFY(QThreadPool::globalInstance()->waitForDone(60000));
        qInfo("cancelled pocket worker stopped after %lld ms", stopping.elapsed());
        QCOMPARE(panel->preview().lastOutcome(), outcome);  // nothing from the cancelled run
        panel->reject();
        waitIdle(window);
    }

    // Pictures of each panel over the example job (kept in CAMWB_SHOTS_DIR when set); each must
    // show something.
    // 3+2: the contour round the boss on an inclined face previews in that face's plane (the
    // preview in the workpiece frame, nothing below the face), and flat it cannot be made.
    void workingPlaneOfTheFiveAxisExample()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_FIVE_AXIS_JOB)));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        const int index = indexOfKind(window, OperationKind::Contour);
        QVERIFY(index >= 0);
        OperationPanel* panel = openPanel(window, index);
        QVERIFY(panel);
        auto* mode = panel->findChild<QComboBox*>(QStringLiteral("planeMode"));
        QVERIFY(mode);
        QCOMPARE(mode->currentData().toInt(), int(camwb::document::WorkingPlaneSpec::Mode::Face));
        QCOMPARE(panel->findChild<QSpinBox*>(QStringLiteral("planeFace"))->value(), 26);
        const auto outcome = panel->preview().lastOutcome();
        QVERIFY(outcome && outcome->ok);
        // The -X face's normal; its plane is at 20 + 10 sqrt 3 along it.
        const camwb::base::Vec3 n{-0.5, 0, std::sqrt(3.0) / 2};
        const double face = 20 + 10 * std::sqrt(3.0);
        double lowest = 1e9;
        for (const camwb::base::Vec3& p : previewPoints(window))
            lowest = std::min(lowest, n.dot(p));
        QVERIFY2(std::abs(lowest - 37.3205) < 1e-6, qPrintable(QString::number(lowest, 'f', 6)));
        QVERIFY(lowest > face - 1e-4);
        saveShot(&window, QStringLiteral("panel-working-plane.png"));
        {
            QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
            mode->setCurrentIndex(mode->findData(int(camwb::document::WorkingPlaneSpec::Mode::Flat)));
            QVERIFY(waitPreview(finished));
        }
        QVERIFY(!panel->preview().lastOutcome()->ok);
        QCOMPARE(panel->operation().plane.mode, camwb::document::WorkingPlaneSpec::Mode::Flat);
        panel->reject();
        QCOMPARE(window.workbench().job().operations[static_cast<std::size_t>(index)].plane.mode,
                 camwb::document::WorkingPlaneSpec::Mode::Face);
    }

    // Swarf on the five-axis example: the panel previews five-axis moves with the tool axes drawn
    // along them, hides the working plane, a tighter chord tolerance gives more points, OK is one
    // undo step; New Swarf proposes the drafted boss' cone.
    void swarfPanelOnTheFiveAxisExample()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_FIVE_AXIS_JOB)));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        const int index = indexOfKind(window, OperationKind::Swarf);
        QVERIFY(index >= 0);
        const std::string original = jobText(window);
        const std::size_t undoSteps = window.workbench().document().undoStack().count();
        OperationPanel* panel = openPanel(window, index);
        QVERIFY(panel);
        const auto first = panel->preview().lastOutcome();
        QVERIFY2(first && first->ok, qPrintable(panel->statusText()));
        QVERIFY2(first->result.counts.lines > 50, qPrintable(counts(first->result.counts)));
        QVERIFY(!panel->findChild<QComboBox*>(QStringLiteral("planeMode"))->isVisibleTo(panel));
        const auto* polylines = window.view()->overlay().previewPolylines();
        QVERIFY(polylines);
        int axes = 0;
        for (const auto& segment : polylines->segments())
            axes += segment.kind == camwb::toolpath::PathSegmentKind::ToolAxis ? 1 : 0;
        QVERIFY2(axes > 10, qPrintable(QString::number(axes)));
        QTest::qWait(300);
        saveShot(&window, QStringLiteral("panel-swarf.png"));
        {
            QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
            changeParameter(*panel);
            QVERIFY(waitPreview(finished));
        }
        const auto finer = panel->preview().lastOutcome();
        QVERIFY(finer && finer->ok);
        QVERIFY2(finer->result.counts.lines > first->result.counts.lines, qPrintable(counts(finer->result.counts)));
        panel->findChild<QAbstractButton*>(QStringLiteral("okButton"))->click();
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        waitIdle(window);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        waitIdle(window);

        auto proposal =
            camwb::gui::proposeOperation(OperationKind::Swarf, window.workbench().job(), window.workbench().model());
        QVERIFY2(proposal.ok(), proposal.ok() ? "" : proposal.error().message.c_str());
        QCOMPARE(proposal->operation.geometry.faces, std::vector<int>{1});
    }

    void panelScreenshots()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        for (OperationKind kind :
             {OperationKind::Contour, OperationKind::Pocket, OperationKind::Helix, OperationKind::Drill}) {
            const int index = indexOfKind(window, kind);
            QVERIFY2(index >= 0, camwb::document::kindName(kind));
            QVERIFY(openPanel(window, index));
            QTest::qWait(300);
            saveShot(&window, QStringLiteral("panel-%1.png").arg(camwb::document::kindName(kind)));
            window.taskPanel()->reject();
        }
        if (qEnvironmentVariableIsEmpty("CAMWB_SHOTS_DIR"))
            return;  // the 3D one only when pictures are asked for
        openExample(window, QStringLiteral(CAMWB_MOULD_JOB));
        const int rough = indexOfKind(window, OperationKind::Pocket3d);
        QVERIFY(rough >= 0);
        QVERIFY(openPanel(window, rough));
        QTest::qWait(300);
        saveShot(&window, QStringLiteral("panel-pocket3d.png"));
        window.taskPanel()->reject();
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    TaskPanelTest test;
    run.run(&test);
    return run.finish();
}

#include "TaskPanelTest.moc"
