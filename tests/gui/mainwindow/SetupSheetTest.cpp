// Job > Setup Sheet… through the action registry: the example job's sheet is made on a worker
// thread and written where the prompter says (HTML, its pictures, the PDF beside it), with the
// 3D view's picture of the part under Xvfb and the sheet's own renderer offscreen; a job whose
// program is out of date asks for no file and writes nothing; Cancel in the progress dialog, or
// an edit of the job while the sheet is made, writes nothing (and leaves no temporary file).
// Under Xvfb (GL) and offscreen (no GL).
#include "JobStateSupport.h"
#include "QtTestRun.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Workbench.h"
#include "gui/view3d/View3D.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace {

QProgressDialog* sheetProgress(MainWindow& window)
{
    return window.findChild<QProgressDialog*>(QStringLiteral("setupSheetProgress"));
}

// Until the sheet being made is done (its progress dialog gone).
bool waitSheetDone(MainWindow& window)
{
    QElapsedTimer waited;
    waited.start();
    while (sheetProgress(window) != nullptr && waited.elapsed() < 120000)
        QTest::qWait(20);
    return sheetProgress(window) == nullptr;
}

// The files in `dir` (hidden ones too: the sheet's temporaries start with a dot).
QStringList filesIn(const QTemporaryDir& dir)
{
    return QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

// The last report message of `spy` (Workbench::message).
QString lastMessage(const QSignalSpy& spy) { return spy.isEmpty() ? QString() : spy.last().at(1).toString(); }

}  // namespace

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
        QVERIFY(sheetProgress(window) != nullptr);  // made in the background
        QVERIFY(!QFileInfo::exists(html));
        QVERIFY(waitSheetDone(window));
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

    void cancelWritesNothingThenASecondRunWrites()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        const QStringList before = filesIn(dir);
        QSignalSpy messages(&window.workbench(), &Workbench::message);
        const QString html = dir.filePath(QStringLiteral("sheet.html"));
        prompter->files = {html};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QProgressDialog* progress = sheetProgress(window);
        QVERIFY(progress != nullptr);
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel != nullptr);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(waitSheetDone(window));
        QCOMPARE(filesIn(dir), before);  // no sheet, no PDF, no temporaries
        QVERIFY(prompter->errors.isEmpty());
        QCOMPARE(lastMessage(messages), QStringLiteral("Setup sheet cancelled: nothing was written"));

        // Again, to the end: written.
        prompter->files = {html};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QVERIFY(waitSheetDone(window));
        QVERIFY2(prompter->errors.isEmpty(), qPrintable(prompter->errors.join('\n')));
        QVERIFY(readFile(html).contains(QLatin1String("<h1>Setup sheet: Example block</h1>")));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("sheet.pdf"))));
        QCOMPARE(lastMessage(messages), QStringLiteral("Setup sheet written: %1").arg(html));
        QStringList expected = before;
        expected << QStringLiteral("sheet-images") << QStringLiteral("sheet.html") << QStringLiteral("sheet.pdf");
        expected.sort();
        QCOMPARE(filesIn(dir), expected);
    }

    void anEditWhileItIsMadeDiscardsIt()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        const QStringList before = filesIn(dir);
        QSignalSpy messages(&window.workbench(), &Workbench::message);
        prompter->files = {dir.filePath(QStringLiteral("sheet.html"))};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QVERIFY(sheetProgress(window) != nullptr);
        window.workbench().removeOperation(0);  // the sheet's snapshot is of the job before this
        QVERIFY(waitSheetDone(window));
        QCOMPARE(filesIn(dir), before);
        bool said = false;
        for (const QList<QVariant>& message : messages)
            said = said || message.at(1).toString().startsWith(QLatin1String("The job changed while the setup sheet"));
        QVERIFY(said);
        waitIdle(window);
    }

    // With the display unit in inch the window's sheet shows inch (the CLI's stays in mm).
    void writesLengthsInTheDisplayUnit()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        camwb::gui::setDisplayUnit(camwb::gui::LengthUnit::Inch);
        const QString html = dir.filePath(QStringLiteral("inch.html"));
        prompter->files = {html};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SetupSheet")));
        QVERIFY(waitSheetDone(window));
        camwb::gui::setDisplayUnit(camwb::gui::LengthUnit::Millimetre);
        const QString text = readFile(html);
        QVERIFY(text.contains(QLatin1String("Lengths in in, feeds in in/min")));
        // T2, the D6 end mill: 6 mm = 0.2362 in.
        QVERIFY(text.contains(QLatin1String("<td>T2</td><td>Flat end mill D6</td><td>flat</td><td>0.2362</td>")));
        QVERIFY(text.contains(QLatin1String("<th>Feed in/min</th>")));
        QVERIFY(!text.contains(QLatin1String(" mm")));
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
