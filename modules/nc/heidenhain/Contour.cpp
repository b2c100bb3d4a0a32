// Contour elements of Klartext: L, LP (polar about CC), C (about CC), CR (radius), CT (tangential),
// CP (polar circle and helix), APPR/DEP (straight approximations), and the RND/CHF corners between
// two lines, which shorten the element before them (planned here with a look-ahead).
#include "nc/heidenhain/Machine.h"

#include "base/NumberFormat.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kEps = 1e-9;

double& axis(Vec3& v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }

bool isContour(BlockKind k)
{
    return k == BlockKind::Line || k == BlockKind::LinePolar || k == BlockKind::Circle ||
           k == BlockKind::CircleRadius || k == BlockKind::CircleTangent || k == BlockKind::CirclePolar;
}

bool isFiller(BlockKind k) { return k == BlockKind::Empty || k == BlockKind::Comment; }

// Four decimals, independent of the C locale (the GUI sets the user's).
std::string mm(double v) { return base::formatFixed(v, 4); }

}  // namespace

std::optional<Vec3> Machine::target(const Block& b, const BlockWords& w, const Vec3& from, bool quiet)
{
    Vec3 t = from;
    for (int i = 0; i < 3; ++i) {
        const auto& absolute = w.axes[static_cast<std::size_t>(i)];
        const auto& incremental = w.axes[static_cast<std::size_t>(9 + i)];
        if (absolute && incremental) {
            if (!quiet)
                report(Severity::Error, b.line, b.column, "absolute and incremental value for the same axis");
            return std::nullopt;
        }
        if (absolute)
            axis(t, i) = axis(m_shift, i) + *absolute * m_scale;
        if (incremental)
            axis(t, i) += *incremental * m_scale;
    }
    return t;
}

