// The job tree on the example job in the real window: disabling an operation leaves its section
// out of the NC, moving (by action, drag and keys) reorders the NC's sections with one undo step
// each, duplicate and rename, the context menu of each kind of row, and a picture of the tree
// with a disabled operation and its menu (CAMWB_SHOTS_DIR keeps it).
#include "gui/shell/JobTree.h"
#include "QtTestRun.h"
#include "Shots.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/view3d/View3D.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QPainter>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using camwb::gui::JobTree;
using camwb::gui::MainWindow;
using camwb::gui::Workbench;
using Kind = JobTree::ItemKind;

namespace {

const QString kOuter = QStringLiteral("Outer contour");
const QString kPocket = QStringLiteral("Pocket with island");
const QString kHole = QStringLiteral("Through hole D10");
const QString kDrill = QStringLiteral("Four holes D5");

QString golden()
{
    QFile file(QStringLiteral(CAMWB_EXAMPLE_GOLDEN));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// The operations' sections of the posted program, by the comment the post writes at each start
// (without the parentheses a SINUMERIK comment cannot hold).
QStringList sections(const QString& nc, const camwb::document::Job& job)
{
    QStringList names, found;
    for (const auto& op : job.operations)
        names << QString::fromStdString(op.name()).remove(QLatin1Char('(')).remove(QLatin1Char(')'));
    static const QRegularExpression comment(QStringLiteral("^N\\d+ ;(.*)$"), QRegularExpression::MultilineOption);
    for (auto it = comment.globalMatch(nc); it.hasNext();) {
        const QString text = it.next().captured(1);
        if (names.contains(text))
            found << text;
    }
    return found;
}

QStringList jobOrder(const Workbench& wb)
{
    QStringList names;
    for (const auto& op : wb.job().operations)
        names << QString::fromStdString(op.name());
    return names;
}

QStringList idsOf(QMenu* menu)
{
    QStringList ids;
    for (QAction* a : menu->actions())
        if (!a->isSeparator())
            ids << a->objectName();
    return ids;
}

}  // namespace

class JobTreeTest : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> m_window;

    Workbench& wb() { return m_window->workbench(); }
    JobTree* tree() { return m_window->jobTree(); }
    std::size_t undoCount() { return wb().document().undoStack().count(); }

    // Waits until the edits are applied and the program of the job as it is now is posted.
    bool settle()
    {
        QSignalSpy posted(&wb(), &Workbench::postFinished);
        QTest::qWait(50);
        while (wb().isBusy())
            if (!posted.wait(120000))
                return false;
        return wb().isProgramCurrent();
    }

    QString nc() { return m_window->ncEditor()->text(); }

private slots:
    void init()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1400, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QSignalSpy posted(&wb(), &Workbench::postFinished);
        QVERIFY(m_window->openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(posted.wait(120000));
        QVERIFY(settle());
        QCOMPARE(sections(nc(), wb().job()), (QStringList{kOuter, kPocket, kHole, kDrill}));
    }

    void cleanup() { m_window.reset(); }

