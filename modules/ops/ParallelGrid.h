// Parallel finishing's raster: lines at the raster angle across the area, spaced evenly at no more
// than the stepover, each sampled at one spacing along it and dropped onto the model; the slope of
// the dropped surface at each sample decides where a line cuts and where it goes over the top.
#pragma once

#include "ops/ParallelOp.h"
#include "ops/surface/DropCutter.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace camwb::ops {

class ParallelGrid {
public:
    ParallelGrid(const SurfaceInput& input, const ParallelParams& params, double toolRadius);

    // Drops every sample (spread over the cores); false when `step` (the fraction done) says stop.
    bool drop(const surface::DropCutter& cutter, const std::function<bool(double)>& step);

    int lines() const { return m_lines; }
    double sampleStep() const { return m_du; }
    bool inside(base::Vec2 p) const;  // in the area the tool centre may use
    double topZ() const { return m_top; }
    base::Vec3 point(int line, int sample) const;
    // A run of neighbouring samples of a line that cut (inside the area, over the model and no
    // steeper than the limit), with the points where the line leaves the area just before and
    // after it, where it does there (so that the cut reaches the area's edge).
    struct Run {
        int from = 0, to = 0;
        std::optional<base::Vec2> before, after;
    };
    std::vector<Run> cutRuns(int line) const;

private:
    base::Vec2 xy(int line, int sample) const;
    double z(int line, int sample) const { return m_z[std::size_t(line) * m_samples + sample]; }
    // The surface's rise per mm at a sample: in each direction the gentler of the one-sided
    // differences (none across a peak or a valley), so a sample beside a wall is not called steep.
    double slope(int line, int sample) const;
    bool outside(int line, int sample) const { return !m_in[std::size_t(line) * m_samples + sample]; }
    // Where the segment from an inside point to an outside one crosses the area's edge (bisected).
    base::Vec2 edge(base::Vec2 in, base::Vec2 out) const;

    const SurfaceInput& m_input;
    base::Vec2 m_u, m_v;  // along and across the lines
    double m_u0 = 0, m_v0 = 0, m_du = 0, m_dv = 0;
    int m_lines = 0, m_samples = 0;
    double m_maxSlope = 0, m_top = 0;
    std::vector<double> m_z;         // -infinity: outside the area or no model under the tool
    std::vector<std::uint8_t> m_in;  // inside the area
};

}  // namespace camwb::ops
