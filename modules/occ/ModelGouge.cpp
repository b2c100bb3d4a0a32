// Model::firstGouge: the gouge check of five-axis tool poses against the solid. Points on a flat
// end mill shrunk by the tolerance (its side every ~1 mm around and along, its bottom in rings)
// are classified against the model; one inside is a gouge deeper than the tolerance. Points
// outside the model's box are skipped (most of a tool above the part).
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

namespace camwb::occ {

namespace {

constexpr double kPi = 3.14159265358979323846;

base::Vec3 unit(const base::Vec3& v) { return v * (1 / v.length()); }

// Two unit vectors square to the axis and to each other.
std::pair<base::Vec3, base::Vec3> crossAxes(const base::Vec3& axis)
{
    const base::Vec3 helper = std::abs(axis.z) < 0.9 ? base::Vec3{0, 0, 1} : base::Vec3{1, 0, 0};
    const base::Vec3 u = unit(axis.cross(helper));
    return {u, axis.cross(u)};
}

// The sample points of one pose's tool, shrunk by the tolerance.
std::vector<base::Vec3> toolPoints(const ToolPose& pose, double radius, double length, double tolerance)
{
    std::vector<base::Vec3> points;
    const auto [u, v] = crossAxes(pose.axis);
    const double r = std::max(radius - tolerance, 0.0);
    const int around = std::max(8, static_cast<int>(std::ceil(2 * kPi * r / 1.0)));
    const int along = std::max(1, static_cast<int>(std::ceil((length - tolerance) / 1.0)));
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

// The poses with poses between them, so that the tip and the flute's top move no more than `step`.
std::vector<std::pair<int, ToolPose>> densePoses(const std::vector<ToolPose>& poses, double length, double step)
{
    std::vector<std::pair<int, ToolPose>> out;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        if (i > 0) {
            const ToolPose& a = poses[i - 1];
            const ToolPose& b = poses[i];
            const double moved =
                std::max(distance(a.tip, b.tip), distance(a.tip + a.axis * length, b.tip + b.axis * length));
            const int n = static_cast<int>(std::ceil(moved / step));
            for (int k = 1; k < n; ++k) {
                const double f = static_cast<double>(k) / n;
                out.push_back(
                    {static_cast<int>(i), {a.tip + (b.tip - a.tip) * f, unit(a.axis + (b.axis - a.axis) * f)}});
            }
        }
        out.push_back({static_cast<int>(i), poses[i]});
    }
    return out;
}

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

std::optional<Gouge> Model::firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                       double toleranceMm) const
{
    if (!hasBRep() || poses.empty())
        return std::nullopt;
    try {
        BRepClass3d_SolidClassifier classifier(m_data->shape);
        const base::Vec3 lo = boundsMin() - base::Vec3{1e-3, 1e-3, 1e-3};
        const base::Vec3 hi = boundsMax() + base::Vec3{1e-3, 1e-3, 1e-3};
        for (const auto& [index, pose] : densePoses(poses, fluteLengthMm, 0.5)) {
            for (const base::Vec3& p : toolPoints(pose, radiusMm, fluteLengthMm, toleranceMm)) {
                if (p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x || p.y > hi.y || p.z > hi.z)
                    continue;
                classifier.Perform(gp_Pnt(p.x, p.y, p.z), 1e-7);
                if (classifier.State() == TopAbs_IN)
                    return Gouge{index, p, nearestFace(*m_data, p)};
            }
        }
    } catch (const Standard_Failure&) {
        return Gouge{0, poses.front().tip, 0};  // a check that could not run is no pass
    }
    return std::nullopt;
}

}  // namespace camwb::occ
