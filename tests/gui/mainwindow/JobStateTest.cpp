// The window never shows or saves what is not true about the job: a failed post marks the program
// out of date and Save NC refuses it; Import Model keeps the operations and asks before dropping
// any; a job whose model is missing shows nothing of the previous job; OK and New… do not lose
// or accept what they should not; the small things (Ctrl+Y, the toolbar, the docks, errors shown).
// Questions are answered by a ScriptedPrompter. Under Xvfb (GL) and offscreen (no GL).
// CAMWB_SHOTS_DIR=<dir> saves a picture of each state (Xvfb run).
#include "JobStateSupport.h"
#include "QtTestRun.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/JobTree.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PreviewRunner.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThreadPool>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>

using camwb::gui::MainWindow;
using camwb::gui::OperationPanel;
using camwb::gui::PreviewRunner;
using camwb::gui::Prompter;
using camwb::gui::Workbench;

class JobStateTest : public QObject {
    Q_OBJECT

private slots:
    // Closing the window while the job computes stops and waits for that work: left running it
    // outlived the application, whose exit then aborted in the post's script engine. The mould
    // job computes for half a minute; stopped, its worker is gone at once (the pool marks its
    // thread idle a moment after the work itself has returned, hence the short poll). Either the
    // stop or the wait alone passes this; only the time ~Workbench takes tells them apart.
    void aClosedWorkbenchLeavesNoWorkRunning()
    {
        QThreadPool* pool = QThreadPool::globalInstance();
        QTRY_COMPARE_WITH_TIMEOUT(pool->activeThreadCount(), 0, 60000);  // nothing from before
        {
            Workbench workbench;
            QVERIFY(workbench.openJob(QStringLiteral(CAMWB_MOULD_JOB)));
            QVERIFY(workbench.isBusy());  // loading its model and computing
        }
        QTRY_COMPARE_WITH_TIMEOUT(pool->activeThreadCount(), 0, 5000);
    }

    void failedPostIsMarkedAndCannotBeSaved()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        Workbench& wb = window.workbench();
        QVERIFY(wb.isProgramCurrent());
        QVERIFY(!banner(window, "ncBanner")->isVisibleTo(&window));
        const QString good = window.ncEditor()->text();
        QVERIFY(!good.isEmpty());

