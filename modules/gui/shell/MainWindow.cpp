#include "gui/shell/MainWindow.h"

#include "base/AtomicFile.h"
#include "camwb_version.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/NcEditorActions.h"
#include "gui/inspector/InspectorPanel.h"
#include "gui/inspector/ModalStatePanel.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/Banner.h"
#include "gui/shell/JobTree.h"
#include "gui/shell/KeyboardFocus.h"
#include "gui/shell/NcDocument.h"
#include "gui/shell/NewOperation.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/RecentFiles.h"
#include "gui/shell/ReportView.h"
#include "gui/shell/Session.h"
#include "gui/shell/SetupSheetActions.h"
#include "gui/shell/Workbench.h"
#include "gui/sim/SimActions.h"
#include "gui/sim/SimDock.h"
#include "gui/sim/SimPlayer.h"
#include "gui/sim/SimRequest.h"
#include "gui/tasks/JobSetupActions.h"
#include "gui/tasks/JobSetupPanel.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/tasks/PostSettingsPanel.h"
#include "gui/tools/ToolActions.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"
#include "kinematics/Machine.h"
#include "sim/TurningCheck.h"
#include "toolpath/ClImport.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QScopedValueRollback>
#include <QStatusBar>
#include <QToolBar>

#include <utility>

namespace camwb::gui {

namespace {

QDockWidget* addDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                     Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, window);
    dock->setObjectName(name);
    dock->setWidget(content);
    window->addDockWidget(area, dock);
    return dock;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) :
    QMainWindow(parent),
    m_prompter(std::make_unique<DialogPrompter>(this)),
    m_workbench(new Workbench(this)),
    m_actions(new ActionRegistry(this)),
    m_view(new View3D(this)),
    m_editor(new NcEditor(this)),
    m_ncDocument(new NcDocument(
        m_editor, [this]() -> Prompter& { return *m_prompter; }, this)),
    m_report(new ReportView(this)),
    m_jobTree(new JobTree(*m_workbench, this)),
    m_progress(new QProgressBar(this)),
    m_inspector(new NcInspector(this)),
    m_inspectorPanel(new InspectorPanel(this)),
    m_simPlayer(new SimPlayer(this)),
    m_viewBanner(new Banner(QStringLiteral("viewBanner"), this)),
    m_ncBanner(new Banner(QStringLiteral("ncBanner"), this))
{
    setObjectName(QStringLiteral("mainWindow"));
    m_view->setObjectName(QStringLiteral("view3d"));
    m_editor->setObjectName(QStringLiteral("ncEditor"));
    m_editor->setReadOnly(true);
    m_workbench->setPrompter(m_prompter.get());
    // The banners say when what the view and the editor show is not the job's current program.
    setCentralWidget(Banner::above(m_viewBanner, m_view, this));

    QDockWidget* jobDock = addDock(this, tr("Job"), QStringLiteral("jobDock"), m_jobTree, Qt::LeftDockWidgetArea);
    QDockWidget* ncDock = addDock(this, tr("NC program"), QStringLiteral("ncDock"),
                                  Banner::above(m_ncBanner, m_editor, this), Qt::RightDockWidgetArea);
    m_ncDock = ncDock;
    QDockWidget* reportDock =
        addDock(this, tr("Report"), QStringLiteral("reportDock"), m_report, Qt::BottomDockWidgetArea);
    QDockWidget* modalDock =
        addDock(this, tr("NC inspector"), QStringLiteral("modalDock"), m_inspectorPanel, Qt::LeftDockWidgetArea);
    // Wide enough for a full NC block and the job tree's values; the 3D view takes the rest.
    // The task panel (FreeCAD's place for it): on the right, over the NC dock while open.
    m_taskDock = addDock(this, tr("Task"), QStringLiteral("taskDock"), new QWidget(this), Qt::RightDockWidgetArea);
    tabifyDockWidget(ncDock, m_taskDock);
    // Closed by the panel's OK or Cancel only: a close button would leave the panel open unseen.
    m_taskDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    m_taskDock->hide();
    resizeDocks({jobDock, ncDock}, {330, 470}, Qt::Horizontal);
    resizeDocks({reportDock}, {140}, Qt::Vertical);
    m_simDock = new SimDock(m_simPlayer, this);
    m_simDockWidget = addDock(this, tr("Simulator"), QStringLiteral("simDock"), m_simDock, Qt::BottomDockWidgetArea);
    tabifyDockWidget(reportDock, m_simDockWidget);
    reportDock->raise();
    resizeDocks({jobDock, modalDock}, {260, 420}, Qt::Vertical);

    m_progress->setMaximumWidth(220);
    m_progress->setRange(0, 100);
    m_progress->hide();
    statusBar()->addPermanentWidget(m_progress);

    registerActions();
    m_actions->buildMenus(menuBar());
    auto* toolBar = addToolBar(tr("Main"));
    toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_actions->buildToolBar(toolBar);

    connectWorkbench();
    connectInspector();
    connect(m_jobTree, &JobTree::editOperationRequested, this, &MainWindow::editOperation);

    QString reason;
    if (!m_view->hasOpenGl() && !View3D::openGlAvailable(&reason))
        m_report->append(Workbench::Severity::Warning, tr("3D view unavailable: %1").arg(reason));
    resize(1400, 860);
    updateTitle();
}

