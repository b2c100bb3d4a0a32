// Tests of the NC editor: highlighting at exact positions and folding for Sinumerik, ISO and
// Heidenhain, diagnostics markers, find, the NC tools through their actions (renumber is one undo
// step, remove numbers, go to block, compare, program info) and a million-line program whose
// figures are printed, never asserted. Screenshots always (Shots.h: CAMWB_SHOTS_DIR=<dir> keeps them).
#include "LargeProgramTest.h"
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "Shots.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/CompareDialog.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/NcEditorActions.h"
#include "gui/editor/NcStyles.h"
#include "gui/editor/ProgramInfoDialog.h"
#include "gui/editor/RenumberDialog.h"
#include "nc/tools/BlockNumbers.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>

using camwb::gui::ActionRegistry;
using camwb::gui::CompareDialog;
using camwb::gui::NcEditor;
using camwb::gui::NcEditorDiagnostic;
using camwb::gui::NcStyle;
using camwb::gui::ProgramInfoDialog;
using camwb::gui::RenumberDialog;
namespace nc = camwb::nc;
namespace toolpath = camwb::toolpath;

namespace {

constexpr const char* kSinumerik = "; contour subprogram\n"                // 1
                                   "PROC CONTOUR(REAL DEPTH)\n"            // 2
                                   "N10 DEF INT I\n"                       // 3
                                   "N20 IF DEPTH > 5\n"                    // 4
                                   "N30   G1 Z=-DEPTH F200\n"              // 5
                                   "N40 ELSE\n"                            // 6
                                   "N50   G1 Z-5\n"                        // 7
                                   "N60 ENDIF\n"                           // 8
                                   "N70 FOR I = 1 TO 3\n"                  // 9
                                   "N80   WHILE R1 < 10\n"                 // 10
                                   "N90     R1 = R1 + 1\n"                 // 11
                                   "N100  ENDWHILE\n"                      // 12
                                   "N110 ENDFOR\n"                         // 13
                                   "N120 REPEAT\n"                         // 14
                                   "N130   MCALL CYCLE81(10, 0, 2, -5)\n"  // 15
                                   "N140 UNTIL R2 > 4\n"                   // 16
                                   "N150 IF R1 > 2 GOTOF N10\n"            // 17
                                   "N160 M17\n";                           // 18

constexpr const char* kIso = "%\n"                           // 1
                             "(ISO test program)\n"          // 2
                             "N10 G21 G90 G17\n"             // 3
                             "o100 sub\n"                    // 4
                             "  #1 = [#1 + 1]\n"             // 5
                             "  o101 if [#1 GT 5]\n"         // 6
                             "    G81 X10 Y5 Z-3 R2 F100\n"  // 7
                             "  o101 else\n"                 // 8
                             "    G0 X0\n"                   // 9
                             "  o101 endif\n"                // 10
                             "o100 endsub\n"                 // 11
                             "o102 do\n"                     // 12
                             "  M3 S1000\n"                  // 13
                             "o102 while [#2 LT 3]\n"        // 14
                             "T1 M6 (tool)\n"                // 15
                             "M30\n"                         // 16
                             "%\n";                          // 17

constexpr const char* kHeidenhain = "0  BEGIN PGM F3D_TEST MM\n"           // 1
                                    "1  BLK FORM 0.1 Z X+0 Y+0 Z-40\n"     // 2
                                    "2  TOOL CALL 1 Z S5000 DL+0.1\n"      // 3
                                    "3  L  Z+100 R0 FMAX M3\n"             // 4
                                    "4  CYCL DEF 200 DRILLING ~\n"         // 5
                                    "    Q200=2    ;SET-UP CLEARANCE ~\n"  // 6
                                    "    Q201=-20  ;DEPTH\n"               // 7
                                    "5  CALL LBL 1 REP 2\n"                // 8
                                    "6  * - subprogram\n"                  // 9
                                    "7  LBL 1\n"                           // 10
                                    "8  CC X+50 Y+50\n"                    // 11
                                    "9  C  X+0 Y+50 DR-\n"                 // 12
                                    "10 FN 0: Q1 = +5\n"                   // 13
                                    "11 LBL 0\n"                           // 14
                                    "12 END PGM F3D_TEST MM\n";            // 15

// Runs `handle` on the next modal dialog that opens (polling, so the timer cannot fire before
// exec() shows it).
void onNextModal(std::function<void(QWidget*)> handle)
{
    auto* timer = new QTimer;
    timer->setInterval(10);
    QObject::connect(timer, &QTimer::timeout, [timer, handle] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            timer->stop();
            timer->deleteLater();
            handle(modal);
        }
    });
    timer->start();
}

}  // namespace

