// The display unit (Edit > Preferences > Units) on what the window shows: with inch, the job
// tree's lengths are in inch, an operation panel's and the job setup panel's spin boxes show
// their mm values in inch ("0.2362 in" for 6 mm) and what the user types in inch is stored in mm
// (1 in -> 25.4 mm); the job stays in mm. Back to mm, the same rows read mm. Under Xvfb and
// offscreen.
#include "QtTestRun.h"
#include "document/JobFile.h"
#include "gui/shell/JobTree.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Session.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/JobSetupPanel.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tools/ToolModels.h"
#include "gui/view3d/View3D.h"
#include "ops/ContourOp.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidgetItem>

#include <cmath>
#include <memory>

using camwb::document::OperationKind;
using camwb::gui::JobTree;
using camwb::gui::LengthUnit;
using camwb::gui::MainWindow;
using camwb::gui::OperationPanel;
using camwb::gui::Workbench;

namespace {

void waitIdle(MainWindow& window)
{
    QElapsedTimer waited;
    waited.start();
    while (window.workbench().isBusy() && waited.elapsed() < 120000)
        QTest::qWait(20);
}

void setUnit(MainWindow& window, LengthUnit unit)
{
    camwb::gui::Preferences preferences = window.session().preferences();
    preferences.units = unit;
    window.session().setPreferences(preferences);
}

QString treeText(MainWindow& window, JobTree::ItemKind kind, int child = -1)
{
    QTreeWidgetItem* item = window.jobTree()->itemOf(kind);
    if (item != nullptr && child >= 0)
        item = item->child(child);
    return item != nullptr ? item->text(1) : QString();
}

int contourIndex(MainWindow& window)
{
    const auto& operations = window.workbench().job().operations;
    for (std::size_t i = 0; i < operations.size(); ++i)
        if (operations[i].kind() == OperationKind::Contour)
            return static_cast<int>(i);
    return -1;
}

// Types `text` into `box` as the user does (select all, type, Enter).
void type(QDoubleSpinBox* box, const QString& text)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

}  // namespace

// The example job open and posted in a shown window.
bool showExample(MainWindow& window)
{
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
    if (!window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)) || !posted.wait(120000))
        return false;
    waitIdle(window);
    return true;
}

class UnitsTest : public QObject {
    Q_OBJECT

private slots:
    void inchInTheTreeAndThePanels()
    {
        MainWindow window;
        QVERIFY(showExample(window));
        setUnit(window, LengthUnit::Millimetre);  // whatever an earlier run left in the settings
        QCOMPARE(treeText(window, JobTree::ItemKind::Stock), QStringLiteral("box 94.000 × 64.000 × 16.000 mm"));

        setUnit(window, LengthUnit::Inch);
        // A failure below must not leave inch in this test's settings for the next run.
        const std::unique_ptr<MainWindow, void (*)(MainWindow*)> backToMm(
            &window, [](MainWindow* w) { setUnit(*w, LengthUnit::Millimetre); });
        QCOMPARE(camwb::gui::displayUnit(), LengthUnit::Inch);
        // The example's stock is 94 × 64 × 16 mm from (−2, −2, 0).
        QCOMPARE(treeText(window, JobTree::ItemKind::Stock), QStringLiteral("box 3.7008 × 2.5197 × 0.6299 in"));
        QCOMPARE(treeText(window, JobTree::ItemKind::Stock, 0), QStringLiteral("-0.0787, -0.0787, 0.0000 in"));
        bool d6 = false;
        QTreeWidgetItem* tools = window.jobTree()->itemOf(JobTree::ItemKind::Tools);
        for (int i = 0; tools != nullptr && i < tools->childCount(); ++i)
            d6 = d6 || tools->child(i)->text(1).contains(QStringLiteral("Flat end mill D6, Ø0.2362 in"));
        QVERIFY2(d6, "the D6 tool is not shown in inch");

        const int index = contourIndex(window);
        QVERIFY(index >= 0);
        window.editOperation(index);
        OperationPanel* panel = window.taskPanel();
        QVERIFY(panel);
        // The geometry list describes the contour's faces and edges in inch too.
        auto* geometry = panel->findChild<QListWidget*>(QStringLiteral("geometryList"));
        QVERIFY(geometry && geometry->count() > 0);
        for (int i = 0; i < geometry->count(); ++i) {
            const QString text = geometry->item(i)->text();
            QVERIFY2(!text.contains(QStringLiteral("mm")), qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral(" in")), qPrintable(text));
        }
        auto* stepDown = panel->findChild<QDoubleSpinBox*>(QStringLiteral("stepDownBox"));
        QVERIFY(stepDown);
        QCOMPARE(stepDown->suffix(), QStringLiteral(" in"));
        QCOMPARE(stepDown->value(), 3.0);  // the value stays in mm
        QCOMPARE(stepDown->text(), QStringLiteral("0.1181 in"));
        stepDown->setValue(6.0);
        QCOMPARE(stepDown->text(), QStringLiteral("0.2362 in"));
        type(stepDown, QStringLiteral("1"));
        QCOMPARE(stepDown->value(), 25.4);
        QCOMPARE(std::get<camwb::ops::ContourParams>(panel->operation().params).stepDownMm, 25.4);
        QCOMPARE(stepDown->text(), QStringLiteral("1.0000 in"));
        type(stepDown, QStringLiteral("0.0625"));  // four decimals in inch are kept (1/16 in)
        QCOMPARE(std::get<camwb::ops::ContourParams>(panel->operation().params).stepDownMm, 1.5875);
        type(stepDown, QStringLiteral("0.125"));
        QCOMPARE(std::get<camwb::ops::ContourParams>(panel->operation().params).stepDownMm, 3.175);
        auto* safe = panel->findChild<QDoubleSpinBox*>(QStringLiteral("safeBox"));  // the heights box
        QVERIFY(safe);
        QCOMPARE(safe->suffix(), QStringLiteral(" in"));
        // OK: the job holds mm.
        const std::size_t undoSteps = window.workbench().document().undoStack().count();
        QVERIFY(panel->accept());
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        const auto& params = std::get<camwb::ops::ContourParams>(window.workbench().job().operations[index].params);
        QCOMPARE(params.stepDownMm, 3.175);
        waitIdle(window);

