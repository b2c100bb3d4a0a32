// The workpiece material as the simulator removes it: one interface over the representations
// (a height field for three-axis work, tri-dexels where the tool tilts), so the checks, the
// command line and the simulator dock do not care which one cuts. A stock knows the design model
// it is compared with, so every cut says at once how deep it went into the part.
#pragma once

#include "base/Vec.h"
#include "sim/Moves.h"
#include "sim/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace camwb::sim {

class ToolShape;

// No stock cell is finer than this, whatever resolution is asked for.
constexpr double kFinestCellMm = 1e-3;

// How many cells a stock of `resolutionMm` puts across `widthMm`: the width divided evenly into
// cells no larger than that (at least 2). A double, so that a size check can count a grid far too
// large to make (MakeStock.h).
inline double cellsAcross(double widthMm, double resolutionMm)
{
    return std::max(2.0, std::ceil(widthMm / std::max(resolutionMm, kFinestCellMm) - 1e-9));
}

// What one move did to the stock.
struct CutResult {
    double removedMm3 = 0;            // material the cutter removed
    double gougeMm = 0;               // deepest the cutter went into the design model (0: not at all)
    Vec3 gougeAt;                     // where (workpiece frame)
    double holderInterferenceMm = 0;  // deepest the shank or holder reaches into the remaining stock
    Vec3 holderAt;
    bool removedOnAxis = false;  // material removed under the tool's centre (an axial plunge)

    // Adds what a following move did: the removal summed, the worst depths kept.
    void add(const CutResult& next)
    {
        removedMm3 += next.removedMm3;
        if (next.gougeMm > gougeMm)
            gougeMm = next.gougeMm, gougeAt = next.gougeAt;
        if (next.holderInterferenceMm > holderInterferenceMm)
            holderInterferenceMm = next.holderInterferenceMm, holderAt = next.holderAt;
        removedOnAxis = removedOnAxis || next.removedOnAxis;
    }
};

// Remaining material against the design model, sampled over the stock's surface.
struct Deviation {
    // One value per vertex of Stock::mesh(): + material left above the model (mm), - gouge depth.
    std::vector<float> perVertex;
    // Over the model (where a ray or column meets it): the remaining material's distance from it.
    double maxLeftoverMm = 0;
    Vec3 leftoverAt;
    std::int64_t leftoverMove = -1;  // the last move that cut near there; -1: none did
    double maxGougeMm = 0;
    Vec3 gougeAt;
    std::int64_t gougeMove = -1;
    // Beside the model (no column or ray of it there): how thick the material still is, e.g. the
    // foot a job leaves to hold the part. Not leftover of the part: a separate figure.
    double maxOutsideMm = 0;
    Vec3 outsideAt;
};

class Stock {
public:
    virtual ~Stock() = default;

    // Removes what `tool` sweeps along `move` (index `moveIndex` of its MoveList, so a result can
    // name its block later). Pauses (dwell, tool change) cut nothing.
    virtual CutResult cut(const Move& move, std::size_t moveIndex, const ToolShape& tool) = 0;
    // The pieces [first, first + count) of one arc or helix (each continuesArc() the one
    // before), all marked as move `moveIndex`, as one cut: the same stock as cut() of each in
    // turn, and their results added. A stock that can cut the run faster does (a quarter arc's
    // fifteen pieces as one annular sector).
    virtual CutResult cutArcRun(const Move* first, std::size_t count, std::size_t moveIndex, const ToolShape& tool)
    {
        CutResult sum;
        for (std::size_t k = 0; k < count; ++k)
            sum.add(cut(first[k], moveIndex, tool));
        return sum;
    }

    // The design model the cuts and compare() measure against, with the tolerance under which a
    // cut into it is not a gouge. An empty mesh: no model (gouges are never reported).
    virtual void setDesign(const TriangleMesh& model, double toleranceMm) = 0;
    virtual Deviation compare() const = 0;

    virtual double volumeMm3() const = 0;
    virtual base::Box3 bounds() const = 0;
    virtual double resolutionMm() const = 0;
    // The remaining material's surface: closed, outward-facing (an STL of the cut part).
    virtual TriangleMesh mesh() const = 0;
    // The same surface for a file (an STL): flat areas may be fewer, larger triangles, still
    // closed and outward-facing. mesh() keeps one vertex per cell because compare()'s values and
    // the playing view's updates are per vertex of it.
    virtual TriangleMesh fileMesh() const { return mesh(); }
    // A copy: each operation can start from what the previous one left.
    virtual std::unique_ptr<Stock> clone() const = 0;
    // The memory the stock holds (without its meshes): what a clone() costs.
    virtual std::size_t memoryBytes() const = 0;
};

}  // namespace camwb::sim
