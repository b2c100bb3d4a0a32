// Drives the real main window: opens the example job, posts through the action registry and
// checks the editor dock, the 3D view and undo; unsaved NC edits are never replaced without
// asking (answered by a ScriptedPrompter). Runs twice: under Xvfb (GL) and offscreen (no GL).
#include "gui/shell/MainWindow.h"
#include "MotionMatch.h"
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "Shots.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/ProgramInfoDialog.h"
#include "gui/inspector/InspectorPanel.h"
#include "gui/inspector/ModalStatePanel.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/NcDocument.h"
#include "gui/shell/ReportView.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/view3d/View3D.h"
#include "kinematics/Machine.h"
#include "toolpath/ToolpathPolylines.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <cmath>

using camwb::gui::MainWindow;
using camwb::gui::NcInspector;
using Answer = camwb::gui::Prompter::Answer;
using camwb::gui::View3D;
using camwb::gui::Workbench;

class MainWindowTest : public QObject {
    Q_OBJECT

private:
    static bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

    static QString golden()
    {
        QFile file(QStringLiteral(CAMWB_EXAMPLE_GOLDEN));
        if (!file.open(QIODevice::ReadOnly))
            return {};
        return QString::fromUtf8(file.readAll());
    }

    // Opens the example job and waits for the first post to finish.
    static void openExample(MainWindow& window)
    {
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
    }

    // Waits until the inspector has no trace running and holds one.
    static bool waitForTrace(MainWindow& window)
    {
        NcInspector* inspector = window.inspector();
        QElapsedTimer waited;
        waited.start();
        while ((inspector->isTracing() || !inspector->trace()) && waited.elapsed() < 120000)
            QTest::qWait(20);
        return !inspector->isTracing() && inspector->trace();
    }

    static QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text)
    {
        QFile file(dir.filePath(name));
        if (!file.open(QIODevice::WriteOnly))
            return {};
        file.write(text);
        return file.fileName();
    }

    static QByteArray readFile(const QString& path)
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }

    // The first error of a trace, for a failure's message (QVERIFY2 evaluates it in any case).
    static QString firstError(const camwb::document::NcTrace& trace)
    {
        for (const auto& d : trace.result.diagnostics)
            if (d.severity == camwb::nc::Severity::Error)
                return QString::fromStdString(camwb::nc::formatDiagnostic(d));
        return QStringLiteral("no error");
    }

    // Gives the window a prompter the test answers; the window owns it.
    static ScriptedPrompter* scriptPrompts(MainWindow& window)
    {
        auto* prompter = new ScriptedPrompter;
        window.setPrompter(std::unique_ptr<camwb::gui::Prompter>(prompter));
        return prompter;
    }

    static QString ncDockTitle(MainWindow& window)
    {
        return window.findChild<QDockWidget*>(QStringLiteral("ncDock"))->windowTitle();
    }

