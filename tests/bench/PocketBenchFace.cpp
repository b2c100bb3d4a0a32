#include "PocketBenchFace.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

namespace camwb::bench {

namespace {

using base::Vec2;
using geom::Profile;
using geom::Segment;

constexpr double kDeg = std::numbers::pi / 180.0;

Vec2 rotated(Vec2 v, double radians)
{
    const double c = std::cos(radians), s = std::sin(radians);
    return {v.x * c - v.y * s, v.x * s + v.y * c};
}

// Draws tangent-continuous lines and arcs from a position and heading, like a plotter pen.
class Turtle {
public:
    Turtle(Vec2 at, double headingRad) : m_at(at), m_heading(headingRad) {}

    void line(double length)
    {
        const Vec2 to = m_at + Vec2{std::cos(m_heading), std::sin(m_heading)} * length;
        m_out.segments.push_back(Segment::line(m_at, to));
        m_at = to;
    }
    // Turns left (turnRad > 0, counter-clockwise) or right (turnRad < 0) on a circle of `radius`.
    void arc(double radius, double turnRad)
    {
        const Vec2 direction{std::cos(m_heading), std::sin(m_heading)};
        const bool left = turnRad > 0;
        const Vec2 centre = m_at + (left ? direction.leftNormal() : direction.rightNormal()) * radius;
        const Vec2 to = centre + rotated(m_at - centre, turnRad);
        m_out.segments.push_back(Segment::arc(m_at, to, centre, left));
        m_at = to;
        m_heading += turnRad;
    }
    // Ends the drawing exactly at `at` (removes the rounding drift of many small steps).
    void snapTo(Vec2 at)
    {
        m_out.segments.back().end = at;
        m_at = at;
    }
    Profile take() { return std::move(m_out); }

private:
    Vec2 m_at;
    double m_heading;
    Profile m_out;
};

// One side of the outline: a short straight start, then `periods` waves, each of 8 segments and
// the same length, so that the side ends at heading 0 where a straight side would. The wave goes inwards (left) over a
// left arc R 3.5 (>= the tool radius: the tool reaches it), a slanted line, a right arc R 1, a short plateau, and back
// out the same way; its slope varies from wave to wave between 18 and 24 deg.
void drawWavySide(Turtle& pen, double length, int periods, double phase)
{
    constexpr double kLeftRadius = 3.5, kRightRadius = 1.0, kFlat = 0.2;
    pen.line(kFlat);
    const double period = (length - kFlat) / periods;
    for (int k = 0; k < periods; ++k) {
        const double slope = (21.0 + 3.0 * std::sin(0.7 * k + phase)) * kDeg;
        const double slanted =
            (period - 2 * kFlat - 2 * (kLeftRadius + kRightRadius) * std::sin(slope)) / (2 * std::cos(slope));
        pen.arc(kLeftRadius, slope);
        pen.line(slanted);
        pen.arc(kRightRadius, -slope);
        pen.line(kFlat);
        pen.arc(kRightRadius, -slope);
        pen.line(slanted);
        pen.arc(kLeftRadius, slope);
        pen.line(kFlat);
    }
}

Profile wavyOutline()
{
    constexpr double kWidth = 200, kHeight = 150, kCorner = 10;
    // 36 waves on the long sides, 26 on the short ones: 8 * 124 + 4 starts + 4 corners = 1000 segments.
    struct Side {
        Vec2 start, end;
        double heading;
        int periods;
    };
    const std::array<Side, 4> sides{{
        {{kCorner, 0}, {kWidth - kCorner, 0}, 0, 36},
        {{kWidth, kCorner}, {kWidth, kHeight - kCorner}, 90 * kDeg, 26},
        {{kWidth - kCorner, kHeight}, {kCorner, kHeight}, 180 * kDeg, 36},
        {{0, kHeight - kCorner}, {0, kCorner}, 270 * kDeg, 26},
    }};
    Profile outline;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const Side& side = sides[i];
        Turtle pen(side.start, side.heading);
        drawWavySide(pen, distance(side.start, side.end), side.periods, 1.3 * static_cast<double>(i));
        pen.snapTo(side.end);
        pen.arc(kCorner, 90 * kDeg);
        pen.snapTo(sides[(i + 1) % sides.size()].start);
        const Profile drawn = pen.take();
        outline.segments.insert(outline.segments.end(), drawn.segments.begin(), drawn.segments.end());
    }
    return outline;
}

// Clockwise circle as two half arcs.
Profile circleIsland(Vec2 centre, double diameter)
{
    const Vec2 east = centre + Vec2{diameter / 2, 0}, west = centre - Vec2{diameter / 2, 0};
    Profile circle;
    circle.segments = {Segment::arc(east, west, centre, false), Segment::arc(west, east, centre, false)};
    return circle;
}

// Clockwise rounded rectangle of width x height turned by `angleRad` about its centre.
Profile roundedRectangleIsland(Vec2 centre, double width, double height, double cornerRadius, double angleRad)
{
    const double w = width / 2, h = height / 2, r = cornerRadius;
    const auto at = [&](double x, double y) { return centre + rotated({x, y}, angleRad); };
    Profile ccw;
    ccw.segments = {
        Segment::line(at(-w + r, -h), at(w - r, -h)),
        Segment::arc(at(w - r, -h), at(w, -h + r), at(w - r, -h + r), true),
        Segment::line(at(w, -h + r), at(w, h - r)),
        Segment::arc(at(w, h - r), at(w - r, h), at(w - r, h - r), true),
        Segment::line(at(w - r, h), at(-w + r, h)),
        Segment::arc(at(-w + r, h), at(-w, h - r), at(-w + r, h - r), true),
        Segment::line(at(-w, h - r), at(-w, -h + r)),
        Segment::arc(at(-w, -h + r), at(-w + r, -h), at(-w + r, -h + r), true),
    };
    return ccw.reversed();
}

void appendNumber(std::string& out, double value)
{
    std::array<char, 32> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), end);
}

