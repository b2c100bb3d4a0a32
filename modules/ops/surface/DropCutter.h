// The drop-cutter: where a revolved tool (flat, ball, bull-nose, by sim::ToolShape's profile)
// standing over a point first touches the part's triangle mesh when lowered along -Z, tested
// against each nearby triangle's facet, edges and vertices (the OpenCAMLib technique) through a
// bucket grid of the triangles; the tip height that parallel finishing, the waterline's contours
// (DropContours.h) and the checks use.
#pragma once

#include "base/Vec.h"
#include "sim/TriangleMesh.h"
#include "toolpath/ClRecords.h"

#include <limits>
#include <memory>
#include <vector>

namespace camwb::ops::surface {

class DropCutter {
public:
    // `stockMm` grows the tool by that much all round (the stock to leave on the model).
    DropCutter(const sim::TriangleMesh& mesh, const toolpath::Tool& tool, double stockMm = 0);
    ~DropCutter();
    DropCutter(DropCutter&&) noexcept;

    // The lowest tip height at `xy` at which the tool touches no triangle; `floorZ` where the tool
    // meets none there.
    double dropZ(base::Vec2 xy, double floorZ = -std::numeric_limits<double>::infinity()) const;
    // Many points at once, spread over `threads` threads (0: all cores); same results as dropZ one
    // by one.
    std::vector<double> dropZ(const std::vector<base::Vec2>& points, double floorZ, int threads = 0) const;

private:
    struct Index;
    std::unique_ptr<Index> m_index;
};

}  // namespace camwb::ops::surface
