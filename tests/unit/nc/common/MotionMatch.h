// Round-trip comparison of two toolpaths by what the machine does, not by their records: both
// are flattened into polylines (arcs tessellated, cycles expanded as the backplot expands them,
// consecutive rapids merged into one transit) and each one's points must lie, in order, on the
// other within a tolerance, with the same kind of motion, tool, spindle speed and feed, and no
// rapid transit of `a` deeper than `b`'s. So a post may split an arc, linearise it, write a
// cycle natively or as moves, and the comparison still holds; a wrong point, order or feed fails.
#pragma once

#include "toolpath/Toolpath.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::nc::test {

struct MotionSample {
    toolpath::Vec3 point;
    bool rapid = false;     // of the segment ending here
    bool midpoint = false;  // inside a segment (its kind/feed/spindle/tool are checked)
    double feed = 0;        // mm/min, or the mode's unit
    bool perMinute = true;
    double rpm = 0;
    int tool = 0;
    int record = 0;      // index of the record that made it
    double lowestZ = 0;  // of a rapid transit: its lowest point
};

// Every segment end and midpoint, starting from the origin; arcs within chordToleranceMm.
std::vector<MotionSample> flattenMotion(const toolpath::Toolpath& path, double chordToleranceMm);

struct MatchTolerance {
    double pointMm = 0.002;      // a sample of `a` off `b`'s polyline
    double backPointMm = 0.002;  // a sample of `b` off `a`'s polyline (larger when `a` linearises arcs)
    double feedRelative = 5e-3;
    double rpmRelative = 1e-3;
};

// Empty when `a` (the NC traced back) and `b` (the CL it was posted from) move alike; otherwise
// the first difference, naming the records on both sides.
std::optional<std::string> matchMotion(const toolpath::Toolpath& a, const toolpath::Toolpath& b,
                                       const MatchTolerance& tolerance = {});

}  // namespace camwb::nc::test
