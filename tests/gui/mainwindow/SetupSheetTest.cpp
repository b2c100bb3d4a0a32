// Job > Setup Sheet… through the action registry: the example job's sheet is written where the
// prompter says (HTML, its pictures, the PDF beside it), with the 3D view's picture of the part
// under Xvfb and the sheet's own renderer offscreen; a job whose program is out of date asks for
// no file and writes nothing. Under Xvfb (GL) and offscreen (no GL).
#include "JobStateSupport.h"
#include "QtTestRun.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/view3d/View3D.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

class SetupSheetTest : public QObject {
    Q_OBJECT

private slots:
    void writesTheSheetOfTheCurrentJob()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        const QString html = dir.filePath(QStringLiteral("sheet.html"));
        prompter->files = {html};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QVERIFY2(prompter->errors.isEmpty(), qPrintable(prompter->errors.join('\n')));
        const QString text = readFile(html);
        QVERIFY(text.contains(QLatin1String("<h1>Setup sheet: Example block</h1>")));
        QVERIFY(text.contains(QLatin1String("<td>T2</td><td>Flat end mill D6</td>")));
        QVERIFY(text.contains(QLatin1String("Simulated: no errors.")));
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("sheet.pdf"))).size() > 10000);
        const QImage part(dir.filePath(QStringLiteral("sheet-images/part.png")));
        QVERIFY(showsSomething(part));
        if (!shotsDir().isEmpty())
            part.save(QDir(shotsDir())
                          .filePath(withGl() ? QStringLiteral("sheet-part-gl.png")
                                             : QStringLiteral("sheet-part-offscreen.png")));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("sheet-images/op-4.png"))));
        // The picture is the view's under GL (its window's shape, scaled to the sheet's width), the
        // renderer's 720 × 480 without.
        QCOMPARE(part.width(), 720);
        QCOMPARE(part.height() == 480, !withGl());
        QVERIFY(text.contains(QStringLiteral("width=\"720\" height=\"%1\"").arg(part.height())));
    }

    void refusesAProgramThatIsOutOfDate()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        window.workbench().removeOperation(0);  // recomputed in the background: not current now
        QVERIFY(window.workbench().isBusy());
        prompter->files = {dir.filePath(QStringLiteral("stale.html"))};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QCOMPARE(prompter->files.size(), 1);  // not asked
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("stale.html"))));
        QCOMPARE(prompter->errors.size(), 1);
        waitIdle(window);
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    SetupSheetTest test;
    run.run(&test);
    return run.finish();
}

#include "SetupSheetTest.moc"
