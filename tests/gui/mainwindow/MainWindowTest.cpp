// Drives the real main window: opens the example job, posts through the action registry and
// checks the editor dock, the 3D view and undo. Runs twice: under Xvfb (GL) and offscreen (no GL).
#include "gui/shell/MainWindow.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/ProfileDialog.h"
#include "gui/shell/Workbench.h"
#include "gui/view3d/View3D.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGuiApplication>
#include <QLabel>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTest>

using camwb::gui::MainWindow;
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

private slots:
    void actionsHaveStableIdsAndMenus()
    {
        MainWindow window;
        const QStringList ids = window.actions().ids();
        for (const char* id :
             {"Cam.File.Open", "Cam.File.Save", "Cam.File.ImportModel", "Cam.Edit.Undo", "Cam.Op.NewProfile",
              "Cam.Job.Post", "Cam.Job.SaveNc", "Cam.View.Isometric", "Cam.View.FitAll"})
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
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewProfile")));
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
        camwb::gui::ProfileDialog dialog(wb.job().operations[0], wb.job(), wb.model(), &window);
        auto* faces = dialog.findChild<QComboBox*>(QStringLiteral("faceCombo"));
        QVERIFY(faces);
        QVERIFY(faces->count() >= 3);  // top, pocket floor, bottom: the horizontal faces only
        QCOMPARE(faces->currentData().toInt(), wb.job().operations[0].profile.faceIndex);
        auto* depth = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("finalDepthBox"));
        QVERIFY(depth);
        depth->setValue(8.0);
        if (withGl())
            dialog.grab().save(QStringLiteral(CAMWB_SCREENSHOT_DIR "/profiledialog.png"));

        QSignalSpy posted(&wb, &Workbench::postFinished);
        wb.updateOperation(0, dialog.operation());
        QVERIFY(posted.wait(120000));
        QVERIFY(window.ncEditor()->text().contains(QLatin1String("G1 Z8.000 F150")));
        QVERIFY(window.windowTitle().contains(QLatin1Char('*')));

        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(posted.wait(120000));
        QVERIFY(window.ncEditor()->text().contains(QLatin1String("G1 Z10.000 F150")));
        QCOMPARE(window.workbench().job().operations[0].profile.finalDepthZ, 10.0);
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

    void withoutOpenGlTheViewSaysSo()
    {
        if (withGl())
            QSKIP("runs on the offscreen platform only");
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
};

int main(int argc, char** argv)
{
    View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    MainWindowTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "MainWindowTest.moc"