MainWindow::~MainWindow()
{
    // An open task panel refers to the workbench and the 3D view's overlay, which (children made
    // before the task dock) would be destroyed before it: it goes first, while both are there.
    delete std::exchange(m_taskPanel, nullptr);
    delete std::exchange(m_jobSetupPanel, nullptr);
    m_workbench->setPrompter(nullptr);
}

void MainWindow::setPrompter(std::unique_ptr<Prompter> prompter)
{
    if (!prompter)
        return;
    m_prompter = std::move(prompter);
    m_workbench->setPrompter(m_prompter.get());
}

bool MainWindow::openJob(const QString& path)
{
    if (!path.endsWith(QLatin1String(".camwb"), Qt::CaseInsensitive))
        return openNcFile(path);
    if (!m_ncDocument->mayReplace(
            tr("Opening the job %1 replaces them with its program.").arg(QFileInfo(path).fileName())))
        return false;
    closeTaskPanel();                 // its operation belongs to the job being replaced
    return m_session->openJob(path);  // offers to recover a newer autosave first
}

bool MainWindow::openNcFile(const QString& path)
{
    if (!m_ncDocument->mayReplace(tr("Opening %1 replaces them.").arg(QFileInfo(path).fileName())))
        return false;
    auto text = base::readPlainTextFile(path.toStdString());
    if (!text) {
        m_report->append(Workbench::Severity::Error, QString::fromStdString(text.error().toString()));
        m_prompter->showError(tr("Open NC program"), QString::fromStdString(text.error().toString()));
        return false;
    }
    m_fitWithTrace = true;
    m_editorShowsPosted = false;
    showProgramState();
    m_inspector->loadProgram(QString::fromStdString(text.value()), QFileInfo(path).absoluteFilePath());
    m_ncDocument->openedFile(path);
    m_session->recentFiles().add(path);
    m_report->append(Workbench::Severity::Note, toolpath::clFormatFromExtension(path.toStdString())
                                                    ? tr("Opened CL file %1").arg(path)
                                                    : tr("Opened NC program %1").arg(path));
    return true;
}

