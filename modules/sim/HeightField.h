// Three-axis stock as a z-map: one column of material per grid cell, from a bottom to a top
// height. A vertical tool's move is swept analytically per column, so the cost of a cut is set by
// the resolution and the swept area, never by time samples; the mesh keeps one vertex per column
// so that playing only rewrites the heights of the columns a cut touched.
#pragma once

#include "sim/Stock.h"
#include "sim/ToolShape.h"

#include <algorithm>
#include <limits>

namespace camwb::sim {

// A rectangle of columns [i0, i1] x [j0, j1]; empty when i0 > i1.
struct ColumnRect {
    int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
    bool empty() const { return i0 > i1 || j0 > j1; }
    void add(int i, int j)
    {
        if (empty()) {
            *this = {i, j, i, j};
            return;
        }
        i0 = std::min(i0, i), j0 = std::min(j0, j), i1 = std::max(i1, i), j1 = std::max(j1, j);
    }
    void add(const ColumnRect& r);
};

class HeightField final : public Stock {
public:
    // A block filling `box`; cells of at most `resolutionMm` (the box's sides divided evenly).
    HeightField(const base::Box3& box, double resolutionMm);
    // A cast or forged blank: each column from the lowest to the highest point of `blank` over its
    // centre (a z-map holds one span per column: a hole through the blank's side is filled).
    static std::unique_ptr<HeightField> fromMesh(const TriangleMesh& blank, double resolutionMm);

    CutResult cut(const Move& move, std::size_t moveIndex, const ToolShape& tool) override;
    // A flat tool's level arc as annular sectors of at most a third of a turn, each with its end
    // discs: the columns its pieces cut one by one (interior pieces' end discs lie inside the
    // sector: a column can differ only where its centre lies within rounding of the sweep's edge).
    CutResult cutArcRun(const Move* first, std::size_t count, std::size_t moveIndex, const ToolShape& tool) override;
    void setDesign(const TriangleMesh& model, double toleranceMm) override;
    Deviation compare() const override;
    double volumeMm3() const override;
    base::Box3 bounds() const override { return m_box; }
    double resolutionMm() const override { return std::max(m_dx, m_dy); }
    TriangleMesh mesh() const override;
    // mesh() with the flat cells gathered into rectangles, each a fan around its centre through
    // the vertices of its edges that a neighbour or the side walls use, so that neighbours meet
    // vertex to vertex: a pocket's floor at 0.1 mm in tens of triangles instead of a million (the
    // example job's stock: 40,000 triangles against the plain mesh's 1.1 million).
    TriangleMesh fileMesh() const override;
    std::unique_ptr<Stock> clone() const override { return std::make_unique<HeightField>(*this); }
    std::size_t memoryBytes() const override;

    int columnsX() const { return m_nx; }
    int columnsY() const { return m_ny; }
    double columnX(int i) const { return m_box.min.x + (i + 0.5) * m_dx; }
    double columnY(int j) const { return m_box.min.y + (j + 0.5) * m_dy; }
    double top(int i, int j) const { return m_top[index(i, j)]; }
    double bottom(int i, int j) const { return m_bottom.empty() ? m_floor : m_bottom[index(i, j)]; }
    // The top height of the design model over a column; -infinity where the model is not.
    double designTop(int i, int j) const { return m_design.empty() ? kNone : m_design[index(i, j)]; }
    // The last move that lowered a column while a design was set; -1: none did.
    std::int64_t lastCut(int i, int j) const { return m_lastCut.empty() ? -1 : m_lastCut[index(i, j)]; }

