// Model::load: reads STEP, IGES, BREP and STL files, reporting progress through OCCT's
// Message_ProgressIndicator and turning every OCCT failure into a base::Error.
#include "occ/Model.h"

#include "occ/detail/DataExchangeLock.h"
#include "occ/detail/ModelData.h"
#include "occ/detail/OcctMessages.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Poly_Triangulation.hxx>
#include <RWStl.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <exception>
#include <filesystem>
#include <limits>

namespace camwb::occ {
namespace {

// Forwards OCCT progress to a ProgressFn; a false return sets UserBreak() for the algorithms.
class ProgressBridge : public Message_ProgressIndicator {
public:
    explicit ProgressBridge(const ProgressFn& fn) : m_fn(fn) {}

    Standard_Boolean UserBreak() override { return m_cancelled.load(); }

    void Show(const Message_ProgressScope&, const Standard_Boolean force) override
    {
        const double position = GetPosition();
        // Algorithms call Show() on every step; the callback only needs to hear about real progress.
        if (force || position - m_lastReported >= 0.005 || position >= 1.0)
            report(position);
    }

    // Also called directly around the phases that OCCT 7.6 cannot report (reading the file).
    bool report(double fraction)
    {
        if (m_cancelled.load())
            return false;
        m_lastReported = fraction;
        if (m_fn && !m_fn(std::clamp(fraction, 0.0, 1.0)))
            m_cancelled = true;
        return !m_cancelled.load();
    }

    bool cancelled() const { return m_cancelled.load(); }

private:
    const ProgressFn& m_fn;
    double m_lastReported = -1;
    std::atomic<bool> m_cancelled{false};
};

std::string lowerExtension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::string statusText(IFSelect_ReturnStatus status)
{
    switch (status) {
    case IFSelect_RetVoid:
        return "nothing could be read";
    case IFSelect_RetDone:
        return "done";
    case IFSelect_RetError:
        return "syntax error";
    case IFSelect_RetFail:
        return "read failed";
    case IFSelect_RetStop:
        return "read stopped";
    }
    return "unknown status";
}

bool hasSubShapes(const TopoDS_Shape& shape)
{
    return !shape.IsNull() && (shape.ShapeType() != TopAbs_COMPOUND || TopoDS_Iterator(shape).More());
}

// STEP and IGES share XSControl_Reader: read the file (no progress in 7.6), then transfer.
base::Result<TopoDS_Shape> readExchange(XSControl_Reader& reader, const std::string& path, const char* notA,
                                        const Message_ProgressRange& range, ProgressBridge& bridge)
{
    Message_ProgressScope scope(range, "Read", 10);
    const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
    if (status != IFSelect_RetDone)
        return base::makeError(std::string(notA) + " or damaged: " + statusText(status), path);
    scope.Next(3);
    if (bridge.cancelled())
        return base::makeError("cancelled", path);
    if (reader.NbRootsForTransfer() <= 0)
        return base::makeError("contains no shape", path);
    reader.TransferRoots(scope.Next(7));
    if (bridge.cancelled())
        return base::makeError("cancelled", path);
    return reader.OneShape();
}

base::Result<TopoDS_Shape> readBRep(const std::string& path, const Message_ProgressRange& range, ProgressBridge& bridge)
{
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder, range)) {
        if (bridge.cancelled())
            return base::makeError("cancelled", path);
        return base::makeError("not a BREP file or damaged", path);
    }
    return shape;
}

DisplayMesh stlToMesh(const Poly_Triangulation& tri)
{
    // Flat facets: each triangle gets its own three vertices carrying the facet normal.
    DisplayMesh mesh;
    const int count = tri.NbTriangles();
    mesh.positions.reserve(static_cast<std::size_t>(count) * 9);
    mesh.normals.reserve(static_cast<std::size_t>(count) * 9);
    mesh.triangles.reserve(static_cast<std::size_t>(count) * 3);
    mesh.triangleFace.assign(static_cast<std::size_t>(count), 0);
    constexpr double inf = std::numeric_limits<double>::infinity();
    base::Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    for (int i = 1; i <= count; ++i) {
        int n[3];
        tri.Triangle(i).Get(n[0], n[1], n[2]);
        gp_Pnt p[3] = {tri.Node(n[0]), tri.Node(n[1]), tri.Node(n[2])};
        gp_Vec normal = gp_Vec(p[0], p[1]).Crossed(gp_Vec(p[0], p[2]));
        if (normal.Magnitude() > 1e-300)
            normal.Normalize();
        for (const gp_Pnt& q : p) {
            mesh.triangles.push_back(static_cast<std::uint32_t>(mesh.positions.size() / 3));
            mesh.positions.insert(mesh.positions.end(), {float(q.X()), float(q.Y()), float(q.Z())});
            mesh.normals.insert(mesh.normals.end(), {float(normal.X()), float(normal.Y()), float(normal.Z())});
            lo = {std::min(lo.x, q.X()), std::min(lo.y, q.Y()), std::min(lo.z, q.Z())};
            hi = {std::max(hi.x, q.X()), std::max(hi.y, q.Y()), std::max(hi.z, q.Z())};
        }
    }
    if (count > 0) {
        mesh.boundsMin = lo;
        mesh.boundsMax = hi;
    }
    return mesh;
}

