#include "gui/shell/MainWindow.h"

#include "base/AtomicFile.h"
#include "camwb_version.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/NcEditorActions.h"
#include "gui/inspector/InspectorPanel.h"
#include "gui/inspector/ModalStatePanel.h"
#include "gui/inspector/NcInspector.h"
#include "gui/shell/JobTree.h"
#include "gui/shell/NcDocument.h"
#include "gui/shell/NewOperation.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/ReportView.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/OperationPanel.h"
#include "gui/view3d/TaskOverlay.h"
#include "gui/view3d/View3D.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
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
    m_inspectorPanel(new InspectorPanel(this))
{
    setObjectName(QStringLiteral("mainWindow"));
    m_view->setObjectName(QStringLiteral("view3d"));
    m_editor->setObjectName(QStringLiteral("ncEditor"));
    m_editor->setReadOnly(true);
    setCentralWidget(m_view);

    QDockWidget* jobDock = addDock(this, tr("Job"), QStringLiteral("jobDock"), m_jobTree, Qt::LeftDockWidgetArea);
    QDockWidget* ncDock = addDock(this, tr("NC program"), QStringLiteral("ncDock"), m_editor, Qt::RightDockWidgetArea);
    m_ncDock = ncDock;
    QDockWidget* reportDock =
        addDock(this, tr("Report"), QStringLiteral("reportDock"), m_report, Qt::BottomDockWidgetArea);
    QDockWidget* modalDock =
        addDock(this, tr("NC inspector"), QStringLiteral("modalDock"), m_inspectorPanel, Qt::LeftDockWidgetArea);
    // Wide enough for a full NC block and the job tree's values; the 3D view takes the rest.
    // The task panel (FreeCAD's place for it): on the right, over the NC dock while open.
    m_taskDock = addDock(this, tr("Task"), QStringLiteral("taskDock"), new QWidget(this), Qt::RightDockWidgetArea);
    tabifyDockWidget(ncDock, m_taskDock);
    m_taskDock->hide();
    resizeDocks({jobDock, ncDock}, {330, 470}, Qt::Horizontal);
    resizeDocks({reportDock}, {140}, Qt::Vertical);
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

MainWindow::~MainWindow() = default;

void MainWindow::setPrompter(std::unique_ptr<Prompter> prompter)
{
    if (prompter)
        m_prompter = std::move(prompter);
}

bool MainWindow::openJob(const QString& path)
{
    if (!path.endsWith(QLatin1String(".camwb"), Qt::CaseInsensitive))
        return openNcFile(path);
    if (!m_ncDocument->mayReplace(
            tr("Opening the job %1 replaces them with its program.").arg(QFileInfo(path).fileName())))
        return false;
    return m_workbench->openJob(path);
}

bool MainWindow::openNcFile(const QString& path)
{
    if (!m_ncDocument->mayReplace(tr("Opening %1 replaces them.").arg(QFileInfo(path).fileName())))
        return false;
    auto text = base::readTextFile(path.toStdString());
    if (!text) {
        m_report->append(Workbench::Severity::Error, QString::fromStdString(text.error().toString()));
        return false;
    }
    m_fitWithTrace = true;
    m_inspector->loadProgram(QString::fromStdString(text.value()), QFileInfo(path).absoluteFilePath());
    m_ncDocument->openedFile(path);
    m_report->append(Workbench::Severity::Note, tr("Opened NC program %1").arg(path));
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
        if (!confirmDiscard() || !m_ncDocument->mayReplace(tr("Opening another job replaces them with its program.")))
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Open job"), {}, tr("CAM Workbench jobs (*.camwb)"));
        if (!path.isEmpty())
            m_workbench->openJob(path);
    });
    add({"Cam.File.Save", tr("&Save Job"), file, QKeySequence::Save, true}, [this] {
        const QString path = QString::fromStdString(m_workbench->document().path());
        if (path.isEmpty())
            m_actions->trigger(QStringLiteral("Cam.File.SaveAs"));
        else
            m_workbench->saveJob(path);
    });
    add({"Cam.File.SaveAs", tr("Save Job &As…"), file, QKeySequence::SaveAs}, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save job"), {}, tr("CAM Workbench jobs (*.camwb)"));
        if (!path.isEmpty())
            m_workbench->saveJob(path.endsWith(QLatin1String(".camwb")) ? path : path + QStringLiteral(".camwb"));
    });
    add({"Cam.File.ImportModel", tr("&Import Model…"), file, QKeySequence(Qt::CTRL | Qt::Key_I), true, true}, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Import model"), {}, tr("Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl);;All files (*)"));
        if (!path.isEmpty())
            m_workbench->importModel(path);
    });
    add({"Cam.File.Quit", tr("&Quit"), file, QKeySequence::Quit, false, true}, [this] { close(); });

    QAction* undo =
        add({"Cam.Edit.Undo", tr("&Undo"), edit, QKeySequence::Undo, true, true}, [this] { m_workbench->undo(); });
    QAction* redo =
        add({"Cam.Edit.Redo", tr("&Redo"), edit, QKeySequence::Redo, true}, [this] { m_workbench->redo(); });
    auto updateUndo = [this, undo, redo] {
        auto& stack = m_workbench->document().undoStack();
        undo->setEnabled(stack.canUndo());
        redo->setEnabled(stack.canRedo());
        undo->setText(stack.canUndo() ? tr("&Undo %1").arg(QString::fromStdString(stack.undoText())) : tr("&Undo"));
        redo->setText(stack.canRedo() ? tr("&Redo %1").arg(QString::fromStdString(stack.redoText())) : tr("&Redo"));
    };
    connect(m_workbench, &Workbench::jobChanged, this, updateUndo);
    updateUndo();

    using document::OperationKind;
    add({"Cam.Op.NewContour", tr("New &Contour…"), operation, QKeySequence(Qt::CTRL | Qt::Key_P), true, true},
        [this] { newOperation(OperationKind::Contour); });
    add({"Cam.Op.NewPocket", tr("New P&ocket…"), operation, {}, true}, [this] { newOperation(OperationKind::Pocket); });
    add({"Cam.Op.NewHelix", tr("New &Helix…"), operation, {}, true}, [this] { newOperation(OperationKind::Helix); });
    add({"Cam.Op.NewDrill", tr("New &Drilling…"), operation, {}, true}, [this] { newOperation(OperationKind::Drill); });
    // The foundation's profile is the contour now; the id stays for scripts (no menu entry).
    add({"Cam.Op.NewProfile", tr("New &Profile"), {}}, [this] { newOperation(OperationKind::Contour); });
    add({"Cam.Op.Edit", tr("&Edit Operation…"), operation, QKeySequence(Qt::Key_F2)},
        [this] { editOperation(m_jobTree->selectedOperation()); });
    add({"Cam.Op.Delete", tr("&Delete Operation"), operation, QKeySequence::Delete},
        [this] { m_workbench->removeOperation(m_jobTree->selectedOperation()); });

    add({"Cam.Job.Post", tr("&Post"), jobMenu, QKeySequence(Qt::Key_F9), true, true}, [this] {
        if (m_ncDocument->mayReplace(tr("Posting the job replaces them with its program.")))
            m_workbench->post();
    });
    add({"Cam.Job.SaveNc", tr("&Save NC Program…"), jobMenu, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)}, [this] {
        const QString suffix = m_workbench->ncExtension();
        const QString base = QFileInfo(QString::fromStdString(m_workbench->document().path())).completeBaseName();
        const QString path = QFileDialog::getSaveFileName(this, tr("Save NC program"), base + '.' + suffix,
                                                          tr("NC programs (*.%1);;All files (*)").arg(suffix));
        if (!path.isEmpty())
            m_workbench->saveNc(path);
    });

    const QString nc = tr("&NC");
    add({"Cam.Nc.Open", tr("&Open NC Program…"), nc, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), true}, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open NC program"), {},
            tr("NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;All files (*)"));
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
    registerNcEditorActions(*m_actions, m_editor, this, [this]() -> Prompter& { return *m_prompter; });

    add({"Cam.View.Isometric", tr("&Isometric"), view, QKeySequence(Qt::Key_0), true, true},
        [this] { m_view->setViewPreset(View3D::Preset::Isometric); });
    add({"Cam.View.Top", tr("&Top"), view, QKeySequence(Qt::Key_1), true},
        [this] { m_view->setViewPreset(View3D::Preset::Top); });
    add({"Cam.View.Front", tr("&Front"), view, QKeySequence(Qt::Key_2), true},
        [this] { m_view->setViewPreset(View3D::Preset::Front); });
    add({"Cam.View.Right", tr("&Right"), view, QKeySequence(Qt::Key_3), true},
        [this] { m_view->setViewPreset(View3D::Preset::Right); });
    add({"Cam.View.FitAll", tr("Fit &All"), view, QKeySequence(Qt::Key_F), true}, [this] { m_view->fitAll(); });

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
        m_view->setToolpath(m_workbench->toolpath());
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
        m_inspector->loadProgram(m_workbench->ncText(), base + '.' + m_workbench->ncExtension());
        m_ncDocument->showsPostedProgram();
    });
    connect(m_ncDocument, &NcDocument::message, m_report, &ReportView::append);
    connect(m_ncDocument, &NcDocument::titleChanged, this, [this](const QString& title) {
        m_ncDock->setWindowTitle(title.isEmpty() ? tr("NC program") : tr("NC program — %1").arg(title));
    });
    connect(m_workbench, &Workbench::jobChanged, this, &MainWindow::updateTitle);
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
    const auto& operations = m_workbench->job().operations;
    if (index < 0 || index >= static_cast<int>(operations.size()))
        return;
    openTaskPanel(index, operations[static_cast<std::size_t>(index)], std::nullopt);
}

