// Drives the turning groove on the real main window: the Kod 1 job (resources/examples) opens in
// the lathe's XZ view with its half-section; the groove panel shows each input with its R name,
// the insert width from the tool, previews, follows a change of the depth, shows the operation's
// own message for an invalid value (and no stale preview), Cancel changes nothing, OK is one undo
// step; New Groove Roughing works without a model. Under Xvfb and offscreen.
// CAMWB_SHOTS_DIR=<dir> keeps the pictures (groove-kod1.png: panel and view).
#include "QtTestRun.h"
#include "Shots.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PreviewRunner.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"
#include "toolpath/ToolpathPolylines.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTest>

using camwb::document::OperationKind;
using camwb::gui::MainWindow;
using camwb::gui::OperationPanel;
using camwb::gui::PreviewRunner;
using camwb::gui::View3D;
using camwb::gui::Workbench;

namespace {

bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

std::string jobText(MainWindow& window) { return camwb::document::serializeJob(window.workbench().job()); }

std::vector<camwb::base::Vec3> previewPoints(MainWindow& window)
{
    const auto* polylines = window.view()->overlay().previewPolylines();
    return polylines ? polylines->points() : std::vector<camwb::base::Vec3>{};
}

void waitIdle(MainWindow& window)
{
    QElapsedTimer waited;
    waited.start();
    while (window.workbench().isBusy() && waited.elapsed() < 120000)
        QTest::qWait(20);
    QVERIFY(!window.workbench().isBusy());
}

// The label the panel's form shows beside the field named `name`.
QString labelOf(OperationPanel& panel, const char* name)
{
    auto* field = panel.findChild<QWidget*>(QLatin1String(name));
    if (field == nullptr)
        return {};
    for (auto* form : panel.findChildren<QFormLayout*>())
        if (auto* label = qobject_cast<QLabel*>(form->labelForField(field)))
            return label->text();
    return {};
}

// Sets a spin box as typing and Enter would, and waits for the preview that follows.
bool setAndPreview(OperationPanel& panel, const char* name, double value)
{
    auto* box = panel.findChild<QDoubleSpinBox*>(QLatin1String(name));
    if (box == nullptr)
        return false;
    QSignalSpy finished(&panel.preview(), &PreviewRunner::finished);
    box->setValue(value);
    return finished.wait(120000);
}

}  // namespace

class GroovePanelTest : public QObject {
    Q_OBJECT

private:
    static void openKod1(MainWindow& window)
    {
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_GROOVE_JOB)));
        QVERIFY(posted.count() > 0 || posted.wait(120000));
        waitIdle(window);
    }

    static int grooveIndex(MainWindow& window)
    {
        const auto& ops = window.workbench().job().operations;
        for (std::size_t i = 0; i < ops.size(); ++i)
            if (ops[i].kind() == OperationKind::Groove)
                return static_cast<int>(i);
        return -1;
    }