void MainWindow::registerActions()
{
    const QString file = tr("&File"), edit = tr("&Edit"), operation = tr("&Operation"), jobMenu = tr("&Job"),
                  view = tr("&View"), help = tr("&Help");
    auto add = [this](ActionSpec spec, auto slot) {
        QAction* action = m_actions->add(spec);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };

    add({"Cam.File.Open", tr("&Open Job…"), file, QKeySequence::Open, true}, [this] {
        if (!settleTaskPanel() || !confirmDiscard() ||
            !m_ncDocument->mayReplace(tr("Opening another job replaces them with its program.")))
            return;
        const QString path = m_prompter->openFileName(tr("Open job"), tr("CAM Workbench jobs (*.camwb)"));
        if (!path.isEmpty())
            openJob(path);
    });
    add({"Cam.File.Save", tr("&Save Job"), file, QKeySequence::Save, true}, [this] {
        const QString path = QString::fromStdString(m_workbench->document().path());
        if (path.isEmpty())
            m_actions->trigger(QStringLiteral("Cam.File.SaveAs"));
        else
            m_workbench->saveJob(path);
    });
    add({"Cam.File.SaveAs", tr("Save Job &As…"), file, QKeySequence::SaveAs}, [this] {
        const QString path = m_prompter->saveFileName(tr("Save job"), {}, tr("CAM Workbench jobs (*.camwb)"));
        if (!path.isEmpty())
            m_workbench->saveJob(path.endsWith(QLatin1String(".camwb")) ? path : path + QStringLiteral(".camwb"));
    });
    add({"Cam.File.ImportModel", tr("&Import Model…"), file, QKeySequence(Qt::CTRL | Qt::Key_I), true, true}, [this] {
        if (!settleTaskPanel())  // an open panel's references belong to the model being replaced
            return;
        const QString path = m_prompter->openFileName(
            tr("Import model"), tr("Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl);;All files (*)"));
        if (!path.isEmpty())
            m_workbench->importModel(path);
    });
    add({"Cam.File.Quit", tr("&Quit"), file, QKeySequence::Quit, false, true}, [this] { close(); });

    QAction* undo =
        add({"Cam.Edit.Undo", tr("&Undo"), edit, QKeySequence::Undo, true, true}, [this] { m_workbench->undo(); });
    QAction* redo =
        add({"Cam.Edit.Redo", tr("&Redo"), edit, QKeySequence::Redo, true}, [this] { m_workbench->redo(); });
    // Ctrl+Y beside the platform's redo keys (Ctrl+Shift+Z here): what users of other programs press.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (!redoKeys.contains(QKeySequence(Qt::CTRL | Qt::Key_Y)))
        redoKeys << QKeySequence(Qt::CTRL | Qt::Key_Y);
    redo->setShortcuts(redoKeys);
    // The step's name goes into the menu and the tooltip; the toolbar keeps its short label
    // (ActionRegistry fixes iconText), so it does not grow with the name.
    auto updateUndo = [this, undo, redo] {
        auto& stack = m_workbench->document().undoStack();
        undo->setEnabled(stack.canUndo());
        redo->setEnabled(stack.canRedo());
        undo->setText(stack.canUndo() ? tr("&Undo %1").arg(QString::fromStdString(stack.undoText())) : tr("&Undo"));
        redo->setText(stack.canRedo() ? tr("&Redo %1").arg(QString::fromStdString(stack.redoText())) : tr("&Redo"));
        undo->setToolTip(QString(undo->text()).remove(QLatin1Char('&')));
        redo->setToolTip(QString(redo->text()).remove(QLatin1Char('&')));
    };
    connect(m_workbench, &Workbench::jobChanged, this, updateUndo);
    updateUndo();

    using document::OperationKind;
    add({"Cam.Op.NewContour", tr("New &Contour…"), operation, QKeySequence(Qt::CTRL | Qt::Key_P), true, true},
        [this] { newOperation(OperationKind::Contour); });
    add({"Cam.Op.NewPocket", tr("New P&ocket…"), operation, {}, true}, [this] { newOperation(OperationKind::Pocket); });
    add({"Cam.Op.NewHelix", tr("New &Helix…"), operation, {}, true}, [this] { newOperation(OperationKind::Helix); });
    add({"Cam.Op.NewDrill", tr("New &Drilling…"), operation, {}, true}, [this] { newOperation(OperationKind::Drill); });
    add({"Cam.Op.NewSwarf", tr("New &Swarf (five-axis)…"), operation, {}, true},
        [this] { newOperation(OperationKind::Swarf); });
    add({"Cam.Op.NewPocket3d", tr("New 3D P&ocket…"), operation, {}, true},
        [this] { newOperation(OperationKind::Pocket3d); });
    add({"Cam.Op.NewWaterline", tr("New &Waterline…"), operation, {}, true},
        [this] { newOperation(OperationKind::Waterline); });
    add({"Cam.Op.NewParallel", tr("New P&arallel…"), operation, {}, true},
        [this] { newOperation(OperationKind::Parallel); });
    add({"Cam.Op.NewGroove", tr("New &Groove Roughing…"), operation, {}, true},
        [this] { newOperation(OperationKind::Groove); });
    // The foundation's profile is the contour now; the id stays for scripts (no menu entry).
    add({"Cam.Op.NewProfile", tr("New &Profile"), {}}, [this] { newOperation(OperationKind::Contour); });
    // Without a selected operation these say so where the user looks (the status bar).
    auto selected = [this] {
        const int index = m_jobTree->selectedOperation();
        if (index < 0)
            statusBar()->showMessage(tr("Select an operation in the job tree first."), 5000);
        return index;
    };
    add({"Cam.Op.Edit", tr("&Edit Operation…"), operation, QKeySequence(Qt::Key_F2)},
        [this, selected] { editOperation(selected()); });
    add({"Cam.Op.Delete", tr("&Delete Operation"), operation, QKeySequence::Delete},
        [this, selected] { m_workbench->removeOperation(selected()); });
    m_jobTree->registerActions(*m_actions, operation);

    registerJobSetupActions(*m_actions, [this] { editJobSetup(); });
    add({"Cam.Job.Post", tr("&Post"), jobMenu, QKeySequence(Qt::Key_F9), true, true}, [this] {
        if (m_ncDocument->mayReplace(tr("Posting the job replaces them with its program.")))
            m_workbench->post();
    });
    add({"Cam.Job.SaveNc", tr("&Save NC Program…"), jobMenu, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)}, [this] {
        if (!m_workbench->ncSavable())  // out of date or none: says why, asks for no file name
            return;
        const QString suffix = m_workbench->ncExtension();
        const std::string jobPath = m_workbench->document().path();
        QString suggested = QFileInfo(QString::fromStdString(jobPath)).completeBaseName() + '.' + suffix;
        if (const std::string own = document::jobOutputPath(m_workbench->job(), jobPath, suffix.toStdString());
            !own.empty() && !jobPath.empty())
            suggested = QString::fromStdString(own);  // the job's own output (job setup panel)
        const QString path = m_prompter->saveFileName(tr("Save NC program"), suggested,
                                                      tr("NC programs (*.%1);;All files (*)").arg(suffix));
        if (!path.isEmpty())
            m_workbench->saveNc(path);
    });
    registerSetupSheetActions(
        *m_actions, jobMenu, m_workbench, this, [this]() -> Prompter& { return *m_prompter; },
        [this] { return m_view->grabImage(); });

    registerPostSettingsActions(*m_actions, m_workbench, this);

    const QString nc = tr("&NC");
    add({"Cam.Nc.Open", tr("&Open NC Program…"), nc, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), true}, [this] {
        const QString path = m_prompter->openFileName(
            tr("Open NC program"), tr("NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;"
                                      "CL files (*.apt *.aptsource *.cl *.cls *.dump *.trace);;All files (*)"));
        if (!path.isEmpty())
            openNcFile(path);
    });
    add({"Cam.Nc.Save", tr("&Save NC File"), nc, QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S)}, [this] {
        // The posted program is not an editable file: it is saved with Save NC Program.
        if (m_editor->isReadOnly())
            m_actions->trigger(QStringLiteral("Cam.Job.SaveNc"));
        else
            m_ncDocument->save();
    });
    add({"Cam.Nc.Trace", tr("&Trace NC Program"), nc, QKeySequence(Qt::Key_F5), true},
        [this] { m_inspector->traceNow(); });
    registerNcEditorActions(
        *m_actions, m_editor, this, [this]() -> Prompter& { return *m_prompter; },
        [this] { return m_inspector->sharedMachine(); });
    setUpSimulator();

    add({"Cam.View.Isometric", tr("&Isometric"), view, QKeySequence(Qt::Key_0), true, true},
        [this] { m_view->setViewPreset(View3D::Preset::Isometric); });
    add({"Cam.View.Top", tr("&Top"), view, QKeySequence(Qt::Key_1), true},
        [this] { m_view->setViewPreset(View3D::Preset::Top); });
    add({"Cam.View.Front", tr("&Front"), view, QKeySequence(Qt::Key_2), true},
        [this] { m_view->setViewPreset(View3D::Preset::Front); });
    add({"Cam.View.Right", tr("&Right"), view, QKeySequence(Qt::Key_3), true},
        [this] { m_view->setViewPreset(View3D::Preset::Right); });
    add({"Cam.View.LatheXZ", tr("&XZ (lathe)"), view, QKeySequence(Qt::Key_4), true},
        [this] { m_view->setViewPreset(View3D::Preset::LatheXZ); });
    add({"Cam.View.FitAll", tr("Fit &All"), view, QKeySequence(Qt::Key_F), true}, [this] { m_view->fitAll(); });
    registerDockActions(view);
    registerFocusActions(*m_actions, *this, view);
    m_session = new Session(*this, file, edit);
    // Lengths in the tree follow the display unit (the panels take it when they open).
    connect(m_session, &Session::preferencesChanged, m_jobTree, &JobTree::rebuild);
    m_jobTree->rebuild();
    registerToolActions(
        *m_actions, *m_workbench, [this]() -> Prompter& { return *m_prompter; }, this);

    add({"Cam.Help.About", tr("&About CAM Workbench"), help}, [this] {
        QMessageBox::about(
            this, tr("About CAM Workbench"),
            tr("CAM Workbench %1\nCAM and post-processor workbench.").arg(QStringLiteral(CAMWB_VERSION)));
    });
}

