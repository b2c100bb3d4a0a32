// Drives the job setup task panel on the real main window with the example job: the stock from
// the model's bounds + 2 mm, the work origin on the stock's top front left corner, another machine
// and post, an output name; OK is one undo step and the posted NC follows (Heidenhain, its blank in
// work coordinates); undo restores job and NC; Cancel changes nothing; a stock larger than the
// machine's travels is warned about. Under Xvfb (GL: the view's stock and axes) and offscreen.
#include "QtTestRun.h"
#include "ScriptedPrompter.h"
#include "Shots.h"
#include "document/JobFile.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/MainWindow.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/JobSetupPanel.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"

#include "gui/tasks/PostPropertiesForm.h"
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>

using camwb::gui::JobSetupPanel;
using camwb::gui::MainWindow;
using camwb::gui::Workbench;

namespace {

bool withGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

std::string jobText(MainWindow& window) { return camwb::document::serializeJob(window.workbench().job()); }

template <class W> W* child(QWidget* panel, const char* name)
{
    auto* widget = panel->findChild<W*>(QLatin1String(name));
    if (widget == nullptr)
        qWarning("no widget %s", name);
    return widget;
}

bool chooseText(QWidget* panel, const char* combo, const QString& text)
{
    auto* box = child<QComboBox>(panel, combo);
    const int index = box ? box->findText(text) : -1;
    if (index < 0)
        return false;
    box->setCurrentIndex(index);
    return true;
}

bool near(const camwb::base::Vec3& a, const camwb::base::Vec3& b) { return (a - b).length() < 1e-9; }

void setSpin(QWidget* panel, const QString& name, double value)
{
    auto* spin = panel->findChild<QDoubleSpinBox*>(name);
    QVERIFY2(spin, qPrintable(name));
    spin->setValue(value);
}

}  // namespace

class JobSetupTest : public QObject {
    Q_OBJECT

private:
    ScriptedPrompter* m_prompter = nullptr;

    void openExample(MainWindow& window)
    {
        auto prompter = std::make_unique<ScriptedPrompter>();
        m_prompter = prompter.get();
        window.setPrompter(std::move(prompter));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_EXAMPLE_JOB)));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
    }

    static void waitIdle(MainWindow& window)
    {
        QElapsedTimer waited;
        waited.start();
        while (window.workbench().isBusy() && waited.elapsed() < 120000)
            QTest::qWait(20);
        QVERIFY(!window.workbench().isBusy());
    }

    static JobSetupPanel* openPanel(MainWindow& window)
    {
        if (!window.actions().trigger(QStringLiteral("Cam.Job.Setup")))
            return nullptr;
        return window.jobSetupPanel();
    }

