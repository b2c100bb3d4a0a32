#include "gui/view3d/detail/ToolpathScene.h"

#include "toolpath/Toolpath.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

namespace camwb::gui {

namespace {

vtkSmartPointer<vtkPolyData> linesOf(vtkPoints* points, vtkCellArray* lines)
{
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    return data;
}

}  // namespace

std::shared_ptr<ToolpathScene> ToolpathScene::build(const toolpath::Toolpath& toolpath, double chordToleranceMm)
{
    auto scene = std::make_shared<ToolpathScene>();
    scene->m_polylines = ToolpathPolylines::fromToolpath(toolpath, chordToleranceMm);
    const ToolpathPolylines& polylines = scene->m_polylines;
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
    struct Builder {
        vtkSmartPointer<vtkCellArray> cut = vtkSmartPointer<vtkCellArray>::New();
        vtkSmartPointer<vtkCellArray> rapid = vtkSmartPointer<vtkCellArray>::New();
        vtkSmartPointer<vtkUnsignedCharArray> colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    };
    std::vector<Builder> builders;
    auto partOf = [&](int tool) -> std::size_t {
        for (std::size_t i = 0; i < scene->m_parts.size(); ++i)
            if (scene->m_parts[i].tool == tool)
                return i;
        scene->m_parts.push_back({tool, nullptr, nullptr, {}, {}});
        builders.emplace_back();
        builders.back().colors->SetNumberOfComponents(3);
        builders.back().colors->SetName("kind");
        return scene->m_parts.size() - 1;
    };
    const auto& segments = polylines.segments();
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const PathSegment& segment = segments[s];
        const std::size_t index = partOf(segment.tool);
        Part& part = scene->m_parts[index];
        Builder& builder = builders[index];
        const vtkIdType ids[2]{segment.from, segment.to};
        if (segment.kind == PathSegmentKind::Rapid) {
            builder.rapid->InsertNextCell(2, ids);
            part.rapidSegments.push_back(static_cast<std::uint32_t>(s));
        } else {
            builder.cut->InsertNextCell(2, ids);
            builder.colors->InsertNextTypedTuple(segment.kind == PathSegmentKind::Arc ? kArcRgb : kFeedRgb);
            part.cutSegments.push_back(static_cast<std::uint32_t>(s));
        }
    }
    for (std::size_t i = 0; i < scene->m_parts.size(); ++i) {
        Part& part = scene->m_parts[i];
        if (!part.cutSegments.empty()) {
            part.cut = linesOf(scene->m_points, builders[i].cut);
            part.cut->GetCellData()->SetScalars(builders[i].colors);
        }
        if (!part.rapidSegments.empty())
            part.rapid = linesOf(scene->m_points, builders[i].rapid);
    }
    return scene;
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
