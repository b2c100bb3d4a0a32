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
    void setDesign(const TriangleMesh& model, double toleranceMm) override;
    Deviation compare() const override;
    double volumeMm3() const override;
    base::Box3 bounds() const override { return box_; }
    double resolutionMm() const override { return std::max(dx_, dy_); }
    TriangleMesh mesh() const override;
    std::unique_ptr<Stock> clone() const override { return std::make_unique<HeightField>(*this); }

    int columnsX() const { return nx_; }
    int columnsY() const { return ny_; }
    double columnX(int i) const { return box_.min.x + (i + 0.5) * dx_; }
    double columnY(int j) const { return box_.min.y + (j + 0.5) * dy_; }
    double top(int i, int j) const { return top_[index(i, j)]; }
    double bottom(int i, int j) const { return bottom_[index(i, j)]; }
    // The top height of the design model over a column; -infinity where the model is not.
    double designTop(int i, int j) const { return design_.empty() ? kNone : design_[index(i, j)]; }
    std::int64_t lastCut(int i, int j) const { return lastCut_[index(i, j)]; }

    // Playing: the columns cut since the last call (and forget them), and mesh() brought up to
    // date over such a rectangle; mesh()'s triangles never change, only its top heights.
    ColumnRect takeChanged();
    void updateMesh(TriangleMesh& mesh, const ColumnRect& changed) const;
    // The deviation of one column's top from the design (compare()'s per-column value).
    double deviation(int i, int j) const;

private:
    static constexpr float kNone = -std::numeric_limits<float>::infinity();
    std::size_t index(int i, int j) const { return std::size_t(j) * nx_ + i; }
    bool sameBottom() const;
    // The cut of a vertical tool (the analytic sweep) and of a tilted one (poses).
    void cutVertical(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result);
    void cutTilted(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result);
    // Lowers column (i, j) to `height`; accounts the removed volume, the gouge and the change.
    void lower(int i, int j, double height, std::size_t moveIndex, CutResult& result);
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

    base::Box3 box_;
    int nx_ = 0, ny_ = 0;
    double dx_ = 0, dy_ = 0;
    std::vector<float> top_, bottom_, design_;
    std::vector<float> designNear_;  // the highest design top within the search cap of each column
    std::vector<std::int32_t> lastCut_;
    double tolerance_ = 0;
    ColumnRect changed_, cutNow_;
    int tilesX_ = 0, tilesY_ = 0;
    mutable std::vector<float> tileTop_;
    mutable std::vector<std::uint8_t> tileStale_;
    // Where the last cut left the tool: a level flat move starting there finds its start disc
    // already at its height, so it sweeps only what lies beyond (see cutVertical).
    Vec3 lastEnd_;
    double lastRadius_ = -1;
    bool lastFlatVertical_ = false;
};

}  // namespace camwb::sim
