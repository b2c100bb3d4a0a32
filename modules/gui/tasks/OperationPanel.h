// The task panel of one operation (like FreeCAD's task panel, docked on the right, not modal):
// name, tool, geometry, the kind's parameters, heights, and a live preview of the toolpath in the
// 3D view computed off the GUI thread (progress, Cancel). OK applies the edit as one undoable step
// (or adds the new operation) unless the preview shows the operation cannot be made; Cancel
// leaves the job as it was. Each kind adds its own rows
// (ContourPanel.cpp, PocketPanel.cpp, HelixPanel.cpp, DrillPanel.cpp, SwarfPanel.cpp,
// Pocket3dPanel.cpp, FinishingPanels.cpp, GroovePanel.cpp).
#pragma once

#include "document/Job.h"

#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace camwb::gui {

class GeometryList;
class HeightsBox;
class WorkingPlaneBox;
class ParamForm;
struct OperationPanelArgs;
class PreviewRunner;
class TaskOverlay;
class Workbench;

class OperationPanel : public QWidget {
    Q_OBJECT
public:
    // `index` of the operation in the job, or -1 for a new one (added on OK with `newTool`).
    // `overlay` (may be null) shows the preview and offers the picked faces.
    static OperationPanel* create(Workbench& workbench, TaskOverlay* overlay, int index,
                                  const document::Operation& operation,
                                  const std::optional<ops::ToolController>& newTool = {}, QWidget* parent = nullptr);
    ~OperationPanel() override;

    const document::Operation& operation() const { return m_op; }
    int operationIndex() const { return m_index; }
    PreviewRunner& preview() const { return *m_preview; }
    // "N lines, M arcs, K helices, C cycles", the error, or "Computing…".
    QString statusText() const;

    // OK: applies (one undo step) and closes. Refused (false, the reason in the status) when the
    // preview of the operation as it stands failed: an operation that cannot be made is not added.
    // While the preview is still computing it applies; the job's post then marks a failure.
    bool accept();
    void reject();  // Cancel: changes nothing and closes
    // Whether OK would change the job: the operation differs from what the panel opened with.
    bool hasUnappliedChanges() const;

    // The job as OK would make it (the edited operation in place, or added with its tool).
    document::Job editedJob() const;

signals:
    void closed();
    void edited();  // a parameter changed: editedJob() differs (the preview restarts)

protected:
    explicit OperationPanel(const OperationPanelArgs& args);
    // The kind's rows, bound to fields of m_op.params.
    virtual void buildParameters(ParamForm& form) = 0;
    virtual int geometryKinds() const = 0;                   // GeometryList::Kind flags; 0: no geometry box
    virtual bool takesWorkingPlane() const { return true; }  // false: the plane box is hidden
    virtual bool takesHeights() const { return true; }       // false: the heights box is hidden
    virtual void toolChanged() {}                            // after the tool combo changed m_op.toolNumber
    void parametersChanged();                                // restarts the preview
    // The tool the operation uses now (of the job, or the one to add with it), or nullptr.
    const ops::ToolController* selectedTool() const;

    document::Operation m_op;

private:
    document::Operation current() const;  // m_op with the name as typed
    void build();
    document::Job previewJob(int* index) const;
    void showOutcome();
    void setComputing(bool computing);
    void finish();

    Workbench& m_workbench;
    TaskOverlay* m_overlay;
    int m_index;
    std::optional<ops::ToolController> m_newTool;
    PreviewRunner* m_preview;
    std::unique_ptr<ParamForm> m_form;
    QLineEdit* m_name = nullptr;
    QComboBox* m_tool = nullptr;
    GeometryList* m_geometry = nullptr;
    HeightsBox* m_heights = nullptr;
    WorkingPlaneBox* m_plane = nullptr;
    QLabel* m_status = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancelCompute = nullptr;
    document::Operation m_original;
    bool m_finished = false;
    bool m_outcomeCurrent = false;  // the last preview is of the operation as it stands
};

}  // namespace camwb::gui
