// The backplot's VTK data, built from a toolpath off the GUI thread (the NC inspector traces a
// million-line program in a worker and hands the finished scene to the view): one polydata pair
// (cutting, rapid) per tool so tools can be hidden, connected segments drawn as polylines, and
// the exact segments of every part for picking. Private to gui/view3d; the view's public header
// only forward-declares it.
#pragma once

#include "toolpath/ToolpathPolylines.h"

#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <set>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::gui {

// World -> widget pixels (y down) with a camera's composite projection matrix (row major).
struct ScreenProjection {
    double m[16]{};
    double width = 0;
    double height = 0;

    bool project(const base::Vec3& p, double& x, double& y) const;  // false behind the camera
};

class ToolpathScene {
public:
    struct Part {
        int tool = 0;
        vtkSmartPointer<vtkPolyData> cut;        // feed and arc segments, colour per cell
        vtkSmartPointer<vtkPolyData> rapid;      // rapid segments
        std::vector<std::uint32_t> cutSegments;  // exact segments, in order
        std::vector<std::uint32_t> rapidSegments;
    };

    // Safe on any thread: touches no render window. `recordsInError`: see ToolpathPolylines.
    static std::shared_ptr<ToolpathScene> build(const toolpath::Toolpath& toolpath, double chordToleranceMm,
                                                const std::vector<bool>& recordsInError = {});

    const toolpath::ToolpathPolylines& polylines() const { return m_polylines; }
    const std::vector<Part>& parts() const { return m_parts; }
    vtkPoints* points() const { return m_points; }
    // Tool numbers in order of first use.
    std::vector<int> tools() const;
    // Lines for the given segment indices (highlighting), sharing this scene's points.
    vtkSmartPointer<vtkPolyData> subset(const std::vector<std::uint32_t>& segments) const;
    // The segment nearest to (x, y) within `tolerancePx` on screen, skipping hidden tools; -1 if
    // none. A plain search over the exact segments: linear (a million take a few tens of ms),
    // exact for thin lines where a ray picker needs a world tolerance.
    int nearestSegment(const ScreenProjection& projection, double x, double y, double tolerancePx,
                       const std::set<int>& hiddenTools) const;
    // How far the drawn lines may stray from the exact segments (only huge programs stray).
    double displayToleranceMm() const { return m_displayToleranceMm; }

    // Vertices drawn at most before the display is simplified, and the simplification's
    // tolerance: the first step and the limit, as fractions of the bounding-box diagonal.
    static constexpr std::size_t kDisplayVertexBudget = 400000;
    static constexpr double kCollinearMm = 1e-6;
    static constexpr double kFirstToleranceOfDiagonal = 2e-5;
    static constexpr double kMaxToleranceOfDiagonal = 2e-3;

private:
    double boundsDiagonal() const;
    std::size_t buildCells(const std::vector<std::size_t>& partOfSegment, double tolerance);

    toolpath::ToolpathPolylines m_polylines;
    vtkSmartPointer<vtkPoints> m_points;
    std::vector<Part> m_parts;
    double m_displayToleranceMm = 0;
};

// Colours of the backplot (as SinuTrain and CAMotics draw them): rapid red, feed green, arc blue.
inline constexpr unsigned char kFeedRgb[3]{25, 160, 55};
inline constexpr unsigned char kArcRgb[3]{40, 95, 230};
// Blocks with an error: magenta dashes, a colour no move has.
inline constexpr unsigned char kErrorRgb[3]{225, 0, 200};
// The tool axis along five-axis moves: orange, apart from the moves' colours.
inline constexpr unsigned char kToolAxisRgb[3]{245, 140, 0};
inline constexpr double kRapidColor[3]{0.90, 0.12, 0.10};
inline constexpr double kHighlightColor[3]{1.0, 0.85, 0.0};

}  // namespace camwb::gui
