// The backplot's VTK data, built from a toolpath off the GUI thread (the NC inspector traces a
// million-line program in a worker and hands the finished scene to the view): one polydata pair
// (cutting, rapid) per tool so tools can be hidden, plus the segment index of every cell for
// picking. Private to gui/view3d; the view's public header only forward-declares it.
#pragma once

#include "gui/view3d/ToolpathPolylines.h"

#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::gui {

class ToolpathScene {
public:
    struct Part {
        int tool = 0;
        vtkSmartPointer<vtkPolyData> cut;    // feed and arc segments, colour per cell
        vtkSmartPointer<vtkPolyData> rapid;  // rapid segments
        std::vector<std::uint32_t> cutSegments;
        std::vector<std::uint32_t> rapidSegments;
    };

    // Safe on any thread: touches no render window.
    static std::shared_ptr<ToolpathScene> build(const toolpath::Toolpath& toolpath, double chordToleranceMm);

    const ToolpathPolylines& polylines() const { return m_polylines; }
    const std::vector<Part>& parts() const { return m_parts; }
    vtkPoints* points() const { return m_points; }
    // Tool numbers in order of first use.
    std::vector<int> tools() const;
    // Lines for the given segment indices (highlighting), sharing this scene's points.
    vtkSmartPointer<vtkPolyData> subset(const std::vector<std::uint32_t>& segments) const;

private:
    ToolpathPolylines m_polylines;
    vtkSmartPointer<vtkPoints> m_points;
    std::vector<Part> m_parts;
};

// Colours of the backplot (as SinuTrain and CAMotics draw them): rapid red, feed green, arc blue.
inline constexpr unsigned char kFeedRgb[3]{25, 160, 55};
inline constexpr unsigned char kArcRgb[3]{40, 95, 230};
inline constexpr double kRapidColor[3]{0.90, 0.12, 0.10};
inline constexpr double kHighlightColor[3]{1.0, 0.85, 0.0};

}  // namespace camwb::gui