private slots:
    void actionsHaveStableIdsAndMenus()
    {
        MainWindow window;
        const QStringList ids = window.actions().ids();
        for (const char* id :
             {"Cam.File.Open", "Cam.File.Save", "Cam.File.ImportModel", "Cam.Edit.Undo", "Cam.Op.NewProfile",
              "Cam.Job.Post", "Cam.Job.SaveNc", "Cam.View.Isometric", "Cam.View.FitAll", "Cam.Nc.Open", "Cam.Nc.Trace"})
            QVERIFY2(ids.contains(QLatin1String(id)), id);
        QVERIFY(window.menuBar()->actions().size() >= 5);
        QCOMPARE(window.actions().action(QStringLiteral("Cam.Job.Post"))->shortcut(), QKeySequence(Qt::Key_F9));
        QVERIFY(!window.actions().trigger(QStringLiteral("Cam.No.Such")));
    }

    void postFromRegistryFillsEditorWithGoldenNc()
    {
        const QString expected = golden();
        QVERIFY2(!expected.isEmpty(), "golden NC missing");
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);

        window.ncEditor()->setText(QString());  // prove the post below refills it
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Post")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
        QCOMPARE(window.ncEditor()->text(), expected);

        QCOMPARE(window.view()->hasOpenGl(), withGl());
        QVERIFY(window.view()->hasModelActor());
        QVERIFY(window.view()->hasToolpathActor());
        QVERIFY(window.view()->toolpathSegmentCount() > 10);
        if (withGl()) {
            const QImage image = window.grab().toImage();
            QVERIFY(!image.isNull());
            image.save(QStringLiteral(CAMWB_SCREENSHOT_DIR "/mainwindow.png"));
        }
    }

    void newProfileIsUndoable()
    {
        MainWindow window;
        openExample(window);
        const auto before = window.workbench().job().operations.size();
        // The foundation's id opens the contour's task panel; OK adds the operation.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewProfile")));
        QVERIFY(window.taskPanel());
        QCOMPARE(window.workbench().job().operations.size(), before);
        window.taskPanel()->accept();
        QCOMPARE(window.workbench().job().operations.size(), before + 1);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(window.workbench().job().operations.size(), before);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Redo")));
        QCOMPARE(window.workbench().job().operations.size(), before + 1);
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        if (window.workbench().isBusy())
            QVERIFY(posted.wait(120000));
    }

    void editedOperationRepostsAndUndoes()
    {
        MainWindow window;
        openExample(window);
        Workbench& wb = window.workbench();
        const QString postedBefore = window.ncEditor()->text();
        window.editOperation(0);
        camwb::gui::OperationPanel* panel = window.taskPanel();
        QVERIFY(panel);
        auto* finalAuto = panel->findChild<QCheckBox*>(QStringLiteral("finalAuto"));
        auto* finalBox = panel->findChild<QDoubleSpinBox*>(QStringLiteral("finalBox"));
        QVERIFY(finalAuto && finalBox);
        finalAuto->setChecked(false);
        finalBox->setValue(8.0);
        if (withGl())
            panel->grab().save(QStringLiteral(CAMWB_SCREENSHOT_DIR "/operationpanel.png"));

        QSignalSpy posted(&wb, &Workbench::postFinished);
        panel->accept();
        QVERIFY(posted.wait(120000));
        QCOMPARE(wb.job().operations[0].heights.finalZ, std::optional<double>(8.0));
        QVERIFY(window.ncEditor()->text() != postedBefore);
        QVERIFY(window.windowTitle().contains(QLatin1Char('*')));

        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(window.ncEditor()->text(), postedBefore);
        QVERIFY(!window.windowTitle().contains(QLatin1Char('*')));
    }

    void badModelImportLeavesJobUnchanged()
    {
        MainWindow window;
        openExample(window);
        const std::string modelBefore = window.workbench().job().modelPath;
        QSignalSpy finished(&window.workbench(), &Workbench::modelImportFinished);
        QSignalSpy messages(&window.workbench(), &Workbench::message);
        window.workbench().importModel(QStringLiteral("/nonexistent/part.step"));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().first().toBool(), false);
        QCOMPARE(window.workbench().job().modelPath, modelBefore);
        QVERIFY(!window.workbench().document().isModified());
        bool named = false;
        for (const auto& m : messages)
            named = named || m.at(1).toString().contains(QLatin1String("/nonexistent/part.step"));
        QVERIFY(named);
    }

    void openNcProgramIsTracedAndLinked()
    {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("part.ngc"),
                                       "(part)\nG21 G90 G17\nT1 M6\nS2000 M3\nG0 X0 Y0 Z5\nG1 Z-1 F150\n"
                                       "G2 X20 Y0 I10 J0\nG0 Z5\nT2 M6\nG0 X0 Y20\nG1 Z-1 F90\nG1 X20\nG0 Z5\nM30\n");
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("modalDock")) != nullptr);
        QVERIFY(window.openJob(path));  // not a .camwb: opened as an NC program
        QVERIFY(!window.ncEditor()->isReadOnly());
        QVERIFY(window.ncEditor()->text().startsWith(QLatin1String("(part)")));
        QVERIFY(waitForTrace(window));
        const auto trace = window.inspector()->trace();
        QVERIFY2(!(trace->program.empty() && trace->result.hasErrors()), qPrintable(firstError(*trace)));
        QCOMPARE(trace->dialect, camwb::nc::Dialect::Iso);
        QVERIFY(window.view()->hasToolpathActor());
        QVERIFY(window.view()->toolpathSegmentCount() > 10);

        // The cursor on the arc: its segments highlighted, its state in the dock.
        window.ncEditor()->gotoLine(7);
        QVERIFY(!window.view()->highlightedSegments().empty());
        auto* modal = window.inspectorPanel()->modalPanel();
        QCOMPARE(modal->value(QStringLiteral("move")), QStringLiteral("arc CW"));
        QCOMPARE(modal->value(QStringLiteral("tool")), QStringLiteral("T1"));

        // Tools from the dock's list: unchecking T2 hides its segments.
        QListWidget* tools = window.inspectorPanel()->toolList();
        QCOMPARE(tools->count(), 2);
        const int all = window.view()->visibleSegmentCount();
        tools->item(1)->setCheckState(Qt::Unchecked);
        QVERIFY(!window.view()->isToolVisible(2));
        QVERIFY(window.view()->visibleSegmentCount() < all);
        tools->item(1)->setCheckState(Qt::Checked);
        QCOMPARE(window.view()->visibleSegmentCount(), all);

        // Re-trace from the registry.
        QSignalSpy finished(window.inspector(), &NcInspector::traceFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Nc.Trace")));
        QVERIFY(finished.wait(60000));

        if (withGl()) {
            // A click on the T2 cut moves the editor there.
            const auto* polylines = window.view()->toolpathPolylines();
            std::size_t target = polylines->segments().size();
            for (std::size_t s = 0; s < polylines->segments().size(); ++s)
                if (trace->lineOfRecord(polylines->segments()[s].record) == 12)
                    target = s;
            QVERIFY(target < polylines->segments().size());
            const auto& segment = polylines->segments()[target];
            const auto middle = (polylines->points()[segment.from] + polylines->points()[segment.to]) * 0.5;
            const auto at = window.view()->projectToWidget(middle);
            QVERIFY(at.has_value());
            auto* gl = window.view()->findChild<QWidget*>(QStringLiteral("view3dGl"));
            QTest::mouseClick(gl, Qt::LeftButton, {}, gl->mapFrom(window.view(), at->toPoint()));
            QCOMPARE(window.ncEditor()->currentLine(), 12);
        }
    }

    // A program's diagnostics reach the report in the form editors read, file:line:column:
    // severity: message, and once: no second "error: " in front.
    void reportShowsDiagnosticsOnce()
    {
        QTemporaryDir dir;
        const QString path =
            writeFile(dir, QStringLiteral("broken.ngc"), "G21 G90 G17\nG0 X0 Y0 Z5\nG1 X1..2 F100\nM30\n");
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openJob(path));
        QVERIFY(waitForTrace(window));
        const QString report = window.reportView()->toPlainText();
        QVERIFY2(report.contains(QLatin1String("broken.ngc:3:")), qPrintable(report));
        QVERIFY2(report.contains(QLatin1String(": error: ")), qPrintable(report));
        QVERIFY2(!report.contains(QRegularExpression(QStringLiteral("error: \\S*broken\\.ngc"))), qPrintable(report));
    }

    void postedProgramIsTraced()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        QVERIFY(waitForTrace(window));
        const auto trace = window.inspector()->trace();
        QCOMPARE(trace->dialect, camwb::nc::Dialect::Sinumerik);
        QVERIFY2(!(trace->program.empty() && trace->result.hasErrors()),
                 qPrintable(QStringLiteral("SINUMERIK interpreter: ") + firstError(*trace)));
        // Checked against the machine its post checked the CL against (the EMCO, the post's default),
        // which the inspector names; the example job breaks none of its limits.
        QVERIFY(window.inspector()->machine() != nullptr);
        QCOMPARE(QString::fromStdString(window.inspector()->machine()->id), QStringLiteral("emco-concept-mill-105"));
        QVERIFY(window.inspectorPanel()
                    ->findChild<QComboBox*>(QStringLiteral("machineCombo"))
                    ->currentText()
                    .startsWith(QLatin1String("EMCO Concept MILL 105")));
        QVERIFY2(!trace->result.hasErrors() && trace->result.diagnostics.empty(), qPrintable(firstError(*trace)));
        // The view shows the trace of the posted program, not the operations' toolpath.
        QVERIFY(window.inspector()->showsInView());
        QCOMPARE(window.view()->toolpathSegmentCount(),
                 int(camwb::toolpath::ToolpathPolylines::fromToolpath(trace->program).segments().size()));
        QVERIFY(window.view()->toolpathSegmentCount() > 10);
        // The operations' toolpath on request, and back.
        window.inspectorPanel()->setShowsNcTrace(false);
        QVERIFY(!window.inspector()->showsInView());
        QVERIFY(window.view()->hasToolpathActor());
        window.inspectorPanel()->setShowsNcTrace(true);
        QVERIFY(window.inspector()->showsInView());
    }

    // Opens a generated ISO program (CAMWB_INSPECTOR_LINES lines, 20000 unless set), traces it and
    // reports how long open, trace and first display take and the longest stall of the event loop
    // meanwhile. Figures only: a test never asserts a time.
    void largeProgramKeepsTheGuiResponsive()
    {
        const int lines = qEnvironmentVariableIsSet("CAMWB_INSPECTOR_LINES")
                              ? qEnvironmentVariableIntValue("CAMWB_INSPECTOR_LINES")
                              : 20000;
        QTemporaryDir dir;
        QByteArray text;
        text.reserve(lines * 32);
        text += "(generated)\nG21 G90 G17 G54\nT1 M6\nS6000 M3\nG0 X0 Y0 Z5\nG1 Z-1 F1200\n";
        for (int i = 6; i < lines - 1; ++i) {
            // A 3D finishing pass as CAM writes it: rows of short moves over a wavy surface.
            const double x = (i % 2000) * 0.05, y = (i / 2000) * 0.5;
            const double z = -1.0 - 0.8 * std::sin(x * 0.35) * std::cos(y * 0.05);
            // Every 50th move a small arc, but none where a row starts (that one jumps back).
            const bool arc = i % 50 == 0 && i % 2000 != 0;
            text += (arc ? "G2 X" : "G1 X") + QByteArray::number(x, 'f', 3) + " Y" + QByteArray::number(y, 'f', 3) +
                    " Z" + QByteArray::number(z, 'f', 3) + (arc ? " I0.025 J0\n" : "\n");
        }
        text += "M30\n";
        const QString path = writeFile(dir, QStringLiteral("large.ngc"), text);

        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        qint64 longestStall = 0;
        QElapsedTimer tick;
        QTimer ticker;
        ticker.setInterval(10);
        connect(&ticker, &QTimer::timeout, &window, [&] { longestStall = std::max(longestStall, tick.restart()); });
        QElapsedTimer clock;
        clock.start();
        QVERIFY(window.openNcFile(path));
        const qint64 openMs = clock.elapsed();
        tick.start();
        ticker.start();
        QVERIFY(waitForTrace(window));
        const qint64 tracedMs = clock.elapsed();
        ticker.stop();
        window.view()->grabImage();  // the first frame with the trace
        const qint64 shownMs = clock.elapsed();
        window.view()->setViewPreset(View3D::Preset::Top);
        window.view()->grabImage();  // a frame with the data already on the GPU
        const qint64 nextFrameMs = clock.elapsed() - shownMs;
        const auto timings = window.inspector()->lastTimings();
        qInfo(
            "%d lines: open %lld ms, traced and in the view %lld ms (interpret %.0f ms, index %.0f ms, "
            "3D data %.0f ms, actors %.0f ms), first frame %lld ms, next frame %lld ms; longest event-loop stall while "
            "tracing %lld ms; %d segments, %d diagnostics",
            lines, openMs, tracedMs, timings.interpret * 1e3, timings.index * 1e3, timings.scene * 1e3,
            timings.show * 1e3, shownMs, nextFrameMs, longestStall, window.view()->toolpathSegmentCount(),
            int(window.inspector()->trace()->result.diagnostics.size()));
        const auto trace = window.inspector()->trace();
        QVERIFY2(!(trace->program.empty() && trace->result.hasErrors()), qPrintable(firstError(*trace)));
        QVERIFY(window.view()->toolpathSegmentCount() >= lines - 10);
        window.ncEditor()->gotoLine(lines / 2);
        QVERIFY(!window.view()->highlightedSegments().empty());
    }

    // The example job posted with the iTNC 530 post: the editor holds Klartext and highlights it as
    // Klartext, the inspector traces it on the post's machine without a diagnostic, and what the
    // trace moves is what the job's CL moves (the round trip of the post goldens, here in the window).
    void heidenhainPostedJobIsKlartextAndMovesAsItsCl()
    {
        QTemporaryDir dir;
        QByteArray job = readFile(QStringLiteral(CAMWB_EXAMPLE_JOB));
        job.replace("\"post\": \"sinumerik828d-emco\"", "\"post\": \"heidenhain-itnc530\"");
        const QByteArray model = QFileInfo(QStringLiteral(CAMWB_EXAMPLE_JOB)).absolutePath().toUtf8() + "/";
        job.replace("\"model\": \"", "\"model\": \"" + model);
        QVERIFY(job.contains("heidenhain-itnc530"));
        const QString path = writeFile(dir, QStringLiteral("example-block.camwb"), job);
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(path));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
        QVERIFY(waitForTrace(window));
        QCOMPARE(window.workbench().ncExtension(), QStringLiteral("h"));
        QVERIFY(window.ncEditor()->text().startsWith(QLatin1String("0 BEGIN PGM example-block MM\n")));
        QCOMPARE(window.ncEditor()->dialect(), camwb::nc::Dialect::Heidenhain);
        const auto trace = window.inspector()->trace();
        QCOMPARE(trace->dialect, camwb::nc::Dialect::Heidenhain);
        QVERIFY2(trace->result.diagnostics.empty(), qPrintable(firstError(*trace)));
        QCOMPARE(QString::fromStdString(window.inspector()->machine()->id), QStringLiteral("mas-mcvl1000"));
        const auto difference = camwb::nc::test::matchMotion(trace->program, window.workbench().toolpath());
        QVERIFY2(!difference, difference ? difference->c_str() : "");
        // The cursor on a circle block: its segment lights up in the view.
        const QStringList lines = window.ncEditor()->text().split(QLatin1Char('\n'));
        int circle = 0;
        for (int i = 0; i < lines.size() && !circle; ++i)
            if (lines[i].contains(QLatin1String(" C X")))
                circle = i + 1;
        QVERIFY(circle > 0);
        window.ncEditor()->gotoLine(circle);
        QTest::qWait(300);
        QVERIFY(!window.view()->highlightedSegments().empty() || !window.view()->hasOpenGl());
        saveShot(&window, QStringLiteral("heidenhain-posted-job.png"));
        // Program Information estimates with the machine's rapid, as the header's time does: the
        // same figure for the same program, to the second.
        const QRegularExpressionMatch header =
            QRegularExpression(QStringLiteral("; MACHINING TIME: (\\d+):(\\d\\d):(\\d\\d)\n"))
                .match(window.ncEditor()->text());
        QVERIFY(header.hasMatch());
        const int headerSeconds =
            header.captured(1).toInt() * 3600 + header.captured(2).toInt() * 60 + header.captured(3).toInt();
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Nc.ProgramInfo")));
        auto* info = window.findChild<camwb::gui::ProgramInfoDialog*>();
        QVERIFY(info != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(info->hasStats() && !info->isBusy(), 20000);
        QCOMPARE(info->stats().rapidMmPerMin, 22000.0);
        QVERIFY2(std::abs(info->stats().totals.totalSeconds() - headerSeconds) <= 1.0,
                 qPrintable(QStringLiteral("%1 s vs the header's %2 s")
                                .arg(info->stats().totals.totalSeconds())
                                .arg(headerSeconds)));
    }

    // Pictures of the inspector (kept in CAMWB_SHOTS_DIR when set): posted SINUMERIK, ISO and
    // Heidenhain programs with the cursor on an arc block, and the example job. Each must show
    // something (the grab of a window that drew nothing is one colour).
    void inspectorScreenshots()
    {
        struct Shot {
            const char* program;
            const char* arcBlock;  // text that starts the block to put the cursor on
            const char* file;
        };
        for (const Shot& shot :
             {Shot{"posts/sinumerik828d-emco/tests/arcs/expected.mpf", "N210 G2", "sinumerik-arcs.png"},
              Shot{"posts/sinumerik828d-emco/tests/cycles/expected.mpf", "N180", "sinumerik-cycles.png"},
              Shot{"posts/linuxcnc/tests/arcs/expected.ngc", "G2 Z-1", "iso-arcs.png"},
              Shot{"tests/golden/nc/heidenhain/arcs-c-cr-ct/input.h", "10 CR", "heidenhain-arcs.png"}}) {
            MainWindow window;
            window.resize(1600, 1000);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QVERIFY(window.openNcFile(QStringLiteral(CAMWB_SOURCE_DIR "/") + QLatin1String(shot.program)));
            QVERIFY(waitForTrace(window));
            const QStringList lines = window.ncEditor()->text().split(QLatin1Char('\n'));
            int line = 1;
            for (int i = 0; i < lines.size(); ++i)
                if (lines[i].startsWith(QLatin1String(shot.arcBlock)) && line == 1 &&
                    !window.inspector()->trace()->recordsOfLine(i + 1).empty())
                    line = i + 1;
            QVERIFY2(line > 1, shot.arcBlock);
            window.ncEditor()->gotoLine(line);
            QTest::qWait(300);
            saveShot(&window, QLatin1String(shot.file));
        }
        // The example job posted: the model with the trace of its program, cursor on an arc.
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        QVERIFY(waitForTrace(window));
        const QStringList lines = window.ncEditor()->text().split(QLatin1Char('\n'));
        for (int i = 0; i < lines.size(); ++i) {
            if (lines[i].contains(QLatin1String(" G2 ")) || lines[i].contains(QLatin1String(" G3 "))) {
                window.ncEditor()->gotoLine(i + 1);
                break;
            }
        }
        QTest::qWait(300);
        saveShot(&window, QStringLiteral("posted-job.png"));
    }

    // Five-axis Klartext read back through the MAS MCVL 1000's kinematics (its machine file): the
    // tip on a circle with the tool tilted 20 degrees outwards, the tool axis drawn along the path,
    // the panel with the tool vector and B/C at the cursor. The picture: heidenhain-five-axis.png.
    void fiveAxisProgramShowsTheToolAxis()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openNcFile(QStringLiteral(CAMWB_SOURCE_DIR "/tests/data/nc/five-axis-cone.h")));
        QVERIFY(waitForTrace(window));
        // Without a machine the B/C words are not traced (the backplot has no tool axes); the
        // user chooses the machine in the inspector and the program is traced again on it.
        QCOMPARE(window.inspector()->machine(), nullptr);
        QVERIFY(window.view()->toolpathPolylines() != nullptr);
        QCOMPARE(window.view()->toolpathPolylines()->segmentCount(camwb::toolpath::PathSegmentKind::ToolAxis),
                 std::size_t(0));
        auto* machines = window.inspectorPanel()->findChild<QComboBox*>(QStringLiteral("machineCombo"));
        QVERIFY(machines != nullptr);
        const int mas = machines->findData(QStringLiteral("mas-mcvl1000"));
        QVERIFY(mas > 0);
        machines->setCurrentIndex(mas);
        QVERIFY(window.inspector()->machine() != nullptr);
        QCOMPARE(QString::fromStdString(window.inspector()->machine()->id), QStringLiteral("mas-mcvl1000"));
        QVERIFY(waitForTrace(window));
        QVERIFY2(!window.inspector()->trace()->result.hasErrors(),
                 window.inspector()->trace()->result.diagnostics.empty()
                     ? ""
                     : window.inspector()->trace()->result.diagnostics.front().message.c_str());
        const camwb::toolpath::ToolpathPolylines* lines = window.view()->toolpathPolylines();
        QVERIFY(lines != nullptr);
        QVERIFY(lines->segmentCount(camwb::toolpath::PathSegmentKind::ToolAxis) >=
                std::size_t(72 / camwb::toolpath::ToolpathPolylines::kToolAxisEvery));
        window.ncEditor()->gotoLine(10);  // L Z+0 F300: down with the tool tilted 20 degrees towards +X
        QTest::qWait(300);
        auto* panel = window.findChild<camwb::gui::ModalStatePanel*>();
        QVERIFY(panel != nullptr);
        QCOMPARE(panel->value(QStringLiteral("toolAxis")), QStringLiteral("I0.3420 J0.0000 K0.9397 (five-axis move)"));
        QCOMPARE(panel->value(QStringLiteral("rotaryAxes")), QStringLiteral("B-20.000 C0.000"));
        window.ncEditor()->gotoLine(17);  // the loop's five-axis block
        window.view()->fitAll();
        QTest::qWait(300);
        saveShot(&window, QStringLiteral("heidenhain-five-axis.png"));
    }

    // The five-axis example job as a user opens it: posted for the MAS MCVL 1000 (its post's and
    // job's machine) and read back through the machine: the four drilling planes and the boss's
    // plane as tilted working planes, the swarf pass as five-axis moves with their tool axes drawn,
    // and no diagnostic but the two the travel-limit retract gives by design (M140 MB MAX leaves Z
    // unknown). The picture: five-axis-example-job.png.
    void fiveAxisExampleJobTracesThroughItsMachine()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_SOURCE_DIR "/resources/examples/example-five-axis.camwb")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.first().first().toBool(), true);
        QVERIFY(waitForTrace(window));
        const auto trace = window.inspector()->trace();
        QVERIFY(window.inspector()->machine() != nullptr);
        QCOMPARE(QString::fromStdString(window.inspector()->machine()->id), QStringLiteral("mas-mcvl1000"));
        for (const auto& d : trace->result.diagnostics)
            QVERIFY2(d.severity == camwb::base::Severity::Warning &&
                         (d.message.rfind("M140 MB MAX", 0) == 0 ||
                          d.message.find("rotary axes turned while X, Y or Z is unknown") != std::string::npos),
                     d.message.c_str());
        int tilted = 0, fiveAxis = 0;
        for (const camwb::toolpath::Record& r : trace->program.records()) {
            if (const auto* plane = std::get_if<camwb::toolpath::WorkingPlane>(&r))
                tilted += plane->tilted() ? 1 : 0;
            fiveAxis += std::holds_alternative<camwb::toolpath::ToolAxisMove>(r) ? 1 : 0;
        }
        QCOMPARE(tilted, 5);  // four hole directions and the boss's face
        QVERIFY(fiveAxis > 100);
        const camwb::toolpath::ToolpathPolylines* lines = window.view()->toolpathPolylines();
        QVERIFY(lines != nullptr);
        QVERIFY(lines->segmentCount(camwb::toolpath::PathSegmentKind::ToolAxis) > 10);
        window.view()->fitAll();
        QTest::qWait(300);
        saveShot(&window, QStringLiteral("five-axis-example-job.png"));
    }

    // Offscreen there is no OpenGL; under Xvfb CAMWB_NO_OPENGL=1 turns it off the same way.
    void withoutOpenGlTheViewSaysSo()
    {
        struct NoOpenGl {
            NoOpenGl() { qputenv("CAMWB_NO_OPENGL", "1"); }
            ~NoOpenGl() { qunsetenv("CAMWB_NO_OPENGL"); }
        } noOpenGl;
        MainWindow window;
        window.show();
        QVERIFY(!window.view()->hasOpenGl());
        auto* label = window.view()->findChild<QLabel*>(QStringLiteral("noOpenGlMessage"));
        QVERIFY(label);
        QVERIFY(label->isVisibleTo(&window));
        QVERIFY(label->text().contains(QLatin1String("unavailable")));
        QString reason;
        QVERIFY(!View3D::openGlAvailable(&reason));
        QVERIFY(!reason.isEmpty());
    }

    // Another NC file over unsaved edits: asked first. Cancel keeps everything, Save writes the
    // edits to their file, Discard drops them; the dock's title marks unsaved edits.
    void ncEditsAskBeforeAnotherFileReplacesThem()
    {
        QTemporaryDir dir;
        const QByteArray original = "G0 X0\nG1 X10 F100\nM30\n";
        const QString a = writeFile(dir, QStringLiteral("a.ngc"), original);
        const QString b = writeFile(dir, QStringLiteral("b.ngc"), "G0 X5\nM30\n");
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        auto* editor = window.ncEditor();
        QVERIFY(window.openNcFile(a));
        QVERIFY(window.openNcFile(b));  // no edits: no question
        QVERIFY(window.openNcFile(a));
        QVERIFY(prompter->questions.isEmpty());
        QVERIFY(!ncDockTitle(window).contains(QLatin1Char('*')));

        const QString edited = QStringLiteral("G0 X0\nG1 X12 F100\nM30\n");
        editor->replaceText(edited);  // as typing would
        QVERIFY(window.ncDocument()->hasUnsavedEdits());
        QVERIFY2(ncDockTitle(window).contains(QLatin1String("a.ngc*")), qPrintable(ncDockTitle(window)));

        prompter->answers.push_back(Answer::Cancel);
        QVERIFY(!window.openNcFile(b));
        QCOMPARE(int(prompter->questions.size()), 1);
        QVERIFY2(prompter->questions.last().text.contains(QLatin1String("a.ngc")),
                 qPrintable(prompter->questions.last().text));
        QCOMPARE(editor->text(), edited);
        QCOMPARE(window.ncDocument()->filePath(), QFileInfo(a).absoluteFilePath());

        prompter->answers.push_back(Answer::Accept);
        QVERIFY(window.openNcFile(b));
        QCOMPARE(readFile(a), edited.toUtf8());
        QVERIFY(editor->text().startsWith(QLatin1String("G0 X5")));
        QVERIFY(!window.ncDocument()->hasUnsavedEdits());

        editor->replaceText(QStringLiteral("G0 X6\nM30\n"));
        prompter->answers.push_back(Answer::Discard);
        QVERIFY(window.openNcFile(a));
        QCOMPARE(readFile(b), QByteArray("G0 X5\nM30\n"));
        QCOMPARE(editor->text(), edited);
        QCOMPARE(int(prompter->questions.size()), 3);
        QCOMPARE(prompter->unanswered, 0);
    }

    // F9 and any other post (an operation edited, undo) would put the job's program in the editor:
    // asked first; Cancel keeps the edits (and says the new program is not shown), Discard shows
    // the posted program, read-only again.
    void ncEditsAskBeforeAPostReplacesThem()
    {
        QTemporaryDir dir;
        const QByteArray original = "G0 X0\nG1 X10 F100\nM30\n";
        const QString path = writeFile(dir, QStringLiteral("part.ngc"), original);
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        openExample(window);
        QVERIFY(window.ncEditor()->isReadOnly());  // the posted program is what the post made
        QVERIFY(window.openNcFile(path));
        QVERIFY(!window.ncEditor()->isReadOnly());
        const QString edited = QStringLiteral("G0 X0\nG1 X11 F100\nM30\n");
        window.ncEditor()->replaceText(edited);

        Workbench& wb = window.workbench();
        QSignalSpy posted(&wb, &Workbench::postFinished);
        prompter->answers.push_back(Answer::Cancel);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Post")));
        QCOMPARE(int(prompter->questions.size()), 1);
        QVERIFY(!wb.isBusy());  // not posted
        QCOMPARE(window.ncEditor()->text(), edited);

        prompter->answers.push_back(Answer::Cancel);
        wb.post();  // as an edited operation or undo reposts
        QVERIFY(posted.wait(120000));
        QCOMPARE(int(prompter->questions.size()), 2);
        QCOMPARE(window.ncEditor()->text(), edited);
        QVERIFY(window.reportView()->toPlainText().contains(QLatin1String("keeps the unsaved edits of part.ngc*")));

        prompter->answers.push_back(Answer::Discard);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Post")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(int(prompter->questions.size()), 3);
        QCOMPARE(window.ncEditor()->text(), wb.ncText());
        QVERIFY(window.ncEditor()->isReadOnly());
        QCOMPARE(readFile(path), original);  // discarded, the file untouched
        QCOMPARE(prompter->unanswered, 0);
    }

    // Another job and closing the window ask too.
    void ncEditsAskBeforeAnotherJobOrClosing()
    {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("part.ngc"), "G0 X0\nM30\n");
        MainWindow window;
        ScriptedPrompter* prompter = scriptPrompts(window);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openNcFile(path));
        window.ncEditor()->replaceText(QStringLiteral("G0 X1\nM30\n"));

        prompter->answers.push_back(Answer::Cancel);
        QVERIFY(!window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(window.workbench().job().modelPath.empty());  // no job opened
        prompter->answers.push_back(Answer::Cancel);
        QVERIFY(!window.close());
        QVERIFY(window.isVisible());
        QCOMPARE(int(prompter->questions.size()), 2);

        prompter->answers.push_back(Answer::Accept);
        QVERIFY(window.close());
        QCOMPARE(readFile(path), QByteArray("G0 X1\nM30\n"));
        QCOMPARE(prompter->unanswered, 0);
    }
};

int main(int argc, char** argv)
{
    View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    MainWindowTest test;
    run.run(&test);
    return run.finish();
}

#include "MainWindowTest.moc"