std::optional<Element> Machine::plan(const Block& b, const BlockWords& w, const Vec3& from, const Vec2& cc, bool ccSet,
                                     std::optional<Vec2> tangent, bool quiet)
{
    auto fail = [&](const std::string& message) -> std::optional<Element> {
        if (!quiet)
            report(Severity::Error, b.line, b.column, message);
        return std::nullopt;
    };
    auto needPole = [&]() {
        if (ccSet)
            return true;
        if (!quiet)
            report(Severity::Error, b.line, b.column, "no circle centre CC programmed before this block");
        return false;
    };
    auto direction = [&](bool& clockwise) {
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
    };

    Element e;
    e.start = from;
    const auto to = target(b, w, from, quiet);
    if (!to)
        return std::nullopt;
    e.end = *to;

    switch (b.kind) {
    case BlockKind::Line:
    case BlockKind::Approach:
        if (!w.hasXyz()) {
            if (b.kind == BlockKind::Approach && b.flag && w.len && tangent) {
                // DEP LT LEN: straight on along the contour's tangent.
                const Vec2 d = *tangent * (*w.len * m_scale);
                e.end = {from.x + d.x, from.y + d.y, from.z};
                e.type = Element::Type::Line;
            }
            return e;
        }
        e.type = Element::Type::Line;
        return e;
    case BlockKind::LinePolar: {
        if (!needPole())
            return std::nullopt;
        const Vec2 rel = from.xy() - cc;
        double r = rel.length();
        double a = std::atan2(rel.y, rel.x) / kDeg;
        if (w.pr)
            r = *w.pr * m_scale;
        if (w.ipr)
            r += *w.ipr * m_scale;
        if (w.pa)
            a = *w.pa;
        if (w.ipa)
            a += *w.ipa;
        if (r < 0)
            return fail("negative polar radius PR");
        e.end.x = cc.x + r * std::cos(a * kDeg);
        e.end.y = cc.y + r * std::sin(a * kDeg);
        e.type = Element::Type::Line;
        return e;
    }
    case BlockKind::Circle: {
        if (!needPole() || !direction(e.clockwise))
            return std::nullopt;
        e.type = Element::Type::Arc;
        e.center = cc;
        const double rs = distance(from.xy(), cc);
        const double re = distance(e.end.xy(), cc);
        if (rs < kEps)
            return fail("circle start lies on its centre CC");
        if (!(m_knownX && m_knownY)) {
            if (!quiet)
                report(Severity::Warning, b.line, b.column,
                       "the circle's start point is unknown (no X and Y programmed before it): radius not checked");
        } else if (std::abs(rs - re) > m_options.arcRadiusToleranceMm && !quiet)
            report(Severity::Error, b.line, b.column,
                   "arc start radius " + mm(rs) + " and end radius " + mm(re) + " about CC differ by " +
                       mm(std::abs(rs - re)) + " mm (tolerance " + mm(m_options.arcRadiusToleranceMm) + ")");
        if (distance(from.xy(), e.end.xy()) < kEps)
            e.end = {from.x, from.y, e.end.z};  // full circle
        return e;
    }
    case BlockKind::CircleRadius: {
        if (!w.radius)
            return fail("CR needs the radius R");
        if (!direction(e.clockwise))
            return std::nullopt;
        const double radius = *w.radius * m_scale;
        const Vec2 chord = e.end.xy() - from.xy();
        const double d = chord.length();
        if (std::abs(radius) < kEps)
            return fail("CR radius is zero");
        if (d < kEps)
            return fail("CR end point equals its start point (a full circle needs C)");
        const double half = d / 2;
        if (half > std::abs(radius) + m_options.arcRadiusToleranceMm)
            return fail("CR radius " + mm(std::abs(radius)) + " is smaller than half the chord " + mm(half));
        const double h = std::sqrt(std::max(0.0, radius * radius - half * half));
        const Vec2 mid = (from.xy() + e.end.xy()) * 0.5;
        const Vec2 left = (chord * (1.0 / d)).leftNormal();
        // Counter-clockwise arcs of up to 180 degrees (R+) turn about a centre on the chord's left.
        const bool centreLeft = (!e.clockwise) == (radius > 0);
        e.center = mid + left * (centreLeft ? h : -h);
        e.type = Element::Type::Arc;
        return e;
    }
    case BlockKind::CircleTangent: {
        if (!tangent) {
            if (!quiet)
                report(Severity::Error, b.line, b.column, "CT needs a preceding contour element to be tangent to");
            return std::nullopt;
        }
        const Vec2 v = e.end.xy() - from.xy();
        if (v.length() < kEps)
            return fail("CT end point equals its start point");
        const double cross = tangent->cross(v);
        if (std::abs(cross) < 1e-12 * v.length()) {
            e.type = Element::Type::Line;  // the end lies on the tangent: a straight line
            return e;
        }
        const double r = v.dot(v) / (2 * cross);  // signed: > 0 centre on the left (counter-clockwise)
        e.center = from.xy() + tangent->leftNormal() * r;
        e.clockwise = r < 0;
        e.type = Element::Type::Arc;
        return e;
    }
    case BlockKind::CirclePolar: {
        if (!needPole())
            return std::nullopt;
        const Vec2 rel = from.xy() - cc;
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
            if (!direction(e.clockwise))
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
        if (std::abs(laps - std::round(laps)) < 1e-12) {
            e.end.x = from.x;  // whole laps end exactly where they began
            e.end.y = from.y;
        } else {
            e.end.x = cc.x + r * std::cos(a1);
            e.end.y = cc.y + r * std::sin(a1);
        }
        e.center = cc;
        e.type = Element::Type::Arc;
        return e;
    }
    default:
        return e;
    }
}

bool Machine::needKnown(const Block& b, AxisMask before, AxisMask after, AxisMask given, const char* need)
{
    const int axis = m_known.missing(before, after, given);
    if (axis < 0)
        return true;
    report(Severity::Error, b.line, b.column, unknownAxisMessage(axis, need));
    return false;
}

