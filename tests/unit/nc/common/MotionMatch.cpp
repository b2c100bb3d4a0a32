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

class Flattener {
public:
    explicit Flattener(double chord) : m_chord(chord) {}

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
    void segment(const Vec3& to, bool rapid, double feed)
    {
        if (to == m_at)
            return;
        if (rapid) {
            if (!m_inTransit) {
                m_inTransit = true;
                m_transitStart = m_at;
                m_transitLowestZ = m_at.z;
            }
            m_transitLowestZ = std::min(m_transitLowestZ, to.z);
            m_at = to;
            return;
        }
        flushTransit();
        emit(m_at, to, false, feed, to.z);
        m_at = to;
    }

public:
    void flushTransit()
    {
        if (!m_inTransit)
            return;
        m_inTransit = false;
        if (!(m_transitStart == m_at))
            emit(m_transitStart, m_at, true, 0, m_transitLowestZ);
    }

private:
    void emit(const Vec3& from, const Vec3& to, bool rapid, double feed, double lowestZ)
    {
        MotionSample s{};
        s.rapid = rapid;
        s.feed = feed;
        s.perMinute = m_perMinute;
        s.rpm = m_rpm;
        s.tool = m_tool;
        s.record = m_index;
        s.lowestZ = lowestZ;
        s.point = (from + to) * 0.5;
        s.midpoint = true;
        m_samples.push_back(s);
        s.point = to;
        s.midpoint = false;
        m_samples.push_back(s);
    }
    // A move that gives only some axes keeps the others (both sides start at the origin here).
    Vec3 endOf(const Vec3& to, AxisMask axes) const
    {
        KnownPosition at(m_at);
        at.moveTo(to, axes);
        return at.value();
    }
    void visit(const Rapid& r) { segment(endOf(r.to, r.axes), true, 0); }
    void visit(const Linear& r) { segment(endOf(r.to, r.axes), false, r.feedMmPerMin); }
    void visit(const Arc& r)
    {
        for (const Vec3& p : toolpath::linearizeArc(m_at, r, m_chord))
            segment(p, false, r.feedMmPerMin);
    }
    void visit(const Cycle& c)
    {
        for (const Vec3& hole : c.holes)
            for (const Record& moved : expandCycleHole(c, hole, m_at, {m_rpm, true}))
                std::visit([this](const auto& v) { cycleMove(v); }, moved);
    }
    void cycleMove(const Rapid& r) { segment(endOf(r.to, r.axes), true, 0); }
    void cycleMove(const Linear& r) { segment(endOf(r.to, r.axes), false, r.feedMmPerMin); }
    template <class T> void cycleMove(const T&) {}  // tapping's spindle reversals: the rpm stays
    // Along the spindle axis only: enough for the 3-axis posts (tilted axes are the five-axis posts' business).
    void visit(const ToolAxisMove& r) { segment(r.tip, r.feedMmPerMin <= 0, r.feedMmPerMin); }
    void visit(const ToolChange& r) { m_tool = r.tool.number; }
    void visit(const Spindle& r) { m_rpm = r.rpm; }
    void visit(const FeedModeChange& r) { m_perMinute = r.mode == FeedMode::PerMinute; }
    template <class T> void visit(const T&) {}

    double m_chord;
    Vec3 m_at;
    double m_rpm = 0;
    int m_tool = 0;
    bool m_perMinute = true;
    int m_index = 0;
    bool m_inTransit = false;
    Vec3 m_transitStart;
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
    if (!s.rapid && s.perMinute && o.perMinute && !near(s.feed, o.feed, tol.feedRelative))
        return "feed";
    return nullptr;
}

// Every sample of `from` must lie, in order, on the polyline of `onto` (first fit going forward,
// so a path that passes the same place twice is matched in its own order).
std::optional<std::string> oneWay(const std::vector<MotionSample>& from, const std::vector<MotionSample>& onto,
                                  double toleranceMm, const MatchTolerance& tol, const Toolpath& fromPath,
                                  const Toolpath& ontoPath, const char* fromName, const char* ontoName, bool rapidDepth)
{
    // onto's vertices: the origin, then its segment ends (midpoints only carry attributes).
    std::vector<Vec3> vertices{Vec3{}};
    std::vector<const MotionSample*> segmentOf{nullptr};
    for (const MotionSample& s : onto)
        if (!s.midpoint) {
            vertices.push_back(s.point);
            segmentOf.push_back(&s - 1);  // the midpoint before each end describes the segment
        }
    std::size_t segment = 1;
    auto within = [&](const MotionSample& s, std::size_t j) {
        return distanceToSegment(s.point, vertices[j - 1], vertices[j]) <= toleranceMm;
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
        if (!s.midpoint) {
            segment = j;
            continue;
        }
        // Near a junction a point is on two segments: take the first one that also agrees in kind,
        // tool, spindle and feed, and report the nearest one's difference when none does.
        const char* what = nullptr;
        std::size_t agreeing = j;
        for (; agreeing < vertices.size(); ++agreeing) {
            if (!within(s, agreeing))
                continue;
            what = difference(s, *segmentOf[agreeing], tol, rapidDepth);
            if (!what)
                break;
        }
        if (agreeing < vertices.size()) {
            segment = agreeing;
            continue;
        }
        what = difference(s, *segmentOf[j], tol, rapidDepth);
        const MotionSample& o = *segmentOf[j];
        why << what << " differs: " << fromName << ' ' << describe(fromPath, s.record) << " (tool " << s.tool << ", S"
            << s.rpm << ", F" << s.feed << ", lowest " << s.lowestZ << ") vs " << ontoName << ' '
            << describe(ontoPath, o.record) << " (tool " << o.tool << ", S" << o.rpm << ", F" << o.feed << ", lowest "
            << o.lowestZ << ")";
        return why.str();
    }
    return std::nullopt;
}

}  // namespace

std::vector<MotionSample> flattenMotion(const Toolpath& path, double chordToleranceMm)
{
    Flattener flattener(chordToleranceMm);
    for (std::size_t i = 0; i < path.size(); ++i)
        flattener.record(path.record(i), static_cast<int>(i));
    return flattener.take();
}

std::optional<std::string> matchMotion(const Toolpath& a, const Toolpath& b, const MatchTolerance& tolerance)
{
    const double chord = tolerance.pointMm / 4;
    const std::vector<MotionSample> fa = flattenMotion(a, chord), fb = flattenMotion(b, chord);
    if (auto why = oneWay(fa, fb, tolerance.pointMm, tolerance, a, b, "NC", "CL", true))
        return why;
    return oneWay(fb, fa, tolerance.backPointMm, tolerance, b, a, "CL", "NC", false);
}

}  // namespace camwb::nc::test
