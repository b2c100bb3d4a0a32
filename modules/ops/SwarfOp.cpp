#include "ops/SwarfOp.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }
std::string operationName(const SwarfParams& p) { return "swarf \"" + p.name + "\""; }

// The distance from p to the segment a-b.
double distanceToChord(const base::Vec3& p, const base::Vec3& a, const base::Vec3& b)
{
    const base::Vec3 ab = b - a;
    const double len2 = ab.dot(ab);
    const double f = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * f);
}

struct PassShape {
    const SwarfDrive& drive;
    double offset, axialOffset, height, chord, angle;

    SwarfPose at(double t) const
    {
        const geom::RulingPoint r = drive.at(t);
        return {r.point + r.normal * offset + r.ruling * axialOffset, r.ruling, t};
    }
    // Whether the straight move from a to b (tip and flute top moving linearly, the axis turning)
    // stays within the tolerances of the exact pose at `mid`.
    bool within(const SwarfPose& a, const SwarfPose& b, const SwarfPose& mid) const
    {
        if (a.axis.angleTo(b.axis) > angle)
            return false;
        if (distanceToChord(mid.tip, a.tip, b.tip) > chord)
            return false;
        const base::Vec3 top = mid.tip + mid.axis * height;
        return distanceToChord(top, a.tip + a.axis * height, b.tip + b.axis * height) <= chord;
    }
};

// Adds the poses after `a` up to and including `b`, bisecting where a straight move would leave
// the tolerances (checked at the quarter points, so an S between two poses is not missed).
void refine(const PassShape& shape, const SwarfPose& a, const SwarfPose& b, int depth, std::vector<SwarfPose>& out)
{
    const SwarfPose mid = shape.at((a.t + b.t) / 2);
    bool ok = depth >= 24 || shape.within(a, b, mid);
    if (ok && depth < 24)
        ok = shape.within(a, b, shape.at(a.t + (b.t - a.t) / 4)) && shape.within(a, b, shape.at(b.t - (b.t - a.t) / 4));
    if (ok) {
        out.push_back(b);
        return;
    }
    refine(shape, a, mid, depth + 1, out);
    refine(shape, mid, b, depth + 1, out);
}

base::Status checkParams(const std::string& what, const SwarfParams& p, const ToolController& tc)
{
    if (auto status = checkToolController(what, tc); !status)
        return status;
    if (!(p.heights.clearanceZ >= p.heights.safeZ))
        return opError(what, "clearance height " + fmt(p.heights.clearanceZ) + " is below the safe height " +
                                 fmt(p.heights.safeZ));
    if (p.radialPasses < 1)
        return opError(what, "radial passes must be at least 1, got " + std::to_string(p.radialPasses));
    if (p.radialPasses > 1 && p.radialStepoverMm <= 0)
        return opError(what, "radial stepover must be positive, got " + fmt(p.radialStepoverMm) + " mm");
    if (p.radialStockMm < 0)
        return opError(what, "radial stock must not be negative, got " + fmt(p.radialStockMm) + " mm");
    if (p.chordToleranceMm <= 0)
        return opError(what, "chord tolerance must be positive, got " + fmt(p.chordToleranceMm) + " mm");
    if (p.angleToleranceDeg <= 0 || p.angleToleranceDeg > 45)
        return opError(what, "angle tolerance must be above 0 and at most 45 degrees, got " + fmt(p.angleToleranceDeg) +
                                 " degrees");
    return base::Status::success();
}

// The distance along the axis from the tip up to workpiece Z `z`; error where the axis cannot get
// there (pointing down or nearly level) or z is below the tip.
base::Result<double> upTo(const std::string& what, const SwarfPose& pose, double z, const char* height)
{
    if (pose.axis.z < 0.05)
        return opError(what, "the tool axis at (" + fmt(pose.tip.x) + ", " + fmt(pose.tip.y) + ", " + fmt(pose.tip.z) +
                                 ") points down or nearly level: no way up to the " + height + " height along it");
    if (z < pose.tip.z)
        return opError(what, std::string("the ") + height + " height " + fmt(z) + " mm is below the tip at (" +
                                 fmt(pose.tip.x) + ", " + fmt(pose.tip.y) + ", " + fmt(pose.tip.z) + ")");
    return (z - pose.tip.z) / pose.axis.z;
}

class SwarfWriter {
public:
    SwarfWriter(OpResult& out, int operationIndex) : m_out(out), m_operation(operationIndex) {}

    void add(const toolpath::Record& record) { m_out.toolpath.add(record, {m_operation, m_index++}); }
    void move(const base::Vec3& tip, const base::Vec3& axis, double feed)
    {
        toolpath::ToolAxisMove m;
        m.tip = tip;
        m.axis = axis;
        m.feedMmPerMin = feed;
        add(m);
    }

private:
    OpResult& m_out;
    int m_operation;
    int m_index = 0;
};

