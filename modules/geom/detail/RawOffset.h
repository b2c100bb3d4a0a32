// Private: the raw offset of region loops as exact lines and arcs, built the way Clipper builds its
// offset polygons (each element moved sideways, round joins at convex corners, a detour through
// the corner at concave ones) but without discretising. A union with positive filling of these
// loops is the offset region; RegionOps resolves that topology with Clipper and PieceSnap puts
// the result back onto these pieces.
#pragma once

#include "geom/Region.h"

#include <cstddef>
#include <vector>

namespace camwb::geom::detail {

// One exact piece of a raw offset loop. `sweep` (arcs only, signed, ccw positive) is kept because
// a piece whose start and end coincide may still be a whole circle.
struct RawPiece {
    Segment segment;
    double sweep = 0;
    double radius = 0;  // arcs only
};

// The loops one after the other, each continuous and closed (a piece ends where the next begins,
// the last where the first begins).
struct RawLoops {
    std::vector<RawPiece> pieces;
    std::vector<std::size_t> loopBegin;  // first piece of each loop, then pieces.size()

    std::size_t loopOf(std::size_t piece) const;
    std::size_t next(std::size_t piece) const;  // cyclic within its loop
    std::size_t prev(std::size_t piece) const;
};

// The raw loops of the regions (normalised: outer loops ccw, holes cw) offset by `distance` > 0
// into the regions (`inward`) or out of them. Winding numbers of the result count the offset
// region positively: union with positive filling gives it. Arcs that collapse (radius up to the
// distance, on the offset side) are offset as their polygon with chords within `chordTolerance`.
RawLoops rawOffset(const std::vector<Region>& regions, double distance, bool inward, double chordTolerance);

// A point of the piece at parameter t in [0, 1] (arcs by angle).
Vec2 piecePoint(const RawPiece& piece, double t);

}  // namespace camwb::geom::detail
