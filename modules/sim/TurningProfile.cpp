#include "sim/TurningProfile.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace camwb::sim {

namespace {

std::string_view trimmed(std::string_view s)
{
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos)
        return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// Numbers separated by commas and/or blanks; false when anything else is there.
bool numbers(std::string_view s, std::vector<double>& out)
{
    out.clear();
    std::size_t i = 0;
    while (i < s.size()) {
        if (s[i] == ',' || s[i] == ' ' || s[i] == '\t') {
            ++i;
            continue;
        }
        double v = 0;
        const auto [end, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
        if (ec != std::errc() || !std::isfinite(v))
            return false;
        out.push_back(v);
        i = static_cast<std::size_t>(end - s.data());
        if (i < s.size() && s[i] != ',' && s[i] != ' ' && s[i] != '\t')
            return false;
    }
    return true;
}

// A region from a closed polygon in either orientation.
geom::Region polygon(const std::vector<Vec2>& points)
{
    geom::Region r;
    for (std::size_t i = 0; i < points.size(); ++i)
        r.outer.segments.push_back(geom::Segment::line(points[i], points[(i + 1) % points.size()]));
    return r.normalized();
}

double tanDeg(double deg) { return std::tan(deg * std::numbers::pi / 180); }
double cosDeg(double deg) { return std::cos(deg * std::numbers::pi / 180); }

// The shaft's outline from left to right with `groove` in between, closed along the axis.
TurningRegion shaftWith(const GrooveParameters& g, const std::vector<Vec2>& groove, double margin)
{
    const GrooveGeometry geo = grooveGeometry(g);
    const double zl = geo.c1.x - margin, zr = geo.p.x + margin;
    std::vector<Vec2> pts{turningPoint(0, zl), turningPoint(0, zr), turningPoint(geo.surfaceX(zr), zr)};
    pts.insert(pts.end(), groove.rbegin(), groove.rend());  // the groove from right to left
    pts.push_back(turningPoint(geo.surfaceX(zl), zl));
    return {polygon(pts)};
}

}  // namespace

base::Result<TurningRegion> parseProfileRectangle(std::string_view spec)
{
    std::vector<double> v;
    const std::string quoted = "stock profile '" + std::string(spec) + "'";
    if (!numbers(spec, v) || v.size() != 4)
        return base::makeError(quoted + ": expected x0,z0,x1,z1 (radius, Z in mm)");
    if (v[0] < 0 || v[2] < 0)
        return base::makeError(quoted + ": a radius is negative");
    if (v[0] == v[2] || v[1] == v[3])
        return base::makeError(quoted + ": the rectangle has no area");
    return TurningRegion{polygon(
        {turningPoint(v[0], v[1]), turningPoint(v[0], v[3]), turningPoint(v[2], v[3]), turningPoint(v[2], v[1])})};
}

base::Result<TurningRegion> parseProfilePoints(std::string_view text, const std::string& fileName)
{
    std::vector<Vec2> pts;
    std::vector<double> v;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t eol = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, eol - pos);
        pos = eol + 1;
        ++lineNo;
        line = trimmed(line.substr(0, std::min(line.find(';'), line.find('#'))));
        if (line.empty())
            continue;
        if (!numbers(line, v) || v.size() != 2)
            return base::makeError("expected X,Z (radius, Z in mm)", fileName, lineNo);
        if (v[0] < 0)
            return base::makeError("the radius X is negative", fileName, lineNo);
        pts.push_back(turningPoint(v[0], v[1]));
    }
    if (pts.size() < 2)
        return base::makeError("a stock profile needs at least two X,Z points", fileName);
    if (pts.back().y > 0 && !(pts.back() == pts.front()))
        pts.push_back(turningPoint(0, pts.back().x));
    if (pts.front().y > 0)
        pts.push_back(turningPoint(0, pts.front().x));
    const geom::Region r = polygon(pts);
    if (r.area() < 1e-9)
        return base::makeError("the stock profile encloses no area", fileName);
    return TurningRegion{r};
}

base::Result<TurningRegion> stockProfileFromArgument(const std::string& argument)
{
    std::vector<double> v;
    if (numbers(argument, v) && v.size() == 4 && argument.find(',') != std::string::npos)
        return parseProfileRectangle(argument);
    std::ifstream in(argument, std::ios::binary);
    if (!in)
        return base::makeError("cannot open the stock profile (neither x0,z0,x1,z1 nor a readable file)", argument);
    std::stringstream text;
    text << in.rdbuf();
    return parseProfilePoints(text.str(), argument);
}

GrooveGeometry grooveGeometry(const GrooveParameters& g)
{
    GrooveGeometry geo;
    const double t2 = tanDeg(g.r2), t5 = tanDeg(g.r5), t6 = tanDeg(g.r6);
    geo.tan2 = t2;
    geo.tan5 = t5;
    geo.tan6 = t6;
    geo.d = g.r3 * t5;
    const double bottomX = g.r0 - g.r3, brZ = g.r1 - geo.d, blZ = brZ - g.r4;
    // C1: the left flank z = blZ - t6 (x - bottomX) meets the surface x = R0 + (z - R1) t2.
    const double c1x = (g.r0 + (blZ + t6 * bottomX - g.r1) * t2) / (1 + t2 * t6);
    const double c1z = blZ - t6 * (c1x - bottomX);
    geo.c = blZ - c1z;
    geo.h1 = g.r0 - c1x;
    geo.h2 = g.r3 - geo.h1;
    // The offset corners on the offset bottom (Rov. 31, 33, 54, 55): the flanks moved by R8 along
    // their normals cross the bottom moved up by R7.
    const double xb = bottomX + g.r7;
    geo.bottomOffsetX = xb;
    const double tz = brZ - (g.r8 / cosDeg(g.r5) - g.r7 * t5);
    const double sz = blZ + g.r8 / cosDeg(g.r6) - g.r7 * t6;
    // U, R: the offset flanks through T and S cross the surface.
    const double ux = (g.r0 + (tz - g.r1 - t5 * xb) * t2) / (1 - t2 * t5);
    const double rx = (g.r0 + (sz + t6 * xb - g.r1) * t2) / (1 + t2 * t6);
    geo.p = turningPoint(g.r0, g.r1);
    geo.bottomRight = turningPoint(bottomX, brZ);
    geo.bottomLeft = turningPoint(bottomX, blZ);
    geo.c1 = turningPoint(c1x, c1z);
    geo.s = turningPoint(xb, sz);
    geo.t = turningPoint(xb, tz);
    geo.u = turningPoint(ux, tz + t5 * (ux - xb));
    geo.r = turningPoint(rx, sz - t6 * (rx - xb));
    return geo;
}

TurningRegion grooveStock(const GrooveParameters& g, double marginMm) { return shaftWith(g, {}, marginMm); }

TurningRegion grooveOffsetPart(const GrooveParameters& g, double marginMm)
{
    const GrooveGeometry geo = grooveGeometry(g);
    return shaftWith(g, {geo.r, geo.s, geo.t, geo.u}, marginMm);
}

}  // namespace camwb::sim
