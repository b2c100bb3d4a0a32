// Preferences (QSettings round trip, the dialog and its picture), New Job with the preferences'
// post and machine, the "*" of an unsaved job in the title, Open Recent (order, limit, a missing
// file), autosave to a side file and its recovery: after the process that made the edit was
// killed (a child run of this program), Discard, and a corrupt autosave that never costs the job.
// Settings and app data live in a temporary folder (XDG_CONFIG_HOME/XDG_DATA_HOME, set in main).
#include "gui/shell/Session.h"
#include "JobStateSupport.h"
#include "QtTestRun.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/Autosave.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/PreferencesDialog.h"
#include "gui/shell/RecentFiles.h"
#include "gui/shell/ReportView.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/view3d/View3D.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

using camwb::gui::Autosaver;
using camwb::gui::Language;
using camwb::gui::LengthUnit;
using camwb::gui::Preferences;
using camwb::gui::PreferencesDialog;

namespace {

// Waits until `path` exists (the atomic writer renames a complete file into place).
bool waitForFile(const QString& path, int ms = 60000)
{
    QElapsedTimer waited;
    waited.start();
    while (!QFile::exists(path) && waited.elapsed() < ms)
        QTest::qWait(20);
    return QFile::exists(path);
}

int workOffsetOnDisk(const QString& path)
{
    auto job = camwb::document::loadJob(path.toStdString());
    return job ? job.value().workOffset : -1;
}

// The edit the recovery must bring back: G55 instead of the example's G54.
void editWorkOffset(MainWindow& window)
{
    window.workbench().document().edit("Work offset G55", [](camwb::document::Job& job) { job.workOffset = 2; });
}

// The side file a window that is no longer running left (no process has this pid on Linux).
QString crashedSidePath(const QString& job)
{
    QDir().mkpath(Autosaver::autosaveFolder());
    return Autosaver::sidePathFor(job, 999999999);
}

QStringList menuTexts(QMenu* menu)
{
    QStringList texts;
    for (QAction* action : menu->actions())
        texts << action->text();
    return texts;
}

QMenu* topMenu(MainWindow& window, const QString& title)
{
    for (QAction* action : window.menuBar()->actions())
        if (action->text() == title)
            return action->menu();
    return nullptr;
}

// Gives the main window's File and Edit menus other titles, as a translation does.
class MenuTitleTranslator : public QTranslator {
public:
    bool isEmpty() const override { return false; }
    QString translate(const char* context, const char* source, const char*, int) const override
    {
        if (qstrcmp(context, "camwb::gui::MainWindow") != 0)
            return {};
        if (qstrcmp(source, "&File") == 0)
            return QStringLiteral("&Fichier");
        if (qstrcmp(source, "&Edit") == 0)
            return QStringLiteral("É&dition");
        return {};
    }
};

// The child of recoveryAfterTheProcessIsKilled: opens the job, makes the edit, waits for its
// autosave and stays until it is killed.
int runAutosaveChild(const QString& job)
{
    MainWindow window;
    scripted(window);
    window.session().autosaver().setDebounceMs(100);
    if (!openAndWait(window, job))
        return 2;
    editWorkOffset(window);
    if (!waitForFile(Autosaver::sidePathFor(job)))
        return 3;
    std::printf("autosaved\n");
    std::fflush(stdout);
    return QApplication::exec();  // killed here
}

}  // namespace