class EditorHighlightTest : public QObject {
    Q_OBJECT

private slots:
    void sinumerik()
    {
        NcEditor editor;
        editor.resize(900, 560);
        QCOMPARE(editor.dialect(), nc::Dialect::Sinumerik);
        editor.setText(QString::fromLatin1(kSinumerik));
        auto style = [&](int line, int column) { return static_cast<NcStyle>(editor.styleAt(line, column)); };
        QCOMPARE(style(1, 1), NcStyle::Comment);
        QCOMPARE(style(2, 1), NcStyle::Keyword);         // PROC
        QCOMPARE(style(3, 1), NcStyle::BlockNumber);     // N10
        QCOMPARE(style(3, 5), NcStyle::Keyword);         // DEF
        QCOMPARE(style(5, 7), NcStyle::GWord);           // G1
        QCOMPARE(style(5, 10), NcStyle::AxisWord);       // Z=
        QCOMPARE(style(5, 19), NcStyle::FeedSpeedTool);  // F200
        QCOMPARE(style(10, 7), NcStyle::Keyword);        // WHILE
        QCOMPARE(style(10, 13), NcStyle::Parameter);     // R1
        QCOMPARE(style(15, 8), NcStyle::Keyword);        // MCALL
        QCOMPARE(style(15, 14), NcStyle::Keyword);       // CYCLE81
        QCOMPARE(style(15, 22), NcStyle::Number);        // 10
        QCOMPARE(style(17, 16), NcStyle::Keyword);       // GOTOF
        QCOMPARE(style(18, 6), NcStyle::MWord);          // M17

        const int depth[] = {0, 0, 1, 1, 2, 1, 2, 2, 1, 2, 3, 3, 2, 1, 2, 2, 1, 1};
        const bool header[] = {false, true,  false, true,  false, true,  false, false, true,
                               true,  false, false, false, true,  false, false, false, false};
        for (int line = 1; line <= 18; ++line) {
            QCOMPARE(editor.foldDepth(line), depth[line - 1]);
            QCOMPARE(editor.isFoldHeader(line), header[line - 1]);
        }
        QCOMPARE(editor.foldDepth(19), 0);  // after M17 the PROC is closed
        saveShot(&editor, QStringLiteral("editor-sinumerik.png"));
    }

    void iso()
    {
        NcEditor editor;
        editor.resize(900, 560);
        editor.setDialect(nc::Dialect::Iso);
        editor.setText(QString::fromLatin1(kIso));
        auto style = [&](int line, int column) { return static_cast<NcStyle>(editor.styleAt(line, column)); };
        QCOMPARE(style(1, 1), NcStyle::Keyword);  // %
        QCOMPARE(style(2, 1), NcStyle::Comment);
        QCOMPARE(style(2, 18), NcStyle::Comment);
        QCOMPARE(style(3, 1), NcStyle::BlockNumber);
        QCOMPARE(style(3, 5), NcStyle::GWord);
        QCOMPARE(style(4, 1), NcStyle::Keyword);         // o100
        QCOMPARE(style(4, 6), NcStyle::Keyword);         // sub
        QCOMPARE(style(5, 3), NcStyle::Parameter);       // #1
        QCOMPARE(style(5, 14), NcStyle::Number);         // 1
        QCOMPARE(style(7, 5), NcStyle::Keyword);         // G81: a canned cycle
        QCOMPARE(style(7, 9), NcStyle::AxisWord);        // X10
        QCOMPARE(style(7, 20), NcStyle::AxisWord);       // R2
        QCOMPARE(style(7, 23), NcStyle::FeedSpeedTool);  // F100
        QCOMPARE(style(9, 5), NcStyle::GWord);           // G0
        QCOMPARE(style(15, 1), NcStyle::FeedSpeedTool);  // T1
        QCOMPARE(style(15, 4), NcStyle::MWord);          // M6
        QCOMPARE(style(15, 7), NcStyle::Comment);        // (tool)

        const int depth[] = {0, 0, 0, 0, 1, 1, 2, 1, 2, 2, 1, 0, 1, 1, 0, 0, 0};
        const bool header[] = {false, false, false, true,  false, true,  false, true, false,
                               false, false, true,  false, false, false, false, false};
        for (int line = 1; line <= 17; ++line) {
            QCOMPARE(editor.foldDepth(line), depth[line - 1]);
            QCOMPARE(editor.isFoldHeader(line), header[line - 1]);
        }
        saveShot(&editor, QStringLiteral("editor-iso.png"));
    }

