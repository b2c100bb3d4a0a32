// camwb: the CAM Workbench desktop application.
//   camwb [job.camwb | program | CL file] [--screenshot file.png [--grab-screen]] [--edit-operation N]
//   | --help | --version
// --screenshot grabs the main window once the job is posted (a program or CL file: traced),
// writes the PNG and quits
// (used for the README picture and for checking the window without a person at it);
// --grab-screen grabs the whole screen instead (what a person sees, menus and docks included).
// --edit-operation opens the task panel of operation N (1-based) once the job is posted; with
// --screenshot the picture waits for the panel's preview.
#include "camwb_version.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Session.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PreviewRunner.h"
#include "gui/view3d/View3D.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QPixmap>
#include <QScreen>
#include <QTimer>
#include <QTranslator>

#include <clocale>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

struct Options {
    QCommandLineOption screenshot{QStringLiteral("screenshot"),
                                  QStringLiteral("Write a PNG of the window once the job is posted, then quit."),
                                  QStringLiteral("file")};
    QCommandLineOption grabScreen{QStringLiteral("grab-screen"),
                                  QStringLiteral("With --screenshot: grab the whole screen, not the window.")};
    QCommandLineOption editOperation{QStringLiteral("edit-operation"),
                                     QStringLiteral("Open the task panel of operation N (1-based) once posted."),
                                     QStringLiteral("N")};
};

// The application's identity, its translations (Qt's own texts such as the help's "Usage:", and
// ours) and its command line, the same for the help and for a run. Made after the application.
struct CommandLine {
    Options options;
    QCommandLineParser parser;
    QTranslator qtTranslator;
    QTranslator appTranslator;

    // Exits the process for --help, --version and a wrong option.
    void process(QCoreApplication& application)
    {
        QCoreApplication::setApplicationName(QStringLiteral("CAM Workbench"));
        QCoreApplication::setApplicationVersion(QStringLiteral(CAMWB_VERSION));
        QCoreApplication::setOrganizationName(QStringLiteral("camwb"));
        // The language of the preferences (System: the user's locale); a change applies at the next start.
        const QLocale locale = camwb::gui::uiLocale(camwb::gui::Preferences::load().language);
        QLocale::setDefault(locale);
        if (qtTranslator.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                              QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            QCoreApplication::installTranslator(&qtTranslator);
        if (appTranslator.load(locale, QStringLiteral("camwb"), QStringLiteral("_"), QStringLiteral(":/i18n")))
            QCoreApplication::installTranslator(&appTranslator);
        parser.setApplicationDescription(QStringLiteral("CAM and post-processor workbench"));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addPositionalArgument(QStringLiteral("job"),
                                     QStringLiteral("Job file (.camwb), NC program or CL file to open."));
        parser.addOption(options.screenshot);
        parser.addOption(options.grabScreen);
        parser.addOption(options.editOperation);
        parser.process(application);
    }
};

// --help and --version need no display: they are answered by a QCoreApplication, before the
// QApplication would load a platform plugin (and abort where there is no X or Wayland server).
bool asksForHelpOrVersion(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        for (const char* option : {"-h", "--help", "-?", "--help-all", "-v", "--version"})
            if (std::strcmp(argv[i], option) == 0)
                return true;
    return false;
}

int printHelpOrVersion(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    CommandLine commandLine;
    commandLine.process(app);  // prints the help or the version and exits
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (asksForHelpOrVersion(argc, argv))
        return printHelpOrVersion(argc, argv);
    camwb::gui::View3D::setDefaultSurfaceFormat();  // before QApplication: VTK needs a core profile
    QApplication app(argc, argv);
    // Qt has set the C library's locale from the environment; under de_DE printf writes 1.5 as
    // "1,5" and strtod stops at the point. Our kernels format and read numbers without the locale,
    // but OCCT, VTK and QScintilla run in this process too: their numbers stay as written. Qt's own
    // texts follow QLocale, not this.
    std::setlocale(LC_NUMERIC, "C");
    CommandLine commandLine;
    commandLine.process(app);
    const QCommandLineParser& parser = commandLine.parser;
    const QCommandLineOption& screenshot = commandLine.options.screenshot;
    const QCommandLineOption& grabScreen = commandLine.options.grabScreen;
    const QCommandLineOption& editOperation = commandLine.options.editOperation;

    camwb::gui::MainWindow window;
    window.show();
    const QStringList jobs = parser.positionalArguments();
    if (!jobs.isEmpty())
        window.openJob(jobs.first());    // offers to recover its autosave when there is a newer one
    else if (!parser.isSet(screenshot))  // a picture taken unattended must not wait for an answer
        window.session().offerRecoveryAtStart();

    const int operation = parser.value(editOperation).toInt();
    if (operation > 0) {
        auto open = std::make_shared<QMetaObject::Connection>();
        *open = QObject::connect(&window.workbench(), &camwb::gui::Workbench::postFinished, &window,
                                 [&window, open, operation] {
                                     QObject::disconnect(*open);
                                     window.editOperation(operation - 1);
                                 });
    }

    if (parser.isSet(screenshot)) {
        const QString file = parser.value(screenshot);
        const bool wholeScreen = parser.isSet(grabScreen);
        auto grabAndQuit = [&window, file, wholeScreen] {
            // Let the view render its first frames before grabbing.
            QTimer::singleShot(800, &window, [&window, file, wholeScreen] {
                const QPixmap picture = wholeScreen ? window.screen()->grabWindow(0) : window.grab();
                const bool saved = picture.save(file);
                std::fprintf(stderr, saved ? "camwb: screenshot written to %s\n" : "camwb: cannot write %s\n",
                             qPrintable(file));
                QApplication::exit(saved ? 0 : 1);
            });
        };
        if (jobs.isEmpty()) {
            grabAndQuit();
        } else if (!jobs.first().endsWith(QLatin1String(".camwb"), Qt::CaseInsensitive)) {
            // An NC program or a CL file: nothing is posted; the picture waits for its trace.
            auto traced = std::make_shared<QMetaObject::Connection>();
            *traced = QObject::connect(window.inspector(), &camwb::gui::NcInspector::traceFinished, &window,
                                       [traced, grabAndQuit] {
                                           QObject::disconnect(*traced);
                                           grabAndQuit();
                                       });
        } else {
            auto posted = std::make_shared<QMetaObject::Connection>();
            *posted = QObject::connect(&window.workbench(), &camwb::gui::Workbench::postFinished, &window,
                                       [&window, posted, operation, grabAndQuit] {
                                           QObject::disconnect(*posted);
                                           camwb::gui::OperationPanel* panel = window.taskPanel();
                                           if (operation > 0 && panel != nullptr)
                                               QObject::connect(&panel->preview(), &camwb::gui::PreviewRunner::finished,
                                                                &window, grabAndQuit);
                                           else
                                               grabAndQuit();
                                       });
        }
    }
    return app.exec();
}
