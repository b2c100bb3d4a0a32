// The NC inspector against the real ISO interpreter: every 3D segment maps to the block that made
// it, the cursor's block is highlighted and its modal state shown, a click in the real view (Xvfb)
// moves the editor, edits re-trace after the debounce, tools can be hidden, a block with an error
// is drawn marked. Runs under Xvfb and offscreen (no GL: everything but the clicks, which
// InspectorViewTest does under Xvfb).
#include "QtTestRun.h"
#include "document/ModalState.h"
#include "gui/editor/NcEditor.h"
#include "gui/inspector/ModalStatePanel.h"
#include "gui/inspector/NcInspector.h"
#include "gui/view3d/View3D.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathPolylines.h"

#include <QApplication>
#include <QFile>
#include <QGuiApplication>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>
#include <set>

using namespace camwb::gui;
namespace tp = camwb::toolpath;

namespace {

// Line numbers are the test's expectations: keep them in step with the comments.
const char* const kProgram = "(inspector test)\n"  // 1
                             "G21 G90 G17 G54\n"   // 2
                             "T1 M6\n"             // 3
                             "S1000 M3 M8\n"       // 4
                             "G0 X0 Y0 Z5\n"       // 5: first move, only positions
                             "G1 Z-1 F100\n"       // 6
                             "G1 X10\n"            // 7
                             "G2 X20 Y0 I5 J0\n"   // 8
                             "G0 Z5\n"             // 9
                             "T2 M6\n"             // 10
                             "G0 X30 Y0\n"         // 11
                             "G1 Z-2 F200\n"       // 12
                             "G3 X40 Y0 I5 J0\n"   // 13
                             "G0 Z5\n"             // 14
                             "M30\n";              // 15

bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

// Editor, view, panel and inspector wired as the main window wires them.
struct Rig {
    NcEditor editor;
    View3D view;
    ModalStatePanel panel;
    NcInspector inspector;

    Rig()
    {
        inspector.attach(&editor, &view, &panel);
        inspector.setFilePath(QStringLiteral("inspector-test.ngc"));
    }

    // Loads the text and waits for its trace; false (with the reason) when there is none: a hang or
    // an interpreter that cannot read the program is a failure of the test that needs it.
    bool load(const QString& text, QString* why)
    {
        QSignalSpy finished(&inspector, &NcInspector::traceFinished);
        editor.setText(text);
        inspector.traceNow();
        if (!finished.wait(60000)) {
            *why = QStringLiteral("no trace within a minute");
            return false;
        }
        const auto trace = inspector.trace();
        if (trace->program.empty() && trace->result.hasErrors()) {
            *why = QStringLiteral("the ISO interpreter reports: ") +
                   QString::fromStdString(trace->result.diagnostics.front().message);
            return false;
        }
        return true;
    }

    // The main-program line of each segment's record.
    std::vector<int> segmentLines() const
    {
        std::vector<int> lines;
        for (const tp::PathSegment& s : view.toolpathPolylines()->segments())
            lines.push_back(inspector.trace()->lineOfRecord(s.record));
        return lines;
    }
};

#define LOAD_OR_FAIL(rig, text)                                                                                        \
    do {                                                                                                               \
        QString why;                                                                                                   \
        QVERIFY2((rig).load((text), &why), qPrintable(why));                                                           \
    } while (false)

}  // namespace

class InspectorTest : public QObject {
    Q_OBJECT

private slots:
    void modalTableMatchesAPlainReplay()
    {
        tp::Toolpath path;
        tp::ToolChange change;
        for (int i = 0; i < 50; ++i) {
            change.tool.number = i % 3 + 1;
            path.add(change);
            path.add(tp::Spindle{1000.0 + i, i % 2 == 0});
            path.add(tp::Linear{{double(i), 0, 0}, 100.0 + i});
            tp::Arc arc;
            arc.to = {double(i), 1, 0};
            arc.center = {double(i), 0.5, 0};
            arc.normal = {0, 1, 0};
            path.add(arc);
        }
        const camwb::document::ModalStateTable table(path, 7);
        camwb::document::ModalState plain;
        for (std::size_t i = 0; i <= path.size(); ++i) {
            const camwb::document::ModalState fromTable = table.before(path, i);
            QCOMPARE(fromTable.tool, plain.tool);
            QCOMPARE(fromTable.spindleRpm, plain.spindleRpm);
            QCOMPARE(fromTable.feed, plain.feed);
            QCOMPARE(fromTable.position.x, plain.position.x);
            QCOMPARE(fromTable.hasArcNormal, plain.hasArcNormal);
            if (i < path.size())
                camwb::document::applyRecord(plain, path.record(i));
        }
        QCOMPARE(camwb::document::planeOfNormal({0, 1, 0}), std::string("G18 (ZX)"));
        QCOMPARE(camwb::document::planeOfNormal({0, 0, -1}), std::string("G17 (XY)"));
    }