        window.editJobSetup();
        QVERIFY(window.jobSetupPanel());
        auto* stockMinX = window.jobSetupPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("stockMinX"));
        QVERIFY(stockMinX);
        QCOMPARE(stockMinX->text(), QStringLiteral("-0.0787 in"));
        QCOMPARE(stockMinX->value(), -2.0);
        // The summary too: 94 x 64 x 16 mm from (-2, -2, -16).
        auto* summary = window.jobSetupPanel()->findChild<QLabel*>(QStringLiteral("stockSummary"));
        QVERIFY(summary);
        QCOMPARE(summary->text(), QStringLiteral("3.70079 × 2.51969 × 0.629921 in, from (-0.0787402, -0.0787402, 0)"));
        QVERIFY(!window.jobSetupPanel()->hasUnappliedChanges());  // showing in inch changes nothing
        window.jobSetupPanel()->reject();
        QTest::qWait(0);

        // Back to mm: the tree reads mm again, and a panel opened now too.
        setUnit(window, LengthUnit::Millimetre);
        QCOMPARE(treeText(window, JobTree::ItemKind::Stock), QStringLiteral("box 94.000 × 64.000 × 16.000 mm"));
        window.editOperation(index);
        QVERIFY(window.taskPanel());
        stepDown = window.taskPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("stepDownBox"));
        QCOMPARE(stepDown->text(), QStringLiteral("3.175 mm"));
        window.taskPanel()->reject();
        waitIdle(window);
    }

    // The job's tools and the library's table: lengths and feeds in inch, typed in inch, kept in mm.
    void inchInTheToolTables()
    {
        MainWindow window;
        QVERIFY(showExample(window));
        setUnit(window, LengthUnit::Inch);
        const std::unique_ptr<MainWindow, void (*)(MainWindow*)> backToMm(
            &window, [](MainWindow* w) { setUnit(*w, LengthUnit::Millimetre); });

        using camwb::gui::JobToolsModel;
        JobToolsModel jobTools(window.workbench());
        const camwb::ops::ToolController first = window.workbench().job().tools.at(0);
        QCOMPARE(jobTools.headerData(JobToolsModel::CuttingFeed, Qt::Horizontal, Qt::DisplayRole).toString(),
                 QStringLiteral("Feed (in/min)"));
        QCOMPARE(jobTools.headerData(JobToolsModel::Diameter, Qt::Horizontal, Qt::DisplayRole).toString(),
                 QStringLiteral("D (in)"));
        QCOMPARE(jobTools.data(jobTools.index(0, JobToolsModel::Diameter), Qt::DisplayRole).toDouble(),
                 std::round(first.tool.diameterMm / 25.4 * 1e4) / 1e4);
        QVERIFY(jobTools.setData(jobTools.index(0, JobToolsModel::CuttingFeed), QStringLiteral("10"), Qt::EditRole));
        QCOMPARE(window.workbench().job().tools.at(0).cuttingFeedMmPerMin, 254.0);
        QCOMPARE(jobTools.data(jobTools.index(0, JobToolsModel::CuttingFeed), Qt::DisplayRole).toDouble(), 10.0);
        // A plunge feed that is no round number of inches: typed back as shown, it stays as it was.
        const double plunge = first.plungeFeedMmPerMin;
        const QString shownPlunge =
            jobTools.data(jobTools.index(0, JobToolsModel::PlungeFeed), Qt::DisplayRole).toString();
        QVERIFY(jobTools.setData(jobTools.index(0, JobToolsModel::PlungeFeed), shownPlunge, Qt::EditRole));
        QCOMPARE(window.workbench().job().tools.at(0).plungeFeedMmPerMin, plunge);
        QVERIFY(!jobTools.setData(jobTools.index(0, JobToolsModel::CuttingFeed), QStringLiteral("-1"), Qt::EditRole));

        using camwb::gui::ToolTableModel;
        std::vector<camwb::ops::ToolController> library{first};
        ToolTableModel table(&library);
        QCOMPARE(table.headerData(ToolTableModel::Length, Qt::Horizontal, Qt::DisplayRole).toString(),
                 QStringLiteral("Length (in)"));
        QVERIFY(table.setData(table.index(0, ToolTableModel::Diameter), QStringLiteral("0.25"), Qt::EditRole));
        QCOMPARE(library[0].tool.diameterMm, 6.35);
        QCOMPARE(table.data(table.index(0, ToolTableModel::Diameter), Qt::DisplayRole).toDouble(), 0.25);

        setUnit(window, LengthUnit::Millimetre);
        QCOMPARE(jobTools.headerData(JobToolsModel::CuttingFeed, Qt::Horizontal, Qt::DisplayRole).toString(),
                 QStringLiteral("Feed (mm/min)"));
        QCOMPARE(jobTools.data(jobTools.index(0, JobToolsModel::CuttingFeed), Qt::DisplayRole).toDouble(), 254.0);
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    UnitsTest test;
    run.run(&test);
    return run.finish();
}

#include "UnitsTest.moc"
