// Model::mesh: triangulates the B-rep with BRepMesh and copies triangles, normals and edge
// polylines into a DisplayMesh, so that the 3D view never touches OCCT.
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <vector>

namespace camwb::occ {
namespace {

constexpr double kAngularDeflectionRad = 0.5;

void appendFace(DisplayMesh& mesh, const TopoDS_Face& face, int faceIndex)
{
    TopLoc_Location location;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, location);
    if (tri.IsNull() || tri->NbTriangles() == 0)
        return;
    const gp_Trsf trsf = location.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const int nodeCount = tri->NbNodes();

    // Triangle normals summed per node: the fallback where the surface normal is undefined (apexes).
    std::vector<gp_Pnt> nodes(static_cast<std::size_t>(nodeCount));
    for (int n = 1; n <= nodeCount; ++n)
        nodes[static_cast<std::size_t>(n - 1)] = tri->Node(n).Transformed(trsf);
    std::vector<gp_Vec> normals(static_cast<std::size_t>(nodeCount), gp_Vec(0, 0, 0));
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size() / 3);
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
        int a, b, c;
        tri->Triangle(t).Get(a, b, c);
        if (reversed)
            std::swap(b, c);
        const gp_Pnt& pa = nodes[static_cast<std::size_t>(a - 1)];
        const gp_Vec normal = gp_Vec(pa, nodes[static_cast<std::size_t>(b - 1)])
                                  .Crossed(gp_Vec(pa, nodes[static_cast<std::size_t>(c - 1)]));
        for (int n : {a, b, c})
            normals[static_cast<std::size_t>(n - 1)] += normal;
        mesh.triangles.insert(mesh.triangles.end(), {offset + std::uint32_t(a - 1), offset + std::uint32_t(b - 1),
                                                     offset + std::uint32_t(c - 1)});
        mesh.triangleFace.push_back(faceIndex);
    }

    const BRepAdaptor_Surface surface(face);  // includes the face location: results are global
    for (int n = 1; n <= nodeCount; ++n) {
        gp_Vec normal = normals[static_cast<std::size_t>(n - 1)];
        if (tri->HasUVNodes()) {
            const gp_Pnt2d uv = tri->UVNode(n);
            gp_Pnt p;
            gp_Vec du, dv;
            surface.D1(uv.X(), uv.Y(), p, du, dv);
            gp_Vec exact = du.Crossed(dv);
            if (exact.Magnitude() > 1e-12) {
                if (reversed)
                    exact.Reverse();
                normal = exact;
            }
        }
        if (normal.Magnitude() > 1e-300)
            normal.Normalize();
        const gp_Pnt& p = nodes[static_cast<std::size_t>(n - 1)];
        mesh.positions.insert(mesh.positions.end(), {float(p.X()), float(p.Y()), float(p.Z())});
        mesh.normals.insert(mesh.normals.end(), {float(normal.X()), float(normal.Y()), float(normal.Z())});
    }
}

// The edge as BRepMesh discretised it on one of its faces (so lines sit on the triangle edges),
// or a tangential deflection of its curve when there is none.
std::vector<base::Vec3> edgePolyline(const TopoDS_Edge& edge, const TopTools_ListOfShape& faces, double deflectionMm)
{
    std::vector<base::Vec3> line;
    if (!faces.IsEmpty()) {
        TopLoc_Location location;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(TopoDS::Face(faces.First()), location);
        if (!tri.IsNull()) {
            const Handle(Poly_PolygonOnTriangulation) polygon = BRep_Tool::PolygonOnTriangulation(edge, tri, location);
            if (!polygon.IsNull()) {
                const gp_Trsf trsf = location.Transformation();
                for (int i = 1; i <= polygon->NbNodes(); ++i) {
                    const gp_Pnt p = tri->Node(polygon->Node(i)).Transformed(trsf);
                    line.push_back({p.X(), p.Y(), p.Z()});
                }
                return line;
            }
        }
    }
    const BRepAdaptor_Curve curve(edge);
    const GCPnts_TangentialDeflection points(curve, kAngularDeflectionRad, deflectionMm);
    for (int i = 1; i <= points.NbPoints(); ++i) {
        const gp_Pnt p = points.Value(i);
        line.push_back({p.X(), p.Y(), p.Z()});
    }
    return line;
}

}  // namespace

DisplayMesh ModelData::mesh(double linearDeflectionMm) const
{
    if (!hasBRep())
        return stlMesh;
    const double deflection = linearDeflectionMm > 0 ? linearDeflectionMm : 0.05;

    std::lock_guard lock(meshMutex);
    DisplayMesh mesh;
    try {
        BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, kAngularDeflectionRad, Standard_False);
    } catch (const Standard_Failure&) {
        // Faces that failed to mesh are simply missing from the display; edges still show.
    }
    for (int i = 1; i <= faces.Extent(); ++i) {
        const std::size_t positions = mesh.positions.size(), triangles = mesh.triangles.size();
        try {
            appendFace(mesh, TopoDS::Face(faces(i)), i);
        } catch (const Standard_Failure&) {
            // Drop the half-copied face so that every index stays valid.
            mesh.positions.resize(positions);
            mesh.normals.resize(positions);
            mesh.triangles.resize(triangles);
            mesh.triangleFace.resize(triangles / 3);
        }
    }

    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(edgeFaces.FindKey(i));
        if (BRep_Tool::Degenerated(edge))
            continue;
        try {
            std::vector<base::Vec3> line = edgePolyline(edge, edgeFaces(i), deflection);
            if (line.size() >= 2)
                mesh.featureEdges.push_back(std::move(line));
        } catch (const Standard_Failure&) {
        }
    }
    mesh.boundsMin = boundsMin;
    mesh.boundsMax = boundsMax;
    return mesh;
}

}  // namespace camwb::occ
