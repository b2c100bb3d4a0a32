// Private to modules/occ: what a Model holds. Includes OCCT, so no public header may include it.
#pragma once

#include "occ/DisplayMesh.h"
#include "occ/Model.h"

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

#include <mutex>
#include <string>
#include <vector>

namespace camwb::occ {

// A unit normal counts as +-Z when 1 - |n.z| is below this (about 4.5e-5 rad).
inline constexpr double kZAxisTolerance = 1e-9;

struct ModelData {
    std::string path;
    TopoDS_Shape shape;                // null for STL
    TopTools_IndexedMapOfShape faces;  // TopExp::MapShapes(shape, TopAbs_FACE) order
    std::vector<FaceInfo> faceInfos;   // [i - 1] describes faces(i)
    TopTools_IndexedMapOfShape edges;  // TopExp::MapShapes(shape, TopAbs_EDGE) order
    std::vector<EdgeInfo> edgeInfos;   // [i - 1] describes edges(i)
    DisplayMesh stlMesh;               // STL only: the file's triangles
    base::Vec3 boundsMin;
    base::Vec3 boundsMax;

    // BRepMesh writes the triangulation into the shared shape; one mesher per model at a time.
    mutable std::mutex meshMutex;
};

// Curve kind, ends in the edge's parameter direction, length (ModelEdges.cpp).
EdgeInfo describeEdge(const TopoDS_Edge& edge, int index);

// Fills faces, edges, their infos and the bounds from data.shape (ModelLoad.cpp).
void describeShape(ModelData& data);

}  // namespace camwb::occ