    // Playing: the columns cut since the last call (and forget them), and mesh() brought up to
    // date over such a rectangle; mesh()'s triangles never change, only its top heights.
    ColumnRect takeChanged();
    void updateMesh(TriangleMesh& mesh, const ColumnRect& changed) const;
    // The deviation of one column's top from the design (compare()'s per-column value).
    double deviation(int i, int j) const;

private:
    static constexpr float kNone = -std::numeric_limits<float>::infinity();
    std::size_t index(int i, int j) const { return std::size_t(j) * m_nx + i; }
    bool sameBottom() const;  // a block's always; a blank's when it is flat underneath
    float floorHeight() const { return m_bottom.empty() ? m_floor : m_bottom.front(); }  // when sameBottom()
    TriangleMesh buildMesh(bool mergeFlats) const;
    // The cut of a vertical tool (the analytic sweep) and of a tilted one (poses).
    // `discCovered`: a flat tool's disc where the move is lowest (its end going down, its start
    // going up) is cut at least as low by the neighbouring piece of a run (cutHelixRun).
    void cutVertical(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result,
                     bool discCovered = false);
    // The columns (clamped to the grid) whose cells meet the box of segment a-b grown by `reach`:
    // all a tool of that reach can touch along it. Empty when that box misses the stock.
    ColumnRect columnsWithin(base::Vec2 a, base::Vec2 b, double reach) const;
    // True when a vertical move's cutter stays above every column within `reach` of it.
    bool clearOfStock(const Move& move, double reach) const;
    // True when no column of `near` rises above z (by the tiles' upper bounds).
    bool tilesBelow(const ColumnRect& near, double z) const;
    // How far an arc piece strays from its chord (0 for a straight move).
    static double arcBulge(const Move& move);
    // A flat tool's sweep at height z along the arc from a to b about `centre` (at most a
    // third of a turn, the way the shorter turn goes): the annular sector between the rays through
    // a and b, the disc at b and, unless `startDone`, the disc at a. Its rows' bounds are computed
    // the same way for a piece and for a run of pieces, so the pieces' sectors tile the run's.
    void sweepLevelArc(base::Vec2 a, base::Vec2 b, base::Vec2 centre, double arcRadius, double z, double r,
                       bool startDone, std::size_t moveIndex, CutResult& result);
    // True when the shank and holder of `tool` at height z stay above every column within their
    // reach of the box lo-hi: a run of cuts there cannot meet them (cuts only lower columns).
    bool holderClear(base::Vec2 lo, base::Vec2 hi, double z, const ToolShape& tool) const;
    // cutArcRun() of a helix (pieces not all level): any vertical tool, any mix of pieces.
    CutResult cutHelixRun(const Move* first, std::size_t count, std::size_t moveIndex, const ToolShape& tool);
    void cutTilted(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result);
    // Lowers column (i, j) to `height`; accounts the removed volume, the gouge and the change.
    void lower(int i, int j, double height, std::size_t moveIndex, CutResult& result);
    // lower() over the columns i0..i1 of row j, all to one height (lower() is this over one column).
    void lowerSpan(int j, int i0, int i1, double height, std::size_t moveIndex, CutResult& result);
    // lowerSpan() called, not inlined: for long spans (a ramp's end disc) inside a loop that
    // needs many registers, where inlined its sum went to the stack at every column.
    void lowerLongSpan(int j, int i0, int i1, double height, std::size_t moveIndex, CutResult& result);
    void noteGouge(int i, int j, double z, CutResult& result) const;  // out of the hot loop
    // The shank's and holder's reach into the stock along a vertical move (before it cuts).
    void checkHolder(const Move& move, const ToolShape& tool, CutResult& result) const;
    // Tiles of kTile x kTile columns keep an upper bound of their tops, so the wide holder's
    // check skips the tiles it stays above (nearly all of them, nearly always).
    static constexpr int kTile = 16;
    void refreshTiles(const ColumnRect& rect);
    float tileTop(int ti, int tj) const;  // brought up to date on demand (cuts only mark tiles)
    // How deep the point at height z over column (i, j) lies inside the design (> 0), or how far
    // above it (< 0), measured to the nearest column boundary within a capped search.
    double depthInDesign(int i, int j, double z) const;
    double distanceToDesign(int i, int j, double z) const;

    base::Box3 m_box;
    int m_nx = 0, m_ny = 0;
    double m_dx = 0, m_dy = 0;
    // A block's columns all stand on its floor: m_bottom is made only for a blank (fromMesh), and
    // m_lastCut, which only the design comparison reads, only with a design. Each is a float or an
    // int per column, megabytes at 0.1 mm that a command would otherwise spend its time faulting in.
    std::vector<float> m_top, m_bottom, m_design;
    float m_floor = 0;
    std::vector<float> m_designNear;      // the highest design top within the search cap of each column
    std::vector<std::int32_t> m_lastCut;  // per column, with m_design: the last move that lowered it
    double m_tolerance = 0;
    ColumnRect m_changed, m_cutNow;
    int m_tilesX = 0, m_tilesY = 0;
    mutable std::vector<float> m_tileTop;
    mutable std::vector<std::uint8_t> m_tileStale;
    // A disc's half chords on rows j0.. (-1 off it): the level sweep keeps its end disc's for the
    // next move, which starts there (the chords are geometry: the stock's state does not age them).
    struct DiscChords {
        base::Vec2 centre;
        double radius = -1;
        int j0 = 0;
        std::vector<double> half;
    };
    DiscChords m_endChords, m_spareChords;
    // The end disc's chords (round b, radius r) on rows j0..j1 of a level sweep, in a loop of
    // their own (the roots overlap), into the spare set; keepEndChords() makes them the kept ones
    // once the sweep is done.
    const DiscChords& computeEndChords(base::Vec2 b, double r, int j0, int j1);
    void keepEndChords() { std::swap(m_endChords, m_spareChords); }
    // The start disc's half chord (round a, radius r) on row j: the one kept from the move before
    // when it ended there, else its root.
    double startChord(base::Vec2 a, double r, int j) const;
    // Where the last cut left the tool: a level flat move starting there finds its start disc
    // already at its height, so it sweeps only what lies beyond (see cutVertical).
    Vec3 m_lastEnd;
    double m_lastRadius = -1;
    bool m_lastFlatVertical = false;
};

}  // namespace camwb::sim