    void heidenhain()
    {
        NcEditor editor;
        editor.resize(900, 560);
        editor.setDialect(nc::Dialect::Heidenhain);
        editor.setText(QString::fromLatin1(kHeidenhain));
        auto style = [&](int line, int column) { return static_cast<NcStyle>(editor.styleAt(line, column)); };
        QCOMPARE(style(1, 1), NcStyle::BlockNumber);
        QCOMPARE(style(1, 4), NcStyle::Keyword);   // BEGIN
        QCOMPARE(style(1, 14), NcStyle::Default);  // F3D_TEST: a program name, no feed word
        QCOMPARE(style(1, 16), NcStyle::Default);
        QCOMPARE(style(1, 23), NcStyle::Keyword);        // MM
        QCOMPARE(style(2, 4), NcStyle::Keyword);         // BLK
        QCOMPARE(style(2, 13), NcStyle::Number);         // 0.1
        QCOMPARE(style(2, 17), NcStyle::AxisWord);       // Z (tool axis)
        QCOMPARE(style(2, 19), NcStyle::AxisWord);       // X+0
        QCOMPARE(style(3, 14), NcStyle::Number);         // tool 1
        QCOMPARE(style(3, 18), NcStyle::FeedSpeedTool);  // S5000
        QCOMPARE(style(3, 24), NcStyle::FeedSpeedTool);  // DL+0.1
        QCOMPARE(style(4, 4), NcStyle::Keyword);         // L
        QCOMPARE(style(4, 7), NcStyle::AxisWord);        // Z+100
        QCOMPARE(style(4, 13), NcStyle::Keyword);        // R0
        QCOMPARE(style(4, 16), NcStyle::FeedSpeedTool);  // FMAX
        QCOMPARE(style(4, 21), NcStyle::MWord);          // M3
        QCOMPARE(style(5, 4), NcStyle::Keyword);         // CYCL
        QCOMPARE(style(5, 13), NcStyle::Number);         // 200
        QCOMPARE(style(5, 17), NcStyle::Keyword);        // DRILLING
        QCOMPARE(style(6, 5), NcStyle::Parameter);       // Q200 on a continuation line
        QCOMPARE(style(6, 10), NcStyle::Number);
        QCOMPARE(style(6, 15), NcStyle::Comment);
        QCOMPARE(style(7, 10), NcStyle::Number);      // -20
        QCOMPARE(style(9, 4), NcStyle::Comment);      // * - subprogram
        QCOMPARE(style(12, 4), NcStyle::Keyword);     // C
        QCOMPARE(style(12, 7), NcStyle::AxisWord);    // X+0
        QCOMPARE(style(12, 16), NcStyle::Keyword);    // DR-
        QCOMPARE(style(13, 4), NcStyle::Keyword);     // FN
        QCOMPARE(style(13, 10), NcStyle::Parameter);  // Q1
        QCOMPARE(style(13, 15), NcStyle::Number);     // +5

        const int depth[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0};
        for (int line = 1; line <= 15; ++line)
            QCOMPARE(editor.foldDepth(line), depth[line - 1]);
        QVERIFY(editor.isFoldHeader(10));  // LBL 1
        QVERIFY(!editor.isFoldHeader(8));  // CALL LBL 1 is no definition
        saveShot(&editor, QStringLiteral("editor-heidenhain.png"));
    }

    void realProgramsForALook()
    {
        // Screenshots of programs from the repository's goldens, one per dialect.
        const std::pair<const char*, nc::Dialect> programs[] = {
            {"tests/golden/jobs/example-block/expected.mpf", nc::Dialect::Sinumerik},
            {"tests/golden/nc/heidenhain/thesis/input.h", nc::Dialect::Heidenhain},
            {"tests/golden/nc/iso/subroutines-loops/input.ngc", nc::Dialect::Iso}};
        for (const auto& [path, dialect] : programs) {
            QFile file(QStringLiteral(CAMWB_SOURCE_DIR "/") + QString::fromLatin1(path));
            QVERIFY2(file.open(QIODevice::ReadOnly), path);
            NcEditor editor;
            editor.resize(1000, 640);
            editor.setDialect(dialect);
            editor.setText(QString::fromUtf8(file.readAll()));
            saveShot(&editor, QStringLiteral("program-%1.png").arg(QString::fromLatin1(nc::dialectName(dialect))));
        }
    }

    void fanucMacroLoopsFold()
    {
        NcEditor editor;
        editor.setDialect(nc::Dialect::Iso);
        editor.setText(QStringLiteral("O1000\n#1=0\nWHILE[#1LT3]DO1\nG91 G1 X10 F100\n#1=#1+1\nEND1\n"
                                      "IF[#1GT2]GOTO10\nN10 M30\n"));
        QCOMPARE(static_cast<NcStyle>(editor.styleAt(3, 1)), NcStyle::Keyword);   // WHILE
        QCOMPARE(static_cast<NcStyle>(editor.styleAt(3, 13)), NcStyle::Keyword);  // DO1
        QCOMPARE(static_cast<NcStyle>(editor.styleAt(7, 10)), NcStyle::Keyword);  // GOTO10
        const int depth[] = {0, 0, 0, 1, 1, 1, 0, 0};
        for (int line = 1; line <= 8; ++line)
            QCOMPARE(editor.foldDepth(line), depth[line - 1]);
        QVERIFY(editor.isFoldHeader(3));
    }

