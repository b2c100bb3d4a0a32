#include "gui/view3d/TaskOverlay.h"

#include "gui/view3d/detail/ModelActors.h"
#include "gui/view3d/detail/ToolpathScene.h"
#include "toolpath/ToolpathPolylines.h"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>

namespace camwb::gui {

namespace {

// Orange: apart from the backplot's red/green/blue and the inspector's yellow highlight.
constexpr double kPreviewCutColor[3]{1.0, 0.45, 0.0};
constexpr double kPreviewRapidColor[3]{0.95, 0.65, 0.35};
constexpr double kSelectedFaceColor[3]{0.30, 0.80, 0.35};
constexpr std::size_t kThickPreviewSegments = 100000;
constexpr double kLatheFeedColor[3]{kFeedRgb[0] / 255.0, kFeedRgb[1] / 255.0, kFeedRgb[2] / 255.0};

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
    vtkSmartPointer<vtkActor> model;
    std::vector<int> selected;
    std::optional<base::Vec3> pickedPoint;

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

void TaskOverlay::showPreview(std::shared_ptr<const ToolpathScene> scene, bool lathe)
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
                d->previewActors.push_back(lineActor(part.rapid, lathe ? kRapidColor : kPreviewRapidColor, 1.0f));
            if (part.cut)
                d->previewActors.push_back(lineActor(part.cut, lathe ? kLatheFeedColor : kPreviewCutColor, width));
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

const toolpath::ToolpathPolylines* TaskOverlay::previewPolylines() const
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

const std::optional<base::Vec3>& TaskOverlay::pickedPoint() const { return d->pickedPoint; }

void TaskOverlay::setPickedPoint(const std::optional<base::Vec3>& point)
{
    d->pickedPoint = point;
    emit pointPicked();
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

void TaskOverlay::setModel(vtkActor* model)
{
    d->model = model;
    d->selected.clear();
    rebuildSelection();
    emit selectionChanged();
}

void TaskOverlay::rebuildSelection()
{
    auto* data = d->model ? vtkPolyData::SafeDownCast(d->model->GetMapper()->GetInput()) : nullptr;
    auto* faceOf = data ? vtkIntArray::SafeDownCast(data->GetCellData()->GetArray("face")) : nullptr;
    if (faceOf == nullptr) {
        d->render();
        return;
    }
    vtkMapper* mapper = d->model->GetMapper();
    if (d->selected.empty()) {
        mapper->ScalarVisibilityOff();  // the property's grey for every face
    } else {
        // One colour per triangle: the model's grey, the selected faces' green.
        vtkNew<vtkUnsignedCharArray> colors;
        colors->SetName("selection");
        colors->SetNumberOfComponents(3);
        colors->SetNumberOfTuples(data->GetNumberOfCells());
        auto byte = [](double c) { return static_cast<unsigned char>(c * 255.0 + 0.5); };
        for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
            const bool picked =
                std::find(d->selected.begin(), d->selected.end(), faceOf->GetValue(cell)) != d->selected.end();
            const double* color = picked ? kSelectedFaceColor : kModelColor;
            colors->SetTypedTuple(cell,
                                  std::array<unsigned char, 3>{byte(color[0]), byte(color[1]), byte(color[2])}.data());
        }
        data->GetCellData()->SetScalars(colors);
        mapper->SetScalarModeToUseCellData();
        mapper->SetColorModeToDirectScalars();
        mapper->ScalarVisibilityOn();
    }
    d->render();
}

}  // namespace camwb::gui
