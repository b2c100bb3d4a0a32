// What a task panel draws over the model in the 3D view, apart from the job's backplot: the live
// preview of the operation being edited (orange, thick, rapids thin) and the faces picked as the
// operation's geometry (the model's own triangles coloured green: a second surface at the same
// place would lose the depth test to the model). Owned by View3D (View3D::overlay()); VTK stays in the .cpp,
// so the data calls work without OpenGL too (headless tests).
#pragma once

#include "base/Vec.h"

#include <QObject>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace camwb::toolpath {
class ToolpathPolylines;
}

namespace camwb::gui {

class ToolpathScene;

class TaskOverlay : public QObject {
    Q_OBJECT
public:
    ~TaskOverlay() override;

    // Replaces the preview; null or empty clears it. Prepare the scene on a worker with
    // View3D::prepareToolpath (huge paths are simplified for display there, not here). Orange,
    // apart from the job's backplot; `lathe`: in the backplot's own rapid red and feed green, as
    // SinuTrain draws a turning path (the main window hides the job's path meanwhile).
    void showPreview(std::shared_ptr<const ToolpathScene> scene, bool lathe = false);
    void clearPreview();
    int previewSegmentCount() const;                              // exact segments; 0 when no preview is shown
    const toolpath::ToolpathPolylines* previewPolylines() const;  // nullptr when no preview is shown

    // Model faces (1-based) picked in the view, in picking order.
    const std::vector<int>& selectedFaces() const;
    void setSelectedFaces(std::vector<int> faces);
    // A click on `face` (0 = on nothing): alone it selects just that face (nothing clears);
    // `toggle` (Ctrl held) adds or removes it and keeps the rest.
    void clickFace(int face, bool toggle);
    // Where the last click met the model (work coordinates; none: it met nothing). A click on the
    // face already selected changes no selection but picks a new point, hence a signal of its own.
    const std::optional<base::Vec3>& pickedPoint() const;
    void setPickedPoint(const std::optional<base::Vec3>& point);

signals:
    void selectionChanged();
    void pointPicked();

private:
    friend class View3D;
    TaskOverlay(vtkRenderer* renderer, std::function<void()> render, QObject* parent);
    // The model's actor (triangles with a "face" cell array); null when the model is cleared.
    void setModel(vtkActor* model);
    void rebuildSelection();

    struct Private;
    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
