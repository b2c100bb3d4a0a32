// camwb: the CAM Workbench desktop application.
//   camwb [job.camwb] [--screenshot file.png [--grab-screen]] [--edit-operation N]
// --screenshot grabs the main window once the job is posted, writes the PNG and quits
// (used for the README picture and for checking the window without a person at it);
// --grab-screen grabs the whole screen instead (what a person sees, menus and docks included).
// --edit-operation opens the task panel of operation N (1-based) once the job is posted; with
// --screenshot the picture waits for the panel's preview.
#include "camwb_version.h"
#include "gui/shell/MainWindow.h"
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

#include <cstdio>
#include <memory>

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();  // before QApplication: VTK needs a core profile
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("CAM Workbench"));
    QApplication::setApplicationVersion(QStringLiteral(CAMWB_VERSION));
    QApplication::setOrganizationName(QStringLiteral("camwb"));

    QTranslator qtTranslator, appTranslator;
    if (qtTranslator.load(QLocale(), QStringLiteral("qtbase"), QStringLiteral("_"),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    if (appTranslator.load(QLocale(), QStringLiteral("camwb"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QApplication::installTranslator(&appTranslator);

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CAM and post-processor workbench"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("job"), QStringLiteral("Job file (.camwb) to open."));
    QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                  QStringLiteral("Write a PNG of the window once the job is posted, then quit."),
                                  QStringLiteral("file"));
    parser.addOption(screenshot);
    QCommandLineOption grabScreen(QStringLiteral("grab-screen"),
                                  QStringLiteral("With --screenshot: grab the whole screen, not the window."));
    parser.addOption(grabScreen);
    QCommandLineOption editOperation(QStringLiteral("edit-operation"),
                                     QStringLiteral("Open the task panel of operation N (1-based) once posted."),
                                     QStringLiteral("N"));
    parser.addOption(editOperation);
    parser.process(app);

    camwb::gui::MainWindow window;
    window.show();
    const QStringList jobs = parser.positionalArguments();
    if (!jobs.isEmpty())
        window.openJob(jobs.first());

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