void MainWindow::connectWorkbench()
{
    connect(m_workbench, &Workbench::message, m_report, &ReportView::append);
    connect(m_workbench, &Workbench::modelChanged, this, [this] {
        m_view->setModel(m_workbench->displayMesh());
        m_view->fitAll();
        m_fitWithToolpath = true;
    });
    connect(m_workbench, &Workbench::toolpathChanged, this, [this] {
        // Shown until the posted program's trace replaces it (or for good when chosen so).
        // A lathe job's path gives no Y: drawn in the turning plane (Y = 0), as the checks read it.
        if (document::jobNeedsModel(m_workbench->job()))
            m_view->setToolpath(m_workbench->toolpath());
        else
            m_view->setToolpath(sim::inTurningPlane(m_workbench->toolpath()));
        m_inspector->setShowInView(false);
        refreshToolList();
        // The first toolpath of a new model is fitted too; later ones keep the user's camera.
        if (std::exchange(m_fitWithToolpath, false))
            m_view->fitAll();
    });
    connect(m_workbench, &Workbench::ncChanged, this, [this] {
        if (!m_ncDocument->mayReplace(tr("The job's program, posted again, replaces them."))) {
            m_report->append(Workbench::Severity::Warning,
                             tr("The editor keeps the unsaved edits of %1; the job's new program is not shown "
                                "(Post shows it).")
                                 .arg(m_ncDocument->title()));
            return;
        }
        // The posted program is traced as the machine will read it; its name gives the dialect.
        const QString job = QString::fromStdString(m_workbench->document().path());
        const QString base = job.isEmpty() ? tr("posted") : QFileInfo(job).completeBaseName();
        m_editorShowsPosted = true;
        showProgramState();
        const auto machine = m_workbench->machine();
        m_inspector->setMachine(machine);
        m_inspector->setToolTable(m_workbench->toolTable());
        m_inspectorPanel->setMachineId(machine ? QString::fromStdString(machine->id) : QString());
        m_inspector->loadProgram(m_workbench->ncText(), base + '.' + m_workbench->ncExtension());
        m_ncDocument->showsPostedProgram();
    });
    connect(m_ncDocument, &NcDocument::message, m_report, &ReportView::append);
    connect(m_ncDocument, &NcDocument::titleChanged, this, &MainWindow::updateNcDockTitle);
    connect(m_workbench, &Workbench::programStateChanged, this, &MainWindow::showProgramState);
    connect(m_workbench, &Workbench::jobChanged, this, &MainWindow::updateTitle);
    connect(m_workbench, &Workbench::jobChanged, this,
            [this] { m_inspector->setTurningPlane(!document::jobNeedsModel(m_workbench->job())); });
    showJobSetupInView(*m_workbench, *m_view);
    connect(m_workbench, &Workbench::busyChanged, this, [this](bool busy) {
        m_progress->setVisible(busy);
        m_progress->setValue(0);
        statusBar()->showMessage(busy ? tr("Working…") : tr("Ready"));
    });
    connect(m_workbench, &Workbench::progress, this, [this](int percent, const QString& what) {
        m_progress->setValue(percent);
        statusBar()->showMessage(what);
    });
}

