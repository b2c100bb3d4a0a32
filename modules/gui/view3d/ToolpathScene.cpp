#include "gui/view3d/detail/ToolpathScene.h"

#include "toolpath/Toolpath.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace camwb::gui {

namespace {

// Distance of p from the segment a-b.
double distanceToChord(const base::Vec3& p, const base::Vec3& a, const base::Vec3& b)
{
    const base::Vec3 ab = b - a;
    const double lengthSquared = ab.dot(ab);
    double t = lengthSquared > 0 ? (p - a).dot(ab) / lengthSquared : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return base::distance(p, a + ab * t);
}

vtkSmartPointer<vtkPolyData> linesOf(vtkPoints* points, vtkCellArray* lines)
{
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    return data;
}

double distanceToSegment2d(double px, double py, double ax, double ay, double bx, double by)
{
    const double dx = bx - ax, dy = by - ay;
    const double lengthSquared = dx * dx + dy * dy;
    double t = lengthSquared > 0 ? ((px - ax) * dx + (py - ay) * dy) / lengthSquared : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

}  // namespace

bool ScreenProjection::project(const base::Vec3& p, double& x, double& y) const
{
    const double w = m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15];
    if (w <= 1e-12)
        return false;
    const double nx = (m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3]) / w;
    const double ny = (m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7]) / w;
    x = (nx + 1.0) * 0.5 * width;
    y = (1.0 - ny) * 0.5 * height;
    return true;
}

int ToolpathScene::nearestSegment(const ScreenProjection& projection, double x, double y, double tolerancePx,
                                  const std::set<int>& hiddenTools) const
{
    const auto& points = m_polylines.points();
    const auto& segments = m_polylines.segments();
    int best = -1;
    double bestDistance = tolerancePx;
    for (const Part& part : m_parts) {
        if (hiddenTools.count(part.tool) > 0)
            continue;
        for (const auto* list : {&part.cutSegments, &part.rapidSegments}) {
            for (std::uint32_t s : *list) {
                double ax = 0, ay = 0, bx = 0, by = 0;
                if (!projection.project(points[segments[s].from], ax, ay) ||
                    !projection.project(points[segments[s].to], bx, by))
                    continue;
                const double distance = distanceToSegment2d(x, y, ax, ay, bx, by);
                // Ties (shared end points) go to the later segment, the one drawn on top.
                if (distance < bestDistance || (distance == bestDistance && best >= 0 && int(s) > best)) {
                    bestDistance = distance;
                    best = static_cast<int>(s);
                }
            }
        }
    }
    return best;
}

std::shared_ptr<ToolpathScene> ToolpathScene::build(const toolpath::Toolpath& toolpath, double chordToleranceMm,
                                                    const std::vector<bool>& recordsInError)
{
    auto scene = std::make_shared<ToolpathScene>();
    scene->m_polylines = toolpath::ToolpathPolylines::fromToolpath(toolpath, chordToleranceMm, recordsInError);
    const toolpath::ToolpathPolylines& polylines = scene->m_polylines;
    if (polylines.empty())
        return scene;

    scene->m_points = vtkSmartPointer<vtkPoints>::New();
    scene->m_points->SetDataTypeToDouble();
    scene->m_points->SetNumberOfPoints(static_cast<vtkIdType>(polylines.points().size()));
    for (std::size_t i = 0; i < polylines.points().size(); ++i) {
        const base::Vec3& p = polylines.points()[i];
        scene->m_points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }

    // Parts in order of first use of their tool; most programs have a handful of tools.
    std::vector<std::size_t> partOfSegment;
    partOfSegment.reserve(polylines.segments().size());
    for (std::size_t s = 0; s < polylines.segments().size(); ++s) {
        const toolpath::PathSegment& segment = polylines.segments()[s];
        std::size_t index = 0;
        while (index < scene->m_parts.size() && scene->m_parts[index].tool != segment.tool)
            ++index;
        if (index == scene->m_parts.size())
            scene->m_parts.push_back({segment.tool, nullptr, nullptr, {}, {}});
        Part& part = scene->m_parts[index];
        (segment.kind == toolpath::PathSegmentKind::Rapid ? part.rapidSegments : part.cutSegments)
            .push_back(static_cast<std::uint32_t>(s));
        partOfSegment.push_back(index);
    }

    // Display cells: a software renderer needs seconds per frame for a million lines, so huge
    // programs are drawn simplified within a tolerance grown until the vertices fit the budget.
    // Picking and highlighting keep using the exact segments.
    double tolerance = kCollinearMm;
    const double diagonal = scene->boundsDiagonal();
    for (;;) {
        const std::size_t vertices = scene->buildCells(partOfSegment, tolerance);
        if (vertices <= kDisplayVertexBudget || tolerance >= diagonal * kMaxToleranceOfDiagonal)
            break;
        tolerance = std::max(tolerance * 4.0, diagonal * kFirstToleranceOfDiagonal);
    }
    scene->m_displayToleranceMm = tolerance;
    return scene;
}

