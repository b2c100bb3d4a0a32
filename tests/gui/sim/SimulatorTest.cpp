// Drives the simulator dock in the real main window: Simulate on the example job's posted program,
// play to the end, block steps and jumps through the action registry, the editor and the 3D view
// following and leading the playback, the stock actor and its deviation map, the five-axis
// example's path coloured by an analysed quantity with reversal markers, its machine frame (the
// table and the stock turned by the rotary axes), cancelling a long build,
// a program edited after simulating, and a measured trace imported, overlaid, cleared and marked
// out of date. Runs under Xvfb (GL) and offscreen (no GL).
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "Shots.h"
#include "document/NcTrace.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/ReportView.h"
#include "gui/shell/Workbench.h"
#include "gui/sim/MachineFrame.h"
#include "gui/sim/MeasuredImportDialog.h"
#include "gui/sim/SimChart.h"
#include "gui/sim/SimDock.h"
#include "gui/sim/SimOverlay.h"
#include "gui/sim/SimPlayer.h"
#include "gui/view3d/View3D.h"
#include "kinematics/Machine.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using camwb::gui::MainWindow;
using camwb::gui::SimPlayer;
using camwb::gui::View3D;
using camwb::gui::Workbench;

class SimulatorTest : public QObject {
    Q_OBJECT

private:
    static bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

    static bool waitForTrace(MainWindow& window)
    {
        camwb::gui::NcInspector* inspector = window.inspector();
        QElapsedTimer waited;
        waited.start();
        while ((inspector->isTracing() || !inspector->trace()) && waited.elapsed() < 120000)
            QTest::qWait(20);
        return !inspector->isTracing() && inspector->trace();
    }

    // Opens a job, waits for its post and the trace of the posted program.
    static void openJob(MainWindow& window, const QString& path)
    {
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(path));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
        QVERIFY(waitForTrace(window));
    }

    // Writes `program` as `name` in `dir`, opens it as an NC file apart from any job and waits for
    // its trace.
    static void openProgram(MainWindow& window, const QTemporaryDir& dir, const QString& name, const char* program)
    {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(program);
        file.close();
        QVERIFY(window.openNcFile(file.fileName()));
        QVERIFY(waitForTrace(window));
    }

    // Simulate through the registry, as the toolbar's button does.
    static void simulate(MainWindow& window)
    {
        QSignalSpy ready(window.simPlayer(), &SimPlayer::ready);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Start")));
        QVERIFY(ready.wait(120000));
        QVERIFY(window.simPlayer()->hasRun());
    }

    static bool waitUntil(const std::function<bool()>& done, int ms = 120000)
    {
        QElapsedTimer waited;
        waited.start();
        while (!done() && waited.elapsed() < ms)
            QTest::qWait(10);
        return done();
    }

    static void playToEnd(MainWindow& window, double speed)
    {
        SimPlayer* player = window.simPlayer();
        player->setSpeed(speed);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Play")));
        QVERIFY(player->isPlaying());
        QVERIFY(waitUntil([player] { return !player->isPlaying(); }));
        QVERIFY(player->atEnd());
        // Cut to the end and shown: the frame comes through the event loop, however late the
        // worker posts it (a fixed wait here failed once on a loaded machine).
        QVERIFY(waitUntil([player] { return player->stockCaughtUp(); }));
    }

    // A simulation of NC text, as the dock asks for one (no machine, no stock unless set).
    static camwb::gui::SimRunRequest requestFor(const char* text, const char* path)
    {
        camwb::document::NcTraceRequest request;
        request.text = text;
        request.path = path;
        camwb::gui::SimRunRequest simRequest;
        simRequest.trace = std::make_shared<const camwb::document::NcTrace>(camwb::document::traceNc(request));
        return simRequest;
    }

    static int movingMoves(const camwb::gui::SimRun& run)
    {
        int count = 0;
        for (const camwb::sim::Move& move : run.moves.moves)
            count += move.moves() && move.positionKnown ? 1 : 0;
        return count;
    }