void MainWindow::connectInspector()
{
    m_inspector->attach(m_editor, m_view, m_inspectorPanel->modalPanel());
    connect(m_inspector, &NcInspector::message, m_report, &ReportView::append);
    connect(m_inspector, &NcInspector::busyChanged, this,
            [this](bool busy) { statusBar()->showMessage(busy ? tr("Tracing the NC program…") : tr("Ready")); });
    connect(m_inspector, &NcInspector::traceFinished, this, [this] {
        // A trace that drew nothing (an interpreter error on the first block) leaves the
        // operations' toolpath in view; the report says why.
        const auto trace = m_inspector->trace();
        const toolpath::ToolpathStats stats = toolpath::statistics(trace->program);
        const bool drawable = stats.rapids + stats.lines + stats.arcs + stats.helices + stats.cycles > 0;
        if (m_inspectorPanel->showsNcTrace() && (drawable || m_workbench->toolpath().empty()))
            m_inspector->setShowInView(true);
        if (std::exchange(m_fitWithTrace, false))
            m_view->fitAll();
        refreshToolList();
    });
    connect(m_inspector, &NcInspector::pickedInSubprogram, this, [this](const QString& where) {
        statusBar()->showMessage(tr("Segment from the called program %1; the editor shows its call.").arg(where), 5000);
    });
    connect(m_inspectorPanel, &InspectorPanel::dialectChosen, m_inspector, &NcInspector::setDialect);
    connect(m_inspectorPanel, &InspectorPanel::machineChosen, this, &MainWindow::traceOnMachine);
    fillMachineList();
    connect(m_inspectorPanel, &InspectorPanel::toolVisibilityChanged, m_view, &View3D::setToolVisible);
    connect(m_inspectorPanel, &InspectorPanel::showNcTraceChosen, this, [this](bool show) {
        if (show) {
            m_inspector->setShowInView(true);
        } else {
            m_inspector->setShowInView(false);
            m_view->setToolpath(m_workbench->toolpath());
        }
        refreshToolList();
    });
}