bool MainWindow::newOperation(document::OperationKind kind)
{
    auto proposal = proposeOperation(kind, m_workbench->job(), m_workbench->model(), m_view->overlay().selectedFaces());
    if (!proposal) {
        m_report->append(Workbench::Severity::Error, QString::fromStdString(proposal.error().toString()));
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
    m_taskDock->setWidget(m_taskPanel);
    m_taskDock->setWindowTitle(tr("Task: %1").arg(QString::fromStdString(operation.name())));
    m_taskDock->show();
    m_taskDock->raise();
}

void MainWindow::closeTaskPanel()
{
    if (m_taskPanel == nullptr)
        return;
    OperationPanel* panel = std::exchange(m_taskPanel, nullptr);
    panel->reject();  // no-op after OK or Cancel
    m_taskDock->hide();
    m_taskDock->setWidget(new QWidget(m_taskDock));
    panel->deleteLater();
}

bool MainWindow::confirmDiscard()
{
    if (!m_workbench->document().isModified())
        return true;
    return QMessageBox::question(this, tr("Unsaved changes"), tr("Discard the unsaved changes of this job?")) ==
           QMessageBox::Yes;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_ncDocument->mayReplace(tr("Closing the window loses them."))) {
        event->ignore();
        return;
    }
    if (confirmDiscard())
        event->accept();
    else
        event->ignore();
}

}  // namespace camwb::gui