    // CL files in their own words: APT's major and minor words (a continued statement's next line
    // starts with a minor word), a FreeCAD dump's commands and parameters, our trace's records.
    // None of them folds.
    void clFilesAreHighlightedAsCl()
    {
        NcEditor editor;
        editor.setClFormat(toolpath::ClFormat::Apt);
        editor.setText(QStringLiteral("$$ from CATIA\n"                 // 1
                                      "PARTNO Part Operation.1\n"       // 2
                                      "SPINDL/ 2400.0,RPM,$\n"          // 3
                                      " CLW\n"                          // 4
                                      "GOTO / -63.0, 8.5E-1, 1\n"       // 5
                                      "TLON,GOFWD/ (CIRCLE/ 1,2),ON\n"  // 6
                                      "FINI\n"));
        auto style = [&](int line, int column) { return static_cast<NcStyle>(editor.styleAt(line, column)); };
        QCOMPARE(style(1, 4), NcStyle::Comment);
        QCOMPARE(style(2, 1), NcStyle::Keyword);     // PARTNO
        QCOMPARE(style(2, 8), NcStyle::String);      // its text
        QCOMPARE(style(3, 1), NcStyle::Keyword);     // SPINDL
        QCOMPARE(style(3, 9), NcStyle::Number);      // 2400.0
        QCOMPARE(style(3, 16), NcStyle::Parameter);  // RPM
        QCOMPARE(style(4, 2), NcStyle::Parameter);   // CLW continues the statement: no major word
        QCOMPARE(style(5, 1), NcStyle::Keyword);     // GOTO
        QCOMPARE(style(5, 8), NcStyle::Number);      // -63.0
        QCOMPARE(style(5, 18), NcStyle::Number);     // the exponent of 8.5E-1
        QCOMPARE(style(6, 6), NcStyle::Keyword);     // GOFWD/
        QCOMPARE(style(6, 14), NcStyle::Keyword);    // CIRCLE/ inside the brackets
        QCOMPARE(style(6, 27), NcStyle::Parameter);  // ON
        QCOMPARE(style(7, 1), NcStyle::Keyword);     // FINI
        for (int line = 1; line <= 7; ++line) {
            QCOMPARE(editor.foldDepth(line), 0);
            QVERIFY(!editor.isFoldHeader(line));
        }

        editor.setClFormat(toolpath::ClFormat::FreeCadDump);
        editor.setText(QStringLiteral("(Path: Profile)\nCommand G1 [ X:10 Y:-5.5 F:300 Q:1 ]\nCommand M6 [ T:4 ]\n"));
        QCOMPARE(style(1, 2), NcStyle::Comment);
        QCOMPARE(style(2, 1), NcStyle::Keyword);         // Command
        QCOMPARE(style(2, 9), NcStyle::GWord);           // G1
        QCOMPARE(style(2, 14), NcStyle::AxisWord);       // X:10
        QCOMPARE(style(2, 24), NcStyle::AxisWord);       // Y:-5.5 to its last digit
        QCOMPARE(style(2, 26), NcStyle::FeedSpeedTool);  // F:300
        QCOMPARE(style(2, 32), NcStyle::Parameter);      // Q:1
        QCOMPARE(style(3, 9), NcStyle::MWord);           // M6

        editor.setClFormat(toolpath::ClFormat::Trace);
        editor.setText(QStringLiteral("# camwb trace\nsection \"Holes\" drilling tool 3\nrapid 8.0 -8.0 25\n"));
        QCOMPARE(style(1, 3), NcStyle::Comment);
        QCOMPARE(style(2, 1), NcStyle::Keyword);     // section
        QCOMPARE(style(2, 10), NcStyle::String);     // "Holes"
        QCOMPARE(style(2, 18), NcStyle::Parameter);  // drilling
        QCOMPARE(style(3, 1), NcStyle::Keyword);     // rapid
        QCOMPARE(style(3, 11), NcStyle::Number);     // -8.0

        // Back to NC: the same text in the editor's dialect again.
        editor.setClFormat(std::nullopt);
        editor.setDialect(nc::Dialect::Iso);
        editor.setText(QStringLiteral("$$ not a comment in ISO\n"));
        QVERIFY(style(1, 4) != NcStyle::Comment);
    }