// The machines of the machine folders, by name; a file that does not load is reported, not offered.
void MainWindow::fillMachineList()
{
    std::vector<std::pair<QString, QString>> machines;
    for (const base::DataFile& file : kinematics::listMachineFiles()) {
        auto machine = kinematics::loadMachine(file.path);
        if (!machine) {
            m_report->append(Workbench::Severity::Warning, QString::fromStdString(machine.error().toString()));
            continue;
        }
        const std::string& name = machine.value().name;
        machines.emplace_back(QString::fromStdString(file.id), QString::fromStdString(name.empty() ? file.id : name));
    }
    m_inspectorPanel->setMachines(machines);
}

// The program in the editor traced again on the machine the user chose (a standalone five-axis
// program needs its machine's kinematics; a posted one starts on its job's machine).
void MainWindow::traceOnMachine(const QString& id)
{
    std::shared_ptr<const kinematics::Machine> machine;
    if (!id.isEmpty()) {
        auto found = kinematics::findMachine(id.toStdString(), kinematics::defaultMachineDirs());
        if (!found) {
            m_report->append(Workbench::Severity::Error, QString::fromStdString(found.error().toString()));
            m_prompter->showError(tr("Machine"), QString::fromStdString(found.error().toString()));
            m_inspectorPanel->setMachineId(m_inspector->machine() ? QString::fromStdString(m_inspector->machine()->id)
                                                                  : QString());
            return;
        }
        machine = std::make_shared<const kinematics::Machine>(std::move(found).value());
    }
    m_inspector->setMachine(std::move(machine));
    m_inspector->traceNow();
    m_report->append(Workbench::Severity::Note, id.isEmpty()
                                                    ? tr("The NC program is traced without a machine")
                                                    : tr("The NC program is traced on the machine %1").arg(id));
}

// The simulator plays what the editor holds (gui/sim/SimRequest.h says with which stock).
void MainWindow::setUpSimulator()
{
    m_simPlayer->attach(m_editor, m_view, m_simDock->chart());
    auto request = [this]() -> std::optional<SimRunRequest> {
        QString why;
        auto what = simulationRequest(*m_inspector, *m_workbench, m_editorShowsPosted, m_simDock->resolutionMm(), &why);
        if (!what)
            m_report->append(Workbench::Severity::Error, why);
        m_simDockWidget->setVisible(true);
        m_simDockWidget->raise();
        return what;
    };
    registerSimulatorActions(
        *m_actions, m_simPlayer, request, [this] { return m_simDock->lineToJumpTo(); },
        [this] { m_simDock->importMeasured(*m_prompter); });
    m_simDock->addActions(*m_actions);
    connect(m_simPlayer, &SimPlayer::message, m_report, &ReportView::append);
    connect(m_workbench, &Workbench::modelChanged, m_simPlayer, &SimPlayer::clear);
}

void MainWindow::refreshToolList()
{
    std::vector<int> hidden;
    for (int tool : m_view->toolpathTools())
        if (!m_view->isToolVisible(tool))
            hidden.push_back(tool);
    m_inspectorPanel->setTools(m_view->toolpathTools(), hidden);
}

