// The main window only assembles: the 3D view in the centre, docks for the job tree, the NC
// editor and the report, menus and toolbar built from the action registry.
#pragma once

#include "document/Job.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class QDockWidget;
class QProgressBar;

namespace camwb::gui {

class ActionRegistry;
class Banner;
class InspectorPanel;
class NcInspector;
class JobSetupPanel;
class JobTree;
class NcDocument;
class NcEditor;
class OperationPanel;
class Prompter;
class ReportView;
class SimDock;
class Session;
class SimPlayer;
class View3D;
class Workbench;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Workbench& workbench() { return *m_workbench; }
    ActionRegistry& actions() { return *m_actions; }
    View3D* view() const { return m_view; }
    NcEditor* ncEditor() const { return m_editor; }
    // The editor's program as a document: its file, unsaved edits, Save and the prompt before loss.
    NcDocument* ncDocument() const { return m_ncDocument; }
    ReportView* reportView() const { return m_report; }
    JobTree* jobTree() const { return m_jobTree; }
    NcInspector* inspector() const { return m_inspector; }
    InspectorPanel* inspectorPanel() const { return m_inspectorPanel; }
    SimPlayer* simPlayer() const { return m_simPlayer; }
    SimDock* simDock() const { return m_simDock; }
    // The open task panel (docked on the right), or nullptr.
    OperationPanel* taskPanel() const { return m_taskPanel; }
    // Asks the user's questions and shows the errors that stop an action (dialogs by default;
    // tests put in one that answers by itself).
    Prompter& prompter() const { return *m_prompter; }
    void setPrompter(std::unique_ptr<Prompter> prompter);

    // A .camwb job, or any other file as an NC program (openNcFile). False when it cannot be opened
    // or the user keeps the editor's unsaved edits (Cancel).
    bool openJob(const QString& path);
    // Reads an NC program of any dialect into the editor (editable) and traces it. False when it
    // cannot be read or the user keeps the editor's unsaved edits (Cancel).
    bool openNcFile(const QString& path);
    // Opens the task panel of operation `index`; a panel already open with unapplied changes is
    // first settled (settleTaskPanel), else replaced.
    void editOperation(int index);
    // Proposes an operation of `kind` from the faces picked in the 3D view (or the model's
    // defaults) and opens its panel; OK adds it. False (shown) when the model has nothing, or
    // when the user keeps the open panel's unapplied changes.
    bool newOperation(document::OperationKind kind);
    // Closes the open task panel; with unapplied changes the user is asked first: Apply (refused
    // when the operation cannot be made), Discard, or Cancel (false: the panel stays).
    bool settleTaskPanel();
    // When the job has unsaved changes, asks whether to save them: false when the user cancels
    // (or the save did not happen), true when saved or discarded.
    bool confirmDiscard();
    // New job, recent files, autosave and recovery, preferences (gui/shell/Session.h).
    Session& session() const { return *m_session; }
    // Opens the job setup task panel (gui/tasks/JobSetupPanel.h) after settling an open panel.
    void editJobSetup();
    JobSetupPanel* jobSetupPanel() const { return m_jobSetupPanel; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void registerActions();
    void connectWorkbench();
    void connectInspector();
    void setUpSimulator();
    void refreshToolList();
    void fillMachineList();
    void traceOnMachine(const QString& id);
    void updateTitle();
    void openTaskPanel(int index, const document::Operation& operation,
                       const std::optional<ops::ToolController>& newTool);
    void closeTaskPanel();
    void registerDockActions(const QString& viewMenu);
    void showProgramState();
    void updateNcDockTitle();

    std::unique_ptr<Prompter> m_prompter;
    Workbench* m_workbench;
    ActionRegistry* m_actions;
    View3D* m_view;
    NcEditor* m_editor;
    NcDocument* m_ncDocument;
    QDockWidget* m_ncDock = nullptr;
    ReportView* m_report;
    JobTree* m_jobTree;
    QProgressBar* m_progress;
    NcInspector* m_inspector;
    InspectorPanel* m_inspectorPanel;
    SimPlayer* m_simPlayer;
    SimDock* m_simDock = nullptr;
    QDockWidget* m_simDockWidget = nullptr;
    QDockWidget* m_taskDock = nullptr;
    OperationPanel* m_taskPanel = nullptr;
    Session* m_session = nullptr;
    JobSetupPanel* m_jobSetupPanel = nullptr;
    bool m_importingFromSetup = false;  // the setup panel's Import: it stays open
    Banner* m_viewBanner;
    Banner* m_ncBanner;
    bool m_editorShowsPosted = false;  // the editor holds the job's posted program (not an opened file)
    bool m_fitWithToolpath = false;
    bool m_fitWithTrace = false;
};

}  // namespace camwb::gui
