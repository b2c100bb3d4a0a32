#include "MotionMatch.h"

#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/TraceWriter.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace camwb::nc::test {

namespace {

using namespace camwb::toolpath;

// A unit vector; a zero one (no axis given) is the spindle's +Z.
Vec3 unit(const Vec3& v) { return v.length() > 0 ? v.normalized() : Vec3{0, 0, 1}; }

class Flattener {
public:
    Flattener(double chord, const kinematics::KinematicChain* machineMotion) :
        m_chord(chord),
        m_machineMotion(machineMotion)
    {
    }

    void record(const Record& r, int index)
    {
        m_index = index;
        std::visit([this](const auto& v) { visit(v); }, r);
    }
    std::vector<MotionSample> take() { return std::move(m_samples); }

private:
    // Rapids between two feed moves are one transit, compared by its ends and its lowest point:
    // posts add positioning moves of their own (to the clearance plane before a cycle, back up
    // after one), so only where a transit starts, ends and how deep it goes are the CL's promise.
    // A move that only turns the tool axis is a segment too (of length 0). `to` is in the workpiece
    // frame: after a working plane the samples stay there, so that a plane and the moves after it
    // compare by where the tool goes, whichever records make the way there.
    void segment(const Vec3& to, bool rapid, double feed, const Vec3& axis)
    {
        m_local = KnownPosition(m_plane.toLocal(to));
        if (to == m_at && axis == m_axis)
            return;
        if (rapid) {
            if (!m_inTransit) {
                m_inTransit = true;
                m_transitStart = m_at;
                m_transitStartAxis = m_axis;
                m_transitLowestZ = m_at.z;
            }
            m_transitLowestZ = std::min(m_transitLowestZ, to.z);
            m_at = to;
            m_axis = axis;
            return;
        }
        flushTransit();
        emit(m_at, m_axis, to, axis, false, feed, to.z);
        m_at = to;
        m_axis = axis;
    }
    // Three-axis records move with the tool along +Z, the working plane's Z in a tilted plane.
    void segment(const Vec3& to, bool rapid, double feed) { segment(to, rapid, feed, m_plane.zAxis); }

public:
    void flushTransit()
    {
        if (!m_inTransit)
            return;
        m_inTransit = false;
        if (!(m_transitStart == m_at) || !(m_transitStartAxis == m_axis))
            emit(m_transitStart, m_transitStartAxis, m_at, m_axis, true, 0, m_transitLowestZ);
    }

private:
    void emit(const Vec3& from, const Vec3& fromAxis, const Vec3& to, const Vec3& toAxis, bool rapid, double feed,
              double lowestZ)
    {
        MotionSample s{};
        s.rapid = rapid;
        s.feed = feed;
        s.feedChecked = !m_machineFeed;
        s.perMinute = m_perMinute;
        s.rpm = m_rpm;
        s.tool = m_tool;
        s.record = m_index;
        s.lowestZ = lowestZ;
        s.point = (from + to) * 0.5;
        s.axis = unit(fromAxis + toAxis);
        s.midpoint = true;
        m_samples.push_back(s);
        s.point = to;
        s.axis = toAxis;
        s.midpoint = false;
        s.exact = m_exactEnd;
        m_samples.push_back(s);
    }
    // A move that gives only some axes keeps the others (both sides start at the origin here);
    // after a working plane the position in its frame is unknown until the moves give every axis.
    void straight(const Vec3& to, AxisMask axes, bool rapid, double feed)
    {
        m_local.moveTo(to, axes);
        if (m_local.complete())
            segment(m_plane.toWorkpiece(m_local.value()), rapid, feed);
    }
    void visit(const Rapid& r)
    {
        m_angles.reset();
        straight(r.to, r.axes, true, 0);
    }
    void visit(const Linear& r)
    {
        m_angles.reset();
        straight(r.to, r.axes, false, r.feedMmPerMin);
    }
    void visit(const Arc& r)
    {
        m_angles.reset();
        for (const Vec3& p : toolpath::linearizeArc(m_local.value(), r, m_chord))
            segment(m_plane.toWorkpiece(p), false, r.feedMmPerMin);
    }
    void visit(const Cycle& c)
    {
        m_angles.reset();
        for (const Vec3& hole : c.holes)
            for (const Record& moved : expandCycleHole(c, hole, m_local.value(), {m_rpm, true}))
                std::visit([this](const auto& v) { cycleMove(v); }, moved);
    }
    void cycleMove(const Rapid& r) { straight(r.to, r.axes, true, 0); }
    void cycleMove(const Linear& r) { straight(r.to, r.axes, false, r.feedMmPerMin); }
    // The moves after it are in its frame (a post retracts and turns the table in between: the
    // transit goes on to the first point the new frame gives whole).
    void visit(const WorkingPlane& r)
    {
        m_plane = r;
        m_local = KnownPosition();
    }
    template <class T> void cycleMove(const T&) {}  // tapping's spindle reversals: the rpm stays
    void visit(const ToolAxisMove& r)
    {
        const bool rapid = r.feedMmPerMin <= 0;
        const std::optional<std::array<double, 2>> angles = jointAngles(r.machine);
        if (m_machineMotion && r.jointInterpolated && angles && m_angles)
            machineMove(r, *angles, rapid);
        else {
            m_exactEnd = true;
            segment(r.tip, rapid, r.feedMmPerMin, unit(r.axis));
            m_exactEnd = false;
        }
        m_angles = angles;
    }
    // Linear and rotary machine axes interpolated together from the last pose to this one, in
    // steps of at most 0.1 degree (at 100 mm from the rotary axis the tip's curve strays less than
    // 0.00004 mm from the chords between the samples).
    void machineMove(const ToolAxisMove& r, const std::array<double, 2>& to, bool rapid)
    {
        const std::array<double, 2>& from = *m_angles;
        const Vec3 linearFrom = kinematics::linearAxesFor(*m_machineMotion, m_at, from);
        const Vec3 linearTo = kinematics::linearAxesFor(*m_machineMotion, r.tip, to);
        const double turn = std::max(std::abs(to[0] - from[0]), std::abs(to[1] - from[1]));
        const int steps = std::max(1, static_cast<int>(std::ceil(turn / 0.1)));
        m_machineFeed = true;
        for (int k = 1; k <= steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            kinematics::MachinePose pose;
            pose.linear = linearFrom + (linearTo - linearFrom) * t;
            pose.rotaryDeg = {from[0] + (to[0] - from[0]) * t, from[1] + (to[1] - from[1]) * t};
            const kinematics::ToolPose tool = kinematics::forwardKinematics(*m_machineMotion, pose);
            m_exactEnd = k == steps;
            segment(k == steps ? r.tip : tool.tip, rapid, r.feedMmPerMin, k == steps ? unit(r.axis) : tool.axis);
        }
        m_exactEnd = false;
        m_machineFeed = false;
    }
    // The record's rotary axes in the chain's joint order, when it gives both (table joints only:
    // a head joint's tip would need the tool length, which the record does not carry).
    std::optional<std::array<double, 2>> jointAngles(const RotaryAxes& machine) const
    {
        if (!m_machineMotion || !m_machineMotion->fiveAxis())
            return std::nullopt;
        std::array<double, 2> deg{};
        for (std::size_t i = 0; i < 2; ++i) {
            const kinematics::RotaryJoint& joint = m_machineMotion->joints[i];
            const char name = joint.axis.empty() ? '?' : joint.axis[0];
            const unsigned char bit = name == 'A' ? RotaryAxes::kA : name == 'B' ? RotaryAxes::kB : RotaryAxes::kC;
            if (!joint.onTable || !machine.has(bit) || (name != 'A' && name != 'B' && name != 'C'))
                return std::nullopt;
            deg[i] = name == 'A' ? machine.aDeg : name == 'B' ? machine.bDeg : machine.cDeg;
        }
        return deg;
    }
    void visit(const ToolChange& r) { m_tool = r.tool.number; }
    void visit(const Spindle& r) { m_rpm = r.rpm; }
    void visit(const FeedModeChange& r) { m_perMinute = r.mode == FeedMode::PerMinute; }
    template <class T> void visit(const T&) {}

