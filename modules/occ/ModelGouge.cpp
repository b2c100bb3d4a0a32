// Model::firstGouge: the gouge check of five-axis tool poses against the solid. Points on a flat
// end mill shrunk by the tolerance (its side every ~1 mm around and along, its bottom in rings)
// are classified against the model; one inside is a gouge deeper than the tolerance. Points
// outside the model's box are skipped (most of a tool above the part).
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

namespace camwb::occ {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpacing = 1.0;  // mm between sample points on the tool, around and along

// Two unit vectors square to the axis and to each other.
std::pair<base::Vec3, base::Vec3> crossAxes(const base::Vec3& axis)
{
    const base::Vec3 helper = std::abs(axis.z) < 0.9 ? base::Vec3{0, 0, 1} : base::Vec3{1, 0, 0};
    const base::Vec3 u = axis.cross(helper).normalized();
    return {u, axis.cross(u)};
}

// The sample points of one pose's tool, shrunk by the tolerance.
std::vector<base::Vec3> toolPoints(const ToolPose& pose, double radius, double length, double tolerance)
{
    std::vector<base::Vec3> points;
    const auto [u, v] = crossAxes(pose.axis);
    const double r = std::max(radius - tolerance, 0.0);
    const int around = std::max(8, static_cast<int>(std::ceil(2 * kPi * r / kSpacing)));
    const int along = std::max(1, static_cast<int>(std::ceil((length - tolerance) / kSpacing)));
    for (int i = 0; i <= along; ++i) {
        const base::Vec3 centre = pose.tip + pose.axis * (tolerance + (length - tolerance) * i / along);
        for (int k = 0; k < around; ++k) {
            const double a = 2 * kPi * k / around;
            points.push_back(centre + (u * std::cos(a) + v * std::sin(a)) * r);
        }
    }
    const base::Vec3 bottom = pose.tip + pose.axis * tolerance;
    points.push_back(bottom);
    for (double f : {0.33, 0.67}) {
        for (int k = 0; k < around; ++k) {
            const double a = 2 * kPi * (k + 0.5) / around;
            points.push_back(bottom + (u * std::cos(a) + v * std::sin(a)) * (r * f));
        }
    }
    return points;
}

struct DensePose {
    int index;  // the pose asked about (the move's end)
    ToolPose pose;
    double length;  // of the tool's side to check
};

// The poses with poses between them, so that the tip and the flute's top move no more than `step`.
// A move along the tool's own axis sweeps a longer cylinder: one pose at the lower end, longer.
std::vector<DensePose> densePoses(const std::vector<ToolPose>& poses, double length, double step)
{
    std::vector<DensePose> out;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const int index = static_cast<int>(i);
        if (i > 0) {
            const ToolPose& a = poses[i - 1];
            const ToolPose& b = poses[i];
            const base::Vec3 travel = b.tip - a.tip;
            if (a.axis == b.axis && travel.cross(a.axis).length() < 1e-9) {
                const ToolPose& lower = travel.dot(a.axis) < 0 ? b : a;
                out.push_back({index, lower, length + travel.length()});
                continue;
            }
            const double moved =
                std::max(distance(a.tip, b.tip), distance(a.tip + a.axis * length, b.tip + b.axis * length));
            const int n = static_cast<int>(std::ceil(moved / step));
            for (int k = 1; k < n; ++k) {
                const double f = static_cast<double>(k) / n;
                out.push_back({index, {a.tip + travel * f, (a.axis + (b.axis - a.axis) * f).normalized()}, length});
            }
        }
        out.push_back({index, poses[i], length});
    }
    return out;
}

// Where the model's boundary may be near a point: each face's box, and for planes the plane,
// widened by the sampling step. A sample point far from every face has the state of any other
// such point of the same tool, unless a face passes between them, and then sample points near
// that face are classified themselves; so one far point per pose is enough.
class NearFaces {
public:
    NearFaces(const ModelData& data, double step) : m_step(step)
    {
        for (int i = 1; i <= data.faces.Extent(); ++i) {
            const TopoDS_Face& face = TopoDS::Face(data.faces(i));
            Bnd_Box box;
            BRepBndLib::AddOptimal(face, box, false, false);
            box.Enlarge(step);
            BRepAdaptor_Surface surface(face, false);
            m_faces.push_back(
                {box, surface.GetType() == GeomAbs_Plane ? std::optional<gp_Pln>(surface.Plane()) : std::nullopt});
        }
    }
    bool near(const base::Vec3& p) const
    {
        const gp_Pnt q(p.x, p.y, p.z);
        return std::any_of(m_faces.begin(), m_faces.end(), [&](const FaceZone& f) {
            return !f.box.IsOut(q) && (!f.plane || f.plane->Distance(q) <= m_step);
        });
    }

private:
    struct FaceZone {
        Bnd_Box box;
        std::optional<gp_Pln> plane;
    };
    double m_step;
    std::vector<FaceZone> m_faces;
};

int nearestFace(const ModelData& data, const base::Vec3& p)
{
    const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z));
    int best = 0;
    double bestDistance = 1e300;
    for (int i = 1; i <= data.faces.Extent(); ++i) {
        BRepExtrema_DistShapeShape dist(vertex, data.faces(i));
        if (dist.IsDone() && dist.Value() < bestDistance) {
            bestDistance = dist.Value();
            best = i;
        }
    }
    return best;
}

}  // namespace

std::optional<Gouge> ModelData::firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                           double toleranceMm) const
{
    if (!hasBRep() || poses.empty())
        return std::nullopt;
    try {
        BRepClass3d_SolidClassifier classifier(shape);
        const base::Vec3 lo = boundsMin - base::Vec3{1e-3, 1e-3, 1e-3};
        const base::Vec3 hi = boundsMax + base::Vec3{1e-3, 1e-3, 1e-3};
        const NearFaces nearFaces(*this, kSpacing);
        for (const auto& [index, pose, length] : densePoses(poses, fluteLengthMm, 0.5)) {
            bool farOneSeen = false;
            for (const base::Vec3& p : toolPoints(pose, radiusMm, length, toleranceMm)) {
                if (p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x || p.y > hi.y || p.z > hi.z)
                    continue;
                if (!nearFaces.near(p)) {
                    if (farOneSeen)
                        continue;
                    farOneSeen = true;
                }
                classifier.Perform(gp_Pnt(p.x, p.y, p.z), 1e-7);
                if (classifier.State() == TopAbs_IN)
                    return Gouge{index, p, nearestFace(*this, p)};
            }
        }
    } catch (const Standard_Failure&) {
        return Gouge{0, poses.front().tip, 0};  // a check that could not run is no pass
    }
    return std::nullopt;
}

}  // namespace camwb::occ