    void everySegmentMapsToItsLine()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        const tp::ToolpathPolylines* polylines = rig.view.toolpathPolylines();
        QVERIFY(polylines != nullptr);
        const std::vector<int> lines = rig.segmentLines();
        std::map<tp::PathSegmentKind, std::set<int>> linesByKind;
        for (std::size_t s = 0; s < lines.size(); ++s)
            linesByKind[polylines->segments()[s].kind].insert(lines[s]);
        QCOMPARE(linesByKind[tp::PathSegmentKind::Feed], (std::set<int>{6, 7, 12}));
        QCOMPARE(linesByKind[tp::PathSegmentKind::Arc], (std::set<int>{8, 13}));
        QCOMPARE(linesByKind[tp::PathSegmentKind::Rapid], (std::set<int>{9, 11, 14}));
        // The arc of line 8 is tessellated: many segments, one block.
        QVERIFY(std::count(lines.begin(), lines.end(), 8) > 10);
    }

    void cursorLineHighlightsItsSegments()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        const std::vector<int> lines = rig.segmentLines();
        for (int line : {8, 12, 13}) {
            rig.editor.gotoLine(line);
            const auto& highlighted = rig.view.highlightedSegments();
            QCOMPARE(int(highlighted.size()), int(std::count(lines.begin(), lines.end(), line)));
            for (std::uint32_t s : highlighted)
                QCOMPARE(lines[s], line);
        }
        rig.editor.gotoLine(2);  // no motion: nothing highlighted
        QVERIFY(rig.view.highlightedSegments().empty());
    }

    void modalStateAtChosenLines()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        rig.editor.gotoLine(8);
        QCOMPARE(rig.panel.value(QStringLiteral("move")), QStringLiteral("arc CW"));
        QCOMPARE(rig.panel.value(QStringLiteral("tool")), QStringLiteral("T1"));
        QVERIFY(rig.panel.value(QStringLiteral("feed")).startsWith(QLatin1String("100.0 mm/min")));
        QVERIFY(rig.panel.value(QStringLiteral("spindle")).startsWith(QLatin1String("1000 rpm CW")));
        QVERIFY(rig.panel.value(QStringLiteral("coolant")).startsWith(QLatin1String("flood")));
        QVERIFY(rig.panel.value(QStringLiteral("plane")).startsWith(QLatin1String("G17")));
        QCOMPARE(rig.panel.value(QStringLiteral("before")), QStringLiteral("X10.000 Y0.000 Z-1.000"));
        QCOMPARE(rig.panel.value(QStringLiteral("after")), QStringLiteral("X20.000 Y0.000 Z-1.000"));

        rig.editor.gotoLine(13);
        QCOMPARE(rig.panel.value(QStringLiteral("move")), QStringLiteral("arc CCW"));
        QCOMPARE(rig.panel.value(QStringLiteral("tool")), QStringLiteral("T2"));
        QVERIFY(rig.panel.value(QStringLiteral("feed")).startsWith(QLatin1String("200.0 mm/min")));
        QCOMPARE(rig.panel.value(QStringLiteral("after")), QStringLiteral("X40.000 Y0.000 Z-2.000"));

        rig.editor.gotoLine(4);
        QCOMPARE(rig.panel.value(QStringLiteral("move")), QStringLiteral("spindle on"));
        rig.editor.gotoLine(1);
        QCOMPARE(rig.panel.value(QStringLiteral("move")), QStringLiteral("no motion"));
        QVERIFY(rig.panel.value(QStringLiteral("before")).startsWith(QLatin1String("unknown")));
    }

    // An untraced retract (M140 MB MAX, no machine to say where Z's travel ends): the panel says Z
    // is unknown from that block on, and nothing is drawn from the old depth until Z is given again.
    void anUntracedRetractLeavesZUnknown()
    {
        Rig rig;
        rig.inspector.setFilePath(QStringLiteral("retract.h"));
        LOAD_OR_FAIL(rig, QStringLiteral("0 BEGIN PGM R MM\n"              // 1
                                         "1 TOOL CALL 1 Z S3000\n"         // 2
                                         "2 L X+10 Y+10 Z+5 R0 FMAX M3\n"  // 3: only positions
                                         "3 L Z-5 F200\n"                  // 4
                                         "4 M140 MB MAX\n"                 // 5
                                         "5 L X+90 Y+90 FMAX\n"            // 6: Z unknown
                                         "6 L Z+5 FMAX\n"                  // 7: known again
                                         "7 L Z-5 F200\n"                  // 8
                                         "8 END PGM R MM\n"));
        rig.editor.gotoLine(5);
        QCOMPARE(rig.panel.value(QStringLiteral("move")), QStringLiteral("not traced: Z unknown"));
        QCOMPARE(rig.panel.value(QStringLiteral("before")), QStringLiteral("X10.000 Y10.000 Z-5.000"));
        QVERIFY(rig.panel.value(QStringLiteral("after")).startsWith(QLatin1String("unknown")));
        rig.editor.gotoLine(6);
        QVERIFY(rig.panel.value(QStringLiteral("after")).startsWith(QLatin1String("unknown")));
        rig.editor.gotoLine(7);
        QCOMPARE(rig.panel.value(QStringLiteral("after")), QStringLiteral("X90.000 Y90.000 Z5.000"));
        const std::vector<int> lines = rig.segmentLines();
        QCOMPARE(std::set<int>(lines.begin(), lines.end()), (std::set<int>{4, 8}));
    }

    void editsRetraceAfterTheDebounce()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        rig.inspector.setDebounceMs(150);
        const int before = rig.view.toolpathSegmentCount();
        QSignalSpy started(&rig.inspector, &NcInspector::traceStarted);
        QSignalSpy finished(&rig.inspector, &NcInspector::traceFinished);
        QString edited = QString::fromLatin1(kProgram);
        // Three quick edits (as typing makes them): one trace after the last.
        for (const char* move : {"G1 X45 F300\n", "G1 X45 Y5 F300\n", "G1 X45 Y5 F300\nG1 X50 Y5\n"}) {
            QString text = edited;
            text.replace(QLatin1String("M30\n"), QLatin1String(move) + QStringLiteral("M30\n"));
            rig.editor.setText(text);
        }
        QVERIFY(finished.wait(60000));
        QCOMPARE(started.count(), 1);
        QCOMPARE(rig.view.toolpathSegmentCount(), before + 2);
    }

    void newerTraceSupersedesOlder()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        QSignalSpy finished(&rig.inspector, &NcInspector::traceFinished);
        QString longer = QString::fromLatin1(kProgram);
        longer.replace(QLatin1String("M30\n"), QLatin1String("G1 X60 F300\nM30\n"));
        rig.inspector.traceNow();  // the old text: superseded by the next one
        rig.editor.setText(longer);
        rig.inspector.traceNow();
        QVERIFY(finished.wait(60000));
        QTRY_VERIFY(!rig.inspector.isTracing());
        QCOMPARE(finished.count(), 1);
        const std::vector<int> lines = rig.segmentLines();
        QCOMPARE(std::count(lines.begin(), lines.end(), 15), std::ptrdiff_t(1));  // G1 X60
    }

    // Records of a called program link to the calling block (the editor shows the main program)
    // and name their own place for the status bar.
    void subprogramRecordsLinkToTheCall()
    {
        QTemporaryDir dir;
        auto write = [&dir](const char* name, const char* text) {
            QFile file(dir.filePath(QLatin1String(name)));
            return file.open(QIODevice::WriteOnly) && file.write(text) > 0;
        };
        QVERIFY(write("POCKET.SPF", "G1 X10 F100\nG1 Y10\nG1 X0\nM17\n"));
        const char* main = "G17 G90 G71 G54\n"  // 1
                           "T1 D1 M6\n"         // 2
                           "G0 X0 Y0 Z2\n"      // 3
                           "G1 Z-1 F50\n"       // 4
                           "POCKET\n"           // 5: the call
                           "G0 Z10\n"           // 6
                           "M30\n";             // 7
        QVERIFY(write("MAIN.MPF", main));
        Rig rig;
        rig.inspector.setFilePath(dir.filePath(QStringLiteral("MAIN.MPF")));
        LOAD_OR_FAIL(rig, QString::fromLatin1(main));
        const auto trace = rig.inspector.trace();
        QCOMPARE(trace->dialect, camwb::nc::Dialect::Sinumerik);
        std::vector<std::size_t> called;
        for (std::size_t r = 0; r < trace->program.size(); ++r)
            if (trace->isInSubprogram(r))
                called.push_back(r);
        QVERIFY2(!called.empty(), qPrintable(QStringLiteral("the SINUMERIK interpreter made no subprogram records: ") +
                                             QString::fromStdString(trace->result.diagnostics.empty()
                                                                        ? std::string("no diagnostics")
                                                                        : trace->result.diagnostics.front().message)));
        QCOMPARE(called.size(), std::size_t(3));
        QCOMPARE(trace->whereOf(called.front()), std::string("POCKET.SPF:1"));
        // The interpreter announces the calling block before entering the subprogram.
        const int caller = trace->lineOfRecord(called.front());
        QCOMPARE(caller, 5);
        QCOMPARE(trace->lineOfRecord(called.back()), caller);
    }

    void diagnosticsReachTheEditorMargin()
    {
        Rig rig;
        const QString text =
            QString::fromLatin1(kProgram).replace(QLatin1String("G1 X10\n"), QLatin1String("G1 X10 Q?\n"));
        QSignalSpy messages(&rig.inspector, &NcInspector::message);
        LOAD_OR_FAIL(rig, text);
        const auto trace = rig.inspector.trace();
        QVERIFY(!trace->result.diagnostics.empty());
        const int line = trace->result.diagnostics.front().line;
        QCOMPARE(line, 7);
        // The report hears it too, with file and line.
        bool reported = false;
        for (const auto& m : messages)
            reported = reported || m.at(1).toString().contains(QLatin1String("inspector-test.ngc:7"));
        QVERIFY(reported);
        QCOMPARE(rig.editor.diagnosticSeverityAt(line), std::optional(trace->result.diagnostics.front().severity));
        // (Line 8 gets one too: its arc now starts elsewhere.)
        QVERIFY(!rig.editor.diagnosticSeverityAt(12).has_value());
        // Fixed: the margin clears with the next trace.
        QSignalSpy finished(&rig.inspector, &NcInspector::traceFinished);
        rig.editor.setText(QString::fromLatin1(kProgram));
        QVERIFY(finished.wait(60000));
        QVERIFY(!rig.editor.diagnosticSeverityAt(line).has_value());
    }

    // With a machine (the job's, see MainWindowTest) its limits join the program's diagnostics,
    // in the editor's margin and the report, at the line that first breaks each one.
    void machineLimitsJoinTheDiagnostics()
    {
        auto machine = std::make_shared<camwb::kinematics::Machine>();
        machine->id = "tiny";
        machine->name = "Tiny mill";
        machine->axes = {{"X", false, 0, 25}, {"Y", false, 0, 25}, {"Z", false, -10, 10}};
        machine->spindleMaxRpm = 800;
        machine->toolStations = 1;
        Rig rig;
        rig.inspector.setMachine(machine);
        QSignalSpy messages(&rig.inspector, &NcInspector::message);
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        std::vector<std::string> found;
        for (const camwb::base::Diagnostic& d : rig.inspector.trace()->result.diagnostics)
            found.push_back(camwb::base::formatDiagnostic(d));
        const std::vector<std::string> expected{
            "inspector-test.ngc:4: warning: spindle speed 1000 rpm is above the Tiny mill's maximum of 800 rpm",
            "inspector-test.ngc:4: warning: coolant flood is not available on the Tiny mill",
            "inspector-test.ngc:10: warning: tool T2 has no station: the Tiny mill has stations 1..1",
            "inspector-test.ngc:13: warning: the program spans 40 mm in X (0 to 40); the Tiny mill travels 25 mm"};
        QString all;
        for (const std::string& f : found)
            all += QString::fromStdString(f) + QLatin1Char('\n');
        QVERIFY2(found == expected, qPrintable(all));
        QCOMPARE(rig.editor.diagnosticSeverityAt(10), std::optional(camwb::base::Severity::Warning));
        bool reported = false;
        for (const auto& m : messages)
            reported =
                reported || m.at(1).toString().contains(QLatin1String("inspector-test.ngc:10: warning: tool T2"));
        QVERIFY(reported);
        // Without a machine, nothing of the kind.
        rig.inspector.setMachine(nullptr);
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        QVERIFY(rig.inspector.trace()->result.diagnostics.empty());
    }

    // A CL file (by its name, while no dialect is chosen) is read by its importer: its segments
    // link to their statements' lines both ways, its errors reach the margin at their line, and a
    // chosen dialect reads the same text as NC.
    void aClFileIsReadByItsImporter()
    {
        const QString apt = QStringLiteral("PARTNO/BRACKET\n"   // 1
                                           "CUTTER/10,0\n"      // 2
                                           "LOADTL/3\n"         // 3
                                           "RAPID\n"            // 4
                                           "GOTO/0,0,20\n"      // 5
                                           "FEDRAT/MMPM,300\n"  // 6
                                           "GOTO/0,0,-2\n"      // 7
                                           "GOTO/40,0,-2\n"     // 8
                                           "FINI\n");           // 9
        Rig rig;
        rig.inspector.setFilePath(QStringLiteral("bracket.cls"));
        LOAD_OR_FAIL(rig, apt);
        const auto trace = rig.inspector.trace();
        QCOMPARE(trace->clFormat, std::optional(tp::ClFormat::Apt));
        QVERIFY(trace->result.diagnostics.empty());
        std::set<int> lines;
        for (int line : rig.segmentLines())
            lines.insert(line);
        QCOMPARE(lines, (std::set<int>{7, 8}));  // line 5 only positions the tool, as G0 does first
        rig.editor.gotoLine(8);
        QCOMPARE(int(rig.view.highlightedSegments().size()), 1);
        QCOMPARE(rig.panel.value(QStringLiteral("tool")), QStringLiteral("T3"));
        // The panel says what the CL's records say, in no NC words (no G94, no M5, no M9).
        QCOMPARE(rig.panel.value(QStringLiteral("feed")), QStringLiteral("300.0 mm/min"));
        QCOMPARE(rig.panel.value(QStringLiteral("spindle")), QStringLiteral("stopped"));
        QCOMPARE(rig.panel.value(QStringLiteral("coolant")), QStringLiteral("off"));
        QCOMPARE(rig.panel.value(QStringLiteral("distance")), QStringLiteral("absolute (CL positions)"));
        // The editor holds it as APT: highlighted as one, and its tools know it is no NC program.
        QCOMPARE(rig.editor.clFormat(), std::optional(tp::ClFormat::Apt));
        QCOMPARE(static_cast<NcStyle>(rig.editor.styleAt(6, 1)), NcStyle::Keyword);    // FEDRAT
        QCOMPARE(static_cast<NcStyle>(rig.editor.styleAt(6, 8)), NcStyle::Parameter);  // MMPM
        QCOMPARE(static_cast<NcStyle>(rig.editor.styleAt(6, 13)), NcStyle::Number);    // 300

        // Line 8 made unreadable: one error there, in the margin.
        QSignalSpy finished(&rig.inspector, &NcInspector::traceFinished);
        rig.editor.setText(QString(apt).replace(QLatin1String("GOTO/40"), QLatin1String("GOTO/4O")));
        rig.inspector.traceNow();
        QVERIFY(finished.wait(60000));
        QVERIFY(rig.inspector.trace()->program.empty());
        QCOMPARE(rig.inspector.trace()->result.diagnostics.size(), std::size_t(1));
        QCOMPARE(rig.inspector.trace()->result.diagnostics.front().line, 8);
        QCOMPARE(rig.editor.diagnosticSeverityAt(8), std::optional(camwb::base::Severity::Error));

        // ISO chosen: the same text is NC, and APT words are not ISO words.
        rig.editor.setText(apt);
        rig.inspector.setDialect(camwb::nc::Dialect::Iso);
        QVERIFY(finished.wait(60000));
        QVERIFY(!rig.inspector.trace()->clFormat.has_value());
        QVERIFY(rig.inspector.trace()->result.hasErrors());
        QVERIFY(!rig.editor.clFormat().has_value());
        QCOMPARE(static_cast<NcStyle>(rig.editor.styleAt(6, 8)), NcStyle::Default);  // ISO: no word

        // A program of G words in the same dock is NC again: the panel names the words.
        rig.inspector.setDialect(std::nullopt);
        rig.inspector.setFilePath(QStringLiteral("bracket.ngc"));
        LOAD_OR_FAIL(rig, QStringLiteral("G0 X0 Y0 Z5\nG1 Z-1 F200\n"));
        QVERIFY(!rig.editor.clFormat().has_value());
        rig.editor.gotoLine(2);
        QCOMPARE(rig.panel.value(QStringLiteral("feed")), QStringLiteral("200.0 mm/min (G94)"));
        QCOMPARE(rig.panel.value(QStringLiteral("spindle")), QStringLiteral("stopped (M5)"));
    }

    // Five-axis Klartext on a B/C table machine: the panel shows the tool vector and the machine's
    // rotary axes at the cursor, the view the tool axis along the path (seed 000: B30 C40 gives
    // K = (-0.3830, 0.3214, 0.8660)).
    void fiveAxisMovesShowTheToolAxisAndTheRotaryAxes()
    {
        auto machine = std::make_shared<camwb::kinematics::Machine>();
        machine->id = "bc";
        machine->name = "B/C table";
        machine->axes = {{"X", false, -500, 500},
                         {"Y", false, -500, 500},
                         {"Z", false, -500, 500},
                         {"B", true, -120, 30},
                         {"C", true, -INFINITY, INFINITY, true}};
        machine->kinematics.type = camwb::kinematics::ChainType::TableTable;
        machine->kinematics.joints = {{"B", true, {0, 1, 0}, {}}, {"C", true, {0, 0, 1}, {}}};
        Rig rig;
        rig.inspector.setDialect(camwb::nc::Dialect::Heidenhain);
        rig.inspector.setMachine(machine);
        LOAD_OR_FAIL(rig, QStringLiteral("0 BEGIN PGM FIVE MM\n"                    // 1
                                         "1 TOOL CALL 1 Z S1000\n"                  // 2
                                         "2 L X+0 Y+0 Z+50 R0 FMAX M3\n"            // 3
                                         "3 L X+10 Y+20 Z+5 B+30 C+40 F500 M128\n"  // 4
                                         "4 L X+20 C+60\n"                          // 5
                                         "5 L Z+50 B+0 C+0 FMAX M129\n"             // 6
                                         "6 END PGM FIVE MM\n"));                   // 7
        auto value = [&rig](const char* row) { return rig.panel.value(QLatin1String(row)); };
        rig.editor.gotoLine(4);
        QCOMPARE(value("move"), QStringLiteral("5-axis linear"));
        QCOMPARE(value("toolAxis"), QStringLiteral("I-0.3830 J0.3214 K0.8660 (five-axis move)"));
        QCOMPARE(value("rotaryAxes"), QStringLiteral("B30.000 C40.000"));
        QCOMPARE(value("after"), QStringLiteral("X10.000 Y20.000 Z5.000"));
        rig.editor.gotoLine(3);
        QVERIFY2(value("toolAxis").contains(QLatin1String("3-axis")), qPrintable(value("toolAxis")));
        QVERIFY2(value("rotaryAxes").startsWith(QLatin1String("none known")), qPrintable(value("rotaryAxes")));
        // The tool axis is drawn at the first five-axis move of the run, from the tip to the spindle.
        const tp::ToolpathPolylines* lines = rig.view.toolpathPolylines();
        QVERIFY(lines != nullptr);
        QCOMPARE(lines->segmentCount(tp::PathSegmentKind::ToolAxis), std::size_t(1));
        for (const tp::PathSegment& s : lines->segments()) {
            if (s.kind != tp::PathSegmentKind::ToolAxis)
                continue;
            const camwb::base::Vec3 tip = lines->points()[s.from], end = lines->points()[s.to];
            QCOMPARE(rig.inspector.trace()->lineOfRecord(s.record), 4);
            QVERIFY(std::abs(tip.x - 10) < 1e-9 && std::abs(tip.y - 20) < 1e-9 && std::abs(tip.z - 5) < 1e-9);
            QVERIFY(std::abs((end.z - tip.z) / tp::ToolpathPolylines::kToolAxisLengthMm - 0.8660254) < 1e-6);
        }
    }

    // G41 with the tool's size from the tool table the main window passes (the job's tools): the
    // trace is the tool centre; without one, a warning and the programmed path.
    void compensationTakesTheRadiusFromTheToolTable()
    {
        const QString program = QStringLiteral("G21 G90 G17 G54\n"  // 1
                                               "T1 M6\n"            // 2
                                               "S1000 M3\n"         // 3
                                               "G0 X-10 Y-10 Z5\n"  // 4
                                               "G1 Z-1 F100\n"      // 5
                                               "G41 G1 X0 Y0\n"     // 6
                                               "G1 X20\n"           // 7
                                               "G1 Y20\n"           // 8
                                               "G40 G1 X30 Y30\n"   // 9
                                               "M30\n");            // 10
        auto endYOfLine = [](const camwb::document::NcTrace& trace, int line) {
            const std::vector<std::size_t> records = trace.recordsOfLine(line);
            for (auto it = records.rbegin(); it != records.rend(); ++it)
                if (const auto* l = std::get_if<tp::Linear>(&trace.program.record(*it)))
                    return l->to.y;
            return -1000.0;
        };
        auto table = std::make_shared<camwb::nc::ToolTable>();
        table->set({1, 1, 6.0, 50.0, "D6"});
        Rig rig;
        rig.inspector.setToolTable(table);
        LOAD_OR_FAIL(rig, program);
        const auto& diagnostics = rig.inspector.trace()->result.diagnostics;
        QVERIFY2(diagnostics.empty(), diagnostics.empty() ? "" : diagnostics.front().message.c_str());
        QVERIFY(std::abs(std::abs(endYOfLine(*rig.inspector.trace(), 7)) - 3.0) < 1e-6);

        rig.inspector.setToolTable(nullptr);
        LOAD_OR_FAIL(rig, program);
        QVERIFY(!rig.inspector.trace()->result.diagnostics.empty());
        QCOMPARE(rig.inspector.trace()->result.diagnostics.front().severity, camwb::base::Severity::Warning);
        QVERIFY(std::abs(endYOfLine(*rig.inspector.trace(), 7)) < 1e-9);
    }

    void chosenDialectOverridesTheGuess()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        QVERIFY(rig.inspector.trace()->dialectGuessed);
        QCOMPARE(rig.inspector.trace()->dialect, camwb::nc::Dialect::Iso);
        QSignalSpy finished(&rig.inspector, &NcInspector::traceFinished);
        rig.inspector.setDialect(camwb::nc::Dialect::Heidenhain);  // re-traces at once
        QVERIFY(finished.wait(60000));
        QVERIFY(!rig.inspector.trace()->dialectGuessed);
        QCOMPARE(rig.inspector.trace()->dialect, camwb::nc::Dialect::Heidenhain);
        QCOMPARE(rig.editor.dialect(), camwb::nc::Dialect::Heidenhain);  // highlighting follows
        QVERIFY(rig.inspector.trace()->result.hasErrors());              // ISO is no Klartext
        rig.inspector.setDialect(std::nullopt);
        QVERIFY(finished.wait(60000));
        QCOMPARE(rig.inspector.trace()->dialect, camwb::nc::Dialect::Iso);
    }

    // The modal rows say what the program set, in its own dialect: SINUMERIK G90/G91, G710, G17,
    // G54; Heidenhain MM, the TOOL CALL axis, R0/RL, absolute or incremental words, F.
    void modalStateInTheProgramsOwnWords()
    {
        Rig rig;
        rig.inspector.setFilePath(QStringLiteral("inspector-test.mpf"));
        rig.inspector.setDialect(camwb::nc::Dialect::Sinumerik);
        QString why;
        QVERIFY2(rig.load(QStringLiteral("; modal words\n"           // 1
                                         "G17 G90 G710 G54\n"        // 2
                                         "T1 M6\n"                   // 3
                                         "S1000 M3\n"                // 4
                                         "G0 X0 Y0 Z5\n"             // 5
                                         "G91 G1 Z-6 F100\n"         // 6
                                         "G90 G500 G1 X10 Y0 Z-1\n"  // 7
                                         "M30\n"),                   // 8
                          &why),
                 qPrintable(why));
        rig.editor.gotoLine(5);
        auto value = [&rig](const char* row) { return rig.panel.value(QLatin1String(row)); };
        QVERIFY2(value("distance").startsWith(QLatin1String("G90")), qPrintable(value("distance")));
        QVERIFY2(value("units").startsWith(QLatin1String("G710")), qPrintable(value("units")));
        QVERIFY2(value("plane").startsWith(QLatin1String("G17")), qPrintable(value("plane")));
        QVERIFY2(value("compensation").startsWith(QLatin1String("G40")), qPrintable(value("compensation")));
        QCOMPARE(value("workOffset"), QStringLiteral("G54"));
        rig.editor.gotoLine(6);
        QVERIFY2(value("distance").startsWith(QLatin1String("G91")), qPrintable(value("distance")));
        QVERIFY2(value("feed").contains(QLatin1String("G94")), qPrintable(value("feed")));
        rig.editor.gotoLine(7);
        QVERIFY2(value("distance").startsWith(QLatin1String("G90")), qPrintable(value("distance")));
        QCOMPARE(value("workOffset"), QStringLiteral("G500"));

        Rig klartext;
        klartext.inspector.setFilePath(QStringLiteral("inspector-test.h"));
        klartext.inspector.setDialect(camwb::nc::Dialect::Heidenhain);
        QVERIFY2(klartext.load(QStringLiteral("0 BEGIN PGM MODAL MM\n"         // 1
                                              "1 TOOL DEF 1 L+40 R+3\n"        // 2
                                              "2 TOOL CALL 1 Z S1000\n"        // 3
                                              "3 L X+0 Y-10 Z+5 R0 FMAX M3\n"  // 4
                                              "4 L IZ-6 F100\n"                // 5
                                              "5 L X+10 Y+0 RL\n"              // 6
                                              "6 L X+20\n"                     // 7
                                              "7 L X+30 Y-10 R0\n"             // 8
                                              "8 END PGM MODAL MM\n"),         // 9
                               &why),
                 qPrintable(why));
        auto words = [&klartext](const char* row) { return klartext.panel.value(QLatin1String(row)); };
        klartext.editor.gotoLine(7);
        QVERIFY2(words("compensation").startsWith(QLatin1String("RL")), qPrintable(words("compensation")));
        QVERIFY2(words("units").startsWith(QLatin1String("MM")), qPrintable(words("units")));
        QVERIFY2(words("plane").contains(QLatin1String("TOOL CALL Z")), qPrintable(words("plane")));
        QVERIFY2(words("feed").contains(QLatin1String("(F)")), qPrintable(words("feed")));
        QVERIFY2(words("distance").contains(QLatin1String("absolute")), qPrintable(words("distance")));
        for (const char* row : {"compensation", "plane", "feed", "units", "distance", "workOffset"})
            QVERIFY2(!words(row).contains(QLatin1Char('G')), qPrintable(words(row)));  // no ISO words
        klartext.editor.gotoLine(5);
        QVERIFY2(words("distance").contains(QLatin1String("incremental")), qPrintable(words("distance")));
        QVERIFY2(words("compensation").startsWith(QLatin1String("R0")), qPrintable(words("compensation")));
    }

    void toolsCanBeHidden()
    {
        Rig rig;
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        QCOMPARE(rig.view.toolpathTools(), (std::vector<int>{1, 2}));
        const int all = rig.view.visibleSegmentCount();
        QCOMPARE(all, rig.view.toolpathSegmentCount());
        int ofTool2 = 0;
        for (const tp::PathSegment& s : rig.view.toolpathPolylines()->segments())
            ofTool2 += s.tool == 2 ? 1 : 0;
        QVERIFY(ofTool2 > 10);
        rig.view.setToolVisible(2, false);
        QVERIFY(!rig.view.isToolVisible(2));
        QCOMPARE(rig.view.visibleSegmentCount(), all - ofTool2);
        rig.view.setToolVisible(2, true);
        QCOMPARE(rig.view.visibleSegmentCount(), all);
    }

    // An arc whose radii disagree (an error): dashes from its start to its end, kind Error, not a
    // circle of the wrong radius that would blow up the view's extents.
    void errorBlockIsDrawnMarked()
    {
        Rig rig;
        const QString text = QString::fromLatin1(kProgram).replace(QLatin1String("G2 X20 Y0 I5 J0\n"),
                                                                   QLatin1String("G2 X20 Y0 I100 J0\n"));
        LOAD_OR_FAIL(rig, text);
        const auto trace = rig.inspector.trace();
        QCOMPARE(rig.editor.diagnosticSeverityAt(8), std::optional(camwb::nc::Severity::Error));
        const std::vector<std::size_t> arc = trace->recordsOfLine(8);
        QCOMPARE(arc.size(), std::size_t(1));
        QVERIFY(arc.front() < trace->recordsInError.size() && trace->recordsInError[arc.front()]);

        const tp::ToolpathPolylines* polylines = rig.view.toolpathPolylines();
        QVERIFY(polylines != nullptr);
        const std::vector<int> lines = rig.segmentLines();
        int dashes = 0;
        for (std::size_t s = 0; s < lines.size(); ++s) {
            const tp::PathSegment& segment = polylines->segments()[s];
            QCOMPARE(lines[s] == 8, segment.kind == tp::PathSegmentKind::Error);
            if (lines[s] != 8)
                continue;
            ++dashes;
            for (std::uint32_t p : {segment.from, segment.to}) {  // on the chord X10 -> X20 at Y0 Z-1
                const camwb::base::Vec3& point = polylines->points()[p];
                QVERIFY(point.x >= 10 - 1e-9 && point.x <= 20 + 1e-9);
                QVERIFY(std::abs(point.y) < 1e-9 && std::abs(point.z + 1) < 1e-9);
            }
        }
        QCOMPARE(dashes, tp::ToolpathPolylines::kErrorDashes);
        for (const camwb::base::Vec3& point : polylines->points())
            QVERIFY2(std::abs(point.y) <= 5 + 1e-9, qPrintable(QStringLiteral("a point at Y%1").arg(point.y)));
        // The cursor on the block still highlights it.
        rig.editor.gotoLine(8);
        QCOMPARE(int(rig.view.highlightedSegments().size()), dashes);
    }

    // The report gives the interpreter's time in milliseconds: "0.000 s" told nothing.
    void reportGivesTheTraceTimeInMilliseconds()
    {
        Rig rig;
        QSignalSpy messages(&rig.inspector, &NcInspector::message);
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        QString traced;
        for (const auto& m : messages)
            if (m.at(1).toString().startsWith(QLatin1String("Traced ")))
                traced = m.at(1).toString();
        const QRegularExpression time(QStringLiteral(" in [0-9]+(\\.[0-9]+)? ms$"));
        QVERIFY2(time.match(traced).hasMatch(), qPrintable(traced));
    }
};