    double m_chord;
    const kinematics::KinematicChain* m_machineMotion;
    Vec3 m_at;  // in the workpiece frame
    Vec3 m_axis{0, 0, 1};
    std::optional<std::array<double, 2>> m_angles;  // of the last five-axis move, for machineMove
    bool m_exactEnd = false;                        // the next end is a record's own point
    bool m_machineFeed = false;
    WorkingPlane m_plane;
    KnownPosition m_local{Vec3{}};  // m_at in the plane's frame, as far as known
    double m_rpm = 0;
    int m_tool = 0;
    bool m_perMinute = true;
    int m_index = 0;
    bool m_inTransit = false;
    Vec3 m_transitStart;
    Vec3 m_transitStartAxis{0, 0, 1};
    double m_transitLowestZ = 0;
    std::vector<MotionSample> m_samples;
};

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y + ab.z * ab.z;
    double t = 0;
    if (len2 > 0)
        t = std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y + (p.z - a.z) * ab.z) / len2, 0.0, 1.0);
    const Vec3 q = a + ab * t;
    return std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z));
}

std::string describe(const Toolpath& path, int record)
{
    if (record < 0 || record >= static_cast<int>(path.size()))
        return "(none)";
    Toolpath one;
    one.add(path.record(record));
    std::string text = traceOf(one);
    if (!text.empty() && text.back() == '\n')
        text.pop_back();
    const SourceRef& source = path.source(record);
    return "record " + std::to_string(record) + (source.line > 0 ? " (line " + std::to_string(source.line) + ")" : "") +
           ": " + text;
}