private slots:
    void okIsOneUndoStepAndThePostedProgramFollows()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        const std::string original = jobText(window);
        const camwb::document::Job originalJob = window.workbench().job();
        const QString originalNc = window.workbench().ncText();
        QVERIFY(!originalNc.isEmpty());
        const std::size_t undoSteps = window.workbench().document().undoStack().count();
        const camwb::base::Vec3 lo = window.workbench().model().boundsMin(),
                                hi = window.workbench().model().boundsMax();

        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        QVERIFY(!panel->hasUnappliedChanges());
        QVERIFY(child<QWidget>(panel, "postPropertiesSlot"));
        child<QComboBox>(panel, "stockSize")->setCurrentIndex(0);  // model bounds + offsets
        for (const char* axis : {"X", "Y", "Z"}) {
            setSpin(panel, QStringLiteral("stockBelow") + QLatin1String(axis), 2);
            setSpin(panel, QStringLiteral("stockAbove") + QLatin1String(axis), 2);
        }
        child<QComboBox>(panel, "originAnchor")->setCurrentIndex(1);  // the stock's top front left corner
        QVERIFY(chooseText(panel, "post", QStringLiteral("heidenhain-itnc530")));
        QVERIFY(chooseText(panel, "machine", QStringLiteral("mas-mcvl1000")));
        child<QLineEdit>(panel, "outputName")->setText(QStringLiteral("PART1"));
        QVERIFY(panel->hasUnappliedChanges());
        QVERIFY(!child<QLabel>(panel, "travelWarning")->isVisible());
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps);  // nothing applied yet
        QTest::qWait(200);
        // The dock is as wide as the rows, the post's properties included: nothing cut off on the right.
        QVERIFY(panel->findChild<QScrollArea*>()->minimumWidth() > panel->postProperties()->minimumSizeHint().width());
        saveShot(&window,
                 withGl() ? QStringLiteral("jobsetup-panel.png") : QStringLiteral("jobsetup-panel-offscreen.png"));

        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        child<QAbstractButton>(panel, "okButton")->click();
        QVERIFY(window.jobSetupPanel() == nullptr);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);

        const camwb::document::Job& job = window.workbench().job();
        const camwb::base::Vec3 origin{lo.x - 2, lo.y - 2, hi.z + 2};
        QVERIFY(near(job.origin, origin));
        QVERIFY(job.stock.fromModel.has_value());
        QVERIFY(near(job.stock.min, {0, 0, lo.z - hi.z - 4}));  // work coordinates
        QVERIFY(near(job.stock.max, {hi.x - lo.x + 4, hi.y - lo.y + 4, 0}));
        QCOMPARE(job.postId, std::string("heidenhain-itnc530"));
        QCOMPARE(job.machineId, std::string("mas-mcvl1000"));
        QCOMPARE(job.outputName, std::string("PART1"));
        // The operations' height overrides stay on the part: in work coordinates now.
        const camwb::document::Operation& contour = job.operations[0];
        QVERIFY(contour.heights.finalZ.has_value());
        QCOMPARE(*contour.heights.finalZ, *originalJob.operations[0].heights.finalZ - origin.z);

        QVERIFY(posted.count() > 0 || posted.wait(120000));
        waitIdle(window);
        QVERIFY2(window.workbench().isProgramCurrent(), qPrintable(window.workbench().programProblem()));
        const QString nc = window.workbench().ncText();
        QCOMPARE(window.workbench().ncExtension(), QStringLiteral("h"));
        // The blank in work coordinates: from the top front left corner down and across.
        const QString blank = QStringLiteral("BLK FORM 0.2 X+%1 Y+%2 Z+0").arg(hi.x - lo.x + 4).arg(hi.y - lo.y + 4);
        QVERIFY2(nc.contains(blank), qPrintable(nc.left(600)));
        QVERIFY2(nc.contains(QStringLiteral("BLK FORM 0.1 Z X+0 Y+0 Z-%1").arg(hi.z - lo.z + 4)),
                 qPrintable(nc.left(600)));
        QVERIFY(window.view()->hasStockActor());
        QVERIFY(window.view()->hasWorkAxes());
        if (withGl()) {
            window.view()->setViewPreset(camwb::gui::View3D::Preset::Isometric);
            QTest::qWait(300);
            const QImage view = window.view()->grabImage();
            QVERIFY(showsSomething(view));
            QVERIFY(view.save(shotsDir() + QStringLiteral("/jobsetup-view.png")));
        }

        // Undo: the job and its program as they were.
        QSignalSpy reposted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        QVERIFY(reposted.count() > 0 || reposted.wait(120000));
        waitIdle(window);
        QCOMPARE(window.workbench().ncText(), originalNc);
    }

    void cancelAndSettleChangeNothing()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        const std::string original = jobText(window);
        const std::size_t undoSteps = window.workbench().document().undoStack().count();

        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        child<QComboBox>(panel, "stockShape")->setCurrentIndex(1);  // cylinder
        setSpin(panel, QStringLiteral("originZ"), 5);
        QVERIFY(chooseText(panel, "workOffset", QStringLiteral("G55")));
        QVERIFY(panel->hasUnappliedChanges());
        child<QAbstractButton>(panel, "cancelButton")->click();
        QVERIFY(window.jobSetupPanel() == nullptr);
        QCOMPARE(jobText(window), original);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps);

        // Unapplied changes are asked about before the panel is replaced: Discard keeps the job.
        panel = openPanel(window);
        QVERIFY(panel);
        QVERIFY(chooseText(panel, "workOffset", QStringLiteral("G56")));
        m_prompter->answers.push_back(camwb::gui::Prompter::Answer::Discard);
        panel = openPanel(window);
        QVERIFY(panel);
        QCOMPARE(m_prompter->questions.size(), 1);
        QVERIFY(!panel->hasUnappliedChanges());
        QCOMPARE(jobText(window), original);
        // Apply applies: one step.
        QVERIFY(chooseText(panel, "workOffset", QStringLiteral("G57")));
        m_prompter->answers.push_back(camwb::gui::Prompter::Answer::Accept);
        QVERIFY(window.settleTaskPanel());
        QCOMPARE(window.workbench().job().workOffset, 4);
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        waitIdle(window);
    }

    // The panel's Import runs Cam.File.ImportModel and stays open (it holds no model references),
    // its unapplied changes kept; a "from model" stock follows the new model.
    void importKeepsThePanelOpen()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        child<QComboBox>(panel, "stockSize")->setCurrentIndex(0);
        setSpin(panel, QStringLiteral("stockAboveZ"), 3);
        QVERIFY(panel->hasUnappliedChanges());
        m_prompter->files.push_back(
            QFileInfo(QStringLiteral(CAMWB_EXAMPLE_JOB)).dir().filePath(QStringLiteral("example-block.step")));
        QSignalSpy imported(&window.workbench(), &Workbench::modelImportFinished);
        child<QAbstractButton>(panel, "importModelButton")->click();
        QVERIFY(imported.count() > 0 || imported.wait(120000));
        QCOMPARE(imported.takeFirst().at(0).toBool(), true);
        QVERIFY(m_prompter->questions.isEmpty());
        QCOMPARE(window.jobSetupPanel(), panel);
        QVERIFY(panel->hasUnappliedChanges());
        QCOMPARE(panel->setup().stock.max.z, window.workbench().model().boundsMax().z + 3);
        waitIdle(window);
        panel->reject();
    }

    void originOnAFacePickedInTheView()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        auto* anchor = child<QComboBox>(panel, "originAnchor");
        anchor->setCurrentIndex(anchor->count() - 1);  // Z0 on the picked face: none picked yet
        QVERIFY(!panel->hasUnappliedChanges());
        QVERIFY(child<QLabel>(panel, "originNote")->text().contains(QStringLiteral("Pick")));
        const camwb::occ::Model& model = window.workbench().model();
        const int top = model.topPlanarFace();
        QVERIFY(top > 0);
        window.view()->overlay().setSelectedFaces({top});  // as a click on the face does
        QCOMPARE(panel->setup().origin, (camwb::base::Vec3{0, 0, model.face(top).planeZ}));
        QVERIFY(panel->hasUnappliedChanges());
        panel->reject();
    }

    void stockBeyondTheTravelsIsWarned()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        QVERIFY(chooseText(panel, "machine", QStringLiteral("mas-mcvl1000")));
        auto* warning = child<QLabel>(panel, "travelWarning");
        QVERIFY(warning->isHidden());
        child<QComboBox>(panel, "stockSize")->setCurrentIndex(1);  // explicit
        setSpin(panel, QStringLiteral("stockMaxX"), 2000);
        QVERIFY(!warning->isHidden());
        QVERIFY2(warning->text().contains(QStringLiteral("X: stock")), qPrintable(warning->text()));
        QVERIFY(!warning->text().contains(QStringLiteral("Y: stock")));
        // The example's post (EMCO) does not post for this machine: greyed out and warned about.
        auto* postWarning = child<QLabel>(panel, "postWarning");
        QVERIFY(!postWarning->isHidden());
        QVERIFY2(postWarning->text().contains(QStringLiteral("sinumerik828d-emco")), qPrintable(postWarning->text()));
        QVERIFY(chooseText(panel, "post", QStringLiteral("heidenhain-itnc530")));
        QVERIFY(postWarning->isHidden());
        auto* posts = child<QComboBox>(panel, "post");
        const auto* items = qobject_cast<const QStandardItemModel*>(posts->model());
        QVERIFY(items);
        QVERIFY(!items->item(posts->findText(QStringLiteral("sinumerik828d-emco")))->isEnabled());
        QVERIFY(items->item(posts->findText(QStringLiteral("heidenhain-itnc530")))->isEnabled());
        panel->reject();
    }
};

int main(int argc, char** argv)
{
    qputenv("SOURCE_DATE_EPOCH", "1767225600");  // the programs' date line: undo gives the same text
    camwb::gui::View3D::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    QtTestRun run(argc, argv);
    JobSetupTest test;
    run.run(&test);
    return run.finish();
}

#include "JobSetupTest.moc"