private slots:
    void newGrooveIsInTheOperationsMenu()
    {
        MainWindow window;
        QAction* action = window.actions().action(QStringLiteral("Cam.Op.NewGroove"));
        QVERIFY(action);
        QCOMPARE(action->text(), QStringLiteral("New &Groove Roughing…"));
        bool inMenu = false;
        for (QAction* top : window.menuBar()->actions())
            if (top->menu() != nullptr && top->menu()->actions().contains(action))
                inMenu = top->text().remove(QLatin1Char('&')) == QLatin1String("Operation");
        QVERIFY(inMenu);
        QVERIFY(window.actions().action(QStringLiteral("Cam.View.LatheXZ")));
    }

    void kod1OpensInTheLatheView()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openKod1(window);
        QVERIFY(grooveIndex(window) >= 0);
        QVERIFY(window.view()->viewPreset() == View3D::Preset::LatheXZ);
        QVERIFY(window.view()->hasLatheSection());
        QVERIFY(!window.view()->hasStockActor());  // the half-section instead of a milling stock
        // The path the job shows lies in the XZ plane.
        const auto* polylines = window.view()->toolpathPolylines();
        QVERIFY(polylines != nullptr && !polylines->points().empty());
        for (const camwb::base::Vec3& p : polylines->points())
            QCOMPARE(p.y, 0.0);
        if (withGl())
            saveShot(&window, QStringLiteral("groove-kod1-job.png"));
        // The other presets still turn the view; the lathe's comes back by its action.
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.Isometric")));
        QVERIFY(window.view()->viewPreset() == View3D::Preset::Isometric);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.View.LatheXZ")));
        QVERIFY(window.view()->viewPreset() == View3D::Preset::LatheXZ);
        // The thesis' own program, traced in the lathe job, is drawn in the turning plane too.
        {
            QSignalSpy traced(window.inspector(), &camwb::gui::NcInspector::traceFinished);
            QVERIFY(window.openNcFile(QStringLiteral(CAMWB_KOD5_MPF)));
            QVERIFY(traced.wait(120000));
        }
        QVERIFY2(window.view()->toolpathSegmentCount() > 500,
                 qPrintable(QString::number(window.view()->toolpathSegmentCount())));
        for (const camwb::base::Vec3& p : window.view()->toolpathPolylines()->points())
            QCOMPARE(p.y, 0.0);
        if (withGl())
            saveShot(&window, QStringLiteral("groove-kod5-traced.png"));
        // A milling job afterwards: its stock in the isometric view again, no half-section.
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY(window.view()->viewPreset() == View3D::Preset::Isometric);
        QVERIFY(!window.view()->hasLatheSection());
        QVERIFY(window.view()->hasStockActor());
        QVERIFY(window.view()->isToolpathShown());
    }

    void panelPreviewsValidatesAndApplies()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openKod1(window);
        const int index = grooveIndex(window);
        QVERIFY(index >= 0);
        const std::string original = jobText(window);
        const std::size_t undoSteps = window.workbench().document().undoStack().count();

        window.editOperation(index);
        OperationPanel* panel = window.taskPanel();
        QVERIFY(panel);
        {
            QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
            QVERIFY(finished.count() > 0 || finished.wait(120000));
        }
        const auto first = panel->preview().lastOutcome();
        QVERIFY(first);
        QVERIFY2(first->ok, qPrintable(panel->statusText()));
        qInfo("Kod 1: %s", qPrintable(panel->statusText()));
        QVERIFY(window.view()->overlay().previewSegmentCount() > 0);
        const auto firstPoints = previewPoints(window);
        for (const camwb::base::Vec3& p : firstPoints)
            QCOMPARE(p.y, 0.0);  // in the turning plane
        // The preview, in the backplot's red and green, takes the job's path's place.
        QVERIFY(!window.view()->isToolpathShown());
        QVERIFY(window.view()->viewPreset() == View3D::Preset::LatheXZ);
        if (withGl())
            saveShot(&window, QStringLiteral("groove-kod1.png"));

        // Each input with its R name; the insert width read-only from the tool.
        const std::pair<const char*, const char*> names[] = {{"r0Box", "(R0)"},
                                                             {"r1Box", "(R1)"},
                                                             {"r2Box", "(R2)"},
                                                             {"r3Box", "Depth (R3)"},
                                                             {"r4Box", "Bottom width (R4)"},
                                                             {"r5Box", "Right flank angle (R5)"},
                                                             {"r6Box", "(R6)"},
                                                             {"r7Box", "(R7)"},
                                                             {"r8Box", "(R8)"},
                                                             {"insertWidthEdit", "(R9)"},
                                                             {"stepFactorBox", "Step factor (R10)"},
                                                             {"infeedBox", "Infeed (R11)"},
                                                             {"safetyBox", "Safety distance (R30)"}};
        for (const auto& [field, label] : names)
            QVERIFY2(labelOf(*panel, field).contains(QLatin1String(label)),
                     qPrintable(QStringLiteral("%1: '%2'").arg(field, labelOf(*panel, field))));
        auto* width = panel->findChild<QLineEdit*>(QStringLiteral("insertWidthEdit"));
        QVERIFY(width && width->isReadOnly());
        const auto* tool = window.workbench().job().tool(panel->operation().toolNumber);
        QVERIFY(tool);
        QCOMPARE(tool->tool.diameterMm, 3.0);
        QCOMPARE(width->text(), QStringLiteral("3.000 mm"));  // as every length shows (display unit mm)
        for (const char* field : {"surfaceSpeedBox", "maxRpmBox", "feedBox"})
            QVERIFY2(panel->findChild<QDoubleSpinBox*>(QLatin1String(field)), field);
        QCOMPARE(labelOf(*panel, "maxRpmBox"), QStringLiteral("Spindle limit (LIMS)"));

        // A shallower groove: fewer plunges, another path.
        QVERIFY(setAndPreview(*panel, "r3Box", 60));
        const auto shallower = panel->preview().lastOutcome();
        QVERIFY2(shallower && shallower->ok, qPrintable(panel->statusText()));
        QVERIFY(shallower->result.counts.lines < first->result.counts.lines);
        QVERIFY(previewPoints(window) != firstPoints);
        QCOMPARE(jobText(window), original);  // nothing applied while editing

        // An invalid step factor: the operation's message, no preview left in view, OK refused.
        QVERIFY(setAndPreview(*panel, "stepFactorBox", 1.5));
        QVERIFY(!panel->preview().lastOutcome()->ok);
        qInfo("step factor 1.5: %s", qPrintable(panel->statusText()));
        QCOMPARE(panel->statusText(), QString::fromStdString(panel->preview().lastOutcome()->error));
        QVERIFY2(panel->statusText().contains(QLatin1String("R10")), qPrintable(panel->statusText()));
        QCOMPARE(window.view()->overlay().previewSegmentCount(), 0);
        QVERIFY(!panel->accept());
        QVERIFY(window.taskPanel() == panel);

        QVERIFY(setAndPreview(*panel, "stepFactorBox", 0.8));
        QVERIFY2(panel->preview().lastOutcome()->ok, qPrintable(panel->statusText()));
        QVERIFY(window.view()->overlay().previewSegmentCount() > 0);
        if (withGl())
            saveShot(&window, QStringLiteral("groove-depth60.png"));  // the contour follows the panel

        // Cancel: nothing changed, no step.
        panel->findChild<QAbstractButton*>(QStringLiteral("cancelButton"))->click();
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(window.view()->overlay().previewSegmentCount(), 0);
        QVERIFY(window.view()->isToolpathShown());
        QCOMPARE(jobText(window), original);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps);

        // OK: one undo step; undo gives the job back.
        window.editOperation(index);
        panel = window.taskPanel();
        QVERIFY(panel);
        QVERIFY(setAndPreview(*panel, "r3Box", 60));
        panel->findChild<QAbstractButton*>(QStringLiteral("okButton"))->click();
        QVERIFY(window.taskPanel() == nullptr);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        QCOMPARE(std::get<camwb::ops::GrooveParams>(window.workbench().job().operations[index].params).groove.r3, 60.0);
        waitIdle(window);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        waitIdle(window);
    }

    // Without a model and without a grooving tool: the Kod 1 groove with a 3 mm insert added with it.
    void newGrooveOnAnEmptyJob()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Op.NewGroove")));
        OperationPanel* panel = window.taskPanel();
        QVERIFY(panel);
        QCOMPARE(panel->operationIndex(), -1);
        QVERIFY(panel->operation().kind() == OperationKind::Groove);
        QSignalSpy finished(&panel->preview(), &PreviewRunner::finished);
        QVERIFY(finished.wait(120000));
        QVERIFY2(panel->preview().lastOutcome()->ok, qPrintable(panel->statusText()));
        QCOMPARE(panel->findChild<QLineEdit*>(QStringLiteral("insertWidthEdit"))->text(), QStringLiteral("3.000 mm"));
        QVERIFY(panel->accept());
        const auto& job = window.workbench().job();
        QCOMPARE(job.operations.size(), std::size_t(1));
        const auto* tool = job.tool(job.operations.front().toolNumber);
        QVERIFY(tool && tool->tool.kind == "groove");
        QCOMPARE(window.workbench().document().undoStack().count(), std::size_t(1));
        QVERIFY(window.view()->viewPreset() == View3D::Preset::LatheXZ);
        QVERIFY(window.view()->hasLatheSection());
        waitIdle(window);
    }
};

int main(int argc, char** argv)
{
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    GroovePanelTest test;
    run.run(&test);
    return run.finish();
}

#include "GroovePanelTest.moc"
