// The 2D pieces of a pocket pattern: a cut is one continuous chain of lines and arcs that the tool
// centre follows at a level (a ring, a zig-zag chain, a wall loop), plus the small geometry the
// pattern, clean-up and entry code need on such chains (splitting, nearest points, sampling).
#pragma once

#include "geom/Profile.h"
#include "geom/Region.h"

#include <cstddef>
#include <vector>

namespace camwb::ops::pocket {

using base::Vec2;
using geom::Segment;

struct Cut {
    std::vector<Segment> path;  // continuous; a closed cut ends where it starts
    bool closed = false;

    Vec2 start() const { return path.front().start; }
    Vec2 end() const { return path.back().end; }
    double length() const;
};

// The part of `s` between the parameters t0 < t1 (as Segment::pointAt).
Segment subSegment(const Segment& s, double t0, double t1);

struct PathPoint {
    std::size_t segment = 0;
    double t = 0;  // parameter on that segment
    Vec2 point;
    double distance = 0;
};

PathPoint nearestOnSegment(const Segment& s, Vec2 p);
PathPoint nearestOnPath(const std::vector<Segment>& path, Vec2 p);
// Nearest point on any loop of the regions; `distance` is infinite when there is none.
PathPoint nearestOnRegions(const std::vector<geom::Region>& regions, Vec2 p);

// A closed loop rotated to start at parameter t of segment i (that segment split there).
std::vector<Segment> loopFrom(const std::vector<Segment>& loop, std::size_t i, double t);
// A closed loop started at its point nearest to p.
std::vector<Segment> loopNearest(const std::vector<Segment>& loop, Vec2 p);
// A closed loop started at the midpoint of its longest segment (a straight side where there is
// one: entries and the first cut start there; of equally long ones the lowest, then leftmost).
std::vector<Segment> loopAtLongest(const std::vector<Segment>& loop);

// Points along the path (arcs with chord error <= tolerance), first to last, no duplicates.
std::vector<Vec2> samplePath(const std::vector<Segment>& path, double tolerance);

// Appends a line a-b unless it is degenerate.
void appendLine(std::vector<Segment>& path, Vec2 a, Vec2 b);

}  // namespace camwb::ops::pocket