private slots:
    void actionsAreInTheRegistryAndTheMenu()
    {
        MainWindow window;
        const QStringList ids = window.actions().ids();
        for (const char* id : {"Cam.Sim.Start", "Cam.Sim.Play", "Cam.Sim.Pause", "Cam.Sim.StepForward",
                               "Cam.Sim.StepBack", "Cam.Sim.JumpToLine", "Cam.View.SimDock"})
            QVERIFY2(ids.contains(QLatin1String(id)), id);
        bool inMenu = false;
        for (QAction* menu : window.menuBar()->actions())
            if (menu->text().remove('&') == QLatin1String("Simulate") && menu->menu() != nullptr)
                inMenu = menu->menu()->actions().contains(window.actions().action(QStringLiteral("Cam.Sim.Play")));
        QVERIFY(inMenu);
        // Nothing to play before a simulation: playback actions are off, Simulate says why.
        QVERIFY(!window.actions().trigger(QStringLiteral("Cam.Sim.Play")));
        QVERIFY(!window.actions().trigger(QStringLiteral("Cam.Sim.StepForward")));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Start")));
        QVERIFY(!window.simPlayer()->isBuilding());
        QVERIFY(window.reportView()->toPlainText().contains(QLatin1String("Nothing to simulate")));
    }

    // Block steps go line by line as a control's single block mode; back returns to the start of
    // the block, then to the block before.
    void timelineStepsByBlocks()
    {
        const auto run = camwb::gui::buildSimRun(requestFor(
            "G90 G21 G17\nG0 X0 Y0 Z10\nG1 Z0 F100\nG1 X10\nG1 Y10\nG2 X0 Y10 I-5 J0\nG0 Z10\nM30\n", "steps.ngc"));
        QVERIFY(run);
        const camwb::gui::Timeline& timeline = run->timeline;
        QVERIFY(timeline.total() > 0);
        QList<int> lines;
        for (double at = 0; at < timeline.total(); at = timeline.nextBlock(at))
            lines << timeline.lineOf(timeline.pointAt(at).move);
        QCOMPARE(lines, (QList<int>{3, 4, 5, 6, 7}));  // the first rapid is from an unknown position
        const double arc = timeline.previousBlock(timeline.previousBlock(timeline.total()));
        QCOMPARE(timeline.lineOf(timeline.pointAt(arc).move), 6);
        // From inside the arc, back goes to its start, not to the block before.
        const double inside = arc + 0.5 * (timeline.nextBlock(arc) - arc);
        QCOMPARE(timeline.previousBlock(inside), arc);
        QCOMPARE(timeline.lineOf(timeline.pointAt(timeline.previousBlock(arc)).move), 5);
        // The tool at the arc's middle is on the arc (radius 5 about X5 Y10).
        const auto pose = timeline.poseAt(timeline.pointAt(inside));
        QVERIFY(pose.known);
        QVERIFY(std::abs(std::hypot(pose.tip.x - 5, pose.tip.y - 10) - 5) < 0.05);
    }

    // A stock finer than the computer's memory holds (a large plate at the dock's finest
    // resolution) is not made: the tool plays over the path without it and a note says why and
    // what resolution fits, instead of the window being killed with unsaved work in it.
    void stockBeyondMemoryPlaysWithoutStock()
    {
        camwb::gui::SimRunRequest simRequest =
            requestFor("G90 G21 G17\nT1 M6\nS1000 M3\nG0 X0 Y0 Z10\nG1 Z-1 F100\nG1 X100\nG0 Z10\nM30\n", "plate.ngc");
        camwb::toolpath::Tool tool;
        tool.number = 1;
        tool.diameterMm = 10;
        simRequest.tools[1] = tool;
        camwb::base::Box3 plate;
        plate.add({-2500, -2500, -100});
        plate.add({2500, 2500, 0});
        simRequest.stockBox = plate;
        simRequest.resolutionMm = 0.02;
        const auto run = camwb::gui::buildSimRun(simRequest);
        QVERIFY(run);
        QVERIFY(!run->stock);
        QVERIFY(run->timeline.total() > 0);
        QVERIFY(run->toolShapes.count(1) == 1);  // the tool is still drawn
        bool said = false;
        for (const std::string& note : run->notes)
            said = said || (note.find("No stock removal: the height field stock of 5000.0 x 5000.0 x 100.0 mm at "
                                      "0.0200 mm") == 0 &&
                            note.find("the finest resolution that fits is ") != std::string::npos);
        QVERIFY2(said, run->notes.empty() ? "no note" : run->notes.front().c_str());
        QCOMPARE(run->stockError, run->notes.front());  // the dock's banner shows it
        // The same plate at a resolution that fits is cut.
        simRequest.resolutionMm = 5;
        const auto coarse = camwb::gui::buildSimRun(simRequest);
        QVERIFY(coarse && coarse->stock);

        // In the window: the example job on such a plate says so where the results go.
        QFile example(QStringLiteral(CAMWB_EXAMPLE_JOB));
        QVERIFY(example.open(QIODevice::ReadOnly));
        QJsonObject job = QJsonDocument::fromJson(example.readAll()).object();
        job[QStringLiteral("model")] = QFileInfo(QStringLiteral(CAMWB_EXAMPLE_JOB))
                                           .dir()
                                           .absoluteFilePath(job[QStringLiteral("model")].toString());
        job[QStringLiteral("stock")] = QJsonObject{{QStringLiteral("min"), QJsonArray{-2500, -2500, 0}},
                                                   {QStringLiteral("max"), QJsonArray{2500, 2500, 16}}};
        QTemporaryDir dir;
        QFile plateJob(dir.filePath(QStringLiteral("plate.camwb")));
        QVERIFY(plateJob.open(QIODevice::WriteOnly));
        plateJob.write(QJsonDocument(job).toJson());
        plateJob.close();
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, plateJob.fileName());
        simulate(window);
        QVERIFY(!window.simPlayer()->run()->stock);
        const QString results = window.findChild<QLabel*>(QStringLiteral("simBanner"))->text();
        QVERIFY2(results.startsWith(QLatin1String("No stock removal: the height field stock of 5000.0 x 5000.0 x 16.0 "
                                                  "mm at 0.2500 mm would have 400.0 million columns")),
                 qPrintable(results));
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-stock-too-fine.png"));
    }

    void playsTheExampleJobToTheEnd()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, QStringLiteral(CAMWB_EXAMPLE_JOB));
        simulate(window);
        SimPlayer* player = window.simPlayer();
        const auto run = player->run();
        QVERIFY(run->moves.moves.size() > 100);
        QCOMPARE(player->position(), 0.0);
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("simDock"))->isVisible());
        // A three-axis job: no machine frame (the action says why), no rotary table.
        QAction* machineFrame = window.actions().action(QStringLiteral("Cam.Sim.MachineFrame"));
        QVERIFY(machineFrame && machineFrame->isCheckable() && !machineFrame->isEnabled());
        QVERIFY2(machineFrame->toolTip().startsWith(QLatin1String("Machine frame: ")),
                 qPrintable(machineFrame->toolTip()));
        QVERIFY(!window.view()->simulation().hasTableActor());

        playToEnd(window, 2000);
        camwb::gui::SimOverlay& overlay = window.view()->simulation();
        QCOMPARE(overlay.pathSegmentCount(), movingMoves(*run) - 1);  // the last one is the move under way
        QCOMPARE(window.ncEditor()->currentLine(), player->currentLine());
        QVERIFY(player->currentLine() > 1);
        QVERIFY(window.findChild<QLabel*>(QStringLiteral("simReadout"))
                    ->text()
                    .contains(QStringLiteral("move %1 of %1").arg(run->moves.moves.size())) ||
                player->point().move + 1 < run->moves.moves.size());

        // The stock was cut to the end and compared with the model: the deviation map.
        QVERIFY(overlay.hasStockActor());
        QVERIFY(overlay.stockTriangleCount() > 1000);
        QVERIFY(overlay.hasToolActor());
        QVERIFY(player->deviation().has_value());
        QVERIFY(overlay.showsDeviation());
        const auto deviation = *player->deviation();
        QCOMPARE(deviation.maxGougeMm, 0.0);  // as the summary below says: no errors
        QVERIFY(
            window.findChild<QLabel*>(QStringLiteral("simResults"))->text().contains(QLatin1String("largest gouge")));
        // The checks of the whole run went to the report (the example job is clean). The cycle time
        // counts the spindle's stop after the last M5 (2500 of 5000 rpm: 1.0 s).
        QVERIFY(window.reportView()->toPlainText().contains(
            QLatin1String("Simulated example-block.mpf: cycle time 470.8 s, errors: 0, warnings: 0")));
        QCOMPARE(overlay.findingCount(), 0);
        window.simDock()->findChild<QDoubleSpinBox*>(QStringLiteral("simDeviationLimit"))->setValue(1.5);
        QCOMPARE(player->deviationLimit(), 1.5);
        qInfo("example job: cycle time %.1f s (simple estimate %.1f s), %zu moves, largest gouge %.3f mm at move %lld, "
              "largest leftover %.3f mm at move %lld, %.3f mm beside the part, stock %d triangles",
              run->cycleSeconds, run->simpleSeconds, run->moves.moves.size(), deviation.maxGougeMm,
              static_cast<long long>(deviation.gougeMove), deviation.maxLeftoverMm,
              static_cast<long long>(deviation.leftoverMove), deviation.maxOutsideMm, overlay.stockTriangleCount());
        // The holder hides the part: off for the picture of the deviation map.
        window.simDock()->findChild<QCheckBox*>(QStringLiteral("simShowTool"))->setChecked(false);
        QVERIFY(overlay.hasToolActor());
        window.view()->fitAll();
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-example-job.png"));
    }

    // A pocket cut 0.5 mm below its floor: the simulation finds the gouge at the pocket's blocks,
    // marks it in the view, and the deviation map goes red there.
    void gougingPocketLightsUpAtItsBlock()
    {
        QTemporaryDir dir;
        QFile source(QStringLiteral(CAMWB_EXAMPLE_JOB));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QByteArray job = source.readAll();
        const QByteArray folder = QFileInfo(QStringLiteral(CAMWB_EXAMPLE_JOB)).absolutePath().toUtf8() + "/";
        job.replace("\"model\": \"", "\"model\": \"" + folder);
        const QByteArray pocketHeights = R"("heights": {"clearance": 25.0, "safe": 18.0},
      "params": {"pattern": "offset")";
        QVERIFY(job.contains(pocketHeights));
        job.replace(pocketHeights, R"("heights": {"clearance": 25.0, "safe": 18.0, "final": 9.5},
      "params": {"pattern": "offset")");
        QFile file(dir.filePath(QStringLiteral("gouging.camwb")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(job);
        file.close();

        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, file.fileName());
        simulate(window);
        SimPlayer* player = window.simPlayer();
        const QStringList lines = window.ncEditor()->text().split(QLatin1Char('\n'));
        const int pocketFrom =
            static_cast<int>(lines.indexOf(QRegularExpression(QStringLiteral(".*;Pocket with island")))) + 1;
        const int pocketTo =
            static_cast<int>(lines.indexOf(QRegularExpression(QStringLiteral(".*;Through hole D10")))) + 1;
        QVERIFY(pocketFrom > 0 && pocketTo > pocketFrom);
        int gouges = 0;
        for (const camwb::sim::Check& check : player->run()->checks) {
            if (check.kind != camwb::sim::CheckKind::Gouge)
                continue;
            ++gouges;
            const int line = player->run()->trace->lineOfRecord(static_cast<std::size_t>(check.record));
            QVERIFY2(line > pocketFrom && line < pocketTo, qPrintable(QString::number(line)));
            QVERIFY(check.valueMm > 0.3 && check.valueMm < 0.8);
        }
        QVERIFY(gouges > 0);
        QVERIFY(window.view()->simulation().findingCount() >= gouges);
        QVERIFY(window.reportView()->toPlainText().contains(
            QRegularExpression(QStringLiteral("gouging\\.mpf:\\d+: error: gouge"))));
        const auto deviation = player->deviation();
        QVERIFY(deviation && deviation->maxGougeMm > 0.3);
        playToEnd(window, 2000);
        QVERIFY(window.view()->simulation().showsDeviation());
        QVERIFY(player->deviation()->maxGougeMm > 0.3);  // the animated stock agrees with the full run
        window.simDock()->findChild<QCheckBox*>(QStringLiteral("simShowTool"))->setChecked(false);
        window.view()->setViewPreset(View3D::Preset::Top);
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-gouging-pocket.png"));
    }

    // A CL file opened like a program (NX's APT here) is simulated as one: its blocks are its
    // statements, the playback steps through their lines, and it plays to the end.
    void clFileSimulatesAtItsStatements()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openJob(QStringLiteral(CAMWB_CL_DATA "/nx_face_and_drill.cls")));
        QVERIFY(waitForTrace(window));
        QVERIFY(window.inspector()->trace()->clFormat.has_value());
        simulate(window);
        const camwb::gui::Timeline& timeline = window.simPlayer()->run()->timeline;
        QList<int> lines;
        for (double at = 0; at < timeline.total(); at = timeline.nextBlock(at))
            lines << timeline.lineOf(timeline.pointAt(at).move);
        // The tool changes (LOAD/TOOL on 7 and 47) take time; line 13's rapid comes from an unknown
        // position: the tool stands where it ends; the cycles on 52 and 57 drill two holes each,
        // one block.
        QCOMPARE(lines, (QList<int>{7, 13, 16, 19, 22, 23, 25, 26, 30, 32, 35, 39, 47, 50, 52, 54, 57, 61}));
        playToEnd(window, 2000);
        QCOMPARE(window.ncEditor()->currentLine(), lines.last());
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-cl-file.png"));
    }

    // Playing at the machine's speed x10 for a few seconds: the frames the view drew and the stock
    // meshes it showed per second (printed; a test never asserts a time).
    void frameRateWhilePlaying()
    {
        if (!withGl())
            return;  // no frames are drawn without OpenGL; the other registration measures
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // CAMWB_FRAME_RATE_JOB measures another job (docs/benchmarks.md: the five-axis example).
        const QString job = qEnvironmentVariable("CAMWB_FRAME_RATE_JOB", QStringLiteral(CAMWB_EXAMPLE_JOB));
        openJob(window, job);
        // The floor: a frame of the model and the backplot before simulating.
        QElapsedTimer before;
        before.start();
        for (int i = 0; i < 3; ++i)
            window.view()->grabImage();
        const double beforeMs = before.nsecsElapsed() * 1e-6 / 3;
        simulate(window);
        SimPlayer* player = window.simPlayer();
        // From the first cutting move: a manual tool change (the five-axis example's machine: 60 s)
        // would fill the seconds measured with a standing tool.
        const auto run = player->run();
        for (std::size_t m = 0; m < run->moves.moves.size(); ++m)
            if (run->moves.moves[m].kind == camwb::sim::MoveKind::Feed) {
                player->seek(run->timeline.start(m));
                break;
            }
        player->setSpeed(10);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Play")));
        qint64 longestStall = 0;
        QElapsedTimer tick;
        QTimer ticker;
        ticker.setInterval(5);
        connect(&ticker, &QTimer::timeout, &window, [&] { longestStall = std::max(longestStall, tick.restart()); });
        tick.start();
        ticker.start();
        QTest::qWait(5000);
        ticker.stop();
        const camwb::gui::PlaybackStats stats = player->stats();
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Pause")));
        QVERIFY(stats.frames > 0);
        QVERIFY(window.view()->simulation().hasStockActor());
        // One frame of the same scene, rendered on its own.
        QElapsedTimer render;
        render.start();
        for (int i = 0; i < 3; ++i)
            window.view()->grabImage();
        const double renderMs = render.nsecsElapsed() * 1e-6 / 3;
        qInfo("playing %s at 10x: %.1f frames/s drawn, %.1f stock meshes/s shown (worker remesh %.2f ms "
              "each), GUI update %.2f ms per step, one frame rendered alone %.1f ms (%.1f ms before simulating), %d "
              "frames, %d stock triangles, longest event-loop stall %lld ms",
              qPrintable(QFileInfo(job).fileName()), stats.renderedFps, stats.stockFps, stats.meanStockMeshMs,
              stats.meanUpdateMs, renderMs, beforeMs, stats.frames, window.view()->simulation().stockTriangleCount(),
              longestStall);
    }

    // The five-axis example: the path coloured by an axis' velocity with red markers where the
    // axis reverses, the chart of the same quantity, the stock (tri-dexels) cut by the tilted tool.
    void fiveAxisReversalAnalysis()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, QStringLiteral(CAMWB_FIVE_AXIS_JOB));
        simulate(window);
        SimPlayer* player = window.simPlayer();
        QVERIFY(player->run()->cycleSeconds > player->run()->simpleSeconds);  // tool changes, accelerations
        QVERIFY(!player->run()->analysis.quantities.empty());
        const QStringList ids = player->quantityIds();
        for (const char* id : {"vx", "ax", "tipFeed", "omega0", "omega1", "vRotary0", "vRotary1"})
            QVERIFY2(ids.contains(QLatin1String(id)), id);
        auto* combo = window.simDock()->findChild<QComboBox*>(QStringLiteral("simQuantity"));
        QVERIFY(combo && combo->isEnabled());
        combo->setCurrentIndex(combo->findData(QStringLiteral("vx")));
        QCOMPARE(player->quantity(), QStringLiteral("vx"));
        camwb::gui::SimOverlay& overlay = window.view()->simulation();
        QVERIFY(overlay.showsColouredPath());
        QVERIFY(overlay.markerCount() > 0);
        const auto range = player->quantityRange();
        QVERIFY(range.first < 0 && range.second > 0);  // X goes both ways
        // User limits replace the automatic range.
        window.simDock()->findChild<QCheckBox*>(QStringLiteral("simAutoLimits"))->setChecked(false);
        auto* low = window.simDock()->findChild<QDoubleSpinBox*>(QStringLiteral("simLow"));
        auto* high = window.simDock()->findChild<QDoubleSpinBox*>(QStringLiteral("simHigh"));
        low->setValue(-50);
        high->setValue(50);
        emit high->editingFinished();
        QCOMPARE(player->quantityRange(), std::make_pair(-50.0, 50.0));
        if (withGl())
            QVERIFY(window.simDock()->chart()->plottedPoints() > 10);
        else
            QVERIFY(window.simDock()->findChild<QLabel*>(QStringLiteral("noChartMessage")));

        playToEnd(window, 2000);
        QVERIFY(overlay.hasStockActor());
        // The chart's cursor and a click on it follow the playback both ways.
        QCOMPARE(window.simDock()->chart()->cursorTime(), player->position());
        emit window.simDock()->chart()->timeClicked(player->run()->timeline.total() / 2);
        QCOMPARE(player->position(), player->run()->timeline.total() / 2);
        QCOMPARE(window.simDock()->chart()->cursorTime(), player->position());
        // A real click on the chart: further right is later.
        if (withGl()) {
            QWidget* chartGl = window.simDock()->chart()->findChild<QWidget*>(QStringLiteral("simChartGl"));
            QVERIFY(chartGl);
            QTest::mouseClick(chartGl, Qt::LeftButton, {}, QPoint(chartGl->width() / 3, chartGl->height() / 2));
            const double early = player->position();
            QTest::mouseClick(chartGl, Qt::LeftButton, {}, QPoint(2 * chartGl->width() / 3, chartGl->height() / 2));
            const double late = player->position();
            QVERIFY2(early > 0 && late > early && late < player->run()->timeline.total(),
                     qPrintable(QStringLiteral("%1, %2").arg(early).arg(late)));
        }
        const QString report = window.reportView()->toPlainText();
        qInfo("five-axis report: %s", qPrintable(report.mid(report.lastIndexOf(QLatin1String("Traced")))));
        qInfo("five-axis example: cycle time %.1f s, %zu vx samples, %d X reversals marked, %d stock triangles",
              player->run()->cycleSeconds, player->run()->analysis.tip.size(), overlay.markerCount(),
              overlay.stockTriangleCount());
        // The tool tilted on the swarf pass: the middle of its first tilted move.
        const auto& moves = player->run()->moves.moves;
        std::size_t tilted = 0;
        while (tilted < moves.size() && (!moves[tilted].fiveAxis || moves[tilted].fromAxis().z > 0.999))
            ++tilted;
        QVERIFY(tilted < moves.size());
        const auto& timeline = player->run()->timeline;
        player->seek(0.5 * (timeline.start(tilted) + timeline.end(tilted)));
        QVERIFY(overlay.hasToolActor());
        QVERIFY(waitUntil([player] { return player->stockCaughtUp(); }));
        window.view()->fitAll();
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-five-axis-reversals.png"));
    }

    static bool isIdentity(const std::array<double, 16>& m)
    {
        for (int i = 0; i < 16; ++i)
            if (std::abs(m[i] - (i % 5 == 0 ? 1.0 : 0.0)) > 1e-12)
                return false;
        return true;
    }

    // The machine frame of the five-axis example (mas-mcvl1000, B/C table-table): toggled through
    // the registry, the rotary table and the stock turn by the table's pose at the playback's
    // point (kinematics::machineFrameMotion), the tool stands along the spindle, and toggling off
    // puts them back. Screenshots of both frames at a tilted pose.
    void machineFrameTurnsTheWorkpieceSide()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, QStringLiteral(CAMWB_FIVE_AXIS_JOB));
        simulate(window);
        SimPlayer* player = window.simPlayer();
        const auto run = player->run();
        camwb::gui::SimOverlay& overlay = window.view()->simulation();
        QAction* machineFrame = window.actions().action(QStringLiteral("Cam.Sim.MachineFrame"));
        QVERIFY(machineFrame && machineFrame->isEnabled() && !machineFrame->isChecked());
        QCOMPARE(player->machineFrameSupport(), camwb::gui::MachineFrameSupport::Available);
        QVERIFY(overlay.hasTableActor());  // in the workpiece frame too, standing still
        QVERIFY(isIdentity(overlay.tableMatrix()));

        // A tilted pose and a pose at another C with the tilt (the rotary angles the plan follows).
        const auto& timeline = run->timeline;
        std::optional<double> first, second;
        std::array<double, 2> firstDeg{};
        for (std::size_t m = 0; m < run->moves.moves.size() && !second; ++m) {
            const double at = 0.5 * (timeline.start(m) + timeline.end(m));
            const auto deg = camwb::gui::rotaryAt(*run, timeline.pointAt(at));
            if (std::abs(deg[0]) < 10)
                continue;
            if (!first) {
                first = at;
                firstDeg = deg;
            } else if (std::abs(deg[1] - firstDeg[1]) > 20) {
                second = at;
            }
        }
        QVERIFY2(first && second, "the example tilts B and turns C");
        player->seek(*first);
        QVERIFY(waitUntil([player] { return player->stockCaughtUp(); }));
        QVERIFY(waitUntil([&overlay] { return overlay.hasStockActor(); }));  // the frame's queued delivery
        QVERIFY(isIdentity(overlay.stockMatrix()));
        window.view()->fitAll();
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-workpiece-frame.png"));

        machineFrame->trigger();
        QVERIFY(machineFrame->isChecked() && player->showsMachineFrame());
        const auto tilted = overlay.tableMatrix();
        QVERIFY(!isIdentity(tilted));
        QCOMPARE(overlay.stockMatrix(), tilted);
        // The matrix is the chain's motion at the playback's point, and it stands the tool upright.
        const camwb::kinematics::RigidMotion motion = camwb::kinematics::machineFrameMotion(
            run->machine->kinematics, camwb::gui::rotaryAt(*run, player->point()));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                QVERIFY(std::abs(tilted[4 * r + c] - motion.rotation[3 * r + c]) < 1e-9);
        const camwb::base::Vec3 axis = motion.turn(timeline.poseAt(player->point()).axis);
        QVERIFY2(std::abs(axis.z - 1) < 1e-6,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(axis.x).arg(axis.y).arg(axis.z)));
        window.view()->fitAll();
        if (withGl())
            saveShot(&window, QStringLiteral("simulator-machine-frame.png"));

        player->seek(*second);  // another C: the table and the stock turn on
        QVERIFY(waitUntil([player] { return player->stockCaughtUp(); }));
        QVERIFY(overlay.tableMatrix() != tilted);
        QCOMPARE(overlay.stockMatrix(), overlay.tableMatrix());
        QVERIFY(!isIdentity(overlay.tableMatrix()));

        // Playing in either frame from the same point: the matrices follow (rates printed, not asserted).
        const double from = player->position();
        auto playAWhile = [&](const char* frame) {
            player->seek(from);
            player->setSpeed(20);
            QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Play")));
            QTest::qWait(1500);
            player->pause();
            qInfo("%s frame while playing: %.1f frames/s drawn, %.2f ms GUI per step and stock frame", frame,
                  player->stats().renderedFps, player->stats().meanUpdateMs);
        };
        playAWhile("machine");
        QCOMPARE(overlay.stockMatrix(), overlay.tableMatrix());
        machineFrame->trigger();
        playAWhile("workpiece");
        machineFrame->trigger();
        QVERIFY(player->showsMachineFrame());

        machineFrame->trigger();  // off: everything back in the workpiece frame
        QVERIFY(!machineFrame->isChecked() && !player->showsMachineFrame());
        QVERIFY(isIdentity(overlay.tableMatrix()));
        QVERIFY(isIdentity(overlay.stockMatrix()));
        QVERIFY(overlay.hasTableActor());
    }

    void stepAndJumpThroughTheRegistry()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, QStringLiteral(CAMWB_EXAMPLE_JOB));
        simulate(window);
        SimPlayer* player = window.simPlayer();
        camwb::gui::ActionRegistry& actions = window.actions();

        const int first = player->currentLine();
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.StepForward")));
        const int second = player->currentLine();
        QVERIFY2(second > first, qPrintable(QStringLiteral("%1 -> %2").arg(first).arg(second)));
        QCOMPARE(window.ncEditor()->currentLine(), second);
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.StepForward")));
        const int third = player->currentLine();
        QVERIFY(third > second);
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.StepBack")));
        QCOMPARE(player->currentLine(), second);
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.StepBack")));
        QCOMPARE(player->currentLine(), first);
        QCOMPARE(player->position(), 0.0);

        // Jump to a line in the middle of the program: the first run of that line (or of the next
        // line that moves), and the editor goes there.
        const auto trace = player->run()->trace;
        const int target = trace->lineRecords[trace->lineRecords.size() / 2].first;
        window.simDock()->findChild<QSpinBox*>(QStringLiteral("simLine"))->setValue(target);
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.JumpToLine")));
        QVERIFY2(player->currentLine() >= target,
                 qPrintable(QStringLiteral("%1 for %2").arg(player->currentLine()).arg(target)));
        QCOMPARE(window.ncEditor()->currentLine(), player->currentLine());
        const double there = player->position();
        QVERIFY(there > 0);

        // Pause stops the playback where it is.
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.Play")));
        QVERIFY(waitUntil([&] { return player->position() > there; }, 20000));
        QVERIFY(actions.trigger(QStringLiteral("Cam.Sim.Pause")));
        QVERIFY(!player->isPlaying());
        const double paused = player->position();
        QVERIFY2(paused > there,
                 qPrintable(QStringLiteral("%1 -> %2 at %3x").arg(there).arg(paused).arg(player->speed())));
        QTest::qWait(100);
        QCOMPARE(player->position(), paused);
    }

    // Clicking a line in the editor or a segment in the view moves the playback there.
    void editorAndViewLeadThePlayback()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openJob(window, QStringLiteral(CAMWB_EXAMPLE_JOB));
        simulate(window);
        SimPlayer* player = window.simPlayer();
        const auto trace = player->run()->trace;
        const auto [line, record] = trace->lineRecords[trace->lineRecords.size() / 3];
        window.ncEditor()->gotoLine(line);
        QCOMPARE(player->currentLine(), line);
        const auto [otherLine, otherRecord] = trace->lineRecords[2 * trace->lineRecords.size() / 3];
        emit window.view()->segmentPicked(0, static_cast<int>(otherRecord));
        QCOMPARE(player->currentLine(), otherLine);
        QCOMPARE(player->run()->moves.moves[player->point().move].record, otherRecord);
        Q_UNUSED(record);
    }

    void editedProgramIsOutOfDate()
    {
        QTemporaryDir dir;
        MainWindow window;
        window.show();
        openProgram(window, dir, QStringLiteral("part.ngc"),
                    "G90 G21\nG0 X0 Y0 Z5\nG1 Z-1 F200\nG1 X20\nG1 Y20\nG0 Z5\nM30\n");
        simulate(window);
        QVERIFY(!window.simPlayer()->isOutOfDate());
        auto* banner = window.simDock()->findChild<QLabel*>(QStringLiteral("simBanner"));
        QVERIFY(banner && banner->isHidden());
        // An NC file opened apart plays without the job's stock.
        QVERIFY(!window.simPlayer()->run()->stock);
        window.ncEditor()->replaceText(QStringLiteral("G90 G21\nG0 X0 Y0 Z5\nG1 Z-2 F200\nG1 X20\nM30\n"));
        QVERIFY(window.simPlayer()->isOutOfDate());
        QVERIFY(!banner->isHidden());
        QVERIFY(banner->text().contains(QLatin1String("Out of date")));
        QVERIFY(waitForTrace(window));
        simulate(window);
        QVERIFY(!window.simPlayer()->isOutOfDate());
        QVERIFY(banner->isHidden());
    }

    // A program that plunges before it says where in X and Y: the report names the block whose
    // way the simulator could not follow, as a warning at its file and line.
    void moveFromAnUnknownPositionIsReported()
    {
        QTemporaryDir dir;
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        openProgram(window, dir, QStringLiteral("unknown.ngc"),
                    "G90 G21\nT1 M6\nS1000 M3\nG0 Z5\nG1 Z-1 F100\nG1 X20 Y10\nG1 X40\nM30\n");
        simulate(window);
        const QString report = window.reportView()->toPlainText();
        QVERIFY2(report.contains(QRegularExpression(
                     QStringLiteral("unknown\\.ngc:5: warning: feed move from an unknown position \\(X, Y not given"))),
                 qPrintable(report));
        QVERIFY2(report.contains(QLatin1String("Simulated unknown.ngc: cycle time 21.0 s, errors: 0, warnings: 1")),
                 qPrintable(report));
        if (withGl()) {
            for (QWidget* w = window.reportView(); w; w = w->parentWidget())
                if (auto* dock = qobject_cast<QDockWidget*>(w))
                    dock->raise();
            QTest::qWait(50);
            saveShot(&window, QStringLiteral("simulator-unknown-position.png"));
        }
    }

    // Cam.Sim.ImportMeasured, as a user would: the CSV's name, then the columns dialog (the one
    // shown now: an accepted one may linger until its deferred deletion).
    static camwb::gui::MeasuredImportDialog* askToImport(MainWindow& window, ScriptedPrompter& prompter,
                                                         const QString& file)
    {
        prompter.files.push_back(file);
        if (!window.actions().trigger(QStringLiteral("Cam.Sim.ImportMeasured")))
            return nullptr;
        for (auto* dialog : window.simDock()->findChildren<camwb::gui::MeasuredImportDialog*>())
            if (dialog->isVisible() && dialog->file() == file)
                return dialog;
        return nullptr;
    }

    static void importMeasured(MainWindow& window, ScriptedPrompter& prompter, const QString& file)
    {
        camwb::gui::MeasuredImportDialog* dialog = askToImport(window, prompter, file);
        QVERIFY(dialog);
        dialog->accept();
        QTest::qWait(0);
    }

    // A trace made from the program's own planned motion (tests/data/sim/make-measured-square.py):
    // the actual X runs 0 mm at the start to 1 mm at the end ahead of the nominal, so the
    // deviation's range is exactly [0, 1] mm. Overlaid with the program, charted, coloured with
    // automatic and user limits; a bad CSV names its line and changes nothing; cleared, imported
    // again, and out of date once the program changed and was simulated again.
    void measuredTraceOverlay()
    {
        QTemporaryDir dir;
        const QString program = dir.filePath(QStringLiteral("measured-square.ngc"));
        QVERIFY(QFile::copy(QStringLiteral(CAMWB_SIM_DATA "/measured-square.ngc"), program));
        const QString csv = QStringLiteral(CAMWB_SIM_DATA "/tncscope-square-ramp.csv");
        MainWindow window;
        auto owned = std::make_unique<ScriptedPrompter>();
        ScriptedPrompter* prompter = owned.get();
        window.setPrompter(std::move(owned));
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openNcFile(program));
        QVERIFY(waitForTrace(window));
        SimPlayer* player = window.simPlayer();
        QVERIFY(!window.actions().action(QStringLiteral("Cam.Sim.ImportMeasured"))->isEnabled());  // no run yet
        simulate(window);

        // The dialog starts from sim::TraceColumns' defaults (seed 003's order).
        camwb::gui::MeasuredImportDialog* dialog = askToImport(window, *prompter, csv);
        QVERIFY(dialog);
        const camwb::sim::TraceColumns defaults, asked = dialog->columns();
        QCOMPARE(asked.time, defaults.time);
        QVERIFY(asked.nominal == defaults.nominal && asked.actual == defaults.actual &&
                asked.deviation == defaults.deviation);
        QCOMPARE(asked.headerLines, defaults.headerLines);
        QCOMPARE(asked.linearScale, 1.0);
        QCOMPARE(asked.separator, defaults.separator);
        dialog->accept();
        QTest::qWait(0);
        QVERIFY2(prompter->errors.isEmpty(), qPrintable(prompter->errors.join('\n')));
        const auto measured = player->measured();
        QVERIFY(measured);
        QVERIFY(measured->trace.time.size() > 100);
        QCOMPARE(measured->actualTip.size(), measured->trace.time.size());

        // The overlay: program and nominal drawn, the actual coloured by its deviation.
        camwb::gui::SimOverlay& overlay = window.view()->simulation();
        QVERIFY(overlay.showsMeasured());
        QVERIFY(overlay.showsColouredPath());
        QCOMPARE(player->quantity(), QString::fromLatin1(camwb::gui::kMeasuredFollowingId));
        const auto range = player->quantityRange();
        QVERIFY2(std::abs(range.first) < 1e-9 && std::abs(range.second - 1.0) < 1e-9,
                 qPrintable(QStringLiteral("%1 .. %2").arg(range.first, 0, 'g', 12).arg(range.second, 0, 'g', 12)));
        auto* summary = window.simDock()->findChild<QLabel*>(QStringLiteral("simMeasured"));
        QVERIFY(summary && summary->isVisibleTo(window.simDock()));
        QVERIFY2(summary->text().contains(QLatin1String("actual to nominal up to 1.0000 mm")),
                 qPrintable(summary->text()));
        // The nominal trace is the planned motion the program was sampled by: on the path.
        const QStringList ids = player->quantityIds();
        QVERIFY(ids.contains(QLatin1String(camwb::gui::kMeasuredToProgramId)));
        // User limits, as for every colour map.
        auto* autoLimits = window.simDock()->findChild<QCheckBox*>(QStringLiteral("simAutoLimits"));
        autoLimits->setChecked(false);
        auto* low = window.simDock()->findChild<QDoubleSpinBox*>(QStringLiteral("simLow"));
        auto* high = window.simDock()->findChild<QDoubleSpinBox*>(QStringLiteral("simHigh"));
        low->setValue(0);
        high->setValue(2);
        emit high->editingFinished();
        QCOMPARE(player->quantityRange(), std::make_pair(0.0, 2.0));
        autoLimits->setChecked(true);
        QVERIFY(std::abs(player->quantityRange().second - 1.0) < 1e-9);
        // The chart plots the deviation against time; a click seeks.
        if (withGl())
            QVERIFY(window.simDock()->chart()->plottedPoints() > 10);
        const double middle = measured->trace.time[measured->trace.time.size() / 2];
        emit window.simDock()->chart()->timeClicked(middle);
        QCOMPARE(player->position(), middle);
        if (withGl()) {
            window.view()->fitAll();
            saveShot(&window, QStringLiteral("simulator-measured-trace.png"));
        }

        // A bad CSV: its file and line, and the overlay as it was.
        const QString bad = dir.filePath(QStringLiteral("bad.csv"));
        QFile badFile(bad);
        QVERIFY(badFile.open(QIODevice::WriteOnly));
        badFile.write("time;X_nom;X_act;Y_nom;Y_act;Z_nom;Z_act;A_nom;A_act;C_nom;C_act;dX;dY;dZ;dA;dC\n"
                      "0,000;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0\n"
                      "0,003;0;x1;0;0;0;0;0;0;0;0;0;0;0;0;0\n");
        badFile.close();
        importMeasured(window, *prompter, bad);
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY2(prompter->errors.first().contains(QLatin1String("bad.csv:3:")), qPrintable(prompter->errors.first()));
        QCOMPARE(player->measured(), measured);
        QCOMPARE(player->quantity(), QString::fromLatin1(camwb::gui::kMeasuredFollowingId));
        QVERIFY(overlay.showsMeasured());

        // Cleared: no overlay, no measured quantities; imported again.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.ClearMeasured")));
        QVERIFY(!player->measured());
        QVERIFY(!overlay.showsMeasured());
        QVERIFY(!overlay.showsColouredPath());
        QVERIFY(!player->quantityIds().contains(QLatin1String(camwb::gui::kMeasuredFollowingId)));
        QVERIFY(!summary->isVisibleTo(window.simDock()));
        importMeasured(window, *prompter, csv);
        QVERIFY(player->measured());
        QVERIFY(overlay.showsMeasured());
        QVERIFY(!player->isMeasuredOutOfDate());

        // Simulated again unchanged: still current. Changed and simulated again: out of date.
        simulate(window);
        QVERIFY(player->measured());
        QVERIFY(!player->isMeasuredOutOfDate());
        window.ncEditor()->replaceText(QStringLiteral("G90 G21\nG0 X0 Y0 Z5\nG1 Z-2 F600\nG1 X40 F3000\nM30\n"));
        QVERIFY(waitForTrace(window));
        simulate(window);
        QVERIFY(player->measured());
        QVERIFY(player->isMeasuredOutOfDate());
        QVERIFY(overlay.showsMeasured());
        auto* banner = window.simDock()->findChild<QLabel*>(QStringLiteral("simBanner"));
        QVERIFY(banner && !banner->isHidden());
        QVERIFY2(banner->text().contains(QLatin1String("measured trace")), qPrintable(banner->text()));
    }

    // A long program's simulation is built on a worker and can be cancelled; the GUI keeps
    // serving events meanwhile (the longest stall is printed).
    void longBuildCanBeCancelled()
    {
        QTemporaryDir dir;
        QFile file(dir.filePath(QStringLiteral("long.ngc")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("G90 G21\nG0 X0 Y0 Z5\nG1 Z-1 F2000\n");
        for (int i = 0; i < 200000; ++i)
            file.write(QStringLiteral("G1 X%1 Y%2\n").arg(i % 100).arg((i / 100) % 50).toLatin1());
        file.write("M30\n");
        file.close();
        MainWindow window;
        window.show();
        QVERIFY(window.openNcFile(file.fileName()));
        QVERIFY(waitForTrace(window));
        SimPlayer* player = window.simPlayer();
        QSignalSpy progress(player, &SimPlayer::buildProgress);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Sim.Start")));
        QVERIFY(player->isBuilding());
        auto* cancel = window.simDock()->findChild<QWidget*>(QStringLiteral("simCancel"));
        QVERIFY(cancel && cancel->isVisible());
        static_cast<QAbstractButton*>(cancel)->click();  // at once: no event runs before it
        QVERIFY(waitUntil([player] { return !player->isBuilding(); }));
        QVERIFY(!player->hasRun());
        QVERIFY(window.reportView()->toPlainText().contains(QLatin1String("Simulation cancelled")));

        // And once more to the end, measuring how long the event loop ever waited.
        qint64 longestStall = 0;
        QElapsedTimer tick;
        QTimer ticker;
        ticker.setInterval(10);
        connect(&ticker, &QTimer::timeout, &window, [&] { longestStall = std::max(longestStall, tick.restart()); });
        tick.start();
        ticker.start();
        simulate(window);
        ticker.stop();
        qInfo("200000 moves simulated; longest event-loop stall while building %lld ms", longestStall);
        QCOMPARE(player->run()->timeline.moveCount(), player->run()->moves.moves.size());
    }
};

int main(int argc, char** argv)
{
    View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    SimulatorTest test;
    run.run(&test);
    return run.finish();
}

#include "SimulatorTest.moc"
