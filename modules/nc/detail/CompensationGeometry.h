// Plane geometry of cutter radius compensation (CutterCompensation.h): a programmed element (line
// or arc in XY), its tangents, its offset by the tool radius to one side, and what happens at the
// corner between two offsets: tangent, inside (trimmed to where the offsets meet) or outside.
#pragma once

#include "base/Vec.h"
#include "geom/Profile.h"

#include <optional>
#include <string>

namespace camwb::nc::detail {

using base::Vec2;

struct CompElement {
    bool arc = false;
    Vec2 start, end;
    Vec2 center;             // arcs
    bool clockwise = false;  // arcs, seen from +Z
    bool fullCircle() const { return arc && start == end; }
};

// Unit tangents in the direction of travel; a zero vector for a line without length.
Vec2 startTangent(const CompElement& e);
Vec2 endTangent(const CompElement& e);
// The unit normal towards the tool: left of travel for `left`, else right.
Vec2 sideNormal(Vec2 tangent, bool left);
// True when the tool (left or right of travel) runs inside the arc, towards its centre.
bool toolInsideArc(const CompElement& arc, bool left);

// The offset of `e` by `radius` to the tool's side as a profile segment (the carrier the corner
// intersections use), nullopt for an arc whose offset radius is not positive (the tool does not
// fit inside it).
std::optional<geom::Segment> offsetElement(const CompElement& e, bool left, double radius);

enum class CornerKind { Tangent, Inside, Outside };
// The corner from `before` to `after` seen from the tool's side: turning towards the tool is an
// inside corner; turns smaller than `tangentTolerance` radians are tangent. Also gives the
// signed turn (radians, + = left) for limits such as SINUMERIK's G451 corner angle.
// `reversalOutsideArcIsInside`: LinuxCNC's rule for a reversal next to an arc the tool runs
// outside of ("h" and "m" shapes): it stays on the arc's side (an inside corner) instead of
// going around the tip.
CornerKind classifyCorner(const CompElement& before, const CompElement& after, bool left, double tangentTolerance,
                          bool reversalOutsideArcIsInside = false, double* turn = nullptr);

// Where the offsets of `before` and `after` meet at their common vertex: for an inside corner
// behind the vertex on `before` and ahead on `after`, for an outside one (SINUMERIK G451) the
// other way round; nullopt when they do not meet (the tool does not fit into the corner).
std::optional<Vec2> cornerPoint(const CompElement& before, const CompElement& after, bool left, double radius,
                                bool inside);

// True when moving the end of the offset element (start -> end, a line or an arc) to `newEnd`
// keeps it going the way it was programmed (trimmed to nothing at most): a corner point behind
// its start means the tool cannot reach the corner without gouging.
bool keepsDirection(const CompElement& offset, const CompElement& programmed, Vec2 newEnd);

// Angle in [0, 2*pi) travelled on an arc about `center` from `from` to `to` in its direction.
double arcTravel(Vec2 center, Vec2 from, Vec2 to, bool clockwise);

// "(x, y)" with three decimals, for messages.
std::string formatPoint(Vec2 p);

}  // namespace camwb::nc::detail