// Picking needs the GL view: run in the Xvfb registration only.
class InspectorViewTest : public QObject {
    Q_OBJECT

private slots:
    void clickInTheViewMovesTheEditor()
    {
        Rig rig;
        rig.view.resize(800, 600);
        rig.view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&rig.view));
        LOAD_OR_FAIL(rig, QString::fromLatin1(kProgram));
        rig.view.setViewPreset(View3D::Preset::Top);
        QTest::qWait(50);

        const tp::ToolpathPolylines* polylines = rig.view.toolpathPolylines();
        const std::vector<int> lines = rig.segmentLines();
        auto* gl = rig.view.findChild<QWidget*>(QStringLiteral("view3dGl"));
        QVERIFY(gl != nullptr);
        for (int line : {13, 7}) {
            // The middle segment of the block, clicked at its middle.
            std::vector<std::size_t> ofLine;
            for (std::size_t s = 0; s < lines.size(); ++s)
                if (lines[s] == line)
                    ofLine.push_back(s);
            QVERIFY(!ofLine.empty());
            const tp::PathSegment& segment = polylines->segments()[ofLine[ofLine.size() / 2]];
            const camwb::base::Vec3 middle =
                (polylines->points()[segment.from] + polylines->points()[segment.to]) * 0.5;
            const std::optional<QPointF> at = rig.view.projectToWidget(middle);
            QVERIFY(at.has_value());
            QVERIFY(rig.view.rect().contains(at->toPoint()));
            QSignalSpy picked(&rig.view, &View3D::segmentPicked);
            QTest::mouseClick(gl, Qt::LeftButton, {}, gl->mapFrom(&rig.view, at->toPoint()));
            QCOMPARE(picked.count(), 1);
            QCOMPARE(rig.editor.currentLine(), line);
            QVERIFY(!rig.view.highlightedSegments().empty());  // the jump highlights the block
        }
        // Far from every segment: nothing picked, the editor stays.
        QSignalSpy picked(&rig.view, &View3D::segmentPicked);
        QTest::mouseClick(gl, Qt::LeftButton, {}, QPoint(3, 3));
        QCOMPARE(picked.count(), 0);
        QCOMPARE(rig.editor.currentLine(), 7);
    }
};

int main(int argc, char** argv)
{
    View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    InspectorTest test;
    run.run(&test);
    InspectorViewTest view;
    if (withGl())
        run.run(&view);
    else
        run.notOnThisPlatform("InspectorViewTest", "picking needs OpenGL, which the offscreen platform has not");
    return run.finish();
}

#include "InspectorTest.moc"