    void disabledOperationIsNotPostedAndComesBack()
    {
        const std::size_t steps = undoCount();
        // The check box in the row: the pocket (T2) off, so the helix must change to T2 itself.
        tree()->operationItem(1)->setCheckState(0, Qt::Unchecked);
        QTRY_VERIFY(!wb().job().operations[1].enabled);  // applied after the item's signal
        QVERIFY(settle());
        QCOMPARE(undoCount(), steps + 1);
        QCOMPARE(QString::fromStdString(wb().document().undoStack().undoText()), QStringLiteral("Disable ") + kPocket);
        QCOMPARE(sections(nc(), wb().job()), (QStringList{kOuter, kHole, kDrill}));
        QVERIFY(nc().contains(QStringLiteral("M6 T2")));
        QTreeWidgetItem* item = tree()->operationItem(1);
        QCOMPARE(item->checkState(0), Qt::Unchecked);
        QVERIFY2(item->text(1).startsWith(QStringLiteral("(disabled)")), qPrintable(item->text(1)));
        QCOMPARE(tree()->selectedOperation(), 1);
        // The operations after it keep their rows, problems and times.
        QVERIFY(wb().operationSeconds(2) > 0);
        QVERIFY(wb().operationSeconds(1) < 0);
        QVERIFY2(tree()->operationItem(2)->text(1).contains(QLatin1Char(':')) ||
                     tree()->operationItem(2)->text(1).contains(QStringLiteral(" s")),
                 qPrintable(tree()->operationItem(2)->text(1)));

        // Re-enabled through the action: the program is the golden again.
        QCOMPARE(m_window->actions().action(QStringLiteral("Cam.Op.ToggleEnabled"))->text(),
                 QStringLiteral("&Enable Operation"));
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Op.ToggleEnabled")));
        QVERIFY(settle());
        QVERIFY(wb().job().operations[1].enabled);
        QCOMPARE(nc(), golden());
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(settle());
        QVERIFY(!wb().job().operations[1].enabled);
    }

    void moveByActionReordersTheProgram()
    {
        const std::size_t steps = undoCount();
        tree()->selectOperation(3);
        QVERIFY(!m_window->actions().action(QStringLiteral("Cam.Op.MoveDown"))->isEnabled());
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Op.MoveUp")));
        QVERIFY(settle());
        QCOMPARE(undoCount(), steps + 1);
        QCOMPARE(jobOrder(wb()), (QStringList{kOuter, kPocket, kDrill, kHole}));
        QCOMPARE(sections(nc(), wb().job()), (QStringList{kOuter, kPocket, kDrill, kHole}));
        QCOMPARE(tree()->selectedOperation(), 2);  // the moved operation stays selected
        // T2, T3, then T2 again: the tool changes follow the new order.
        QCOMPARE(nc().count(QStringLiteral("M6 T2")), 2);
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(settle());
        QCOMPARE(nc(), golden());
    }

    void dragReordersTheProgram()
    {
        const std::size_t steps = undoCount();
        tree()->selectOperation(0);
        tree()->scrollToItem(tree()->operationItem(2));
        // Dropped on the lower half of the helix's row: after it.
        const QRect target = tree()->visualItemRect(tree()->operationItem(2));
        const QPoint at(target.center().x(), target.center().y() + target.height() / 4);
        // What the view's drop does at the end of a drag (a real drag needs the platform's).
        QVERIFY(tree()->dropSelectedOperationAt(at));
        QVERIFY(settle());
        QCOMPARE(undoCount(), steps + 1);
        QCOMPARE(jobOrder(wb()), (QStringList{kPocket, kHole, kOuter, kDrill}));
        QCOMPARE(sections(nc(), wb().job()), (QStringList{kPocket, kHole, kOuter, kDrill}));
        QCOMPARE(tree()->selectedOperation(), 2);
        QCOMPARE(tree()->operationItem(2)->text(0), kOuter);
        // The program starts with T2 now, and T1 comes after the helix.
        const QString program = nc();
        QVERIFY(program.indexOf(QStringLiteral("M6 T2")) < program.indexOf(QStringLiteral("M6 T1")));

        // A drop outside the operations, or where it is, moves nothing.
        QVERIFY(!tree()->dropSelectedOperationAt(tree()->visualItemRect(tree()->itemOf(Kind::Stock)).center()));
        QVERIFY(!tree()->dropSelectedOperationAt(tree()->visualItemRect(tree()->operationItem(2)).center()));
        QCOMPARE(undoCount(), steps + 1);
    }

