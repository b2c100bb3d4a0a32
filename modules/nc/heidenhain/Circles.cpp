// Circles and polar moves of Klartext in the three main planes: CC (centre and pole; its two axes
// name the plane), C about CC, CR (radius), CT (tangential), CP (polar circle and helix) and LP
// (polar line). The iTNC 530 makes circles outside the working plane when the blocks name their
// axes, e.g. "C Z... X... DR+" with tool axis Z (iTNC 530 User's Manual, Conversational
// Programming, "Circular path C around circle center CC"). DR+ is the mathematically positive
// direction ("Direction of rotation DR", same manual) and polar angles count from the plane's
// reference axis: X in XY, Z in ZX, Y in YZ ("Angle reference axis", TNC manuals). So DR+ turns
// from u towards v (nc/detail/PlaneAxes.h), counter-clockwise by the right-hand rule about +Z, +Y
// or +X, which is toolpath::Arc's convention. A helix is "a circular movement in a main plane and
// a linear movement perpendicular to this plane" programmed with CP only (same manual, "Helical
// interpolation"), so C, CR and CT outside XY may not move along the normal (in XY they keep
// making a helix, as they always have here).
#include "nc/heidenhain/Machine.h"

#include "nc/detail/PlaneAxes.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;
using detail::component;
using detail::inPlane;
using detail::planeAxes;
using detail::withInPlane;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kEps = 1e-9;

char letter(int axis) { return "XYZ"[axis]; }
std::string planeName(const detail::PlaneAxes& a) { return {letter(a.u), letter(a.v)}; }

// Whether the block writes the linear axis (absolute or incremental).
bool writes(const BlockWords& w, int axis)
{
    return w.axes[static_cast<std::size_t>(axis)].has_value() || w.axes[static_cast<std::size_t>(9 + axis)].has_value();
}

// The plane of exactly two linear axes written (17 XY, 18 ZX, 19 YZ), else 0.
int namedPlane(const BlockWords& w)
{
    const bool x = writes(w, 0), y = writes(w, 1), z = writes(w, 2);
    if (x + y + z != 2)
        return 0;
    return !z ? 17 : !y ? 18 : 19;
}

}  // namespace

// CR and CT have no centre to name their plane: two axes written name it, else the last CC's.
int circlePlane(BlockKind kind, const BlockWords& w, const Pole& pole)
{
    if (kind == BlockKind::CircleRadius || kind == BlockKind::CircleTangent) {
        if (const int named = namedPlane(w))
            return named;
    }
    return pole.plane;
}

// The pole a CC block sets after `previous`, from `from`. Two axes name the plane; one axis keeps
// the previous plane when it lies in it (else XY for X or Y), the other coordinate from `from`;
// none: `from` itself.
std::optional<Pole> Machine::centreOf(const Block& b, const BlockWords& w, const Vec3& from, const Pole& previous,
                                      bool quiet)
{
    auto fail = [&](const std::string& message) -> std::optional<Pole> {
        if (!quiet)
            report(Severity::Error, b.line, b.column, message);
        return std::nullopt;
    };
    if (w.pr || w.pa || w.ipr || w.ipa)
        return fail("a polar CC is not supported");
    int plane = previous.plane;
    int count = 0, axis = -1;
    for (int i = 0; i < 3; ++i) {
        if (writes(w, i)) {
            ++count;
            axis = i;
        }
    }
    if (count == 3)
        return fail("CC with X, Y and Z: a circle centre has the two axes of its plane (X Y, X Z or Y Z)");
    if (count == 2) {
        plane = namedPlane(w);
    } else if (count == 1) {
        const detail::PlaneAxes p = planeAxes(plane);
        if (axis != p.u && axis != p.v) {
            if (axis == 2)
                return fail("CC Z alone does not say the circle's plane: write CC X.. Z.. or CC Y.. Z..");
            plane = 17;
        }
    }
    AxisMask incremental = kNoAxes, given = kNoAxes;
    for (int i = 0; i < 3; ++i) {
        if (w.axes[static_cast<std::size_t>(i)])
            given.bits |= axisBit(i).bits;
        if (w.axes[static_cast<std::size_t>(9 + i)])
            incremental.bits |= axisBit(i).bits;
    }
    if (!quiet && !needKnown(b, incremental, planeMask(plane), given, "the circle centre CC"))
        return std::nullopt;
    const auto t = target(b, w, from, quiet);
    if (!t)
        return std::nullopt;
    return Pole{inPlane(*t, planeAxes(plane)), plane, true};
}

