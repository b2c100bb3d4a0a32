// 2D profiles made of lines and circular arcs, in the XY plane of the part, in mm.
// Arcs stay arcs from the model to the NC: offsets and toolpaths keep Segment::Kind::Arc.
#pragma once

#include "base/Vec.h"

#include <vector>

namespace camwb::geom {

using base::Vec2;

struct Segment {
    enum class Kind { Line, Arc };
    Kind kind = Kind::Line;
    Vec2 start;
    Vec2 end;
    Vec2 center;      // arcs only
    bool ccw = true;  // arcs only: counter-clockwise seen from +Z

    static Segment line(Vec2 a, Vec2 b) { return {Kind::Line, a, b, {}, true}; }
    static Segment arc(Vec2 a, Vec2 b, Vec2 c, bool counterClockwise) { return {Kind::Arc, a, b, c, counterClockwise}; }

    bool isArc() const { return kind == Kind::Arc; }
    double radius() const { return distance(start, center); }
    // Signed sweep in radians (positive = ccw); a closed full circle has |sweep| = 2*pi.
    double sweep() const;
    double length() const;
    // Unit tangent in the direction of travel at the start and at the end.
    Vec2 startTangent() const;
    Vec2 endTangent() const;
    Vec2 pointAt(double t) const;  // t in [0, 1] along the segment
    Segment reversed() const;
};

struct Profile {
    std::vector<Segment> segments;
    bool closed = true;

    bool empty() const { return segments.empty(); }
    // Positive for counter-clockwise closed profiles (arcs included exactly).
    double signedArea() const;
    double length() const;
    Profile reversed() const;
    // Ends of consecutive segments meet within `tolerance` (and the last meets the first if closed).
    bool isContinuous(double tolerance = 1e-6) const;
};

// Points along the profile: lines by their ends, arcs split so the chord error stays within
// `tolerance`. Closed profiles do not repeat the first point.
std::vector<Vec2> discretize(const Profile& profile, double tolerance);

// How many equal chords keep an arc of `radius` and |sweep| `sweepAbs` within `tolerance` of
// its circle (at least 1): the split discretize uses.
int chordCount(double radius, double sweepAbs, double tolerance);

}  // namespace camwb::geom