        QSignalSpy posted(&wb, &Workbench::postFinished);
        wb.updateOperation(0, tooDeep(window));
        // While the edit is computed the program is still the one before it: not saved either.
        const QString target = dir.filePath(QStringLiteral("out.mpf"));
        prompter->files = {target};
        QVERIFY(wb.isBusy());
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SaveNc")));
        QVERIFY(!QFile::exists(target));
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY(prompter->errors.last().contains(QLatin1String("being computed")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.last().first().toBool(), false);
        waitIdle(window);

        // Marked where the program is shown: the editor's banner and dock title, the view's banner.
        QVERIFY(!wb.isProgramCurrent());
        QVERIFY(wb.programProblem().contains(QLatin1String("cutting length")));
        QLabel* ncBanner = banner(window, "ncBanner");
        QLabel* viewBanner = banner(window, "viewBanner");
        QVERIFY(ncBanner && viewBanner);
        QVERIFY(ncBanner->isVisibleTo(&window));
        QVERIFY(viewBanner->isVisibleTo(&window));
        QVERIFY(ncBanner->text().contains(QLatin1String("Out of date")));
        QVERIFY(ncBanner->text().contains(QLatin1String("cutting length")));
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("ncDock"))
                    ->windowTitle()
                    .contains(QLatin1String("out of date")));
        // The failing operation is marked in the job tree with the reason.
        const QString name = QString::fromStdString(wb.job().operations[0].name());
        QVERIFY(problemOf(treeItem(window, name)).contains(QLatin1String("cutting length")));
        shot(window, "failed-post.png");

        // Save NC refuses it, says why and asks for no file name.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SaveNc")));
        QVERIFY(!QFile::exists(target));
        QVERIFY(prompter->fileTitles.isEmpty());
        QCOMPARE(prompter->errors.size(), 2);
        QVERIFY(prompter->errors.last().contains(QLatin1String("out of date")));

        // F9 says it failed where the user looks, not only in the report.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.Post")));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QCOMPARE(prompter->errors.size(), 3);
        QVERIFY(prompter->errors.last().contains(QLatin1String("cutting length")));

        // Undone: current again, the marks go, and Save NC writes the program.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(posted.wait(120000));
        QCOMPARE(posted.last().first().toBool(), true);
        waitIdle(window);
        QVERIFY(wb.isProgramCurrent());
        QVERIFY(!ncBanner->isVisibleTo(&window));
        QVERIFY(!viewBanner->isVisibleTo(&window));
        QVERIFY(problemOf(treeItem(window, name)).isEmpty());
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Job.SaveNc")));
        QCOMPARE(readFile(target), good);
    }

    void okIsRefusedForAnOperationThatCannotBeMade()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(openExample(window, dir, false));
        const std::string before = camwb::document::serializeJob(window.workbench().job());
        window.editOperation(0);
        OperationPanel* panel = window.taskPanel();
        QVERIFY(panel);
        QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
        panel->findChild<QCheckBox*>(QStringLiteral("finalAuto"))->setChecked(false);
        panel->findChild<QDoubleSpinBox*>(QStringLiteral("finalBox"))->setValue(-30.0);
        QVERIFY(finished.wait(120000));
        while (panel->preview().isPending() || panel->preview().isRunning())
            QVERIFY(finished.wait(120000));
        QVERIFY(!panel->preview().lastOutcome()->ok);

        panel->findChild<QAbstractButton*>(QStringLiteral("okButton"))->click();
        QCOMPARE(window.taskPanel(), panel);  // still open
        QVERIFY(panel->statusText().contains(QLatin1String("Not applied")));
        QVERIFY(panel->statusText().contains(QLatin1String("cutting length")));
        QCOMPARE(camwb::document::serializeJob(window.workbench().job()), before);
        panel->reject();
        QVERIFY(window.taskPanel() == nullptr);
    }

    void importingTheSameModelKeepsTheOperations()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        Workbench& wb = window.workbench();
        const auto operations = wb.job().operations;
        const std::size_t steps = wb.document().undoStack().count();

        prompter->files = {dir.filePath(QStringLiteral("example-block.step"))};
        QSignalSpy imported(&wb, &Workbench::modelImportFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.wait(120000));
        QCOMPARE(imported.first().first().toBool(), true);
        QVERIFY(prompter->questions.isEmpty());  // nothing lost, nothing to ask
        QCOMPARE(wb.job().operations.size(), operations.size());
        for (std::size_t i = 0; i < operations.size(); ++i) {
            QCOMPARE(wb.job().operations[i].geometry.faces, operations[i].geometry.faces);
            QCOMPARE(wb.job().operations[i].geometry.holes, operations[i].geometry.holes);
        }
        QCOMPARE(wb.document().undoStack().count(), steps + 1);
        waitIdle(window);
        QVERIFY(wb.isProgramCurrent());
    }

    void importingAnotherModelAsksBeforeDroppingAnything()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        Workbench& wb = window.workbench();
        const std::string original = camwb::document::serializeJob(wb.job());
        const std::size_t count = wb.job().operations.size();
        // A mesh: none of the operations' faces, edges and holes is in it.
        const QString stl = dir.filePath(QStringLiteral("wedge.stl"));
        QVERIFY(writeFile(stl, "solid wedge\nfacet normal 0 0 1\nouter loop\nvertex 0 0 20\nvertex 90 0 20\n"
                               "vertex 0 60 20\nendloop\nendfacet\nendsolid wedge\n"));
        QSignalSpy imported(&wb, &Workbench::modelImportFinished);

        // Cancel: the job stays as it was.
        prompter->files = {stl};
        prompter->answers = {Prompter::Answer::Cancel};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.wait(120000));
        QCOMPARE(imported.last().first().toBool(), false);
        QCOMPARE(prompter->questions.size(), 1);
        const QString asked = prompter->questions.last().text;
        QVERIFY2(asked.contains(QLatin1String("contour \"Outer contour\": face 2")), qPrintable(asked));
        QVERIFY2(asked.contains(QLatin1String("hole 21")), qPrintable(asked));
        QCOMPARE(camwb::document::serializeJob(wb.job()), original);

        // Keep: the operations stay without the lost references, marked; one undo step.
        prompter->files = {stl};
        prompter->answers = {Prompter::Answer::Accept};
        QSignalSpy posted(&wb, &Workbench::postFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.wait(120000));
        QCOMPARE(imported.last().first().toBool(), true);
        QCOMPARE(wb.job().operations.size(), count);
        QVERIFY(wb.job().operations[0].geometry.faces.empty());
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY(!wb.isProgramCurrent());
        const QString name = QString::fromStdString(wb.job().operations[0].name());
        QVERIFY(!problemOf(treeItem(window, name)).isEmpty());
        shot(window, "import-lost-references.png");
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(camwb::document::serializeJob(wb.job()), original);
        waitIdle(window);

        // Delete: the operations that lost references go (here all of them), after asking.
        prompter->files = {stl};
        prompter->answers = {Prompter::Answer::Discard};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.wait(120000));
        QCOMPARE(prompter->questions.size(), 3);
        QVERIFY(wb.job().operations.empty());
        waitIdle(window);
    }

    void aMissingModelLeavesNothingOfThePreviousJob()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        QVERIFY(window.view()->hasModelActor());
        QVERIFY(window.view()->hasToolpathActor());
        QVERIFY(!window.ncEditor()->text().isEmpty());

        Workbench& wb = window.workbench();
        QSignalSpy posted(&wb, &Workbench::postFinished);
        QVERIFY(window.openJob(copyExample(dir, QStringLiteral("missing-part.step"))));
        // At once, not when the load has failed: nothing of the previous job is left to see.
        QVERIFY(wb.model().empty());
        QVERIFY(!window.view()->hasModelActor());
        QVERIFY(window.ncEditor()->text().isEmpty());
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY(wb.model().empty());
        QVERIFY(!window.view()->hasModelActor());
        QVERIFY(!window.view()->hasToolpathActor());
        QVERIFY(window.ncEditor()->text().isEmpty());
        QVERIFY(wb.ncText().isEmpty());
        QVERIFY(!wb.isProgramCurrent());
        // The error is shown, and the operations are marked unresolved.
        QCOMPARE(prompter->errors.size(), 1);
        QVERIFY2(prompter->errors.first().contains(QLatin1String("missing-part.step")),
                 qPrintable(prompter->errors.first()));
        QVERIFY(!wb.job().operations.empty());
        const QString name = QString::fromStdString(wb.job().operations[0].name());
        QVERIFY(problemOf(treeItem(window, name)).contains(QLatin1String("unresolved")));
        QVERIFY(banner(window, "viewBanner")->isVisibleTo(&window));
        shot(window, "missing-model.png");

        // Nothing new is computed on the previous job's model.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewContour")));
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(prompter->errors.size(), 2);
        QVERIFY(prompter->errors.last().contains(QLatin1String("not loaded")));

        // The part found elsewhere: its numbers cannot be checked against a model never loaded,
        // so the user is asked; kept, the job computes again.
        QSignalSpy imported(&wb, &Workbench::modelImportFinished);
        prompter->files = {dir.filePath(QStringLiteral("example-block.step"))};
        prompter->answers = {Prompter::Answer::Accept};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.File.ImportModel")));
        QVERIFY(imported.wait(120000));
        QCOMPARE(prompter->questions.size(), 1);
        QVERIFY(prompter->questions.last().text.contains(QLatin1String("cannot be checked")));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY(wb.isProgramCurrent());
        QVERIFY(window.view()->hasModelActor());
        // Undone, the job names the missing file again: the imported model goes from the view.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY(wb.model().empty());
        QVERIFY(!window.view()->hasModelActor());
        QVERIFY(!wb.isProgramCurrent());
    }

    void newOperationAsksAboutUnappliedChanges()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir, false);
        QVERIFY(prompter);
        Workbench& wb = window.workbench();
        const std::size_t count = wb.job().operations.size();

        // Unchanged: replaced without a question.
        window.editOperation(0);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewPocket")));
        QVERIFY(prompter->questions.isEmpty());
        QCOMPARE(window.taskPanel()->operationIndex(), -1);

        window.editOperation(0);
        OperationPanel* edited = window.taskPanel();
        QCOMPARE(edited->operationIndex(), 0);
        edited->findChild<QLineEdit*>(QStringLiteral("nameEdit"))->setText(QStringLiteral("Renamed contour"));
        QVERIFY(edited->hasUnappliedChanges());

        // Cancel: the panel and its changes stay.
        prompter->answers = {Prompter::Answer::Cancel};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewPocket")));
        QCOMPARE(prompter->questions.size(), 1);
        QVERIFY(prompter->questions.last().acceptText.contains(QLatin1String("Apply")));
        QCOMPARE(window.taskPanel(), edited);

        // Discard: the new panel opens, the job is unchanged.
        prompter->answers = {Prompter::Answer::Discard};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewPocket")));
        QCOMPARE(window.taskPanel()->operationIndex(), -1);
        QVERIFY(wb.job().operations[0].name() != "Renamed contour");

        // Apply: the change is applied, then the next panel opens.
        window.editOperation(0);
        window.taskPanel()->findChild<QLineEdit*>(QStringLiteral("nameEdit"))->setText(QStringLiteral("Renamed"));
        prompter->answers = {Prompter::Answer::Accept};
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewDrill")));
        QCOMPARE(wb.job().operations[0].name(), std::string("Renamed"));
        QCOMPARE(wb.job().operations.size(), count);
        QCOMPARE(window.taskPanel()->operationIndex(), -1);
        window.taskPanel()->reject();
        waitIdle(window);
    }

    void unsavedJobAsksSaveDiscardCancel()
    {
        QTemporaryDir dir;
        MainWindow window;
        ScriptedPrompter* prompter = openExample(window, dir);
        QVERIFY(prompter);
        const QString job = QString::fromStdString(window.workbench().document().path());
        auto op = window.workbench().job().operations[0];
        op.setName("Saved name");
        window.workbench().updateOperation(0, op);
        waitIdle(window);

        prompter->answers = {Prompter::Answer::Cancel};
        QVERIFY(!window.close());
        QCOMPARE(prompter->questions.size(), 1);
        // Save and Discard are the standard buttons (empty texts), not Yes/No.
        QVERIFY(prompter->questions.last().acceptText.isEmpty());
        QVERIFY(prompter->questions.last().discardText.isEmpty());

        prompter->answers = {Prompter::Answer::Accept};
        QVERIFY(window.close());
        QVERIFY(readFile(job).contains(QLatin1String("Saved name")));
    }

    // The real dialog: Save, Discard and Cancel buttons.
    void dialogPrompterOffersSaveDiscardCancel()
    {
        QWidget parent;
        camwb::gui::DialogPrompter prompter(&parent);
        QList<QMessageBox::StandardButton> buttons;
        QTimer::singleShot(0, [&buttons] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (box == nullptr)
                return;
            for (QAbstractButton* b : box->buttons())
                buttons << box->standardButton(b);
            box->button(QMessageBox::Discard)->click();
        });
        QCOMPARE(prompter.ask({QStringLiteral("Unsaved changes"), QStringLiteral("Save?"), {}, {}}),
                 Prompter::Answer::Discard);
        QVERIFY(buttons.contains(QMessageBox::Save));
        QVERIFY(buttons.contains(QMessageBox::Discard));
        QVERIFY(buttons.contains(QMessageBox::Cancel));
        QVERIFY(!buttons.contains(QMessageBox::Yes));
    }

    void redoAnswersCtrlY()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(openExample(window, dir));
        QAction* redo = window.actions().action(QStringLiteral("Cam.Edit.Redo"));
        QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
        for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::Redo))
            QVERIFY(redo->shortcuts().contains(key));

        Workbench& wb = window.workbench();
        wb.removeOperation(0);
        const std::size_t count = wb.job().operations.size();
        wb.undo();
        QCOMPARE(wb.job().operations.size(), count + 1);
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(&window, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(wb.job().operations.size(), count);
        waitIdle(window);
    }

    void undoTextStaysOutOfTheToolbar()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(openExample(window, dir));
        auto* toolBar = window.findChild<QToolBar*>(QStringLiteral("mainToolBar"));
        QAction* undo = window.actions().action(QStringLiteral("Cam.Edit.Undo"));
        auto* button = qobject_cast<QToolButton*>(toolBar->widgetForAction(undo));
        QVERIFY(button);
        const int width = toolBar->sizeHint().width();

        auto op = window.workbench().job().operations[0];
        op.setName("A contour with a long name that would push the toolbar off the screen");
        window.workbench().updateOperation(0, op);
        QVERIFY(undo->text().contains(QLatin1String("long name")));     // the menu says what
        QVERIFY(undo->toolTip().contains(QLatin1String("long name")));  // and so does the tooltip
        QCOMPARE(button->text(), QStringLiteral("Undo"));
        QCOMPARE(toolBar->sizeHint().width(), width);
        waitIdle(window);
    }

    void closedDocksComeBackFromTheViewMenu()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QMenu* viewMenu = nullptr;
        for (QAction* menu : window.menuBar()->actions())
            if (menu->text() == QLatin1String("&View"))
                viewMenu = menu->menu();
        QVERIFY(viewMenu);
        for (const auto& [id, name] :
             {std::pair{"Cam.View.JobDock", "jobDock"}, std::pair{"Cam.View.NcDock", "ncDock"},
              std::pair{"Cam.View.InspectorDock", "modalDock"}, std::pair{"Cam.View.ReportDock", "reportDock"}}) {
            auto* dock = window.findChild<QDockWidget*>(QLatin1String(name));
            QAction* action = window.actions().action(QLatin1String(id));
            QVERIFY2(dock && action, id);
            QVERIFY(viewMenu->actions().contains(action));
            dock->close();
            QVERIFY(!dock->isVisible());
            QVERIFY(window.actions().trigger(QLatin1String(id)));
            QVERIFY2(dock->isVisible(), id);
        }
    }

    // The task dock lives as long as its panel, and only a panel's OK or Cancel closes it.
    void theTaskDockGoesWithItsPanel()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(openExample(window, dir));
        auto* taskDock = window.findChild<QDockWidget*>(QStringLiteral("taskDock"));
        QVERIFY(!taskDock->features().testFlag(QDockWidget::DockWidgetClosable));
        window.editOperation(0);
        QVERIFY(taskDock->isVisible());
        // Opening another job closes the panel of this one.
        QVERIFY(openAndWait(window, copyExample(dir)));
        QVERIFY(window.taskPanel() == nullptr);
        QVERIFY(!taskDock->isVisible());
        QVERIFY(!window.findChild<OperationPanel*>());
    }
};

