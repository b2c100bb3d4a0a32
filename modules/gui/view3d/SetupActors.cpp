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
#include <vtkTriangleFilter.h>

#include "geom/Profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::gui {

namespace {

constexpr double kStockColor[3]{0.93, 0.72, 0.35};  // raw material: a warm tone over the grey model
constexpr double kStockOpacity = 0.22;              // the model stays visible through it
constexpr int kCylinderSides = 72;
constexpr double kLatheStockOpacity = 0.35;           // flat: a little more than the 3D stock's
constexpr double kContourColor[3]{0.10, 0.10, 0.12};  // the part: drawn as on paper
constexpr double kOffsetColor[3]{0.15, 0.35, 0.85};   // what must stay after roughing
constexpr double kChordToleranceMm = 0.01;

// A point of the half-section in the view: X = radius, Y = `y`, Z along the spindle.
void insertLathePoint(vtkPoints* points, const base::Vec2& p, double y) { points->InsertNextPoint(p.y, y, p.x); }

bool finite(const base::Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

vtkSmartPointer<vtkActor> lineActor(const std::vector<base::Vec2>& line, bool closed, const double rgb[3], float width)
{
    vtkNew<vtkPoints> points;
    std::vector<vtkIdType> ids;
    for (const base::Vec2& p : line)
        if (finite(p)) {
            ids.push_back(points->GetNumberOfPoints());
            insertLathePoint(points, p, 0);
        }
    if (ids.size() < 2)
        return nullptr;
    if (closed)
        ids.push_back(ids.front());
    vtkNew<vtkCellArray> lines;
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    vtkSmartPointer<vtkActor> actor = makeActor(data);
    actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
    actor->GetProperty()->SetLineWidth(width);
    actor->GetProperty()->LightingOff();
    actor->PickableOff();
    return actor;
}

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

namespace {

vtkSmartPointer<vtkActor> stockLook(vtkSmartPointer<vtkActor> actor)
{
    vtkProperty* property = actor->GetProperty();
    property->SetColor(kStockColor[0], kStockColor[1], kStockColor[2]);
    property->SetOpacity(kStockOpacity);
    property->SetAmbient(0.3);
    actor->PickableOff();  // clicks pick the model's faces and the backplot through it
    return actor;
}

}  // namespace

vtkSmartPointer<vtkActor> makeStockActor(const sim::TriangleMesh& solid)
{
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(static_cast<vtkIdType>(solid.vertexCount()));
    for (std::size_t i = 0; i < solid.vertexCount(); ++i)
        points->SetPoint(static_cast<vtkIdType>(i), solid.positions[3 * i], solid.positions[3 * i + 1],
                         solid.positions[3 * i + 2]);
    vtkNew<vtkCellArray> polys;
    for (std::size_t t = 0; t < solid.triangleCount(); ++t) {
        const vtkIdType ids[3]{solid.triangles[3 * t], solid.triangles[3 * t + 1], solid.triangles[3 * t + 2]};
        polys->InsertNextCell(3, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(polys);
    return stockLook(makeActor(data));
}

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
    return stockLook(makeActor(prism(outline, box.min.z, box.max.z)));
}

std::vector<vtkSmartPointer<vtkActor>> makeLatheActors(const LatheSection& section)
{
    std::vector<vtkSmartPointer<vtkActor>> actors;
    std::vector<std::vector<base::Vec2>> loops;
    for (const geom::Region& region : section.stock) {
        loops.push_back(geom::discretize(region.outer, kChordToleranceMm));
        for (const geom::Profile& hole : region.holes)
            loops.push_back(geom::discretize(hole, kChordToleranceMm));
    }
    // Filled: the outer loops as polygons, triangulated (a groove makes them concave). Holes are
    // only outlined: a revolved stock reaches the axis, so it has none but a bored one's.
    double size = 0;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> polys;
    for (const geom::Region& region : section.stock) {
        std::vector<vtkIdType> ids;
        for (const base::Vec2& p : geom::discretize(region.outer, kChordToleranceMm)) {
            if (!finite(p))
                continue;
            size = std::max({size, std::abs(p.x), std::abs(p.y)});
            ids.push_back(points->GetNumberOfPoints());
            insertLathePoint(points, p, 0);
        }
        if (ids.size() >= 3)
            polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    if (polys->GetNumberOfCells() > 0) {
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
            double p[3];
            points->GetPoint(i, p);
            points->SetPoint(i, p[0], -1e-3 * std::max(size, 1.0), p[2]);
        }
        vtkNew<vtkPolyData> data;
        data->SetPoints(points);
        data->SetPolys(polys);
        vtkNew<vtkTriangleFilter> triangles;
        triangles->SetInputData(data);
        triangles->Update();
        vtkSmartPointer<vtkActor> fill = makeActor(triangles->GetOutput());
        fill->GetProperty()->SetColor(kStockColor[0], kStockColor[1], kStockColor[2]);
        fill->GetProperty()->SetOpacity(kLatheStockOpacity);
        fill->GetProperty()->LightingOff();
        fill->PickableOff();
        actors.push_back(fill);
    }
    constexpr double kStockEdge[3]{0.62, 0.42, 0.12};
    for (const auto& loop : loops)
        if (auto outline = lineActor(loop, true, kStockEdge, 1.5f))
            actors.push_back(outline);
    for (const auto& line : section.contours)
        if (auto contour = lineActor(line, false, kContourColor, 2.5f))
            actors.push_back(contour);
    for (const auto& line : section.offsetContours)
        if (auto offset = lineActor(line, false, kOffsetColor, 1.5f))
            actors.push_back(offset);
    return actors;
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