bool near(double a, double b, double relative) { return std::abs(a - b) <= relative * std::max(std::abs(b), 1.0); }

// What differs between a sample and the segment it lies on, or nullptr.
const char* difference(const MotionSample& s, const MotionSample& o, const MatchTolerance& tol, bool rapidDepth)
{
    if (s.rapid != o.rapid)
        return "rapid/feed";
    if (rapidDepth && s.rapid && s.lowestZ < o.lowestZ - tol.pointMm)
        return "lowest rapid";
    if (s.tool != o.tool)
        return "tool";
    if (!near(s.rpm, o.rpm, tol.rpmRelative))
        return "spindle speed";
    if (!s.rapid && s.feedChecked && o.feedChecked && s.perMinute && o.perMinute &&
        !near(s.feed, o.feed, tol.feedRelative))
        return "feed";
    return nullptr;
}

// The tool axis of a sample agrees with segment j of `onto` (vertices j-1 to j). `atVertices`
// (from the CL to the NC): a five-axis record's own point must find its axis at a vertex, as
// every CL point is a point of the NC; the CL says nothing of the axis between its points.
// Otherwise (from the NC to the CL) the axis at a vertex is that vertex's, and between two the
// axis turns from one end's to the other's: no further from either than they lie apart, plus
// `betweenRad` (a flip or a wrong plane fails; the exact way is the machine's).
bool axisAgrees(const MotionSample& s, const std::vector<Vec3>& vertices, const std::vector<Vec3>& axes, std::size_t j,
                double toleranceMm, const MatchTolerance& tol, bool atVertices)
{
    if (atVertices && !s.exact)
        return true;
    for (std::size_t end : {j, j - 1})
        if (distanceToSegment(s.point, vertices[end], vertices[end]) <= toleranceMm &&
            s.axis.angleTo(axes[end]) <= tol.axisRad)
            return true;
    if (atVertices)
        return false;
    const double span = axes[j - 1].angleTo(axes[j]) + std::max(tol.axisRad, tol.axisBetweenRad);
    return s.axis.angleTo(axes[j - 1]) <= span && s.axis.angleTo(axes[j]) <= span;
}