// Whether cutting in the drive's direction climbs: the material (against the normal) on the
// right of the travel, seen from the spindle down the axis.
bool drivesClimb(const SwarfDrive& drive)
{
    const double t = drive.t0 + (drive.t1 - drive.t0) * 0.5, dt = (drive.t1 - drive.t0) * 1e-4;
    const geom::RulingPoint a = drive.at(t), b = drive.at(t + dt);
    const base::Vec3 travel = b.point - a.point;
    return (a.normal * -1).dot(travel.cross(a.ruling)) > 0;
}

}  // namespace

std::vector<SwarfPose> swarfPass(const SwarfDrive& drive, double offsetMm, double axialOffsetMm, double heightMm,
                                 double chordToleranceMm, double angleToleranceDeg, const Progress& progress)
{
    const PassShape shape{drive, offsetMm, axialOffsetMm, heightMm, chordToleranceMm, angleToleranceDeg * kPi / 180};
    const int pieces = drive.closed ? 16 : 4;
    std::vector<SwarfPose> out{shape.at(drive.t0)};
    for (int i = 1; i <= pieces; ++i) {
        if (!progress.step(static_cast<double>(i - 1) / pieces))
            return {};
        const SwarfPose from = out.back();
        refine(shape, from, shape.at(drive.t0 + (drive.t1 - drive.t0) * i / pieces), 0, out);
    }
    return out;
}

base::Result<OpResult> computeSwarf(const SwarfDrive& drive, const SwarfParams& params, const ToolController& tc,
                                    int operationIndex, const Progress& progress)
{
    const std::string what = operationName(params);
    if (auto status = checkParams(what, params, tc); !status)
        return status.error();
    if (!drive.at)
        return opError(what, "no face to follow");
    SwarfDrive oriented = drive;
    if (drivesClimb(drive) != params.climb) {
        oriented.t0 = drive.t1;
        oriented.t1 = drive.t0;
    }
    const double radius = tc.tool.diameterMm / 2;
    const geom::RulingPoint first = oriented.at(oriented.t0);
    if (first.ruling.length() < 0.5)
        return opError(what, "the face gives no ruling at its drive edge's start");
    // The face's height above the tip along the rulings must be within the flutes.
    double faceHeight = 0;
    for (int i = 0; i <= 8; ++i)
        faceHeight = std::max(faceHeight, oriented.at(oriented.t0 + (oriented.t1 - oriented.t0) * i / 8).lengthMm);
    faceHeight -= params.axialOffsetMm;
    if (tc.tool.fluteLengthMm > 0 && faceHeight > tc.tool.fluteLengthMm + 1e-9)
        return opError(what, "the face reaches " + fmt(faceHeight) + " mm up the tool from its tip, beyond its " +
                                 fmt(tc.tool.fluteLengthMm) + " mm flute length");
    const double checkHeight = tc.tool.fluteLengthMm > 0 ? std::min(faceHeight, tc.tool.fluteLengthMm) : faceHeight;

    OpResult result;
    SwarfWriter out(result, operationIndex);
    out.add(sectionBegin(params.name, "swarf", tc));
    const double cutting = feedOf(tc, toolpath::FeedKind::Cutting).mmPerMin;
    const double plunge = feedOf(tc, toolpath::FeedKind::Plunge).mmPerMin;
    std::vector<SwarfPose> previous;
    for (int pass = 0; pass < params.radialPasses; ++pass) {
        const double offset =
            radius + params.radialStockMm + (params.radialPasses - 1 - pass) * params.radialStepoverMm;
        Progress step{[&](double f) {
                          if (progress.report)
                              progress.report((pass + f) / params.radialPasses);
                      },
                      progress.cancel};
        std::vector<SwarfPose> poses = swarfPass(oriented, offset, params.axialOffsetMm, std::max(checkHeight, 0.0),
                                                 params.chordToleranceMm, params.angleToleranceDeg, step);
        if (poses.empty())
            return cancelledError(what);
        if (!previous.empty() && oriented.closed) {
            out.move(poses.front().tip, poses.front().axis, cutting);  // across to the next pass
        } else {
            if (!previous.empty()) {
                auto up = upTo(what, previous.back(), params.heights.clearanceZ, "clearance");
                if (!up)
                    return up.error();
                out.move(previous.back().tip + previous.back().axis * up.value(), previous.back().axis, 0);
            }
            const SwarfPose& start = poses.front();
            auto clear = upTo(what, start, params.heights.clearanceZ, "clearance");
            auto safe = upTo(what, start, params.heights.safeZ, "safe");
            if (!clear)
                return clear.error();
            if (!safe)
                return safe.error();
            out.move(start.tip + start.axis * clear.value(), start.axis, 0);
            out.move(start.tip + start.axis * safe.value(), start.axis, 0);
            out.move(start.tip, start.axis, plunge);
        }
        for (std::size_t i = 1; i < poses.size(); ++i)
            out.move(poses[i].tip, poses[i].axis, cutting);
        previous = std::move(poses);
    }
    auto up = upTo(what, previous.back(), params.heights.clearanceZ, "clearance");
    if (!up)
        return up.error();
    out.move(previous.back().tip + previous.back().axis * up.value(), previous.back().axis, 0);
    out.add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