void MainWindow::updateTitle()
{
    const QString path = QString::fromStdString(m_workbench->document().path());
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(
        tr("%1%2 — CAM Workbench").arg(name, m_workbench->document().isModified() ? QStringLiteral("*") : QString()));
}

void MainWindow::editOperation(int index)
{
    if (index < 0 || index >= static_cast<int>(m_workbench->job().operations.size()) || !settleTaskPanel())
        return;
    openTaskPanel(index, m_workbench->job().operations[static_cast<std::size_t>(index)], std::nullopt);
}

bool MainWindow::newOperation(document::OperationKind kind)
{
    if (!settleTaskPanel())
        return false;
    auto proposal = proposeOperation(kind, m_workbench->job(), m_workbench->model(), m_view->overlay().selectedFaces());
    if (!proposal) {
        QString text = QString::fromStdString(proposal.error().toString());
        if (!m_workbench->modelProblem().isEmpty())
            text = tr("The job's model is not loaded: %1").arg(m_workbench->modelProblem());
        m_report->append(Workbench::Severity::Error, text);
        m_prompter->showError(tr("New operation"), text);
        return false;
    }
    m_view->overlay().setSelectedFaces({});  // taken into the operation
    openTaskPanel(-1, proposal->operation, proposal->newTool);
    return true;
}

void MainWindow::openTaskPanel(int index, const document::Operation& operation,
                               const std::optional<ops::ToolController>& newTool)
{
    closeTaskPanel();
    m_taskPanel = OperationPanel::create(*m_workbench, &m_view->overlay(), index, operation, newTool, m_taskDock);
    connect(m_taskPanel, &OperationPanel::closed, this, &MainWindow::closeTaskPanel);
    // A groove's contour follows its panel, as its preview does (the job's again on close).
    auto showSection = [this](const document::Job& job) {
        if (auto section = latheSectionOf(job))
            m_view->setLatheSection(section);
    };
    connect(m_taskPanel, &OperationPanel::edited, this, [this, showSection] {
        if (m_taskPanel != nullptr)
            showSection(m_taskPanel->editedJob());
    });
    connect(m_taskPanel, &OperationPanel::closed, this, [this] {
        m_view->setLatheSection(latheSectionOf(m_workbench->job()));
        m_view->setToolpathShown(true);
    });
    showSection(m_taskPanel->editedJob());
    // A turning preview is drawn in the backplot's red and green: the job's path would read as it.
    m_view->setToolpathShown(!document::isTurningKind(operation.kind()));
    m_taskDock->setWidget(m_taskPanel);
    m_taskDock->setWindowTitle(tr("Task: %1").arg(QString::fromStdString(operation.name())));
    m_taskDock->show();
    m_taskDock->raise();
}

void MainWindow::editJobSetup()
{
    if (!settleTaskPanel())
        return;
    closeTaskPanel();
    m_jobSetupPanel = new JobSetupPanel(*m_workbench, &m_view->overlay(), m_taskDock);
    connect(m_jobSetupPanel, &JobSetupPanel::closed, this, &MainWindow::closeTaskPanel);
    connect(m_jobSetupPanel, &JobSetupPanel::importRequested, this, [this] {
        // The setup panel stays open over an import: it holds no references into the model.
        const QScopedValueRollback keep(m_importingFromSetup, true);
        m_actions->trigger(QStringLiteral("Cam.File.ImportModel"));
    });
    m_taskDock->setWidget(m_jobSetupPanel);
    m_taskDock->setWindowTitle(tr("Task: Job setup"));
    m_taskDock->show();
    m_taskDock->raise();
}

void MainWindow::closeTaskPanel()
{
    if (m_jobSetupPanel != nullptr) {
        JobSetupPanel* setup = std::exchange(m_jobSetupPanel, nullptr);
        setup->reject();  // no-op after OK or Cancel
        m_taskDock->hide();
        m_taskDock->setWidget(new QWidget(m_taskDock));
        setup->deleteLater();
    }
    if (m_taskPanel == nullptr)
        return;
    OperationPanel* panel = std::exchange(m_taskPanel, nullptr);
    panel->reject();  // no-op after OK or Cancel
    m_taskDock->hide();
    m_taskDock->setWidget(new QWidget(m_taskDock));
    panel->deleteLater();
}

