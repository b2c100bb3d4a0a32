// A CAD model loaded from a file (STEP, IGES, BREP or STL) and the questions the workbench asks of it:
// which faces and edges it has, planar faces as geom profiles and regions, picked edges as chains,
// its vertical holes, and a mesh for display.
// OCCT stays behind the pimpl: nothing that includes this header sees an OCCT type, and OCCT itself
// is loaded only when a model is (occ/detail/ModelImpl.h).
#pragma once

#include "base/Result.h"
#include "base/Vec.h"
#include "geom/Hole.h"
#include "geom/Profile.h"
#include "geom/Region.h"
#include "occ/DisplayMesh.h"
#include "occ/Swarf.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::occ {

// Called with the fraction done (0..1); return false to cancel.
using ProgressFn = std::function<bool(double fraction)>;

struct FaceInfo {
    int index = 0;  // 1-based; 0 = no such face
    bool planar = false;
    base::Vec3 normal;  // planar faces: outward unit normal
    double planeZ = 0;  // planar faces with normal +-Z: their Z level
    double areaMm2 = 0;
};

struct EdgeInfo {
    int index = 0;  // 1-based; 0 = no such edge
    enum class Curve { Line, Circle, BSpline, Other } curve = Curve::Other;
    base::Vec3 start, end;  // in the curve's parameter direction (the direction edgeChains follows)
    double lengthMm = 0;
};

class ModelImpl;

// Immutable once loaded; copies share the data, so a Model is cheap to copy and safe to pass
// between threads (mesh() serialises itself per model).
class Model {
public:
    Model();  // empty

    // Reads by extension (case-insensitive): .step .stp .iges .igs .brep .brp (solids/shells),
    // .stl (display only). Never throws; errors name the file and the reason
    // ("file not found", "not a STEP file or damaged: ...", "contains no shape", "cancelled").
    static base::Result<Model> load(const std::string& path, const ProgressFn& progress = {});

    bool empty() const;
    bool hasBRep() const;            // false for STL meshes
    int faceCount() const;           // faces in TopExp::MapShapes order (stable for a given file)
    FaceInfo face(int index) const;  // 1-based; FaceInfo{} (index 0) when out of range

    // The topmost planar face whose normal is +Z (largest Z; ties -> largest area); 0 if none.
    int topPlanarFace() const;

    // Outer wire of a planar face with normal +Z or -Z as a closed counter-clockwise Profile in XY.
    // Lines and circle arcs stay exact; other curves become lines and arcs within toleranceMm
    // (sampled, then geom::fitLinesAndArcs).
    base::Result<geom::Profile> planarFaceOuterProfile(int faceIndex, double toleranceMm = 0.01) const;

    // The whole face seen from +Z: outer wire as the outer loop, inner wires as holes (islands and
    // openings). Faces with normal +Z or -Z only. Lines and circle arcs stay exact; B-splines and
    // other curves become lines and arcs within toleranceMm (geom/ArcFit.h). Consecutive segments
    // meet exactly (they end on the wire's vertices).
    base::Result<geom::Region> planarFaceRegion(int faceIndex, double toleranceMm = 0.01) const;

    int edgeCount() const;           // edges in TopExp::MapShapes order
    EdgeInfo edge(int index) const;  // 1-based; EdgeInfo{} (index 0) when out of range
    // The edges chained end to end into profiles projected on XY (each open or closed; chain
    // direction follows the first listed edge of each chain, in its parameter direction; chains in
    // the order of their first listed edge). Ends within 1e-6 mm meet. Curves as in
    // planarFaceRegion. Errors, naming the edge: unknown edge index, an edge listed twice, an edge
    // not in an XY plane (Z varies by more than 1e-6 mm; vertical edges are refused), branching
    // (three edge ends at one point), no edges.
    base::Result<std::vector<geom::Profile>> edgeChains(const std::vector<int>& edgeIndices,
                                                        double toleranceMm = 0.01) const;

    // Cylindrical holes with a vertical axis (material outside the cylinder), found on the whole
    // model; faces of one hole (same axis and radius within 1e-6 mm, touching Z ranges, e.g. half
    // cylinders) are merged, faceIndex = the smallest; they must cover the full circle (concave
    // fillets are not holes). Holes covered at the top (not reachable from +Z) are left out.
    // through: no material just below the bottom inside the circle (a flat floor, a drill-point
    // cone or a counterbore shoulder make a hole blind). Ordered by faceIndex; empty for STL.
    std::vector<geom::Hole> holes() const;
    // A circular edge with a vertical axis as a hole (a picked circle): diameter and centre from
    // the circle (full or an arc), top and bottom at its Z, faceIndex 0, through false. Error when
    // the edge is not such a circle.
    base::Result<geom::Hole> circleEdgeAsHole(int edgeIndex) const;

    // Triangles (triangleFace filled; 0 for STL), per-vertex normals, feature edges as polylines.
    // STL models return their own triangles and no edges; linearDeflectionMm is ignored for them.
    DisplayMesh mesh(double linearDeflectionMm = 0.05) const;

    // The exact section of the solid by the plane at `z` (ModelSection.cpp, BRepAlgoAPI_Section):
    // closed loops in XY (last point not repeated), edges discretised within toleranceMm, outer
    // loops counter-clockwise and holes clockwise. Slow (a Boolean per call): the reference the mesh
    // slicer is checked against. Errors: an STL model, OCCT failing, edges that do not close.
    base::Result<std::vector<std::vector<base::Vec2>>> sectionLoops(double z, double toleranceMm) const;

    base::Vec3 boundsMin() const;
    base::Vec3 boundsMax() const;

    // 3+2 machining: the same model with its coordinates in the frame whose origin and unit,
    // perpendicular x and z axes (workpiece coordinates) are given, so that every question above
    // (planar faces seen from +Z, vertical holes) is asked along the frame's z. Face and edge
    // indices stay those of this model. Errors: an STL model, axes that are no frame.
    base::Result<Model> inFrame(const base::Vec3& origin, const base::Vec3& xAxis, const base::Vec3& zAxis) const;
    // The unit direction of a cylindrical face's axis (either sense); nullopt for another face.
    std::optional<base::Vec3> cylinderAxis(int faceIndex) const;

    // Swarf milling (ModelSwarf.cpp): the face as a ruled, developable surface (plane, cylinder,
    // cone, linear extrusion) driven along `edgeIndex` (one of its edges, not a ruling), or with
    // edgeIndex 0 along its lowest such edge. Errors name the face: not ruled ("face 12 is a sphere,
    // not a ruled developable surface ..."), an edge not on the face, a ruling that leaves the face.
    base::Result<SwarfFace> swarfFace(int faceIndex, int edgeIndex = 0) const;
    // The first pose (in order; between consecutive poses too, at steps no longer than 0.5 mm) where
    // a flat end mill of `radiusMm` with `fluteLengthMm` of flutes enters the material deeper than
    // toleranceMm (ModelGouge.cpp). Sampled: points on the tool's side and bottom, the tool shrunk by
    // the tolerance, classified against the solid. nullopt: no gouge found.
    std::optional<Gouge> firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                    double toleranceMm) const;

private:
    explicit Model(std::shared_ptr<const ModelImpl> impl);

    std::shared_ptr<const ModelImpl> m_impl;  // null: empty
};

}  // namespace camwb::occ
