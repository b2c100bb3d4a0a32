#include "gui/view3d/TaskOverlay.h"

#include "gui/view3d/ToolpathPolylines.h"
#include "gui/view3d/detail/ToolpathScene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <algorithm>

namespace camwb::gui {

namespace {

// Orange: apart from the backplot's red/green/blue and the inspector's yellow highlight.
constexpr double kPreviewCutColor[3]{1.0, 0.45, 0.0};
constexpr double kPreviewRapidColor[3]{0.95, 0.65, 0.35};
constexpr double kSelectedFaceColor[3]{0.30, 0.80, 0.35};
constexpr std::size_t kThickPreviewSegments = 100000;

vtkSmartPointer<vtkActor> lineActor(vtkPolyData* data, const double color[3], float width)
{
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    // Drawn over the backplot and the model where they coincide (a contour on the face's edge).
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -6.0);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    // Plain wide lines, not tubes: a pocket preview has a million segments.
    actor->GetProperty()->SetLineWidth(width);
    actor->GetProperty()->LightingOff();
    actor->PickableOff();
    return actor;
}

}  // namespace

struct TaskOverlay::Private {
    vtkRenderer* renderer = nullptr;
    std::function<void()> render;
    std::shared_ptr<const ToolpathScene> preview;
    std::vector<vtkSmartPointer<vtkActor>> previewActors;
    vtkSmartPointer<vtkPolyData> model;
    std::vector<int> selected;
    vtkSmartPointer<vtkActor> selectionActor;

    void remove(vtkSmartPointer<vtkActor>& actor)
    {
        if (actor && renderer != nullptr)
            renderer->RemoveActor(actor);
        actor = nullptr;
    }
};

TaskOverlay::TaskOverlay(vtkRenderer* renderer, std::function<void()> render, QObject* parent) :
    QObject(parent),
    d(std::make_unique<Private>())
{
    d->renderer = renderer;
    d->render = std::move(render);
}

TaskOverlay::~TaskOverlay() = default;

void TaskOverlay::showPreview(std::shared_ptr<const ToolpathScene> scene)
{
    for (vtkSmartPointer<vtkActor>& actor : d->previewActors)
        d->remove(actor);
    d->previewActors.clear();
    d->preview = scene && !scene->polylines().empty() ? std::move(scene) : nullptr;
    if (d->preview) {
        // Wide lines cost a pass each on software GL; a dense preview reads as well thin.
        const float width = d->preview->polylines().segments().size() > kThickPreviewSegments ? 1.0f : 2.0f;
        for (const ToolpathScene::Part& part : d->preview->parts()) {
            if (part.rapid)
                d->previewActors.push_back(lineActor(part.rapid, kPreviewRapidColor, 1.0f));
            if (part.cut)
                d->previewActors.push_back(lineActor(part.cut, kPreviewCutColor, width));
        }
        for (const vtkSmartPointer<vtkActor>& actor : d->previewActors)
            d->renderer->AddActor(actor);
    }
    d->render();
}

void TaskOverlay::clearPreview() { showPreview(nullptr); }

int TaskOverlay::previewSegmentCount() const
{
    return d->preview ? static_cast<int>(d->preview->polylines().segments().size()) : 0;
}

const ToolpathPolylines* TaskOverlay::previewPolylines() const
{
    return d->preview ? &d->preview->polylines() : nullptr;
}

const std::vector<int>& TaskOverlay::selectedFaces() const { return d->selected; }

void TaskOverlay::setSelectedFaces(std::vector<int> faces)
{
    if (faces == d->selected)
        return;
    d->selected = std::move(faces);
    rebuildSelection();
    emit selectionChanged();
}

void TaskOverlay::clickFace(int face, bool toggle)
{
    std::vector<int> faces = toggle ? d->selected : std::vector<int>{};
    if (face > 0) {
        const auto at = std::find(faces.begin(), faces.end(), face);
        if (at != faces.end())
            faces.erase(at);
        else
            faces.push_back(face);
    }
    setSelectedFaces(std::move(faces));
}

void TaskOverlay::setModel(vtkPolyData* model)
{
    d->model = model;
    d->selected.clear();
    rebuildSelection();
    emit selectionChanged();
}

void TaskOverlay::rebuildSelection()
{
    d->remove(d->selectionActor);
    auto* faceOf = d->model ? vtkIntArray::SafeDownCast(d->model->GetCellData()->GetArray("face")) : nullptr;
    if (faceOf != nullptr && !d->selected.empty()) {
        vtkNew<vtkCellArray> triangles;
        vtkNew<vtkIdList> ids;
        for (vtkIdType cell = 0; cell < d->model->GetNumberOfCells(); ++cell) {
            const int face = faceOf->GetValue(cell);
            if (std::find(d->selected.begin(), d->selected.end(), face) == d->selected.end())
                continue;
            d->model->GetCellPoints(cell, ids);
            triangles->InsertNextCell(ids);
        }
        vtkNew<vtkPolyData> data;
        data->SetPoints(d->model->GetPoints());
        data->GetPointData()->SetNormals(d->model->GetPointData()->GetNormals());
        data->SetPolys(triangles);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(data);
        mapper->ScalarVisibilityOff();
        // In front of the model's own (pushed back) faces, behind its feature edges.
        mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(0.0, 0.0);
        d->selectionActor = vtkSmartPointer<vtkActor>::New();
        d->selectionActor->SetMapper(mapper);
        d->selectionActor->GetProperty()->SetColor(kSelectedFaceColor[0], kSelectedFaceColor[1], kSelectedFaceColor[2]);
        d->selectionActor->GetProperty()->SetAmbient(0.3);
        d->selectionActor->PickableOff();
        d->renderer->AddActor(d->selectionActor);
    }
    d->render();
}

}  // namespace camwb::gui