bool MainWindow::settleTaskPanel()
{
    if (m_jobSetupPanel != nullptr && !m_importingFromSetup) {
        if (m_jobSetupPanel->hasUnappliedChanges()) {
            const Prompter::Answer answer =
                m_prompter->ask({tr("Unapplied changes"), tr("The job setup panel has changes that are not applied."),
                                 tr("Apply"), tr("Discard")});
            if (answer == Prompter::Answer::Cancel)
                return false;
            if (answer == Prompter::Answer::Accept)
                m_jobSetupPanel->accept();
        }
        closeTaskPanel();
    }
    if (m_taskPanel == nullptr)
        return true;
    if (m_taskPanel->hasUnappliedChanges()) {
        const Prompter::Answer answer =
            m_prompter->ask({tr("Unapplied changes"),
                             tr("The task panel of \"%1\" has changes that are not applied.")
                                 .arg(QString::fromStdString(m_taskPanel->operation().name())),
                             tr("Apply"), tr("Discard")});
        if (answer == Prompter::Answer::Cancel)
            return false;
        if (answer == Prompter::Answer::Accept && !m_taskPanel->accept())
            return false;  // cannot be made: the panel stays open and says why
    }
    closeTaskPanel();
    return true;
}

bool MainWindow::confirmDiscard()
{
    if (!m_workbench->document().isModified())
        return true;
    const Prompter::Answer answer =
        m_prompter->ask({tr("Unsaved changes"), tr("The job has changes that are not saved. Save them?"), {}, {}});
    if (answer != Prompter::Answer::Accept)
        return answer == Prompter::Answer::Discard;
    m_actions->trigger(QStringLiteral("Cam.File.Save"));
    return !m_workbench->document().isModified();  // saved, not cancelled in the file dialog
}

void MainWindow::registerDockActions(const QString& viewMenu)
{
    // The docks' own show/hide actions, so a closed dock comes back from the View menu.
    const std::pair<const char*, const char*> docks[]{{"Cam.View.JobDock", "jobDock"},
                                                      {"Cam.View.NcDock", "ncDock"},
                                                      {"Cam.View.InspectorDock", "modalDock"},
                                                      {"Cam.View.ReportDock", "reportDock"},
                                                      {"Cam.View.SimDock", "simDock"}};
    bool first = true;
    for (const auto& [id, name] : docks) {
        auto* dock = findChild<QDockWidget*>(QLatin1String(name));
        m_actions->adopt({QLatin1String(id), dock->windowTitle(), viewMenu, {}, false, std::exchange(first, false)},
                         dock->toggleViewAction());
    }
}

void MainWindow::showProgramState()
{
    const QString& problem = m_workbench->programProblem();
    // The first reason in the banner (a long list would hide the view); all of them in its
    // tooltip, and each failing operation's in the job tree.
    const QStringList reasons = problem.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QString first = reasons.value(0);
    if (reasons.size() > 1)
        first += tr(" (and %n more, see the job tree)", nullptr, static_cast<int>(reasons.size() - 1));
    QString text;
    if (!problem.isEmpty())
        text = m_workbench->ncText().isEmpty() ? tr("No NC program: %1").arg(first)
                                               : tr("Out of date — the last post failed; this is the previous "
                                                    "program and it cannot be saved:\n%1")
                                                     .arg(first);
    // Only while the editor (and so the view's trace) shows the posted program, not an NC file
    // opened apart.
    m_viewBanner->setMessage(m_editorShowsPosted ? text : QString(), problem);
    m_ncBanner->setMessage(m_editorShowsPosted ? text : QString(), problem);
    updateNcDockTitle();
}

// The program's name (with * while it has unsaved edits) and whether it is out of date.
void MainWindow::updateNcDockTitle()
{
    const QString title = m_ncDocument->title();
    QString text = title.isEmpty() ? tr("NC program") : tr("NC program — %1").arg(title);
    if (m_editorShowsPosted && !m_workbench->programProblem().isEmpty())
        text += tr(" (out of date)");
    m_ncDock->setWindowTitle(text);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_ncDocument->mayReplace(tr("Closing the window loses them."))) {
        event->ignore();
        return;
    }
    if (settleTaskPanel() && confirmDiscard())
        event->accept();
    else
        event->ignore();
}

}  // namespace camwb::gui