// Every sample of `from` must lie, in order, on the polyline of `onto` (first fit going forward,
// so a path that passes the same place twice is matched in its own order), with its tool axis.
// `exactAxes`: a five-axis record's own point of `from` must find `onto`'s axis at a vertex
// (from the CL to the NC: every CL point is a point of the NC too).
std::optional<std::string> oneWay(const std::vector<MotionSample>& from, const std::vector<MotionSample>& onto,
                                  double toleranceMm, const MatchTolerance& tol, const Toolpath& fromPath,
                                  const Toolpath& ontoPath, const char* fromName, const char* ontoName, bool rapidDepth,
                                  bool exactAxes)
{
    // onto's vertices: the origin, then its segment ends (midpoints only carry attributes).
    std::vector<Vec3> vertices{Vec3{}};
    std::vector<Vec3> axes{Vec3{0, 0, 1}};
    std::vector<const MotionSample*> segmentOf{nullptr};
    for (const MotionSample& s : onto)
        if (!s.midpoint) {
            vertices.push_back(s.point);
            axes.push_back(s.axis);
            segmentOf.push_back(&s - 1);  // the midpoint before each end describes the segment
        }
    std::size_t segment = 1;
    auto within = [&](const MotionSample& s, std::size_t j) {
        return distanceToSegment(s.point, vertices[j - 1], vertices[j]) <= toleranceMm;
    };
    auto axisOk = [&](const MotionSample& s, std::size_t j) {
        return axisAgrees(s, vertices, axes, j, toleranceMm, tol, exactAxes);
    };
    for (const MotionSample& s : from) {
        std::size_t j = segment;
        while (j < vertices.size() && !within(s, j))
            ++j;
        std::ostringstream why;
        if (j >= vertices.size()) {
            why << fromName << " point " << s.point.x << ' ' << s.point.y << ' ' << s.point.z << " of "
                << describe(fromPath, s.record) << " is not on the rest of " << ontoName << "'s path (from "
                << describe(ontoPath,
                            segment < segmentOf.size() && segmentOf[segment] ? segmentOf[segment]->record : -1)
                << ")";
            return why.str();
        }
        // Near a junction (or where the tool turns on the spot) a point is on several segments:
        // take the first that also agrees in tool axis and, for a midpoint, in kind, tool,
        // spindle and feed; report the nearest one's difference when none does.
        std::size_t agreeing = j;
        for (; agreeing < vertices.size(); ++agreeing)
            if (within(s, agreeing) && axisOk(s, agreeing) &&
                (!s.midpoint || !difference(s, *segmentOf[agreeing], tol, rapidDepth)))
                break;
        if (agreeing < vertices.size()) {
            segment = agreeing;
            continue;
        }
        const MotionSample& o = *segmentOf[j];
        if (!axisOk(s, j)) {
            why << "tool axis differs: " << fromName << ' ' << describe(fromPath, s.record) << " (axis " << s.axis.x
                << ' ' << s.axis.y << ' ' << s.axis.z << ") vs " << ontoName << ' ' << describe(ontoPath, o.record)
                << " (axis " << axes[j].x << ' ' << axes[j].y << ' ' << axes[j].z << ")";
            return why.str();
        }
        const char* what = difference(s, o, tol, rapidDepth);
        why << what << " differs: " << fromName << ' ' << describe(fromPath, s.record) << " (tool " << s.tool << ", S"
            << s.rpm << ", F" << s.feed << ", lowest " << s.lowestZ << ") vs " << ontoName << ' '
            << describe(ontoPath, o.record) << " (tool " << o.tool << ", S" << o.rpm << ", F" << o.feed << ", lowest "
            << o.lowestZ << ")";
        return why.str();
    }
    return std::nullopt;
}

}  // namespace

std::vector<MotionSample> flattenMotion(const Toolpath& path, double chordToleranceMm,
                                        const kinematics::KinematicChain* machineMotion)
{
    Flattener flattener(chordToleranceMm, machineMotion);
    for (std::size_t i = 0; i < path.size(); ++i)
        flattener.record(path.record(i), static_cast<int>(i));
    return flattener.take();
}

std::optional<std::string> matchMotion(const Toolpath& a, const Toolpath& b, const MatchTolerance& tolerance)
{
    const double chord = tolerance.pointMm / 4;
    const std::vector<MotionSample> fa = flattenMotion(a, chord, tolerance.machineMotion), fb = flattenMotion(b, chord);
    if (auto why = oneWay(fa, fb, tolerance.pointMm, tolerance, a, b, "NC", "CL", true, false))
        return why;
    return oneWay(fb, fa, tolerance.backPointMm, tolerance, b, a, "CL", "NC", false, true);
}

}  // namespace camwb::nc::test