double ToolpathScene::boundsDiagonal() const
{
    const auto& points = m_polylines.points();
    if (points.empty())
        return 0;
    base::Vec3 lo = points.front(), hi = points.front();
    for (const base::Vec3& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    return base::distance(lo, hi);
}

// Runs of connected segments of one kind and tool become one polyline cell; a point closer than
// `tolerance` to the chord from the last kept point to the next one is dropped.
std::size_t ToolpathScene::buildCells(const std::vector<std::size_t>& partOfSegment, double tolerance)
{
    struct Builder {
        vtkSmartPointer<vtkCellArray> cut = vtkSmartPointer<vtkCellArray>::New();
        vtkSmartPointer<vtkCellArray> rapid = vtkSmartPointer<vtkCellArray>::New();
        vtkSmartPointer<vtkUnsignedCharArray> colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    };
    std::vector<Builder> builders(m_parts.size());
    for (Builder& builder : builders) {
        builder.colors->SetNumberOfComponents(3);
        builder.colors->SetName("kind");
    }
    const auto& points = m_polylines.points();
    const auto& segments = m_polylines.segments();
    std::size_t vertices = 0;
    std::vector<vtkIdType> run;
    vtkIdType pending = -1;
    std::size_t runStart = 0;

    auto flush = [&] {
        if (run.empty())
            return;
        run.push_back(pending);
        const toolpath::PathSegment& first = segments[runStart];
        Builder& builder = builders[partOfSegment[runStart]];
        if (first.kind == toolpath::PathSegmentKind::Rapid) {
            builder.rapid->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
        } else {
            builder.cut->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
            builder.colors->InsertNextTypedTuple(first.kind == toolpath::PathSegmentKind::Arc        ? kArcRgb
                                                 : first.kind == toolpath::PathSegmentKind::Error    ? kErrorRgb
                                                 : first.kind == toolpath::PathSegmentKind::ToolAxis ? kToolAxisRgb
                                                                                                     : kFeedRgb);
        }
        vertices += run.size();
        run.clear();
    };
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const toolpath::PathSegment& segment = segments[s];
        const bool continues = !run.empty() && segment.from == static_cast<std::uint32_t>(pending) &&
                               segment.kind == segments[runStart].kind && partOfSegment[s] == partOfSegment[runStart];
        if (!continues) {
            flush();
            runStart = s;
            run.push_back(segment.from);
            pending = segment.to;
            continue;
        }
        if (distanceToChord(points[pending], points[run.back()], points[segment.to]) > tolerance)
            run.push_back(pending);
        pending = segment.to;
    }
    flush();

    for (std::size_t i = 0; i < m_parts.size(); ++i) {
        Part& part = m_parts[i];
        part.cut = nullptr;
        part.rapid = nullptr;
        if (builders[i].cut->GetNumberOfCells() > 0) {
            part.cut = linesOf(m_points, builders[i].cut);
            part.cut->GetCellData()->SetScalars(builders[i].colors);
        }
        if (builders[i].rapid->GetNumberOfCells() > 0)
            part.rapid = linesOf(m_points, builders[i].rapid);
    }
    return vertices;
}

std::vector<int> ToolpathScene::tools() const
{
    std::vector<int> tools;
    for (const Part& part : m_parts)
        tools.push_back(part.tool);
    return tools;
}

vtkSmartPointer<vtkPolyData> ToolpathScene::subset(const std::vector<std::uint32_t>& segments) const
{
    vtkNew<vtkCellArray> lines;
    const auto& all = m_polylines.segments();
    for (std::uint32_t s : segments) {
        if (s >= all.size())
            continue;
        const vtkIdType ids[2]{all[s].from, all[s].to};
        lines->InsertNextCell(2, ids);
    }
    return linesOf(m_points, lines);
}

}  // namespace camwb::gui