    void switchingTheDialectRestyles()
    {
        NcEditor editor;
        editor.setText(QStringLiteral("(comment) G1 X1\n"));
        QVERIFY(static_cast<NcStyle>(editor.styleAt(1, 2)) != NcStyle::Comment);
        editor.setDialect(nc::Dialect::Iso);
        QCOMPARE(static_cast<NcStyle>(editor.styleAt(1, 2)), NcStyle::Comment);
    }

    void diagnosticsMarkersAndAnnotations()
    {
        NcEditor editor;
        editor.resize(900, 400);
        editor.setText(QString::fromLatin1(kSinumerik));
        QList<NcEditorDiagnostic> diagnostics;
        diagnostics.append({5, 10, nc::Severity::Warning, QStringLiteral("feed looks low")});
        diagnostics.append({5, 0, nc::Severity::Error, QStringLiteral("unknown word")});
        diagnostics.append({9, 0, nc::Severity::Note, QStringLiteral("loop runs 3 times")});
        editor.setDiagnostics(diagnostics);
        QCOMPARE(editor.diagnosticSeverityAt(5), std::optional(nc::Severity::Error));
        QCOMPARE(editor.diagnosticSeverityAt(9), std::optional(nc::Severity::Note));
        QCOMPARE(editor.diagnosticSeverityAt(6), std::nullopt);
        QVERIFY(editor.annotationAt(5).contains(QStringLiteral("column 10: warning: feed looks low")));
        QVERIFY(editor.annotationAt(5).contains(QStringLiteral("error: unknown word")));
        QVERIFY(editor.annotationAt(6).isEmpty());
        saveShot(&editor, QStringLiteral("editor-diagnostics.png"));
        editor.clearDiagnostics();
        QCOMPARE(editor.diagnosticSeverityAt(5), std::nullopt);
        QVERIFY(editor.annotationAt(5).isEmpty());

        std::vector<nc::Diagnostic> fromInterpreter{{nc::Severity::Error, "main.mpf", 3, 1, "bad"},
                                                    {nc::Severity::Error, "sub.spf", 4, 1, "elsewhere"}};
        const QList<NcEditorDiagnostic> mine = NcEditor::diagnosticsFor(fromInterpreter, "main.mpf");
        QCOMPARE(mine.size(), 1);
        QCOMPARE(mine[0].line, 3);
    }

    void findsText()
    {
        NcEditor editor;
        editor.setText(QString::fromLatin1(kSinumerik));
        QVERIFY(editor.findText(QStringLiteral("endif")));
        QCOMPARE(editor.currentLine(), 8);
        QVERIFY(editor.findText(QStringLiteral("R1")));
        QCOMPARE(editor.currentLine(), 10);
        QVERIFY(editor.findText(QStringLiteral("R1"), false));
        QVERIFY(editor.currentLine() < 10 || editor.currentLine() == 17);  // wraps backwards
        QVERIFY(!editor.findText(QStringLiteral("NOWHERE")));
    }
};

class EditorActionsTest : public QObject {
    Q_OBJECT

private:
    QMainWindow* m_window = nullptr;
    NcEditor* m_editor = nullptr;
    ActionRegistry* m_registry = nullptr;
    ScriptedPrompter m_prompter;
    QTemporaryDir m_files;

    QString writeFile(const QString& name, const QByteArray& text)
    {
        QFile file(m_files.filePath(name));
        if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size())
            return {};
        return file.fileName();
    }