    void duplicateAndRenameAreUndoable()
    {
        const std::size_t steps = undoCount();
        tree()->selectOperation(0);
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Op.Duplicate")));
        QVERIFY(settle());
        QCOMPARE(jobOrder(wb()), (QStringList{kOuter, kOuter + QStringLiteral(" (copy)"), kPocket, kHole, kDrill}));
        QCOMPARE(tree()->selectedOperation(), 1);
        QCOMPARE(sections(nc(), wb().job()).size(), 5);

        // The name editor closes when it loses the focus, as in an inactive window.
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Op.Rename")));
        auto* editor = tree()->viewport()->findChild<QLineEdit*>();
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("Finish contour"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(wb().job().operations[1].name(), std::string("Finish contour"));  // applied after the editor
        QVERIFY(settle());
        QCOMPARE(tree()->operationItem(1)->text(0), QStringLiteral("Finish contour"));
        QVERIFY(nc().contains(QStringLiteral(";Finish contour")));
        QCOMPARE(undoCount(), steps + 2);
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(wb().job().operations[1].name(), kOuter.toStdString() + " (copy)");
        QVERIFY(m_window->actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QVERIFY(settle());
        QCOMPARE(nc(), golden());
    }

    void contextMenusOfferEachKindsActions()
    {
        camwb::gui::ActionRegistry& actions = m_window->actions();
        auto menuIds = [&](Kind kind) {
            std::unique_ptr<QMenu> menu(tree()->contextMenuFor(tree()->itemOf(kind)));
            return idsOf(menu.get());
        };
        QCOMPARE(menuIds(Kind::Operation),
                 (QStringList{"Cam.Op.Edit", "Cam.Op.ToggleEnabled", "Cam.Op.Duplicate", "Cam.Op.Rename",
                              "Cam.Op.MoveUp", "Cam.Op.MoveDown", "Cam.Op.Delete"}));
        QCOMPARE(menuIds(Kind::Operations),
                 (QStringList{"Cam.Op.NewContour", "Cam.Op.NewPocket", "Cam.Op.NewHelix", "Cam.Op.NewDrill",
                              "Cam.Op.NewSwarf", "Cam.Op.NewPocket3d", "Cam.Op.NewWaterline", "Cam.Op.NewParallel",
                              "Cam.Op.NewGroove"}));
        // The setup's actions come from other parts: offered exactly when registered.
        auto expected = [&](const char* id) {
            return actions.action(QLatin1String(id)) ? QStringList{QLatin1String(id)} : QStringList{};
        };
        QCOMPARE(menuIds(Kind::Tools), expected("Cam.Tools.Library"));
        QCOMPARE(menuIds(Kind::Tool), expected("Cam.Tools.Library"));
        for (Kind kind : {Kind::Stock, Kind::Wcs, Kind::Machine})
            QCOMPARE(menuIds(kind), expected("Cam.Job.Setup"));
        QCOMPARE(menuIds(Kind::Model), expected("Cam.Job.Setup") + QStringList{"Cam.File.ImportModel"});
        QCOMPARE(menuIds(Kind::Post), expected("Cam.Job.PostSettings"));

        // Enter on a setup row asks for its panel, routed to the action by id.
        QSignalSpy setupAsked(tree(), &JobTree::editJobSetupRequested);
        QSignalSpy postAsked(tree(), &JobTree::editPostRequested);
        QAction* setup = actions.action(QStringLiteral("Cam.Job.Setup"));
        const bool stand = setup == nullptr;  // a stand-in where the setup panel is not there yet
        if (stand)
            setup = actions.add({QStringLiteral("Cam.Job.Setup"), QStringLiteral("Setup"), {}});
        QSignalSpy setupTriggered(setup, &QAction::triggered);
        if (!stand)
            setupTriggered.clear();
        tree()->setCurrentItem(tree()->itemOf(Kind::Stock));
        tree()->setFocus();
        QTest::keyClick(tree(), Qt::Key_Return);
        QCOMPARE(setupAsked.size(), 1);
        if (stand)
            QCOMPARE(setupTriggered.size(), 1);
        tree()->setCurrentItem(tree()->itemOf(Kind::Post));
        QTest::keyClick(tree(), Qt::Key_Return);
        QCOMPARE(postAsked.size(), 1);
        QCOMPARE(menuIds(Kind::Stock), QStringList{"Cam.Job.Setup"});
    }

    void keyboardTogglesMovesEditsAndDeletes()
    {
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        tree()->setFocus();
        tree()->selectOperation(1);
        QTest::keyClick(tree(), Qt::Key_Space);
        QVERIFY(settle());
        QVERIFY(!wb().job().operations[1].enabled);
        QTest::keyClick(tree(), Qt::Key_Space);
        QVERIFY(settle());
        QVERIFY(wb().job().operations[1].enabled);

        QTest::keyClick(tree(), Qt::Key_Down, Qt::ControlModifier);
        QVERIFY(settle());
        QCOMPARE(jobOrder(wb()), (QStringList{kOuter, kHole, kPocket, kDrill}));
        QCOMPARE(tree()->selectedOperation(), 2);
        QTest::keyClick(tree(), Qt::Key_Up, Qt::ControlModifier);
        QVERIFY(settle());
        QCOMPARE(nc(), golden());
        QCOMPARE(tree()->selectedOperation(), 1);

        QTest::keyClick(tree(), Qt::Key_Return);
        QVERIFY(m_window->taskPanel());
        m_window->taskPanel()->reject();
        QTRY_VERIFY(m_window->taskPanel() == nullptr);

        tree()->setFocus();
        tree()->selectOperation(1);
        QTest::keyClick(tree(), Qt::Key_Delete);
        QVERIFY(settle());
        QCOMPARE(jobOrder(wb()), (QStringList{kOuter, kHole, kDrill}));
    }

    void screenshotOfADisabledOperationAndItsMenu()
    {
        tree()->operationItem(1)->setCheckState(0, Qt::Unchecked);
        QTRY_VERIFY(!wb().job().operations[1].enabled);
        QVERIFY(settle());
        tree()->selectOperation(1);
        QWidget* dock = tree()->parentWidget();
        while (dock && !dock->inherits("QDockWidget"))
            dock = dock->parentWidget();
        QVERIFY(dock);
        auto* dockWidget = static_cast<QDockWidget*>(dock);
        dockWidget->setFloating(true);  // the whole tree in one picture, whatever the window's layout
        dockWidget->resize(620, 640);
        tree()->resizeColumnToContents(1);
        tree()->scrollToTop();
        tree()->selectOperation(0);  // the disabled row shows greyed, not highlighted
        saveShot(dock, QStringLiteral("jobtree.png"));

        // The tree with the operation's context menu beside the row, as one picture.
        std::unique_ptr<QMenu> menu(tree()->contextMenuFor(tree()->operationItem(1)));
        const QRect row = tree()->visualItemRect(tree()->operationItem(1));
        menu->popup(tree()->viewport()->mapToGlobal(row.center()));
        QVERIFY(QTest::qWaitForWindowExposed(menu.get()));
        QTest::qWait(100);
        const QImage treeImage = dock->grab().toImage();
        const QImage menuImage = menu->grab().toImage();
        const QPoint offset = tree()->viewport()->mapTo(dock, row.center());
        QImage picture(std::max(treeImage.width(), offset.x() + menuImage.width()),
                       std::max(treeImage.height(), offset.y() + menuImage.height()), QImage::Format_RGB32);
        picture.fill(Qt::white);
        QPainter painter(&picture);
        painter.drawImage(0, 0, treeImage);
        painter.drawImage(offset, menuImage);
        painter.end();
        QVERIFY(showsSomething(menuImage));
        QVERIFY(picture.save(shotsDir() + QStringLiteral("/jobtree-menu.png")));
        menu->close();
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    JobTreeTest test;
    run.run(&test);
    return run.finish();
}

#include "JobTreeTest.moc"
