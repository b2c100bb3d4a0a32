// Private to the OCCT kernel (modules/occ but Model.cpp and Kernel.cpp): what a loaded model holds
// and its answers to ModelImpl's questions, each in the file named beside it. Includes OCCT, so no
// public header may include it.
#pragma once

#include "occ/DisplayMesh.h"
#include "occ/Model.h"
#include "occ/detail/ModelImpl.h"

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

#include <mutex>
#include <string>
#include <vector>

namespace camwb::occ {

// path, faceInfos, edgeInfos and the bounds are ModelImpl's.
struct ModelData final : ModelImpl {
    TopoDS_Shape shape;                // null for STL
    TopTools_IndexedMapOfShape faces;  // TopExp::MapShapes(shape, TopAbs_FACE) order: faceInfos
    TopTools_IndexedMapOfShape edges;  // TopExp::MapShapes(shape, TopAbs_EDGE) order: edgeInfos
    DisplayMesh stlMesh;               // STL only: the file's triangles

    // BRepMesh writes the triangulation into the shared shape; one mesher per model at a time.
    mutable std::mutex meshMutex;

    bool empty() const override { return shape.IsNull() && stlMesh.empty(); }
    bool hasBRep() const override { return !shape.IsNull(); }
    // ModelProfile.cpp
    base::Result<geom::Profile> planarFaceOuterProfile(int faceIndex, double toleranceMm) const override;
    base::Result<geom::Region> planarFaceRegion(int faceIndex, double toleranceMm) const override;
    // ModelEdges.cpp
    base::Result<std::vector<geom::Profile>> edgeChains(const std::vector<int>& edgeIndices,
                                                        double toleranceMm) const override;
    // ModelHoles.cpp
    std::vector<geom::Hole> holes() const override;
    base::Result<geom::Hole> circleEdgeAsHole(int edgeIndex) const override;
    // ModelMesh.cpp
    DisplayMesh mesh(double linearDeflectionMm) const override;
    // ModelSection.cpp
    base::Result<std::vector<std::vector<base::Vec2>>> sectionLoops(double z, double toleranceMm) const override;
    // ModelFrame.cpp
    base::Result<std::shared_ptr<const ModelImpl>> inFrame(const base::Vec3& origin, const base::Vec3& xAxis,
                                                           const base::Vec3& zAxis) const override;
    std::optional<base::Vec3> cylinderAxis(int faceIndex) const override;
    // ModelSwarf.cpp
    base::Result<SwarfFace> swarfFace(int faceIndex, int edgeIndex) const override;
    // ModelGouge.cpp
    std::optional<Gouge> firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                    double toleranceMm) const override;
};

// Curve kind, ends in the edge's parameter direction, length (ModelEdges.cpp).
EdgeInfo describeEdge(const TopoDS_Edge& edge, int index);

// Fills faces, edges, their infos and the bounds from data.shape (ModelLoad.cpp).
void describeShape(ModelData& data);

// The kernel's entry points that ModelImpl's table names (ModelLoad.cpp, the example parts' files).
namespace occt {
base::Result<std::shared_ptr<const ModelImpl>> load(const std::string& path, const ProgressFn& progress);
base::Status writeExamplePart(const std::string& stepPath);
base::Status writeFiveAxisExamplePart(const std::string& stepPath);
base::Status writeFiveAxisExampleBlank(const std::string& stepPath);
base::Status writeMouldExamplePart(const std::string& stepPath);
}  // namespace occt

}  // namespace camwb::occ
