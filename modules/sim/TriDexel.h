// Stock for tilted tools and undercuts: tri-dexels, three grids of parallel rays (along X, Y and
// Z, one ray per cell of the stock's side at the resolution) each holding the spans of material
// along it. Memory grows with the stock's area over the resolution squared, not its volume over
// the cube. A cut steps the tool's poses along the move, far enough apart to be quick and near
// enough that their union is within a twentieth of a cell of the tool's sweep, and subtracts the
// cutter's span from every ray it crosses: its cost is set by the resolution, not by time samples.
#pragma once

#include "sim/MeshDistance.h"
#include "sim/MeshRays.h"
#include "sim/Stock.h"
#include "sim/ToolShape.h"

#include <utility>

namespace camwb::sim {

class TriDexel final : public Stock {
public:
    struct Span {
        float lo, hi;
    };
    TriDexel(const base::Box3& box, double resolutionMm);
    // A cast or forged blank: every ray filled with the spans inside `blank` (holes kept).
    static std::unique_ptr<TriDexel> fromMesh(const TriangleMesh& blank, double resolutionMm);

    CutResult cut(const Move& move, std::size_t moveIndex, const ToolShape& tool) override;
    void setDesign(const TriangleMesh& model, double toleranceMm) override;
    Deviation compare() const override;
    // The mean of the three grids' estimates (each is its spans' lengths times its cell area).
    double volumeMm3() const override;
    base::Box3 bounds() const override { return m_box; }
    double resolutionMm() const override { return std::max({m_cell[0], m_cell[1], m_cell[2]}); }
    // The Z rays' spans as boxes with faces merged between neighbours (voxel faces, exact in Z,
    // stepped by a cell across): closed in space and outward-facing, so its volume is the Z
    // grid's, but side faces meet top faces in T-junctions (no shared vertices across heights).
    TriangleMesh mesh() const override;
    std::unique_ptr<Stock> clone() const override { return std::make_unique<TriDexel>(*this); }
    std::size_t memoryBytes() const override;

    // The spans along ray (i, j) of grid `axis` (0 x, 1 y, 2 z); RayGrid says where it runs.
    const std::vector<Span>& spans(int axis, int i, int j) const { return m_grids[axis].spans[m_grids[axis].at(i, j)]; }
    const RayGrid& rays(int axis) const { return m_grids[axis].rays; }
    double gridVolumeMm3(int axis) const;

private:
    struct Grid {
        RayGrid rays;
        std::vector<std::vector<Span>> spans, design;
        std::vector<std::int32_t> lastCut;
        std::size_t at(int i, int j) const { return std::size_t(j) * rays.nu + i; }
    };
    struct PoseCut;  // what one grid saw of a cut (TriDexel.cpp)
    // How many poses a cut steps along `move`: the copies of the cutter fall short of its sweep
    // by at most a twentieth of a cell (by the cutter's curvature and its rims), and stand no
    // closer than half a cell.
    int posesAlong(const Move& move, const ToolShape& tool) const;
    // Whether the cutter's top edge comes near the stock's box along `move`.
    bool topRimMayCut(const Move& move, const ToolShape& tool) const;
    void cutPose(int axis, const Vec3& tip, const Vec3& toolAxis, const base::Box3& reach, const ToolShape& tool,
                 std::size_t moveIndex, PoseCut& seen);
    void checkHolder(const Vec3& tip, const Vec3& toolAxis, const ToolShape& tool, CutResult& result) const;
    // Signed distance along ray (i, j) of grid `axis` from coordinate t to the design's surface
    // (negative inside it); +infinity where the ray meets no design.
    double alongRay(int axis, int i, int j, double t) const;
    // The ray (i, j) of grid `axis` whose cell holds p (clamped to the grid).
    std::pair<int, int> rayThrough(int axis, const Vec3& p) const;
    // How deep `p` is inside the design along the nearest ray of grid `axis` (0 outside it).
    double depthInside(int axis, const Vec3& p) const;
    double vertexDeviation(const Vec3& p) const;
    // A depth `alongRays` measured inside the design, confirmed by the exact distance from `p`
    // to the design's surface (never more than the rays said).
    double trueDepth(const Vec3& p, double alongRays) const;
    // The latest move that cut any of the three rays through p's cells; -1: none did.
    std::int64_t lastCutAt(const Vec3& p) const;

    base::Box3 m_box;
    double m_cell[3] = {1, 1, 1};
    int m_cells[3] = {2, 2, 2};
    Grid m_grids[3];
    std::shared_ptr<const MeshDistance> m_designDistance;  // shared by clones: the design does not change
    double m_tolerance = 0;
    double m_spanSlack = 1e-7;  // shorter removals are float rounding, not material (constructor)
    bool m_hasDesign = false;
    // Where the last cut left the tool, and which cutter it was.
    struct LastPose {
        Vec3 tip, axis;
        double radius = -1, corner = 0, coneSlope = 0, flute = 0;
        bool operator==(const LastPose&) const = default;
    };
    LastPose m_lastPose;
};

}  // namespace camwb::sim