// An incremental word on an unknown axis, a circle, a polar move or compensation from an unknown
// start are errors; `given`: the axes the block puts at a known place.
bool Machine::checkKnown(const Block& b, const BlockWords& w, AxisMask& given)
{
    AxisMask incremental = kNoAxes;
    given = kNoAxes;
    for (int i = 0; i < 3; ++i) {
        if (w.axes[static_cast<std::size_t>(i)])
            given.bits |= axisBit(i).bits;
        if (w.axes[static_cast<std::size_t>(9 + i)])
            incremental.bits |= axisBit(i).bits;
    }
    if (!needKnown(b, incremental, kNoAxes, kNoAxes, "an incremental move"))
        return false;
    switch (b.kind) {
    case BlockKind::LinePolar:
        if (w.pr && w.pa && !w.ipr && !w.ipa)
            given = given | kXyAxes;  // about the pole, which is known (circleCenter)
        else if (!needKnown(b, kXyAxes, kNoAxes, kNoAxes, "the polar move from the current position"))
            return false;
        break;
    case BlockKind::Circle:
    case BlockKind::CircleRadius:
    case BlockKind::CircleTangent:
    case BlockKind::CirclePolar:
        if (!needKnown(b, kXyAxes, AxisMask{}, given, "the circle"))
            return false;
        break;
    case BlockKind::Approach:
        if (!w.hasXyz() && b.flag && w.len && !needKnown(b, kXyAxes, kNoAxes, kNoAxes, "DEP LT"))
            return false;
        break;
    default:
        break;
    }
    return m_comp == CutterCompSide::Off || !w.hasXyz() ||
           needKnown(b, kXyAxes, AxisMask{}, given, "cutter compensation");
}

void Machine::circleCenter(const Block& b)
{
    BlockWords w;
    if (!gather(b, w, false))
        return;
    AxisMask incremental = kNoAxes, given = kNoAxes;
    for (int i = 0; i < 2; ++i) {
        if (w.axes[static_cast<std::size_t>(i)])
            given.bits |= axisBit(i).bits;
        if (w.axes[static_cast<std::size_t>(9 + i)])
            incremental.bits |= axisBit(i).bits;
    }
    if (!needKnown(b, incremental, kXyAxes, given, "the circle centre CC"))
        return;
    if (!w.hasXyz()) {
        m_cc = m_pos.xy();  // CC alone: the last programmed position
        m_ccSet = true;
        return;
    }
    if (w.pr || w.pa || w.ipr || w.ipa) {
        report(Severity::Error, b.line, b.column, "a polar CC is not supported");
        return;
    }
    if (const auto t = target(b, w, m_pos, false)) {
        m_cc = t->xy();
        m_ccSet = true;
    }
}

// A contour or M-only block in the control's order: spindle and coolant, compensation, feed, the
// element (with a planned corner after it), then stops, program end and cycle calls.
void Machine::motionBlock(const Block& b)
{
    BlockWords w;
    if (!gather(b, w, false))
        return;
    if (w.rotary)
        warnOnce(kWarnRotary, b,
                 "rotary and parallel axes (A, B, C, U, V, W) are traced once the five-axis machine model exists; "
                 "their values are ignored");
    if (b.kind == BlockKind::Approach)
        warnOnce(kWarnApproach, b, "APPR/DEP are traced as straight moves to their end points");
    if (w.feed == BlockWords::FeedWord::PerTooth)
        warnOnce(kWarnFeedTooth, b, "FZ (feed per tooth) needs the tooth count: the modal feed is kept");
    if (w.feed == BlockWords::FeedWord::Auto && m_autoFeed <= 0)
        warnOnce(kWarnAutoFeed, b, "F AUTO with no feed in the TOOL CALL: feed 0");

    applySpindleAndCoolant(b, w);
    applyCompensation(w);
    applyFeedRate(w);
    const bool moved = applyMotion(b, w);
    if (b.kind == BlockKind::Stop)
        m_sink.programStop(ProgramStop{false});
    applyStop(b, w, moved);
}