void Machine::circleCenter(const Block& b)
{
    BlockWords w;
    if (!gather(b, w, false))
        return;
    if (const auto pole = centreOf(b, w, m_pos, m_pole, false))
        m_pole = *pole;
}

bool Machine::needPole(const Block& b, const Pole& pole, bool quiet)
{
    if (pole.set)
        return true;
    if (!quiet)
        report(Severity::Error, b.line, b.column, "no circle centre CC programmed before this block");
    return false;
}

// DR+ / DR- of the block, else the last circle's with a warning; false (an error) when neither.
bool Machine::direction(const Block& b, const BlockWords& w, bool quiet, bool& clockwise)
{
    if (w.direction != 0) {
        clockwise = w.direction < 0;
        return true;
    }
    if (m_lastDirection != 0) {
        clockwise = m_lastDirection < 0;
        if (!quiet)
            report(Severity::Warning, b.line, b.column, "no DR+ or DR-: the previous direction is used");
        return true;
    }
    if (!quiet)
        report(Severity::Error, b.line, b.column, "the direction of rotation DR+ or DR- is missing");
    return false;
}

// C, CR, CT, CP and LP from `e` (start and end of the words set) in the plane of the block.
std::optional<Element> Machine::planCircle(const Block& b, const BlockWords& w, Element e, const Pole& pole,
                                           const Tangents& tangents, bool quiet)
{
    auto fail = [&](const std::string& message) -> std::optional<Element> {
        if (!quiet)
            report(Severity::Error, b.line, b.column, message);
        return std::nullopt;
    };
    e.plane = circlePlane(b.kind, w, pole);
    const detail::PlaneAxes a = planeAxes(e.plane);
    const Vec2 from = inPlane(e.start, a);
    const Vec2 to = inPlane(e.end, a);
    const Vec2 cc = pole.at;
    const bool flat = std::abs(component(e.end, a.w) - component(e.start, a.w)) <= kEps;
    if (e.plane != 17 && !flat && b.kind != BlockKind::LinePolar && b.kind != BlockKind::CirclePolar)
        return fail(std::string("a circle in the ") + planeName(a) + " plane cannot move along " + letter(a.w) +
                    ": a helix is programmed with CP");
    auto setEnd = [&](Vec2 q) { e.end = withInPlane(e.end, a, q); };

    switch (b.kind) {
    case BlockKind::LinePolar: {
        if (!needPole(b, pole, quiet))
            return std::nullopt;
        const Vec2 rel = from - cc;
        double r = rel.length();
        double angle = std::atan2(rel.y, rel.x) / kDeg;
        if (w.pr)
            r = *w.pr * m_scale;
        if (w.ipr)
            r += *w.ipr * m_scale;
        if (w.pa)
            angle = *w.pa;
        if (w.ipa)
            angle += *w.ipa;
        if (r < 0)
            return fail("negative polar radius PR");
        setEnd({cc.x + r * std::cos(angle * kDeg), cc.y + r * std::sin(angle * kDeg)});
        e.type = Element::Type::Line;
        return e;
    }
    case BlockKind::Circle: {
        if (!needPole(b, pole, quiet) || !direction(b, w, quiet, e.clockwise))
            return std::nullopt;
        e.type = Element::Type::Arc;
        e.center = cc;
        const double rs = distance(from, cc);
        const double re = distance(to, cc);
        if (rs < kEps)
            return fail("circle start lies on its centre CC");
        if (!(m_programmed.has(a.u) && m_programmed.has(a.v))) {
            if (!quiet)
                report(Severity::Warning, b.line, b.column,
                       std::string("the circle's start point is unknown (no ") + letter(a.u) + " and " + letter(a.v) +
                           " programmed before it): radius not checked");
        } else if (std::abs(rs - re) > m_options.arcRadiusToleranceMm && !quiet)
            report(Severity::Error, b.line, b.column,
                   "arc start radius " + mm(rs) + " and end radius " + mm(re) + " about CC differ by " +
                       mm(std::abs(rs - re)) + " mm (tolerance " + mm(m_options.arcRadiusToleranceMm) + ")");
        if (distance(from, to) < kEps)
            setEnd(from);  // full circle
        return e;
    }
    case BlockKind::CircleRadius: {
        if (!w.radius)
            return fail("CR needs the radius R");
        if (!direction(b, w, quiet, e.clockwise))
            return std::nullopt;
        const double radius = *w.radius * m_scale;
        const Vec2 chord = to - from;
        const double d = chord.length();
        if (std::abs(radius) < kEps)
            return fail("CR radius is zero");
        if (d < kEps)
            return fail("CR end point equals its start point (a full circle needs C)");
        const double half = d / 2;
        if (half > std::abs(radius) + m_options.arcRadiusToleranceMm)
            return fail("CR radius " + mm(std::abs(radius)) + " is smaller than half the chord " + mm(half));
        const double h = std::sqrt(std::max(0.0, radius * radius - half * half));
        const Vec2 mid = (from + to) * 0.5;
        const Vec2 left = (chord * (1.0 / d)).leftNormal();
        // Counter-clockwise arcs of up to 180 degrees (R+) turn about a centre on the chord's left.
        const bool centreLeft = (!e.clockwise) == (radius > 0);
        e.center = mid + left * (centreLeft ? h : -h);
        e.type = Element::Type::Arc;
        return e;
    }
    case BlockKind::CircleTangent: {
        const auto& tangent = tangents[static_cast<std::size_t>(e.plane - 17)];
        if (!tangent)
            return fail("CT needs a preceding contour element to be tangent to" +
                        (e.plane == 17 ? std::string() : " in the " + planeName(a) + " plane"));
        const Vec2 v = to - from;
        if (v.length() < kEps)
            return fail("CT end point equals its start point");
        const double cross = tangent->cross(v);
        if (std::abs(cross) < 1e-12 * v.length()) {
            e.type = Element::Type::Line;  // the end lies on the tangent: a straight line
            return e;
        }
        const double r = v.dot(v) / (2 * cross);  // signed: > 0 centre on the left (counter-clockwise)
        e.center = from + tangent->leftNormal() * r;
        e.clockwise = r < 0;
        e.type = Element::Type::Arc;
        return e;
    }
    case BlockKind::CirclePolar:
        return planPolarCircle(b, w, e, pole, quiet);
    default:
        return e;
    }
}