void appendPoint(std::string& out, const char* key, Vec2 p)
{
    out += ", \"";
    out += key;
    out += "\": [";
    appendNumber(out, p.x);
    out += ", ";
    appendNumber(out, p.y);
    out += ']';
}

void appendLoop(std::string& out, const char* role, const Profile& loop)
{
    out += "    {\"role\": \"";
    out += role;
    out += "\", \"segments\": [\n";
    for (std::size_t i = 0; i < loop.segments.size(); ++i) {
        const Segment& s = loop.segments[i];
        out += s.isArc() ? "      {\"kind\": \"arc\"" : "      {\"kind\": \"line\"";
        appendPoint(out, "start", s.start);
        appendPoint(out, "end", s.end);
        if (s.isArc()) {
            appendPoint(out, "centre", s.center);
            out += s.ccw ? ", \"ccw\": true" : ", \"ccw\": false";
        }
        out += i + 1 < loop.segments.size() ? "},\n" : "}\n";
    }
    out += "    ]}";
}

void appendField(std::string& out, const char* key, double value)
{
    out += "  \"";
    out += key;
    out += "\": ";
    appendNumber(out, value);
    out += ",\n";
}

}  // namespace

geom::Region pocketBenchFace()
{
    geom::Region face;
    face.outer = wavyOutline();
    int circles = 0, rectangles = 0;
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 5; ++column) {
            const int k = row * 5 + column;
            // A grid 37.5 x 35.3 mm apart, each island nudged by up to 2 mm.
            const Vec2 centre{25 + 37.5 * column + 2 * std::sin(1.7 * k), 22 + row * 106.0 / 3 + 2 * std::cos(2.3 * k)};
            if ((row + column) % 2 == 0) {
                face.holes.push_back(circleIsland(centre, 6 + 2 * (circles++ % 5)));
            } else {
                const int r = rectangles++;
                face.holes.push_back(roundedRectangleIsland(centre, 10 + 2 * (r % 4), 8 + 2 * (r % 3),
                                                            1.5 + 0.5 * (r % 3), 15.0 * r * kDeg));
            }
        }
    }
    return face;
}

ops::ToolController pocketBenchTool()
{
    ops::ToolController tc;
    tc.tool.number = 1;
    tc.tool.name = "D6 flat end mill";
    tc.tool.diameterMm = 6;
    tc.tool.fluteLengthMm = 25;
    tc.tool.lengthMm = 60;
    tc.spindleRpm = 8000;
    tc.cuttingFeedMmPerMin = 1200;
    tc.plungeFeedMmPerMin = 300;
    tc.rampFeedMmPerMin = 600;
    return tc;
}

ops::PocketParams pocketBenchParams(ops::PocketPattern pattern, int levels)
{
    ops::PocketParams params;
    params.name = pattern == ops::PocketPattern::Offset ? "Bench pocket offset" : "Bench pocket zigzag";
    params.pattern = pattern;
    params.stepoverMm = 1;
    params.heights = {10, 3, 0, -1.0 * levels};
    params.stepDownMm = 1;
    params.entry = ops::EntryKind::Helix;
    params.toleranceMm = 0.01;
    return params;
}

std::string pocketBenchJson(const geom::Region& face, const ops::PocketParams& params, const ops::ToolController& tc)
{
    double area = face.outer.signedArea();
    for (const Profile& hole : face.holes)
        area += hole.signedArea();
    std::string out = "{\n";
    appendField(out, "toolDiameterMm", tc.tool.diameterMm);
    appendField(out, "stepoverMm", params.stepover(tc.tool.diameterMm));
    appendField(out, "clearanceZ", params.heights.clearanceZ);
    appendField(out, "safeZ", params.heights.safeZ);
    appendField(out, "startZ", params.heights.startZ);
    appendField(out, "finalZ", params.heights.finalZ);
    appendField(out, "stepDownMm", params.stepDownMm);
    appendField(out, "toleranceMm", params.toleranceMm);
    appendField(out, "cuttingFeedMmPerMin", tc.cuttingFeedMmPerMin);
    appendField(out, "plungeFeedMmPerMin", tc.plungeFeedMmPerMin);
    appendField(out, "areaMm2", area);
    out += "  \"loops\": [\n";
    appendLoop(out, "outer", face.outer);
    for (const Profile& hole : face.holes) {
        out += ",\n";
        appendLoop(out, "island", hole);
    }
    out += "\n  ]\n}\n";
    return out;
}

}  // namespace camwb::bench
