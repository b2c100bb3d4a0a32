// The NC editor and the compare dialog with programs of a million and 2 x 100k lines: open,
// paint, scroll, style in idle time, renumber as one undo step, diff. Figures are printed, never
// asserted (a test never asserts a time). Run by EditorTest's main unless CAMWB_EDITOR_SKIP_LARGE.
#pragma once

#include "Shots.h"
#include "gui/editor/CompareDialog.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/NcStyles.h"
#include "nc/tools/BlockNumbers.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QObject>
#include <QTest>
#include <QTimer>

class LargeProgramTest : public QObject {
    Q_OBJECT

private slots:
    void millionLines()
    {
        // ~38 MB of NC: opens, paints, scrolls to the end. Figures printed; times never asserted.
        QString program;
        program.reserve(40'000'000);
        for (int i = 1; i <= 1'000'000; ++i)
            program += QStringLiteral("N%1 G1 X%2 Y%3 F1200 ; move\n").arg(i * 10).arg(i % 1000).arg(i % 97);
        camwb::gui::NcEditor editor;
        editor.resize(1000, 700);
        QElapsedTimer timer;
        timer.start();
        editor.setText(program);
        const qint64 setTextMs = timer.restart();
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        editor.repaint();
        const qint64 firstPaintMs = timer.restart();
        QCOMPARE(editor.lineCount(), 1'000'001);
        editor.gotoLine(1'000'000);
        editor.repaint();
        QApplication::processEvents();
        const qint64 scrollEndMs = timer.restart();
        QVERIFY(editor.firstVisibleLine() > 990'000);
        // Styling up to the view goes on in idle time: wait until the last line is styled, and
        // record the longest the event loop stood still meanwhile (a ticking 5 ms timer).
        QElapsedTimer tick;
        tick.start();
        qint64 longestStallMs = 0;
        QTimer ticker;
        ticker.setInterval(5);
        QObject::connect(&ticker, &QTimer::timeout, [&] { longestStallMs = std::max(longestStallMs, tick.restart()); });
        ticker.start();
        QTRY_VERIFY_WITH_TIMEOUT(editor.isStyledThrough(1'000'000), 60'000);
        ticker.stop();
        const qint64 styledEndMs = timer.restart();
        saveShot(&editor, QStringLiteral("editor-1M-lines-end.png"));
        timer.restart();
        QCOMPARE(static_cast<camwb::gui::NcStyle>(editor.styleAt(1'000'000, 1)), camwb::gui::NcStyle::BlockNumber);
        editor.gotoLine(500'000);
        editor.repaint();
        const qint64 scrollMiddleMs = timer.restart();
        for (int k = 0; k < 50; ++k) {
            editor.gotoLine(500'000 + k * 40);
            editor.repaint();
        }
        const qint64 pageStepsMs = timer.restart();
        // Renumbering the whole program is one undo step, even at this size.
        const QByteArray bytes = editor.utf8Text();
        camwb::nc::RenumberOptions options;
        options.start = 5;
        options.step = 5;
        const camwb::nc::RenumberResult renumbered =
            camwb::nc::renumberBlocks(std::string_view(bytes.constData(), std::size_t(bytes.size())), options);
        const qint64 renumberMs = timer.restart();
        editor.replaceUtf8Text(QByteArray::fromStdString(renumbered.text));
        editor.repaint();
        const qint64 replaceMs = timer.restart();
        QCOMPARE(renumbered.report.linesNumbered, 1'000'000);
        editor.undo();
        editor.repaint();
        const qint64 undoMs = timer.restart();
        QVERIFY(editor.text().startsWith(QStringLiteral("N10 G1")));
        qInfo("1M lines (%lld MB): setText %lld ms, first paint %lld ms, scroll to end %lld ms (styled there after "
              "%lld ms more in idle time, longest stall %lld ms), "
              "back to the middle %lld ms, 50 page steps %lld ms; renumber (kernel) %lld ms, "
              "replace text %lld ms, undo %lld ms",
              static_cast<long long>(program.size() / 1'000'000), static_cast<long long>(setTextMs),
              static_cast<long long>(firstPaintMs), static_cast<long long>(scrollEndMs),
              static_cast<long long>(styledEndMs), static_cast<long long>(longestStallMs),
              static_cast<long long>(scrollMiddleMs), static_cast<long long>(pageStepsMs),
              static_cast<long long>(renumberMs), static_cast<long long>(replaceMs), static_cast<long long>(undoMs));
    }

    void compareHundredThousandLines()
    {
        // Two 100k-line programs, every 100th line changed: diff and display. Figures printed only.
        QString left;
        QString right;
        for (int i = 1; i <= 100'000; ++i) {
            const QString line = QStringLiteral("N%1 G1 X%2 Y%3\n").arg(i * 10).arg(i % 500).arg(i % 37);
            left += line;
            right += i % 100 == 0 ? QStringLiteral("N%1 G1 X%2 Y-1\n").arg(i * 10).arg(i % 500) : line;
        }
        camwb::gui::CompareDialog dialog(camwb::nc::Dialect::Sinumerik);
        QElapsedTimer timer;
        timer.start();
        dialog.setLeft(left, QStringLiteral("a"));
        dialog.setRight(right, QStringLiteral("b"));
        QCOMPARE(dialog.differenceCount(), 1000);  // diffs and fills both views once, here
        const qint64 ms = timer.elapsed();
        qInfo("compare 2 x 100k lines, 1000 differences: %lld ms (diff and both views)", static_cast<long long>(ms));
    }
};
