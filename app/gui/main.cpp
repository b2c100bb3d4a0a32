// camwb: the CAM Workbench desktop application.
//   camwb [job.camwb] [--screenshot file.png]
// --screenshot grabs the main window once the job is posted, writes the PNG and quits
// (used for the README picture and for checking the window without a person at it).
#include "camwb_version.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/view3d/View3D.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

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
    parser.process(app);

    camwb::gui::MainWindow window;
    window.show();
    const QStringList jobs = parser.positionalArguments();
    if (!jobs.isEmpty())
        window.openJob(jobs.first());

    if (parser.isSet(screenshot)) {
        const QString file = parser.value(screenshot);
        auto grabAndQuit = [&window, file] {
            // Let the view render its first frames before grabbing.
            QTimer::singleShot(500, &window, [&window, file] {
                const bool saved = window.grab().save(file);
                std::fprintf(stderr, saved ? "camwb: screenshot written to %s\n" : "camwb: cannot write %s\n",
                             qPrintable(file));
                QApplication::exit(saved ? 0 : 1);
            });
        };
        if (jobs.isEmpty())
            grabAndQuit();
        else
            QObject::connect(&window.workbench(), &camwb::gui::Workbench::postFinished, &window, grabAndQuit);
    }
    return app.exec();
}
