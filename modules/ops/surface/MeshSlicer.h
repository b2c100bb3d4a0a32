// Sections of the part's triangle mesh by horizontal planes: every level of a stack in one pass
// over the triangles (sorted by their lowest Z once), each section as closed loops chained from
// the triangles' crossings. The fast replacement for OCCT's exact section per level
// (occ::Model::sectionLoops), which the tests hold it against within the meshing tolerance.
#pragma once

#include "base/Vec.h"
#include "geom/Region.h"
#include "sim/TriangleMesh.h"

#include <vector>

namespace camwb::ops::surface {

// One level's section: closed loops (last point not repeated), outer boundaries counter-clockwise
// and holes clockwise seen from +Z (the material on the left).
struct MeshSection {
    double z = 0;
    std::vector<std::vector<base::Vec2>> loops;
    // Pieces of chains of crossings that did not close (an open, broken or unwelded mesh): left out of
    // `loops`, so material is missing from the section. Callers that rely on it must say so.
    std::size_t openChains = 0;
};

// The sections at `levels` (any order; returned in the same order). A level through a vertex or
// along a horizontal face is taken as infinitesimally above it, so each crossing is counted once.
// Loops follow the mesh's vertex indices: the mesh must be welded (sim::weldVertices; OCCT's mesh
// repeats the vertices along every edge between faces), else its sections break at those edges.
std::vector<MeshSection> sliceMesh(const sim::TriangleMesh& mesh, const std::vector<double>& levels);

// A section as regions (outer loop with holes), loops within `toleranceMm`.
std::vector<geom::Region> sectionRegions(const MeshSection& section, double toleranceMm);

// The Z of the mesh's horizontal upward-facing areas (normal within `maxAngleDeg` of +Z) of at
// least `minAreaMm2`, ascending, those closer than `toleranceMm` merged: the floors of a mesh
// without a B-rep (an STL); a B-rep's planar faces give them exactly.
std::vector<double> flatLevels(const sim::TriangleMesh& mesh, double maxAngleDeg = 0.5, double minAreaMm2 = 0.01,
                               double toleranceMm = 1e-4);

}  // namespace camwb::ops::surface