private slots:
    void init()
    {
        m_window = new QMainWindow;
        m_editor = new NcEditor(m_window);
        m_window->setCentralWidget(m_editor);
        m_window->statusBar();
        m_registry = new ActionRegistry(m_window);
        m_prompter = ScriptedPrompter();
        camwb::gui::registerNcEditorActions(*m_registry, m_editor, m_window,
                                            [this]() -> camwb::gui::Prompter& { return m_prompter; });
        m_window->resize(900, 600);
    }

    void cleanup()
    {
        delete m_window;
        m_window = nullptr;
    }

    void registersStableIds()
    {
        for (const char* id : {"Cam.Nc.Renumber", "Cam.Nc.RemoveNumbers", "Cam.Nc.GotoBlock", "Cam.Nc.Find",
                               "Cam.Nc.Compare", "Cam.Nc.ProgramInfo"})
            QVERIFY2(m_registry->action(QString::fromLatin1(id)) != nullptr, id);
    }

    void renumberIsOneUndoStep()
    {
        const QString original = QStringLiteral("; header\nN5 G0 X0\nG1 X10 F100\nN7 GOTOB N5\nM30\n");
        m_editor->setText(original);
        onNextModal([](QWidget* modal) {
            auto* dialog = qobject_cast<RenumberDialog*>(modal);
            QVERIFY(dialog != nullptr);
            nc::RenumberOptions options;
            options.start = 100;
            options.step = 10;
            dialog->setOptions(options);
            dialog->accept();
        });
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Renumber")));
        QCOMPARE(m_editor->text(),
                 QStringLiteral("; header\nN100 G0 X0\nN110 G1 X10 F100\nN120 GOTOB N100\nN130 M30\n"));
        QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("4")));
        m_editor->undo();
        QCOMPARE(m_editor->text(), original);
        m_editor->redo();
        QVERIFY(m_editor->text().startsWith(QStringLiteral("; header\nN100")));
    }

    void removeNumbersIsOneUndoStep()
    {
        const QString original = QStringLiteral("N10 G0 X0\nN20 G1 X1\nN30 M30\n");
        m_editor->setText(original);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.RemoveNumbers")));
        QCOMPARE(m_editor->text(), QStringLiteral("G0 X0\nG1 X1\nM30\n"));
        m_editor->undo();
        QCOMPARE(m_editor->text(), original);
    }

    // A CL file has no block numbers: numbering its statements would break it, so both tools
    // leave its text alone and say why.
    void blockNumbersLeaveACLFileAlone()
    {
        const QString apt = QStringLiteral("PARTNO/BRACKET\nRAPID\nGOTO/0,0,20\nFINI\n");
        m_editor->setText(apt);
        m_editor->setProgramPath(QStringLiteral("/tmp/bracket.cls"));
        m_editor->setClFormat(toolpath::ClFormat::Apt);  // as the inspector reads it
        for (const char* id : {"Cam.Nc.Renumber", "Cam.Nc.RemoveNumbers"}) {
            m_window->statusBar()->clearMessage();
            QVERIFY(m_registry->trigger(QString::fromLatin1(id)));  // no dialog: it would wait here
            QCOMPARE(m_editor->text(), apt);
            QCOMPARE(m_window->statusBar()->currentMessage(),
                     QStringLiteral("bracket.cls is a CL file: block numbers are for NC programs"));
        }
        // The same .cls read as NC (the dock's dialect chosen): its blocks are NC blocks.
        m_editor->setClFormat(std::nullopt);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.RemoveNumbers")));
        QVERIFY(m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Removed")));
    }

    void gotoBlock()
    {
        m_editor->setText(QStringLiteral("N10 G0\nN20 G1 X1\nN30 G1 X2\nN40 M30\n"));
        onNextModal([](QWidget* modal) {
            auto* input = qobject_cast<QInputDialog*>(modal);
            QVERIFY(input != nullptr);
            input->setIntValue(30);
            input->accept();
        });
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.GotoBlock")));
        QCOMPARE(m_editor->currentLine(), 3);
    }

    void findShowsTheBar()
    {
        m_editor->setText(QStringLiteral("N10 G0\n"));
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        auto* bar = m_editor->findChild<QWidget*>(QStringLiteral("ncFindBar"));
        QVERIFY(bar != nullptr);
        QVERIFY(!bar->isVisible());
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Find")));
        QVERIFY(bar->isVisible());
        auto* text = bar->findChild<QLineEdit*>(QStringLiteral("ncFindText"));
        QVERIFY(text != nullptr);
        text->setText(QStringLiteral("G0"));
        QTest::keyClick(text, Qt::Key_Return);
        QCOMPARE(m_editor->currentLine(), 1);
        QTest::keyClick(text, Qt::Key_Escape);
        QVERIFY(!bar->isVisible());
    }

    // Compare with File asks for the file first and opens with both programs.
    void compareFindsTheDifferences()
    {
        const QString other = writeFile(QStringLiteral("other.mpf"),
                                        "N10 G0 X0 Y0\nN20 G1 Z-3 F100\nN30 X50\nN40 Y50\nN45 X25\nN50 X0\nN60 M30\n");
        QVERIFY(!other.isEmpty());
        m_editor->setDialect(nc::Dialect::Sinumerik);
        m_editor->setText(QStringLiteral("N10 G0 X0 Y0\nN20 G1 Z-2 F100\nN30 X50\nN40 Y50\nN50 X0\nN60 M30\n"));
        m_prompter.files.push_back(other);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Compare")));
        QCOMPARE(int(m_prompter.fileTitles.size()), 1);
        auto* dialog = m_window->findChild<CompareDialog*>();
        QVERIFY(dialog != nullptr);
        QCOMPARE(dialog->summaryText(), QStringLiteral("2 difference(s)"));
        QCOMPARE(dialog->differenceCount(), 2);
        const nc::LineDiff& diff = dialog->diff();
        QCOMPARE(diff.rows[std::size_t(diff.hunks[0].firstRow)].kind, nc::DiffKind::Changed);
        QCOMPARE(diff.rows[std::size_t(diff.hunks[0].firstRow)].leftLine, 2);
        QCOMPARE(diff.rows[std::size_t(diff.hunks[1].firstRow)].kind, nc::DiffKind::Added);
        QCOMPARE(diff.rows[std::size_t(diff.hunks[1].firstRow)].rightLine, 5);
        QCOMPARE(dialog->currentDifference(), -1);
        dialog->nextDifference();
        dialog->nextDifference();
        QCOMPARE(dialog->currentDifference(), 1);
        dialog->nextDifference();
        QCOMPARE(dialog->currentDifference(), 1);  // stays on the last
        dialog->previousDifference();
        QCOMPARE(dialog->currentDifference(), 0);
        saveShot(dialog, QStringLiteral("compare-dialog.png"));
        dialog->setIgnoreBlockNumbers(true);
        QCOMPARE(dialog->differenceCount(), 2);
    }

    // The dialog is reused, but each Compare takes the program the editor holds now: a CL file
    // after an NC program is highlighted as CL on both sides.
    void compareTakesTheEditorsLanguage()
    {
        const QString nc = writeFile(QStringLiteral("other.mpf"), "N10 G0 X0 ; rapid\n");
        const QString cl = writeFile(QStringLiteral("other.cls"), "$$ from NX\nGOTO/0,0,5\n");
        QVERIFY(!nc.isEmpty() && !cl.isEmpty());
        m_editor->setDialect(nc::Dialect::Sinumerik);
        m_editor->setText(QStringLiteral("N10 G0 X0 ; rapid\n"));
        m_prompter.files.push_back(nc);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Compare")));
        auto* dialog = m_window->findChild<CompareDialog*>();
        QVERIFY(dialog != nullptr);
        QCOMPARE(static_cast<NcStyle>(dialog->styleAt(true, 1, 12)), NcStyle::Comment);  // ; rapid

        m_editor->setText(QStringLiteral("$$ from CATIA\nGOTO/0,0,5\n"));
        m_editor->setClFormat(toolpath::ClFormat::Apt);
        m_prompter.files.push_back(cl);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Compare")));
        QCOMPARE(m_window->findChild<CompareDialog*>(), dialog);  // the same dialog, reused
        QCOMPARE(dialog->differenceCount(), 1);
        QCOMPARE(static_cast<NcStyle>(dialog->styleAt(true, 1, 4)), NcStyle::Comment);   // $$ from CATIA
        QCOMPARE(static_cast<NcStyle>(dialog->styleAt(false, 1, 4)), NcStyle::Comment);  // $$ from NX
        QCOMPARE(static_cast<NcStyle>(dialog->styleAt(true, 2, 1)), NcStyle::Keyword);   // GOTO
    }

    // Without a second program there is nothing to compare: no dialog when the file choice is
    // cancelled, and a dialog with one side says so instead of counting the whole program as one
    // difference.
    void compareWithoutASecondProgramComparesNothing()
    {
        m_editor->setText(QStringLiteral("G0 X0\nG1 X10 F100\nM30\n"));
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.Compare")));  // no answer: cancelled
        QCOMPARE(int(m_prompter.fileTitles.size()), 1);
        QVERIFY(m_window->findChild<CompareDialog*>() == nullptr);

        CompareDialog dialog(nc::Dialect::Iso);
        dialog.setLeft(m_editor->text(), QStringLiteral("in the editor"));
        QCOMPARE(dialog.differenceCount(), 0);
        QCOMPARE(dialog.summaryText(), QStringLiteral("Open a program on the right to compare"));
        dialog.setRight(QString(), QStringLiteral("empty.ngc"));  // an empty file is a program
        QCOMPARE(dialog.differenceCount(), 1);
        QCOMPARE(dialog.summaryText(), QStringLiteral("1 difference(s)"));
    }

    void compareScrollsBothSidesTogether()
    {
        QString left;
        QString right;
        for (int i = 0; i < 400; ++i) {
            left += QStringLiteral("G1 X%1 Y%2\n").arg(i).arg(i % 7);
            right += QStringLiteral("G1 X%1 Y%2\n").arg(i).arg(i == 300 ? 99 : i % 7);
        }
        CompareDialog dialog(nc::Dialect::Iso);
        dialog.setLeft(left, QStringLiteral("a"));
        dialog.setRight(right, QStringLiteral("b"));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QCOMPARE(dialog.differenceCount(), 1);
        dialog.nextDifference();
        QTest::qWait(50);
        QVERIFY(dialog.firstVisibleRow(true) > 250);
        QCOMPARE(dialog.firstVisibleRow(true), dialog.firstVisibleRow(false));
        QVERIFY(dialog.findChild<QWidget*>(QStringLiteral("compareLeft")) != nullptr);
    }

    void programInfo()
    {
        m_editor->setDialect(nc::Dialect::Iso);
        m_editor->setText(QStringLiteral("G21 G90 G17\nT1 M6\nS1000 M3\nG0 X0 Y0 Z10\nG1 Z-1 F100\nG1 X100 F600\n"
                                         "G0 Z10\nM30\n"));
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.ProgramInfo")));
        auto* dialog = m_window->findChild<ProgramInfoDialog*>();
        QVERIFY(dialog != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->hasStats() && !dialog->isBusy(), 20000);
        const toolpath::ProgramStats& s = dialog->stats();
        QCOMPARE(dialog->errorCount(), 0);
        QVERIFY(std::abs(s.totals.feedLengthMm - 111.0) < 1e-6);
        QVERIFY(std::abs(s.totals.cuttingExtents.max.x - 100.0) < 1e-6);
        QVERIFY(std::abs(s.totals.cuttingExtents.min.z + 1.0) < 1e-6);
        QVERIFY(std::abs(s.totals.feedSeconds - (11.0 / 100 + 100.0 / 600) * 60) < 1e-6);
        QVERIFY(dialog->reportText().contains(QStringLiteral("100.000")));
        // The cycle time with accelerations (no machine: the default limits, said so) adds the
        // tool change and the speed ramps to what distance and feed alone give.
        QVERIFY(dialog->reportText().contains(QStringLiteral("default limits")));
        QVERIFY2(
            dialog->plannedSeconds() > s.totals.totalSeconds() + 4,
            qPrintable(
                QStringLiteral("%1 s planned vs %2 s").arg(dialog->plannedSeconds()).arg(s.totals.totalSeconds())));
        saveShot(dialog, QStringLiteral("program-info.png"));
    }

    // Program Information reads the program as the editor holds it: APT here, though its name
    // says nothing of CL, because the inspector read it so.
    void programInfoReadsACLFileAsTheEditorHoldsIt()
    {
        m_editor->setText(QStringLiteral("PARTNO/BRACKET\nCUTTER/10,0\nLOADTL/3\nRAPID\nGOTO/0,0,20\n"
                                         "FEDRAT/MMPM,300\nGOTO/0,0,-2\nGOTO/40,0,-2\nFINI\n"));
        m_editor->setProgramPath(QStringLiteral("/tmp/bracket.txt"));
        m_editor->setClFormat(toolpath::ClFormat::Apt);
        QVERIFY(m_registry->trigger(QStringLiteral("Cam.Nc.ProgramInfo")));
        auto* dialog = m_window->findChild<ProgramInfoDialog*>();
        QVERIFY(dialog != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->hasStats() && !dialog->isBusy(), 20000);
        QCOMPARE(dialog->errorCount(), 0);
        QVERIFY(std::abs(dialog->stats().totals.feedLengthMm - 62.0) < 1e-6);
    }
};