FaceInfo describeFace(const TopoDS_Face& face, int index)
{
    FaceInfo info;
    info.index = index;
    try {
        BRepAdaptor_Surface surface(face, Standard_False);
        if (surface.GetType() == GeomAbs_Plane) {
            const gp_Pln plane = surface.Plane();
            gp_Dir normal = plane.Axis().Direction();
            if (face.Orientation() == TopAbs_REVERSED)
                normal.Reverse();
            info.planar = true;
            info.normal = {normal.X(), normal.Y(), normal.Z()};
            if (1 - std::abs(normal.Z()) < kZAxisTolerance)
                info.planeZ = plane.Location().Z();
        }
        GProp_GProps props;
        BRepGProp::SurfaceProperties(face, props);
        info.areaMm2 = props.Mass();
    } catch (const Standard_Failure&) {
        // A face OCCT cannot evaluate stays listed (indices must not shift) but undescribed.
    }
    return info;
}

}  // namespace

void describeShape(ModelData& data)
{
    TopExp::MapShapes(data.shape, TopAbs_FACE, data.faces);
    data.faceInfos.reserve(static_cast<std::size_t>(data.faces.Extent()));
    for (int i = 1; i <= data.faces.Extent(); ++i)
        data.faceInfos.push_back(describeFace(TopoDS::Face(data.faces(i)), i));
    TopExp::MapShapes(data.shape, TopAbs_EDGE, data.edges);
    data.edgeInfos.reserve(static_cast<std::size_t>(data.edges.Extent()));
    for (int i = 1; i <= data.edges.Extent(); ++i)
        data.edgeInfos.push_back(describeEdge(TopoDS::Edge(data.edges(i)), i));

    Bnd_Box box;
    BRepBndLib::AddOptimal(data.shape, box, Standard_False, Standard_False);
    if (!box.IsVoid()) {
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        data.boundsMin = {x0, y0, z0};
        data.boundsMax = {x1, y1, z1};
    }
}

namespace {

base::Status loadInto(ModelData& data, const std::string& ext, ProgressBridge& bridge)
{
    const std::string& path = data.path;
    Message_ProgressScope root(bridge.Start(), "Load", 10);

    if (ext == ".stl") {
        const Handle(Poly_Triangulation) tri = RWStl::ReadFile(path.c_str(), root.Next(9));
        if (bridge.cancelled())
            return base::makeError("cancelled", path);
        if (tri.IsNull())
            return base::makeError("not an STL file or damaged", path);
        if (tri->NbTriangles() == 0)
            return base::makeError("contains no shape", path);
        data.stlMesh = stlToMesh(*tri);
        data.boundsMin = data.stlMesh.boundsMin;
        data.boundsMax = data.stlMesh.boundsMax;
        return base::Status::success();
    }

    base::Result<TopoDS_Shape> shape = base::makeError("unsupported file type", path);
    if (ext == ".step" || ext == ".stp") {
        const std::lock_guard<std::mutex> lock(detail::dataExchangeMutex());
        STEPControl_Reader reader;
        shape = readExchange(reader, path, "not a STEP file", root.Next(9), bridge);
    } else if (ext == ".iges" || ext == ".igs") {
        const std::lock_guard<std::mutex> lock(detail::dataExchangeMutex());
        IGESControl_Reader reader;
        shape = readExchange(reader, path, "not an IGES file", root.Next(9), bridge);
    } else {
        shape = readBRep(path, root.Next(9), bridge);
    }
    if (!shape)
        return shape.error();
    if (!hasSubShapes(shape.value()))
        return base::makeError("contains no shape", path);
    data.shape = shape.value();
    describeShape(data);
    root.Next(1);
    if (bridge.cancelled())
        return base::makeError("cancelled", path);
    return base::Status::success();
}

}  // namespace

base::Result<std::shared_ptr<const ModelImpl>> occt::load(const std::string& path, const ProgressFn& progress)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return base::makeError("file not found", path);
    if (!std::filesystem::is_regular_file(path, ec))
        return base::makeError("not a regular file", path);
    const std::string ext = lowerExtension(path);
    static constexpr const char* kKnown[] = {".step", ".stp", ".iges", ".igs", ".brep", ".brp", ".stl"};
    if (std::find(std::begin(kKnown), std::end(kKnown), ext) == std::end(kKnown))
        return base::makeError(
            "unsupported file type '" + ext + "' (expected .step, .stp, .iges, .igs, .brep, .brp or .stl)", path);

    ProgressBridge bridge(progress);
    if (!bridge.report(0.0))
        return base::makeError("cancelled", path);
    auto data = std::make_shared<ModelData>();
    data->path = path;
    // OCCT's own complaints become part of the error instead of lines on stdout.
    detail::OcctMessageCapture occt;
    auto failed = [&](std::string message) { return base::makeError(message + occt.failureNote(), path); };
    try {
        if (base::Status status = loadInto(*data, ext, bridge); !status)
            return bridge.cancelled() ? status.error() : failed(status.error().message);
    } catch (const Standard_Failure& e) {
        return failed(std::string("could not read the file: ") + e.GetMessageString());
    } catch (const std::exception& e) {
        return failed(std::string("could not read the file: ") + e.what());
    } catch (...) {
        return failed("could not read the file: unknown error");
    }
    return std::shared_ptr<const ModelImpl>(std::move(data));
}

}  // namespace camwb::occ
