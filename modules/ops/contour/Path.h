// A cutting path in XY (the tool centre, or the programmed contour under cutter compensation):
// lines and arcs with arclength positions, so entries, ramps and tabs can address "s mm along".
#pragma once

#include "geom/Profile.h"

#include <vector>

namespace camwb::ops::contour {

using base::Vec2;
using geom::Segment;

struct Path {
    std::vector<Segment> segments;
    bool closed = true;
    // Which side of travel the material is on (climb with a clockwise spindle: the right).
    bool materialOnRight = true;

    double length() const;
    Vec2 start() const { return segments.front().start; }
    Vec2 end() const { return segments.back().end; }
    Vec2 startTangent() const { return segments.front().startTangent(); }
    Vec2 endTangent() const { return segments.back().endTangent(); }
    // Unit normal pointing away from the material at the start / end.
    Vec2 freeNormalAtStart() const;
    Vec2 freeNormalAtEnd() const;
};

// The part of `s` between the length fractions t0 < t1 (lines and arcs are uniform in length).
Segment partOf(const Segment& s, double t0, double t1);

// The pieces of `path` between arclengths from < to (both within [0, length]).
std::vector<Segment> piecesBetween(const Path& path, double from, double to);

// Arclength of the point of `path` nearest to p.
double nearestArclength(const Path& path, Vec2 p);

// Rotates a closed loop to begin at the midpoint of its longest line (split there), so plunges
// and leads happen on a straight side; unchanged when it has no line.
std::vector<Segment> startAtLongestLine(const std::vector<Segment>& loop);

}  // namespace camwb::ops::contour
