// Contour elements of Klartext: L and APPR/DEP (straight approximations) here, the circles and
// polar moves in Circles.cpp; sending them, and the RND/CHF corners between two elements in the XY
// plane, which shorten the element before them (planned here with a look-ahead).
#include "nc/heidenhain/Machine.h"

#include "nc/detail/PlaneAxes.h"

#include <cmath>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

constexpr double kEps = 1e-9;

bool isContour(BlockKind k)
{
    return k == BlockKind::Line || k == BlockKind::LinePolar || k == BlockKind::Circle ||
           k == BlockKind::CircleRadius || k == BlockKind::CircleTangent || k == BlockKind::CirclePolar;
}

bool isFiller(BlockKind k) { return k == BlockKind::Empty || k == BlockKind::Comment; }

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
            detail::setComponent(t, i, detail::component(m_shift, i) + *absolute * m_scale);
        if (incremental)
            detail::setComponent(t, i, detail::component(t, i) + *incremental * m_scale);
    }
    return t;
}

std::optional<Element> Machine::plan(const Block& b, const BlockWords& w, const Vec3& from, const Pole& pole,
                                     const Tangents& tangents, bool quiet)
{
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
            const auto& tangent = tangents[0];
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
    case BlockKind::LinePolar:
    case BlockKind::Circle:
    case BlockKind::CircleRadius:
    case BlockKind::CircleTangent:
    case BlockKind::CirclePolar:
        return planCircle(b, w, e, pole, tangents, quiet);
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
            given = given | planeMask(m_pole.plane);  // about the pole, which is known (centreOf)
        else if (!needKnown(b, planeMask(m_pole.plane), kNoAxes, kNoAxes, "the polar move from the current position"))
            return false;
        break;
    case BlockKind::Circle:
    case BlockKind::CircleRadius:
    case BlockKind::CircleTangent:
    case BlockKind::CirclePolar:
        if (!needKnown(b, planeMask(circlePlane(b.kind, w, m_pole)), AxisMask{}, given, "the circle"))
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

// A contour or M-only block in the control's order: spindle and coolant, compensation, feed, the
// element (with a planned corner after it), then stops, program end and cycle calls.
void Machine::motionBlock(const Block& b)
{
    BlockWords w;
    if (!gather(b, w, false))
        return;
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
    if (b.kind == BlockKind::Line && inMachineCoordinates(w)) {
        moveInMachineCoordinates(b, w);
        return false;
    }
    const bool rapid = w.feed == BlockWords::FeedWord::Max;
    bool moved = false;
    AxisMask given;
    RotaryTarget rotary;
    bool traced = true;
    if (!rotaryTarget(b, w, rotary) || !checkKnown(b, w, given) || !fiveAxisReady(b, rotary, given, traced)) {
        m_corner.nextPending = false;
        return false;
    }
    std::optional<Element> e;
    if (m_corner.nextPending && m_corner.program == m_prog && m_corner.nextBlock == m_pc) {
        e = m_corner.next;  // planned from the corner before it (RND/CHF)
        e->start = m_pos;
    } else {
        e = plan(b, w, m_pos, m_pole, m_tangents, false);
    }
    m_corner.nextPending = false;
    if (e && e->type == Element::Type::None && rotary.changed && m_five.inPlane()) {
        // In a tilted plane a rotary-only block positions the axes; the tool tip stays in the plane.
        m_five.setAngles(rotary.angles);
        m_planeChecked = false;
        return false;
    }
    if (e && e->type == Element::Type::None && rotary.changed) {
        e->type = Element::Type::Line;  // the rotary axes alone move: the tool turns about its tip or with the table
        e->end = e->start;
    }
    if (e && e->type != Element::Type::None) {
        if (!rotary.spatial) {
            m_planeChecked = m_planeChecked && !rotary.changed;
            m_five.setAngles(rotary.angles);
        } else if (!orientSpatial(b, e->end))
            return false;
        if (e->type == Element::Type::Arc)
            m_lastDirection = e->clockwise ? -1 : 1;
        m_known.give(given);
        if (!traced) {
            m_pos = e->end;  // the axes the block gave; the others stay unknown
            m_five.moveUntraced();
            return false;
        }
        if (m_known.complete())  // a corner is planned from known points only
            planCorner(*e, m_pc + 1);
        send(*e, rapid, m_feed);
        moved = true;
    }
    // Absolute coordinates (or a polar end about a known pole) make the position known.
    for (int i = 0; i < 3; ++i) {
        if (w.axes[static_cast<std::size_t>(i)])
            m_programmed.bits |= axisBit(i).bits;
    }
    if (b.kind == BlockKind::LinePolar && w.pr && w.pa && m_pole.set)
        m_programmed = m_programmed | planeMask(m_pole.plane);
    return moved;
}

void Machine::send(const Element& e, bool rapid, double feed)
{
    if (feed <= 0 && !(rapid && e.type == Element::Type::Line) && !m_warned.test(kWarnZeroFeed)) {
        m_warned.set(kWarnZeroFeed);
        report(Severity::Warning, program().blocks[m_pc].line, 0, "feed motion with no feed programmed");
    }
    checkToolAlongPlane(program().blocks[m_pc]);
    if (m_five.active() && m_five.fiveAxisMove()) {
        sendFiveAxis(e, rapid, feed);
    } else if (e.type == Element::Type::Line) {
        if (rapid)
            m_sink.rapid(Rapid{e.end, m_known.mask()});
        else
            m_sink.linear(Linear{e.end, feed, m_known.mask()});
    } else if (e.type == Element::Type::Arc) {
        if (rapid && !m_warned.test(kWarnRapidArc)) {
            m_warned.set(kWarnRapidArc);
            report(Severity::Warning, program().blocks[m_pc].line, 0, "FMAX on a circle: traced at the modal feed");
        }
        const detail::PlaneAxes plane = detail::planeAxes(e.plane);
        Arc arc;
        arc.to = e.end;
        arc.center = detail::withInPlane(e.start, plane, e.center);  // at the start's height along the normal
        arc.normal = plane.normal;
        arc.clockwise = e.clockwise;
        arc.turns = e.turns;
        arc.feedMmPerMin = feed;
        m_sink.arc(arc);
    }
    m_pos = e.end;
    for (int plane = 17; plane <= 19; ++plane) {
        if (const auto t = endTangent(e, plane))
            m_tangents[static_cast<std::size_t>(plane - 17)] = t;
    }
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

    Pole pole = m_pole;
    std::size_t next = index + 1;
    for (; next < blocks.size(); ++next) {
        const Block& nb = blocks[next];
        if (isFiller(nb.kind))
            continue;
        if (nb.kind != BlockKind::CircleCenter)
            break;
        BlockWords cw;
        if (gather(nb, cw, true)) {
            if (const auto p = centreOf(nb, cw, element.end, pole, true))
                pole = *p;
        }
    }
    if (next >= blocks.size() || !isContour(blocks[next].kind))
        return warn(Severity::Warning,
                    std::string(round ? "RND" : "CHF") + " is not followed by a contour element: ignored");
    BlockWords nw;
    if (!gather(blocks[next], nw, true))
        return;
    Tangents tangents = m_tangents;
    for (int plane = 17; plane <= 19; ++plane) {
        if (const auto t = endTangent(element, plane))
            tangents[static_cast<std::size_t>(plane - 17)] = t;
    }
    const auto following = plan(blocks[next], nw, element.end, pole, tangents, true);
    if (!following || following->type == Element::Type::None)
        return;
    auto outsideXy = [](const Element& e) { return e.type == Element::Type::Arc && e.plane != 17; };
    if (outsideXy(element) || outsideXy(*following))
        return warn(Severity::Warning, std::string(round ? "RND" : "CHF") +
                                           " next to a circle outside the XY working plane is not traced: ignored");
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