// What needs the 3D view drawn (OpenGL): run by the Xvfb registration only.
class JobStateViewTest : public QObject {
    Q_OBJECT

private slots:
    // A face clicked in the 3D view is drawn green over the model (GL only: nothing is drawn
    // on the offscreen platform).
    void aPickedFaceIsHighlighted()
    {
        QTemporaryDir dir;
        MainWindow window;
        QVERIFY(openExample(window, dir));
        const QImage before = window.view()->grabImage();
        // A point of the top face away from the toolpath: between the pocket and the through hole.
        const auto at = window.view()->projectToWidget({58.0, 50.0, 15.0});
        QVERIFY(at);
        auto* gl = window.view()->findChild<QWidget*>(QStringLiteral("view3dGl"));
        QTest::mouseClick(gl, Qt::LeftButton, {}, gl->mapFrom(window.view(), at->toPoint()));
        QCOMPARE(window.view()->overlay().selectedFaces().size(), std::size_t(1));
        const QImage after = window.view()->grabImage();
        const QPoint pixel = gl->mapFrom(window.view(), at->toPoint()) * gl->devicePixelRatioF();
        const QColor was = before.pixelColor(pixel), now = after.pixelColor(pixel);
        qInfo("face pixel before %s, after %s", qPrintable(was.name()), qPrintable(now.name()));
        QVERIFY2(now.green() > now.red() + 40 && now.green() > now.blue() + 40, qPrintable(now.name()));
        QVERIFY(now != was);
        shot(window, "picked-face.png");
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    JobStateTest test;
    run.run(&test);
    JobStateViewTest view;
    if (withGl())
        run.run(&view);
    else
        run.notOnThisPlatform("JobStateViewTest", "the 3D view draws nothing without OpenGL");
    return run.finish();
}

#include "JobStateTest.moc"