class ProgramInfoErrorTest : public QObject {
    Q_OBJECT

private slots:
    // An arc whose radii disagree (an error in the editor's margin) is left out of the extents and
    // lengths: drawn as a circle it would add a 200 mm bulge to a 30 mm program.
    void errorBlocksAreLeftOutOfTheFigures()
    {
        ProgramInfoDialog dialog;
        dialog.analyze(QStringLiteral("G21 G90 G17\nG0 X0 Y0 Z0\nG1 X10 F100\nG2 X20 Y0 I100 J0\nG1 X30\nM30\n"),
                       nc::Dialect::Iso, QStringLiteral("bad-arc.ngc"));
        QTRY_VERIFY_WITH_TIMEOUT(dialog.hasStats() && !dialog.isBusy(), 20000);
        QCOMPARE(dialog.errorCount(), 1);
        const toolpath::ProgramStats& s = dialog.stats();
        QCOMPARE(s.movesLeftOut, 1);
        QVERIFY2(std::abs(s.totals.cuttingExtents.max.y) < 1e-9 && std::abs(s.totals.cuttingExtents.min.y) < 1e-9,
                 qPrintable(QStringLiteral("Y extents %1 .. %2")
                                .arg(s.totals.cuttingExtents.min.y)
                                .arg(s.totals.cuttingExtents.max.y)));
        QVERIFY(std::abs(s.totals.cuttingExtents.max.x - 30.0) < 1e-9);
        QVERIFY(std::abs(s.totals.feedLengthMm - 20.0) < 1e-9);  // the two lines, not the arc
    }
};

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    EditorHighlightTest highlight;
    run.run(&highlight);
    EditorActionsTest actions;
    run.run(&actions);
    ProgramInfoErrorTest errors;
    run.run(&errors);
    LargeProgramTest large;
    if (qEnvironmentVariableIsEmpty("CAMWB_EDITOR_SKIP_LARGE"))
        run.run(&large);
    else
        run.skip("LargeProgramTest", "CAMWB_EDITOR_SKIP_LARGE is set");
    return run.finish();
}

#include "EditorTest.moc"
