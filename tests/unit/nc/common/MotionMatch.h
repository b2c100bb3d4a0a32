// Round-trip comparison of two toolpaths by what the machine does, not by their records: both
// are flattened into polylines (arcs tessellated, cycles expanded as the backplot expands them,
// consecutive rapids merged into one transit) and each one's points must lie, in order, on the
// other within a tolerance, with the same kind of motion, tool, spindle speed and feed, and no
// rapid transit of `a` deeper than `b`'s. So a post may split an arc, linearise it, write a
// cycle natively or as moves, and the comparison still holds; a wrong point, order or feed fails.
// Five-axis moves carry their tool axis: at every point of the CL the NC's axis must agree, and
// between points it must lie between the ends' axes. Moves after a WorkingPlane are taken into
// the workpiece frame, so a plane's angle or origin counts as much as the coordinates in it.
#pragma once

#include "kinematics/KinematicChain.h"
#include "toolpath/Toolpath.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::nc::test {

struct MotionSample {
    toolpath::Vec3 point;
    toolpath::Vec3 axis{0, 0, 1};  // the tool axis there, unit
    bool rapid = false;            // of the segment ending here
    bool midpoint = false;         // inside a segment (its kind/feed/spindle/tool are checked)
    bool exact = false;            // a five-axis record's own point (not one of a curve's samples)
    double feed = 0;               // mm/min, or the mode's unit
    bool feedChecked = true;
    bool perMinute = true;
    double rpm = 0;
    int tool = 0;
    int record = 0;      // index of the record that made it
    double lowestZ = 0;  // of a rapid transit: its lowest point
};

// Every segment end and midpoint, starting from the origin; arcs within chordToleranceMm. With
// `machineMotion`, a jointInterpolated five-axis move (NC without tool-tip control) whose two ends
// give both rotary angles moves as the machine moves it (linear and rotary axes interpolated
// together, the tip on a curve), sampled every 0.1 degree.
std::vector<MotionSample> flattenMotion(const toolpath::Toolpath& path, double chordToleranceMm,
                                        const kinematics::KinematicChain* machineMotion = nullptr);

struct MatchTolerance {
    double pointMm = 0.002;      // a sample of `a` off `b`'s polyline
    double backPointMm = 0.002;  // a sample of `b` off `a`'s polyline (larger when `a` linearises arcs)
    double feedRelative = 5e-3;
    double rpmRelative = 1e-3;
    // Radians between tool axes at a point of `b`. Four decimals of a degree per rotary word (the
    // iTNC post's output) put the axis up to 1.3e-6 rad off.
    double axisRad = 2e-6;
    // Radians the axis of `a` may stray, between two points of `b`, outside the turn from one's
    // axis to the other's (the machine's own interpolation; 0: within axisRad).
    double axisBetweenRad = 0;
    // The chain that moves `a`'s jointInterpolated five-axis moves (flattenMotion): the tip between
    // their points is where the machine takes it, and their feed is the machine's (the post
    // converts it), not the tip's, so it is not compared.
    const kinematics::KinematicChain* machineMotion = nullptr;
};

// Empty when `a` (the NC traced back) and `b` (the CL it was posted from) move alike; otherwise
// the first difference, naming the records on both sides.
std::optional<std::string> matchMotion(const toolpath::Toolpath& a, const toolpath::Toolpath& b,
                                       const MatchTolerance& tolerance = {});

}  // namespace camwb::nc::test