// CP: a circle about the pole by PA (to the angle) or IPA (through it, up to 15 turns) in the
// pole's plane, a helix when the axis along its normal moves too.
std::optional<Element> Machine::planPolarCircle(const Block& b, const BlockWords& w, Element e, const Pole& pole,
                                                bool quiet)
{
    auto fail = [&](const std::string& message) -> std::optional<Element> {
        if (!quiet)
            report(Severity::Error, b.line, b.column, message);
        return std::nullopt;
    };
    if (!needPole(b, pole, quiet))
        return std::nullopt;
    const detail::PlaneAxes a = planeAxes(pole.plane);
    if (writes(w, a.u) || writes(w, a.v))
        return fail(std::string("CP in the ") + planeName(a) + " plane takes the angle PA or IPA and " + letter(a.w) +
                    " or I" + letter(a.w) + ", not " + letter(a.u) + " or " + letter(a.v));
    const Vec2 rel = inPlane(e.start, a) - pole.at;
    const double r = rel.length();
    if (r < kEps)
        return fail("CP start lies on the pole CC");
    const double a0 = std::atan2(rel.y, rel.x) / kDeg;
    double sweep = 0;
    if (w.ipa) {
        sweep = *w.ipa;
        if (std::abs(sweep) > 5400)
            return fail("IPA out of the control's range (+-5400 degrees)");
        if (std::abs(sweep) < kEps)
            return fail("CP with IPA 0");
        if (w.direction != 0 && (w.direction > 0) != (sweep > 0) && !quiet)
            report(Severity::Warning, b.line, b.column,
                   "DR and IPA have different signs: the sign of IPA decides the direction");
        e.clockwise = sweep < 0;
    } else if (w.pa) {
        if (!direction(b, w, quiet, e.clockwise))
            return std::nullopt;
        double s = std::fmod(*w.pa - a0, 360.0);
        if (e.clockwise)
            s = -std::fmod(a0 - *w.pa, 360.0);
        if (!e.clockwise && s <= kEps)
            s += 360;
        if (e.clockwise && s >= -kEps)
            s -= 360;
        sweep = s;
    } else {
        return fail("CP needs PA or IPA");
    }
    const double total = std::abs(sweep);
    e.turns = std::max(0, static_cast<int>(std::ceil(total / 360.0 - 1e-9)) - 1);
    const double a1 = (a0 + sweep) * kDeg;
    const double laps = total / 360.0;
    // Whole laps end exactly where they began.
    const Vec2 end = std::abs(laps - std::round(laps)) < 1e-12 ? inPlane(e.start, a)
                                                               : pole.at + Vec2{r * std::cos(a1), r * std::sin(a1)};
    e.end = withInPlane(e.end, a, end);
    e.center = pole.at;
    e.plane = pole.plane;
    e.type = Element::Type::Arc;
    return e;
}

}  // namespace camwb::nc::heidenhain
