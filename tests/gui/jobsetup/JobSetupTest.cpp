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
#include "gui/shell/JobTree.h"
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
#include <QFile>
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

    // The origin on a model vertex: the point a click meets the model at snaps to the nearest
    // vertex (the block's top front left corner, where its rounded edge R8 starts: (8, 0, 15) in
    // the model file's coordinates), X, Y and Z.
    void originOnAVertexPickedInTheView()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        auto* anchor = child<QComboBox>(panel, "originAnchor");
        anchor->setCurrentIndex(anchor->count() - 2);  // the picked vertex: none picked yet
        QVERIFY(!panel->hasUnappliedChanges());
        QVERIFY(child<QLabel>(panel, "originNote")->text().contains(QStringLiteral("vertex")));
        const camwb::base::Vec3 shown = window.workbench().modelOrigin();  // the view's coordinates
        const int top = window.workbench().model().topPlanarFace();
        window.view()->overlay().setSelectedFaces({top});
        window.view()->overlay().setPickedPoint(camwb::base::Vec3{8.3, 0.2, 15} - shown);  // as a click does
        QVERIFY2((panel->setup().origin - camwb::base::Vec3{8, 0, 15}).length() < 1e-6,
                 qPrintable(child<QLabel>(panel, "originNote")->text()));
        QVERIFY(panel->hasUnappliedChanges());
        // Another click on the same face (no change of selection) picks another vertex.
        window.view()->overlay().setPickedPoint(camwb::base::Vec3{89.8, 8.4, 15.0} - shown);
        QVERIFY((panel->setup().origin - camwb::base::Vec3{90, 8, 15}).length() < 1e-6);
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

    // A max typed below its min is said under the stock's fields as it is typed, and OK keeps the
    // panel open with the job unchanged (the file would not load again); put right, OK applies.
    void stockThatIsNoBoxIsRefused()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        const std::string before = jobText(window);
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        auto* error = child<QLabel>(panel, "stockError");
        QVERIFY(error->isHidden());
        child<QComboBox>(panel, "stockSize")->setCurrentIndex(1);  // explicit
        setSpin(panel, QStringLiteral("stockMaxX"), -10);
        QVERIFY(!error->isHidden());
        QVERIFY2(error->text().contains(QStringLiteral("max x (-10) is not above its min x")),
                 qPrintable(error->text()));
        QVERIFY(!panel->accept());
        QCOMPARE(window.jobSetupPanel(), panel);
        if (withGl())
            saveShot(&window, QStringLiteral("jobsetup-stock-no-box.png"));
        QCOMPARE(jobText(window), before);
        setSpin(panel, QStringLiteral("stockMaxX"), 95);
        QVERIFY(error->isHidden());
        QVERIFY(panel->accept());
        QCOMPARE(window.workbench().job().stock.max.x, 95.0);
        waitIdle(window);
    }

    // "Blank from file…": a file that cannot be read is said in the panel and changes nothing; a
    // blank file becomes the stock (its box the blank's bounds), OK is one undo step, the blank is
    // read with the job and drawn; undo restores the box.
    void blankFromFileIsOneUndoStep()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        openExample(window);
        const std::string original = jobText(window);
        const std::size_t undoSteps = window.workbench().document().undoStack().count();
        JobSetupPanel* panel = openPanel(window);
        QVERIFY(panel);
        const QString examples = QFileInfo(QStringLiteral(CAMWB_FIVE_AXIS_JOB)).absolutePath();
        QVERIFY(!panel->setBlankFile(examples + QStringLiteral("/no-such-blank.step")));
        auto* error = child<QLabel>(panel, "blankError");
        QVERIFY(!error->isHidden());
        QVERIFY2(error->text().contains(QStringLiteral("stock.blank")) &&
                     error->text().contains(QStringLiteral("no-such-blank.step")),
                 qPrintable(error->text()));
        QVERIFY(!panel->hasUnappliedChanges());

        // The block's own file as its blank (a blank the job's heights fit): the box is the model's.
        QVERIFY(panel->setBlankFile(examples + QStringLiteral("/example-block.step")));
        QVERIFY(error->isHidden());
        const camwb::document::Stock& stock = panel->setup().stock;
        QCOMPARE(stock.shape, camwb::document::Stock::Shape::Blank);
        QVERIFY(!stock.fromModel);
        const camwb::occ::Model& model = window.workbench().model();  // in work coordinates
        QVERIFY((stock.min - model.boundsMin()).length() < 1e-2);
        QVERIFY((stock.max - model.boundsMax()).length() < 1e-2);
        QCOMPARE(child<QComboBox>(panel, "stockShape")->currentIndex(), 2);
        QVERIFY(child<QLabel>(panel, "blankLabel")->text() == QStringLiteral("example-block.step"));
        QVERIFY2(
            child<QLabel>(panel, "stockSummary")->text().startsWith(QStringLiteral("Blank in a box of 90 × 60 × 15")),
            qPrintable(child<QLabel>(panel, "stockSummary")->text()));
        QVERIFY(panel->hasUnappliedChanges());
        QTest::qWait(200);
        saveShot(&window, withGl() ? QStringLiteral("jobsetup-blank-panel.png")
                                   : QStringLiteral("jobsetup-blank-offscreen.png"));

        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        child<QAbstractButton>(panel, "okButton")->click();
        QCOMPARE(window.workbench().document().undoStack().count(), undoSteps + 1);
        QVERIFY(posted.count() > 0 || posted.wait(120000));
        waitIdle(window);
        QVERIFY2(window.workbench().isProgramCurrent(), qPrintable(window.workbench().programProblem()));
        QVERIFY(window.workbench().stockBlank());
        QCOMPARE(window.workbench().job().stock.shape, camwb::document::Stock::Shape::Blank);
        QVERIFY(std::abs(window.workbench().stockBlank()->bounds().max.z - window.workbench().job().stock.max.z) <
                1e-6);
        QVERIFY(window.view()->hasStockActor());
        QVERIFY(window.workbench().job().stock.blankPath.find("example-block.step") != std::string::npos);

        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        QCOMPARE(jobText(window), original);
        waitIdle(window);
    }

    // The five-axis example starts from its cast blank: read with the job, drawn in the view.
    void fiveAxisExampleShowsItsBlank()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(QStringLiteral(CAMWB_FIVE_AXIS_JOB)));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        QVERIFY2(window.workbench().isProgramCurrent(), qPrintable(window.workbench().programProblem()));
        QVERIFY(window.workbench().stockBlank());
        QVERIFY(window.workbench().stockBlank()->triangleCount() > 100);
        QVERIFY(window.view()->hasStockActor());
        QCOMPARE(window.workbench().document().undoStack().count(), std::size_t(0));  // the stored box is the blank's
        // The job tree names the blank.
        const QList<QTreeWidgetItem*> stockRows =
            window.jobTree()->findItems(QStringLiteral("Stock"), Qt::MatchExactly | Qt::MatchRecursive, 0);
        QCOMPARE(stockRows.size(), 1);
        QVERIFY2(
            stockRows.front()->text(1).startsWith(QStringLiteral("blank example-five-axis-blank.step in a box 80")),
            qPrintable(stockRows.front()->text(1)));
        if (withGl()) {
            window.view()->setViewPreset(camwb::gui::View3D::Preset::Isometric);
            QTest::qWait(300);
            const QImage view = window.view()->grabImage();
            QVERIFY(showsSomething(view));
            QVERIFY(view.save(shotsDir() + QStringLiteral("/five-axis-blank-view.png")));
        }
    }

    // A "from model" stock stored with a box its model no longer gives (the model changed on
    // disk): opening the job takes the box the model gives, says so, and the step can be undone.
    void staleStockIsResolvedOnOpenAndSaid()
    {
        auto job = camwb::document::loadJob(CAMWB_EXAMPLE_JOB);
        QVERIFY(job.ok());
        job->stock.fromModel = camwb::document::StockFromModel{{1, 1, 0}, {1, 1, 2}};
        job->stock.min = {-50, -50, -50};  // as if resolved against an older, larger model
        job->stock.max = {150, 150, 50};
        const QString path = QDir(QDir::tempPath()).filePath(QStringLiteral("camwb-stale-stock.camwb"));
        QVERIFY(camwb::document::saveJob(job.value(), path.toStdString()).ok());

        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto prompter = std::make_unique<ScriptedPrompter>();
        window.setPrompter(std::move(prompter));
        QStringList warnings;
        connect(&window.workbench(), &Workbench::message, this,
                [&warnings](Workbench::Severity severity, const QString& text) {
                    if (severity == Workbench::Severity::Warning)
                        warnings << text;
                });
        QSignalSpy posted(&window.workbench(), &Workbench::postFinished);
        QVERIFY(window.openJob(path));
        QVERIFY(posted.wait(120000));
        waitIdle(window);
        const camwb::base::Vec3 lo = window.workbench().model().boundsMin(),
                                hi = window.workbench().model().boundsMax();
        const camwb::document::Stock& stock = window.workbench().job().stock;
        QVERIFY(near(stock.min, lo - camwb::base::Vec3{1, 1, 0}));
        QVERIFY(near(stock.max, hi + camwb::base::Vec3{1, 1, 2}));
        QVERIFY2(warnings.filter(QStringLiteral("stock stored in the job")).size() == 1,
                 qPrintable(warnings.join('\n')));
        QCOMPARE(window.workbench().document().undoStack().count(), std::size_t(1));
        QVERIFY(window.workbench().document().isModified());
        // Undo brings the stored box back and it stays (checked once, on opening).
        QVERIFY(window.actions().trigger(QStringLiteral("Cam.Edit.Undo")));
        waitIdle(window);
        QVERIFY(near(window.workbench().job().stock.min, {-50, -50, -50}));
        QFile::remove(path);
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