bool Machine::applyMotion(const Block& b, const BlockWords& w)
{
    if (b.kind == BlockKind::MOnly || b.kind == BlockKind::Stop)
        return false;
    const bool rapid = w.feed == BlockWords::FeedWord::Max;
    bool moved = false;
    AxisMask given;
    if (!checkKnown(b, w, given)) {
        m_corner.nextPending = false;
        return false;
    }
    std::optional<Element> e;
    if (m_corner.nextPending && m_corner.program == m_prog && m_corner.nextBlock == m_pc) {
        e = m_corner.next;  // planned from the corner before it (RND/CHF)
        e->start = m_pos;
    } else {
        e = plan(b, w, m_pos, m_cc, m_ccSet, m_tangent, false);
    }
    m_corner.nextPending = false;
    if (e && e->type != Element::Type::None) {
        if (e->type == Element::Type::Arc)
            m_lastDirection = e->clockwise ? -1 : 1;
        m_known.give(given);
        if (m_known.complete())  // a corner is planned from known points only
            planCorner(*e, m_pc + 1);
        send(*e, rapid, m_feed);
        moved = true;
    }
    // Absolute X/Y (or a polar end about a known pole) make the position known.
    m_knownX = m_knownX || w.axes[0].has_value();
    m_knownY = m_knownY || w.axes[1].has_value();
    if (b.kind == BlockKind::LinePolar && w.pr && w.pa && m_ccSet)
        m_knownX = m_knownY = true;
    return moved;
}

void Machine::send(const Element& e, bool rapid, double feed)
{
    if (feed <= 0 && !(rapid && e.type == Element::Type::Line) && !m_warned.test(kWarnZeroFeed)) {
        m_warned.set(kWarnZeroFeed);
        report(Severity::Warning, program().blocks[m_pc].line, 0, "feed motion with no feed programmed");
    }
    if (e.type == Element::Type::Line) {
        if (rapid)
            m_sink.rapid(Rapid{e.end, m_known.mask()});
        else
            m_sink.linear(Linear{e.end, feed, m_known.mask()});
    } else if (e.type == Element::Type::Arc) {
        if (rapid && !m_warned.test(kWarnRapidArc)) {
            m_warned.set(kWarnRapidArc);
            report(Severity::Warning, program().blocks[m_pc].line, 0, "FMAX on a circle: traced at the modal feed");
        }
        Arc arc;
        arc.to = e.end;
        arc.center = {e.center.x, e.center.y, e.start.z};
        arc.normal = {0, 0, 1};
        arc.clockwise = e.clockwise;
        arc.turns = e.turns;
        arc.feedMmPerMin = feed;
        m_sink.arc(arc);
    }
    m_pos = e.end;
    if (const auto t = endTangent(e))
        m_tangent = t;
}

