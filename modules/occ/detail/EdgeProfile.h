// Private to modules/occ: turning edges and wires that lie in an XY plane into geom segments.
// One implementation for face outlines, face regions and edge chains: lines and circles with a
// vertical axis stay exact, every other curve is sampled and refitted as lines and arcs.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

namespace camwb::occ {

// Appends `edge` projected on XY, travelled from `from` to `to`: against its parameter direction
// when `reversed`. `from` and `to` are the positions of its end vertices (the caller's, so that
// consecutive segments meet exactly). Other curves than lines and vertical circles deviate from
// the edge by at most toleranceMm.
void appendEdge(geom::Profile& profile, const TopoDS_Edge& edge, bool reversed, base::Vec2 from, base::Vec2 to,
                double toleranceMm);

// A closed wire of a face normal to Z, walked in its order around the face, as a closed profile
// (orientation as the wire runs; callers orient it).
base::Result<geom::Profile> wireProfile(const TopoDS_Wire& wire, const TopoDS_Face& face, double toleranceMm);

}  // namespace camwb::occ