class SessionTest : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        camwb::gui::appSettings()->clear();
        QDir(Autosaver::untitledFolder()).removeRecursively();
    }

    void preferencesRoundTrip()
    {
        const Preferences defaults = Preferences::load();
        QCOMPARE(defaults, Preferences());
        Preferences p;
        p.units = LengthUnit::Inch;
        p.defaultPostId = QStringLiteral("heidenhain-itnc530");
        p.defaultMachineId = QStringLiteral("dmu50-840d");
        p.toolLibraryPath = QStringLiteral("/shop/tools/library.json");
        p.language = Language::Czech;
        p.autosaveSeconds = 30;
        p.save();
        QCOMPARE(Preferences::load(), p);
        // Where the brief says: organisation camwb, application "CAM Workbench", under the test's folder.
        const QString file = camwb::gui::appSettings()->fileName();
        QVERIFY2(file.startsWith(qEnvironmentVariable("XDG_CONFIG_HOME")), qPrintable(file));
        QVERIFY(file.endsWith(QLatin1String("camwb/CAM Workbench.conf")));
        QCOMPARE(QSettings(file, QSettings::IniFormat).value("preferences/units").toString(), QStringLiteral("inch"));
        QCOMPARE(camwb::gui::uiLocale(Language::Czech).language(), QLocale::Czech);
        QCOMPARE(camwb::gui::uiLocale(Language::System), QLocale());
    }

    void lengthsAreFormattedInTheDisplayUnit()
    {
        QCOMPARE(camwb::gui::formatLength(12.5, LengthUnit::Millimetre), QStringLiteral("12.500 mm"));
        QCOMPARE(camwb::gui::formatLength(25.4, LengthUnit::Inch), QStringLiteral("1.0000 in"));
        QCOMPARE(camwb::gui::formatLength(-3.175, LengthUnit::Inch), QStringLiteral("-0.1250 in"));
    }

    void preferencesDialogEditsAndSaysWhenARestartIsNeeded()
    {
        ScriptedPrompter prompter;
        Preferences current;
        current.defaultPostId = QStringLiteral("linuxcnc");
        PreferencesDialog dialog(current, prompter);
        auto* post = dialog.findChild<QComboBox*>(QStringLiteral("defaultPost"));
        auto* language = dialog.findChild<QComboBox*>(QStringLiteral("language"));
        auto* notice = dialog.findChild<QLabel*>(QStringLiteral("restartNotice"));
        QVERIFY(post && language && notice);
        QCOMPARE(post->currentData().toString(), QStringLiteral("linuxcnc"));
        QVERIFY(post->findData(QStringLiteral("sinumerik840d")) >= 0);
        QCOMPARE(dialog.preferences(), current);  // opened and OK: nothing changes
        QVERIFY(!notice->isVisibleTo(&dialog));
        language->setCurrentIndex(language->findData(static_cast<int>(Language::Czech)));
        QVERIFY(notice->isVisibleTo(&dialog));
        QCOMPARE(dialog.preferences().language, Language::Czech);

        prompter.files = {QStringLiteral("/shop/tools/lib.json")};
        QTest::mouseClick(dialog.findChild<QPushButton*>(QStringLiteral("browseToolLibrary")), Qt::LeftButton);
        QCOMPARE(dialog.preferences().toolLibraryPath, QStringLiteral("/shop/tools/lib.json"));
        saveShot(&dialog, QStringLiteral("preferences.png"));
    }

    // Edit ▸ Preferences… opens the dialog; OK stores what it shows and the Session uses it.
    void preferencesActionStoresTheDialog()
    {
        MainWindow window;
        scripted(window);
        QMenu* edit = topMenu(window, QObject::tr("&Edit"));
        QVERIFY(edit && edit->actions().contains(window.actions().action(QStringLiteral("Cam.Edit.Preferences"))));
        bool seen = false;
        QTimer::singleShot(0, &window, [&seen] {
            auto* dialog = qobject_cast<PreferencesDialog*>(QApplication::activeModalWidget());
            if (dialog == nullptr)
                return;
            seen = true;
            auto* units = dialog->findChild<QComboBox*>(QStringLiteral("units"));
            units->setCurrentIndex(units->findData(static_cast<int>(LengthUnit::Inch)));
            dialog->findChild<QSpinBox*>(QStringLiteral("autosaveSeconds"))->setValue(20);
            dialog->accept();
        });
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Preferences")));
        QVERIFY(seen);
        QCOMPARE(window.session().preferences().units, LengthUnit::Inch);
        QCOMPARE(Preferences::load().units, LengthUnit::Inch);
        QCOMPARE(Preferences::load().autosaveSeconds, 20);
    }

    // New Job (Ctrl+N, above Open) asks to save, then starts an untitled job on the default post and machine.
    void newJobUsesTheDefaultPostAndMachine()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        Preferences p;
        p.defaultPostId = QStringLiteral("linuxcnc");
        p.defaultMachineId = QStringLiteral("hurco-vmx42sr");
        window.session().setPreferences(p);
        QAction* newJob = window.actions().action(QStringLiteral("Cam.File.New"));
        QVERIFY(newJob);
        QCOMPARE(newJob->shortcut(), QKeySequence(QKeySequence::New));
        const QStringList file = menuTexts(topMenu(window, QObject::tr("&File")));
        QVERIFY2(file.indexOf(newJob->text()) < file.indexOf(QObject::tr("&Open Job…")), qPrintable(file.join('|')));

        editWorkOffset(window);
        QVERIFY2(window.windowTitle().startsWith(QStringLiteral("job.camwb* — ")), qPrintable(window.windowTitle()));
        prompter->answers = {Prompter::Answer::Cancel};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.New")));
        QCOMPARE(window.workbench().job().workOffset, 2);  // Cancel: the job stays
        prompter->answers = {Prompter::Answer::Discard};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.New")));
        QCOMPARE(prompter->questions.size(), 2);
        const camwb::document::Job& job = window.workbench().job();
        QCOMPARE(job.postId, std::string("linuxcnc"));
        QCOMPARE(job.machineId, std::string("hurco-vmx42sr"));
        QVERIFY(job.operations.empty());
        QVERIFY(window.workbench().document().path().empty());
        QVERIFY(!window.workbench().document().isModified());
        QVERIFY(window.windowTitle().startsWith(QObject::tr("Untitled") + QStringLiteral(" — ")));
    }

    // Alt+1 … Alt+4 put the keyboard into the job tree, the task panel (when one is open), the NC
    // editor and the report; F2 then opens the selected operation from the tree.
    void keysReachTheJobTreeAndThePanels()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        auto focusedIn = [](QWidget* widget) {
            QWidget* focus = QApplication::focusWidget();
            return focus != nullptr && (focus == widget || widget->isAncestorOf(focus));
        };
        QCOMPARE(window.actions().action(QStringLiteral("Cam.View.GoToJobTree"))->shortcut(),
                 QKeySequence(Qt::ALT | Qt::Key_1));
        QTest::keyClick(&window, Qt::Key_1, Qt::AltModifier);
        QVERIFY(focusedIn(window.jobTree()));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.GoToTask")));  // none open: says so
        QVERIFY(focusedIn(window.jobTree()));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.GoToNc")));
        QVERIFY(focusedIn(window.ncEditor()));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.GoToReport")));
        QVERIFY(focusedIn(window.reportView()));

        window.editOperation(0);
        QVERIFY(window.taskPanel());
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.GoToJobTree")));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.GoToTask")));
        QVERIFY(focusedIn(window.taskPanel()));
        // Closed before the window goes: ~OperationPanel clears its preview in the 3D view.
        QVERIFY(window.settleTaskPanel());
    }

    // Translated, the window's own menu titles differ from English: the session's actions must
    // join those menus, not open an English "File" and "Edit" beside them.
    void sessionActionsJoinTheTranslatedMenus()
    {
        MenuTitleTranslator translator;
        QCoreApplication::installTranslator(&translator);
        QStringList titles;
        QMenu* file = nullptr;
        {
            MainWindow window;
            for (QAction* action : window.menuBar()->actions())
                titles << action->text();
            file = topMenu(window, QStringLiteral("&Fichier"));
            QVERIFY(file && file->actions().contains(window.actions().action(QStringLiteral("Cam.File.New"))));
            QMenu* edit = topMenu(window, QStringLiteral("É&dition"));
            QVERIFY(edit && edit->actions().contains(window.actions().action(QStringLiteral("Cam.Edit.Preferences"))));
        }
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(!titles.contains(QStringLiteral("&File")) && !titles.contains(QStringLiteral("&Edit")),
                 qPrintable(titles.join(QLatin1Char('|'))));
    }

    void recentFilesKeepTheNewestEightOnce()
    {
        camwb::gui::RecentFiles recent;
        for (int i = 0; i < 10; ++i)
            recent.add(QStringLiteral("/jobs/job%1.camwb").arg(i));
        recent.add(QStringLiteral("/jobs/job5.camwb"));
        const QStringList paths = recent.paths();
        QCOMPARE(paths.size(), camwb::gui::kMaxRecentFiles);
        QCOMPARE(paths.first(), QStringLiteral("/jobs/job5.camwb"));
        QCOMPARE(paths.count(QStringLiteral("/jobs/job5.camwb")), 1);
        QCOMPARE(paths.at(1), QStringLiteral("/jobs/job9.camwb"));
        QVERIFY(!paths.contains(QStringLiteral("/jobs/job1.camwb")));  // the oldest dropped out
    }

    // Opening and saving put a job at the front; a file gone since is greyed, and opening it says so.
    void openRecentListsJobsAndDropsAMissingOne()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        const QString job = dir.filePath(QStringLiteral("job.camwb"));
        camwb::gui::RecentFiles& recent = window.session().recentFiles();
        QCOMPARE(recent.paths(), QStringList{job});
        const QString gone = dir.filePath(QStringLiteral("gone.camwb"));
        QVERIFY(writeFile(gone, "{}"));
        recent.add(gone);
        QVERIFY(QFile::remove(gone));
        const QString other = dir.filePath(QStringLiteral("copy.camwb"));
        prompter->files = {other};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.SaveAs")));
        QCOMPARE(recent.paths(), (QStringList{other, gone, job}));

        auto* menu = window.findChild<QMenu*>(QStringLiteral("recentFilesMenu"));
        QVERIFY(menu);
        QVERIFY(menuTexts(topMenu(window, QObject::tr("&File"))).contains(menu->title()));
        recent.fill(menu);
        const QList<QAction*> entries = menu->actions();
        QVERIFY(entries.at(0)->isEnabled());
        QVERIFY(!entries.at(1)->isEnabled());
        QVERIFY(entries.at(1)->text().contains(QLatin1String("gone.camwb")));

        window.session().openRecent(gone);
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY(prompter->errors.last().contains(gone));
        QCOMPARE(recent.paths(), (QStringList{other, job}));
        QCOMPARE(QString::fromStdString(window.workbench().document().path()), other);  // nothing else opened
    }

    // While edits are unsaved the job is in its side file; a save removes it, as does undo to the saved state.
    void autosaveFollowsTheUnsavedEdits()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        window.session().autosaver().setDebounceMs(50);
        const QString job = dir.filePath(QStringLiteral("job.camwb"));
        const QString side = Autosaver::sidePathFor(job);
        editWorkOffset(window);
        QVERIFY(waitForFile(side));
        QCOMPARE(workOffsetOnDisk(side), 2);
        QCOMPARE(workOffsetOnDisk(job), 1);  // the job itself is not touched
        window.workbench().undo();
        QVERIFY(!QFile::exists(side));
        window.workbench().redo();
        QVERIFY(waitForFile(side));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.Save")));
        QVERIFY(!QFile::exists(side));
        QCOMPARE(workOffsetOnDisk(job), 2);
    }

    // An untitled job goes to the app data folder; a clean close (Discard) removes it.
    void untitledAutosaveGoesToAppDataUntilACleanClose()
    {
        auto window = std::make_unique<MainWindow>();
        ScriptedPrompter& prompter = scripted(*window);
        window->session().autosaver().setDebounceMs(50);
        QVERIFY(window->actions().trigger(QStringLiteral("Cam.File.New")));
        editWorkOffset(*window);
        const QString untitled = window->session().autosaver().sidePath();
        QVERIFY2(untitled.startsWith(Autosaver::untitledFolder() + QLatin1Char('/')), qPrintable(untitled));
        QVERIFY(untitled.startsWith(qEnvironmentVariable("XDG_DATA_HOME")));
        QVERIFY(waitForFile(untitled));
        QCOMPARE(workOffsetOnDisk(untitled), 2);
        QVERIFY(Autosaver::orphanedUntitled().isEmpty());  // this window's, not an orphan
        prompter.answers = {Prompter::Answer::Cancel};
        QVERIFY(!window->close());  // close asks to save; Cancel keeps the window and the side file
        QCOMPARE(prompter.questions.size(), 1);
        QVERIFY(QFile::exists(untitled));
        prompter.answers = {Prompter::Answer::Discard};
        QVERIFY(window->close());
        window.reset();
        QVERIFY(!QFile::exists(untitled));
    }

    // The process is killed after its autosave: the next start offers it (Cancel keeps it), and
    // opening the job recovers the edit, modified and with the job's own path.
    void recoveryAfterTheProcessIsKilled()
    {
        QTemporaryDir dir;
        const QString job = copyExample(dir);
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("--autosave-child"), job});
        QVERIFY(child.waitForStarted());
        QElapsedTimer waited;
        waited.start();
        while (!child.readAllStandardOutput().contains("autosaved") && waited.elapsed() < 120000 &&
               child.state() == QProcess::Running)
            child.waitForReadyRead(200);
        QCOMPARE(child.state(), QProcess::Running);
        const QString side = Autosaver::sidePathFor(job, child.processId());
        QVERIFY(QFile::exists(side));
        QVERIFY(Autosaver::newerAutosave(job).isEmpty());  // a running window's file is not a crash's
        child.kill();
        QVERIFY(child.waitForFinished());
        QCOMPARE(Autosaver::newerAutosave(job), side);
        QCOMPARE(workOffsetOnDisk(job), 1);

        {
            MainWindow window;
            ScriptedPrompter& prompter = scripted(window);
            window.session().offerRecoveryAtStart();  // the child put the job in the recent files
            QCOMPARE(prompter.questions.size(), 1);
            QVERIFY(prompter.questions.last().text.contains(QLatin1String("job.camwb")));
            QVERIFY(window.workbench().document().path().empty());  // Cancel: nothing opened
        }
        QVERIFY(QFile::exists(side));  // and nothing removed

        MainWindow window;
        ScriptedPrompter& prompter = scripted(window);
        prompter.answers = {Prompter::Answer::Accept};
        QVERIFY(openAndWait(window, job));
        QCOMPARE(prompter.questions.size(), 1);
        QCOMPARE(prompter.questions.last().acceptText, QObject::tr("Recover"));
        Workbench& wb = window.workbench();
        QCOMPARE(wb.job().workOffset, 2);
        QCOMPARE(QString::fromStdString(wb.document().path()), job);
        QVERIFY(wb.document().isModified());
        QVERIFY(window.windowTitle().startsWith(QLatin1String("job.camwb*")));
        QCOMPARE(workOffsetOnDisk(job), 1);
        wb.undo();  // what was saved
        QCOMPARE(wb.job().workOffset, 1);
        wb.redo();
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.Save")));
        QCOMPARE(workOffsetOnDisk(job), 2);
        QVERIFY(!QFile::exists(side));
    }

    void discardDeletesTheAutosave()
    {
        QTemporaryDir dir;
        const QString job = copyExample(dir);
        const QString side = crashedSidePath(job);
        QVERIFY(writeFile(side, readFile(job).toUtf8()));
        MainWindow window;
        ScriptedPrompter& prompter = scripted(window);
        prompter.answers = {Prompter::Answer::Discard};
        QVERIFY(openAndWait(window, job));
        QCOMPARE(prompter.questions.size(), 1);
        QVERIFY(!QFile::exists(side));
        QVERIFY(!window.workbench().document().isModified());
    }

    // An autosave that cannot be read: said so, kept as .corrupt, and the job opens as saved.
    void aCorruptAutosaveIsKeptAndTheJobOpens()
    {
        QTemporaryDir dir;
        const QString job = copyExample(dir);
        const QByteArray saved = readFile(job).toUtf8();
        const QString side = crashedSidePath(job);
        QVERIFY(writeFile(side, "{\"format\": \"camwb-job\", \"version\": 5, \"name\": "));
        MainWindow window;
        ScriptedPrompter& prompter = scripted(window);
        prompter.answers = {Prompter::Answer::Accept};
        QVERIFY(openAndWait(window, job));
        QCOMPARE(prompter.errors.size(), 1);
        QVERIFY2(prompter.errors.last().contains(QLatin1String("cannot be read")), qPrintable(prompter.errors.last()));
        QVERIFY(prompter.errors.last().contains(side));
        QVERIFY(!QFile::exists(side));
        QVERIFY(QFile::exists(side + QStringLiteral(".corrupt")));
        QCOMPARE(QString::fromStdString(window.workbench().document().path()), job);
        QCOMPARE(window.workbench().job().operations.size(), std::size_t{4});
        QVERIFY(!window.workbench().document().isModified());
        QCOMPARE(readFile(job).toUtf8(), saved);
    }
};

int main(int argc, char** argv)
{
    // A settings and app data folder of this run (the child inherits it): never the user's.
    QTemporaryDir home;
    if (!qEnvironmentVariableIsSet("CAMWB_SESSION_TEST_HOME")) {
        qputenv("CAMWB_SESSION_TEST_HOME", home.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toUtf8());
        qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toUtf8());
    }
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QLocale::setDefault(QLocale::c());  // lengths formatted with a decimal point
    if (argc == 3 && qstrcmp(argv[1], "--autosave-child") == 0)
        return runAutosaveChild(QString::fromLocal8Bit(argv[2]));
    QtTestRun run(argc, argv);
    SessionTest test;
    run.run(&test);
    return run.finish();
}

#include "SessionTest.moc"