// Looks past the current element for RND/CHF and the element after it; when both neighbours
// are straight lines, shortens `element` to the corner's start and keeps the corner for the
// RND/CHF block.
void Machine::planCorner(Element& element, std::size_t index)
{
    const std::vector<Block>& blocks = program().blocks;
    while (index < blocks.size() && isFiller(blocks[index].kind))
        ++index;
    if (index >= blocks.size() || (blocks[index].kind != BlockKind::Round && blocks[index].kind != BlockKind::Chamfer))
        return;
    const Block& cornerBlock = blocks[index];
    const bool round = cornerBlock.kind == BlockKind::Round;
    auto warn = [&](Severity s, const std::string& message) {
        report(s, cornerBlock.line, cornerBlock.column, message);
        m_cornerWarnedProgram = m_prog;
        m_cornerWarnedBlock = index;
    };

    Vec2 cc = m_cc;
    bool ccSet = m_ccSet;
    std::size_t next = index + 1;
    for (; next < blocks.size(); ++next) {
        const Block& nb = blocks[next];
        if (isFiller(nb.kind))
            continue;
        if (nb.kind != BlockKind::CircleCenter)
            break;
        BlockWords cw;
        if (gather(nb, cw, true)) {
            if (!cw.hasXyz()) {
                cc = element.end.xy();
            } else if (const auto t = target(nb, cw, element.end, true)) {
                cc = t->xy();
            }
            ccSet = true;
        }
    }
    if (next >= blocks.size() || !isContour(blocks[next].kind))
        return warn(Severity::Warning,
                    std::string(round ? "RND" : "CHF") + " is not followed by a contour element: ignored");
    BlockWords nw;
    if (!gather(blocks[next], nw, true))
        return;
    const auto following = plan(blocks[next], nw, element.end, cc, ccSet, endTangent(element), true);
    if (!following || following->type == Element::Type::None)
        return;
    if (!round && (element.type != Element::Type::Line || following->type != Element::Type::Line))
        return warn(Severity::Warning, "CHF is a chamfer between two straight lines: next to a circle it is ignored");

    BlockWords own;
    if (!gather(cornerBlock, own, true))
        return;
    const auto size = round ? own.radius : own.len;
    if (!size || *size <= 0)
        return warn(Severity::Error, round ? "RND needs a positive radius R" : "CHF needs a positive length");
    const double length = *size * m_scale;
    const std::string name = round ? "RND" : "CHF";

    // Heights of the corner points: along a line in proportion, on an arc the corner's.
    const Vec3 v = element.end;
    auto heightOn = [&](const Element& e, const Vec2& p) {
        if (e.type != Element::Type::Line)
            return v.z;
        const Vec2 d = (e.end - e.start).xy();
        const double t = d.dot(d) > 0 ? (p - e.start.xy()).dot(d) / d.dot(d) : 0;
        return e.start.z + (e.end.z - e.start.z) * t;
    };
    Vec2 from, to, center;
    bool clockwise = false;
    if (round) {
        std::string problem;
        const auto r = roundCorner(element, *following, length, problem);
        if (!r)
            return warn(problem.find("fit") != std::string::npos ? Severity::Error : Severity::Warning,
                        "RND radius " + mm(length) + " " + problem);
        from = r->from;
        to = r->to;
        center = r->center;
        clockwise = r->clockwise;
    } else {
        const auto ta = endTangent(element), tb = startTangent(*following);
        if (!ta || !tb)
            return warn(Severity::Warning, "CHF needs motion in the working plane on both sides: ignored");
        if (std::abs(ta->cross(*tb)) < 1e-9)
            return warn(Severity::Warning, "CHF between lines in one direction: ignored");
        const double l1 = distance(element.start.xy(), v.xy()), l2 = distance(v.xy(), following->end.xy());
        if (length > l1 + kEps || length > l2 + kEps)
            return warn(Severity::Error, "CHF length " + mm(length) + " does not fit the adjacent elements");
        from = v.xy() - *ta * length;
        to = v.xy() + *tb * length;
    }
    m_corner.valid = true;
    m_corner.program = m_prog;
    m_corner.block = index;
    m_corner.arc = round;
    m_corner.from = {from.x, from.y, heightOn(element, from)};
    m_corner.to = {to.x, to.y, heightOn(*following, to)};
    m_corner.center = center;
    m_corner.clockwise = clockwise;
    // The element after the corner keeps the geometry planned from the corner point.
    m_corner.next = *following;
    m_corner.next.start = m_corner.to;
    m_corner.nextBlock = next;
    m_corner.nextPending = true;
    element.end = m_corner.from;
}

void Machine::corner(const Block& b)
{
    BlockWords w;
    gather(b, w, false);
    const bool planned = m_corner.valid && m_corner.program == m_prog && m_corner.block == m_pc;
    if (!planned) {
        if (m_cornerWarnedProgram != m_prog || m_cornerWarnedBlock != m_pc)
            report(Severity::Warning, b.line, b.column,
                   std::string(b.kind == BlockKind::Round ? "RND" : "CHF") +
                       " is not between two contour elements: ignored");
        return;
    }
    m_corner.valid = false;
    // A feed in the RND/CHF block holds for that block only.
    const double feed = w.feed == BlockWords::FeedWord::Value ? w.feedValue * m_feedScale : m_feed;
    Element e;
    e.start = m_corner.from;
    e.end = m_corner.to;
    e.type = m_corner.arc ? Element::Type::Arc : Element::Type::Line;
    e.center = m_corner.center;
    e.clockwise = m_corner.clockwise;
    send(e, false, feed);
}

}  // namespace camwb::nc::heidenhain
