#include "gui/view3d/detail/SetupActors.h"

#include "gui/view3d/detail/ModelActors.h"

#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <cmath>
#include <numbers>

namespace camwb::gui {

namespace {

constexpr double kStockColor[3]{0.93, 0.72, 0.35};  // raw material: a warm tone over the grey model
constexpr double kStockOpacity = 0.22;              // the model stays visible through it
constexpr int kCylinderSides = 72;

// A prism over a closed outline in XY from zMin to zMax: side quads, bottom and top polygons.
vtkSmartPointer<vtkPolyData> prism(const std::vector<base::Vec2>& outline, double zMin, double zMax)
{
    vtkNew<vtkPoints> points;
    const auto n = static_cast<vtkIdType>(outline.size());
    for (const base::Vec2& p : outline)
        points->InsertNextPoint(p.x, p.y, zMin);
    for (const base::Vec2& p : outline)
        points->InsertNextPoint(p.x, p.y, zMax);
    vtkNew<vtkCellArray> polys;
    for (vtkIdType i = 0; i < n; ++i) {
        const vtkIdType j = (i + 1) % n;
        const vtkIdType quad[4]{i, j, n + j, n + i};
        polys->InsertNextCell(4, quad);
    }
    std::vector<vtkIdType> bottom, top;
    for (vtkIdType i = n; i-- > 0;)
        bottom.push_back(i);  // facing -Z
    for (vtkIdType i = 0; i < n; ++i)
        top.push_back(n + i);
    polys->InsertNextCell(n, bottom.data());
    polys->InsertNextCell(n, top.data());
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(polys);
    return data;
}

}  // namespace

vtkSmartPointer<vtkActor> makeStockActor(const base::Box3& box, bool cylinder)
{
    std::vector<base::Vec2> outline;
    if (cylinder) {
        const double cx = (box.min.x + box.max.x) / 2, cy = (box.min.y + box.max.y) / 2;
        const double r = (box.max.x - box.min.x) / 2;
        for (int i = 0; i < kCylinderSides; ++i) {
            const double a = 2 * std::numbers::pi * i / kCylinderSides;
            outline.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
        }
    } else {
        outline = {{box.min.x, box.min.y}, {box.max.x, box.min.y}, {box.max.x, box.max.y}, {box.min.x, box.max.y}};
    }
    vtkSmartPointer<vtkActor> actor = makeActor(prism(outline, box.min.z, box.max.z));
    vtkProperty* property = actor->GetProperty();
    property->SetColor(kStockColor[0], kStockColor[1], kStockColor[2]);
    property->SetOpacity(kStockOpacity);
    property->SetAmbient(0.3);
    actor->PickableOff();  // clicks pick the model's faces and the backplot through it
    return actor;
}

vtkSmartPointer<vtkAxesActor> makeWorkAxes(double length)
{
    auto axes = vtkSmartPointer<vtkAxesActor>::New();
    axes->SetTotalLength(length, length, length);
    axes->SetShaftTypeToCylinder();
    axes->SetCylinderRadius(0.02);
    axes->SetConeRadius(0.3);
    for (vtkCaptionActor2D* caption :
         {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(), axes->GetZAxisCaptionActor2D()}) {
        caption->GetCaptionTextProperty()->SetFontSize(13);
        caption->GetCaptionTextProperty()->BoldOn();
        caption->GetCaptionTextProperty()->ShadowOff();
        caption->GetCaptionTextProperty()->SetColor(0.05, 0.05, 0.05);
        caption->GetTextActor()->SetTextScaleModeToNone();
    }
    axes->PickableOff();
    return axes;
}

}  // namespace camwb::gui
