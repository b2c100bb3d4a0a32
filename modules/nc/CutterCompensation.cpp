#include "nc/CutterCompensation.h"

#include "base/NumberFormat.h"
#include "nc/Interpreter.h"

#include <cmath>
#include <numbers>

namespace camwb::nc {

using namespace camwb::toolpath;
using base::Vec2;
using base::Vec3;
using detail::CompElement;

namespace {

constexpr double kPlaneEps = 1e-9;  // mm: less XY travel is a move in Z alone

std::string mm(double v) { return base::NumberFormat{3, true}.format(v); }

Vec3 withXy(Vec3 v, Vec2 xy) { return {xy.x, xy.y, v.z}; }

// The record with its end point replaced (rapids, lines and arcs carry one).
void setEnd(Record& record, Vec3 to)
{
    if (auto* r = std::get_if<Rapid>(&record))
        r->to = to;
    else if (auto* l = std::get_if<Linear>(&record))
        l->to = to;
    else if (auto* a = std::get_if<Arc>(&record))
        a->to = to;
}

Vec3 endOf(const Record& record)
{
    if (const auto* r = std::get_if<Rapid>(&record))
        return r->to;
    if (const auto* l = std::get_if<Linear>(&record))
        return l->to;
    if (const auto* a = std::get_if<Arc>(&record))
        return a->to;
    return {};
}

double feedOf(const Record& record)
{
    if (const auto* l = std::get_if<Linear>(&record))
        return l->feedMmPerMin;
    if (const auto* a = std::get_if<Arc>(&record))
        return a->feedMmPerMin;
    return 0;
}

}  // namespace

CompensationRules CompensationRules::linuxCnc()
{
    CompensationRules rules;
    rules.entrySquareToContour = false;
    rules.arcEntry = true;
    rules.entryMustMoveInPlane = true;
    rules.tangentTolerance = 0.05;  // TOLERANCE_CONCAVE_CORNER
    rules.shortEntryIsError = true;
    rules.reversalOutsideArcIsInside = true;
    return rules;
}

CompensationRules CompensationRules::sinumerik()
{
    CompensationRules rules;        // NORM and G450
    rules.tangentTolerance = 1e-3;  // the rounding of written coordinates
    return rules;
}

CompensationRules CompensationRules::heidenhain()
{
    CompensationRules rules = sinumerik();
    rules.selectWords = "RL/RR";
    rules.cancelWord = "R0";
    rules.arcOutsideXyIsError = true;
    return rules;
}

CutterCompensation::CutterCompensation(MachineSink& out, CompensationRules rules, InterpretResult& result,
                                       std::size_t maxDiagnostics) :
    m_out(out),
    m_rules(rules),
    m_result(result),
    m_maxDiagnostics(maxDiagnostics)
{
}

void CutterCompensation::setRadius(std::optional<double> radiusMm, std::string what)
{
    m_nextRadius = radiusMm;
    m_nextWhat = std::move(what);
}

void CutterCompensation::setOutsideIntersection(bool on, double limitDeg)
{
    m_outsideIntersection = on;
    m_intersectionLimitRad = limitDeg * std::numbers::pi / 180;
}

void CutterCompensation::report(Severity severity, std::string message)
{
    const auto file = static_cast<std::size_t>(std::max(0, m_source.file));
    std::string path = file < m_result.files.size() ? m_result.files[file] : std::string();
    if (path.empty())
        path = "<input>";
    if (!m_reported.insert(path + ":" + std::to_string(m_source.line) + ":" + message).second)
        return;
    if (m_result.diagnostics.size() >= m_maxDiagnostics) {
        ++m_result.diagnosticsDropped;
        return;
    }
    m_result.diagnostics.push_back({severity, path, m_source.line, 0, std::move(message)});
}

void CutterCompensation::setSource(const SourceRef& source)
{
    m_source = source;
    if (m_holding)
        m_waiting.push_back({source, std::nullopt, false});
    else
        m_out.setSource(source);
}

void CutterCompensation::pass(const Record& record)
{
    if (m_holding)
        m_waiting.push_back({m_source, record, false});
    else
        dispatch(record, m_out);
}

void CutterCompensation::emit(const Record& record, const SourceRef& source)
{
    m_out.setSource(source);
    dispatch(record, m_out);
}

void CutterCompensation::flush()
{
    if (!m_holding)
        return;
    m_holding = false;
    emit(m_held, m_heldSource);
    for (const Waiting& w : m_waiting) {
        if (w.record)
            emit(*w.record, w.source);
        else
            m_out.setSource(w.source);
    }
    m_waiting.clear();
}

void CutterCompensation::hold(Record record, const CompElement& programmed, Vec3 toolEnd)
{
    m_holding = true;
    setEnd(record, toolEnd);
    m_held = std::move(record);
    m_heldSource = m_source;
    m_heldProgrammed = programmed;
    m_tool = toolEnd;
}

void CutterCompensation::moveHeldEnd(Vec2 to)
{
    setEnd(m_held, withXy(endOf(m_held), to));
    m_heldOffset.end = to;
    for (Waiting& w : m_waiting)
        if (w.followsHeld && w.record)
            setEnd(*w.record, withXy(endOf(*w.record), to));
    m_tool = withXy(m_tool, to);
}

void CutterCompensation::passProgrammed(const Record& record, Vec3 to)
{
    pass(record);
    m_programmed = to;
    m_tool = to;
}

bool CutterCompensation::active()
{
    if (m_state == State::Off)
        return false;
    if (!m_radiusKnown) {
        if (!m_warnedUnknown)
            report(Severity::Warning, std::string("cutter compensation (") + m_rules.selectWords + "): the radius of " +
                                          m_what +
                                          " is not known (no tool table entry, no tool data in the program): the "
                                          "programmed contour is traced, not the tool centre");
        m_warnedUnknown = true;
        return false;
    }
    return m_radius > 0;
}

void CutterCompensation::rapid(const Rapid& r)
{
    if (!passedThrough<&MachineSink::rapid>(r))
        move(Record(r), r.to, nullptr);
}

void CutterCompensation::linear(const Linear& r)
{
    if (!passedThrough<&MachineSink::linear>(r))
        move(Record(r), r.to, nullptr);
}

void CutterCompensation::arc(const Arc& r)
{
    if (passedThrough<&MachineSink::arc>(r))
        return;
    CompElement e;
    e.arc = true;
    e.start = m_programmed.xy();
    e.end = r.to.xy();
    e.center = r.center.xy();
    e.clockwise = r.normal.z < 0 ? !r.clockwise : r.clockwise;
    const bool outsideXy = m_state != State::Off && std::abs(std::abs(r.normal.z) - 1) > 1e-9;
    if (outsideXy && (m_rules.arcOutsideXyIsError || active())) {
        const std::string words = std::string("cutter compensation (") + m_rules.selectWords + ")";
        if (m_rules.arcOutsideXyIsError)
            report(Severity::Error, words + " works in the XY working plane: an arc in another plane is not allowed "
                                            "with it (traced as programmed)");
        else
            report(Severity::Warning, words + " is traced in the XY plane only: this arc in another plane is traced "
                                              "as programmed");
        flush();
        passProgrammed(Record(r), r.to);
        m_state = State::Starting;
        return;
    }
    move(Record(r), r.to, &e);
}

void CutterCompensation::move(const Record& record, Vec3 to, const CompElement* arcElement)
{
    const bool inPlane = arcElement || distance(to.xy(), m_programmed.xy()) > kPlaneEps;
    if (!active()) {
        if (m_leaving && inPlane) {
            m_leaving = false;
            if (arcElement)
                report(Severity::Error, std::string("cutter compensation must end on a straight move (") +
                                            m_rules.cancelWord +
                                            " with a line): the arc starts from the compensated position");
        }
        passProgrammed(record, to);
        return;
    }
    if (!inPlane)
        return moveInZ(record, to.z);
    CompElement element;
    if (arcElement) {
        element = *arcElement;
    } else {
        element.start = m_programmed.xy();
        element.end = to.xy();
    }
    if (m_state == State::Starting)
        return start(record, to, element);
    turnCorner(record, element);
    continueWith(record, to, element);
}

void CutterCompensation::moveInZ(const Record& record, double z)
{
    Record r = record;
    setEnd(r, Vec3{m_tool.x, m_tool.y, z});
    if (m_state == State::Starting && m_rules.entryMustMoveInPlane)
        report(Severity::Error, std::string("the first move after ") + m_rules.selectWords +
                                    " must move in X or Y (an entry move no longer than the tool radius)");
    if (m_holding)
        m_waiting.push_back({m_source, r, true});
    else
        dispatch(r, m_out);
    m_tool.z = z;
    m_programmed.z = z;
}

void CutterCompensation::start(const Record& record, Vec3 to, const CompElement& element)
{
    if (element.arc) {
        if (m_rules.arcEntry)
            return startOnArc(record, to, element);
        report(Severity::Error, std::string("cutter compensation must start on a straight move (") +
                                    m_rules.selectWords + " with a line): the arc is traced as programmed");
        return passProgrammed(record, to);
    }
    const Vec2 from = m_tool.xy();
    const Vec2 target = to.xy();
    const double length = distance(from, target);
    if (length <= m_radius) {
        const std::string message = "the entry move of cutter compensation (" + mm(length) +
                                    " mm) is not longer than the tool radius " + mm(m_radius) + " mm";
        if (m_rules.shortEntryIsError || length <= kPlaneEps) {
            report(Severity::Error, message + ": traced as programmed");
            return passProgrammed(record, to);
        }
        report(Severity::Warning, message + ": the tool may cut into the contour");
    }
    CompElement entry;
    entry.start = from;
    entry.end = target;
    const Vec2 end = target + detail::sideNormal(detail::startTangent(entry), left()) * m_radius;
    m_heldOffset = CompElement{false, from, end, {}, false};
    hold(record, entry, withXy(to, end));
    m_entryOpen = m_rules.entrySquareToContour;
    m_programmed = to;
    m_state = State::On;
}

// LinuxCNC's entry arc: it ends r beside the programmed end (towards or away from the centre)
// and passes through the tool's position, about a centre on the line from the new end to the
// programmed centre.
void CutterCompensation::startOnArc(const Record& record, Vec3 to, const CompElement& element)
{
    const Vec2 current = m_tool.xy();
    const Vec2 end = element.end, center = element.center;
    if (distance(end, current) <= m_radius) {
        report(Severity::Error, "the entry arc of cutter compensation ends within the tool radius " + mm(m_radius) +
                                    " mm of where it starts: traced as programmed");
        return passProgrammed(record, to);
    }
    const Vec2 gamma =
        detail::toolInsideArc(element, left()) ? (center - end).normalized() : (end - center).normalized();
    const Vec2 newEnd = end + gamma * m_radius;
    const double half = distance(current, newEnd) / 2;
    const double ab = std::atan2(center.y - newEnd.y, center.x - newEnd.x);
    const double a = std::atan2(current.y - newEnd.y, current.x - newEnd.x) - ab;
    if (std::abs(std::cos(a)) < 1e-6) {
        report(Severity::Error, "the tool radius " + mm(m_radius) +
                                    " mm does not fit the entry arc of cutter compensation: traced as programmed");
        return passProgrammed(record, to);
    }
    const double toCentre = half / std::cos(a);
    const Vec2 newCenter = newEnd + Vec2{std::cos(ab), std::sin(ab)} * toCentre;
    Record r = record;
    std::get<Arc>(r).center = withXy(std::get<Arc>(r).center, newCenter);
    m_heldOffset = CompElement{true, current, newEnd, newCenter, element.clockwise};
    hold(r, element, withXy(to, newEnd));
    m_entryOpen = false;
    m_programmed = to;
    m_state = State::On;
}

void CutterCompensation::turnCorner(const Record& record, const CompElement& next)
{
    if (!m_holding)
        return;  // flushed early (a cycle, a five-axis move): go on from where the tool is
    const Vec2 vertex = next.start;
    const Vec2 nextStart = vertex + detail::sideNormal(detail::startTangent(next), left()) * m_radius;
    if (m_entryOpen) {  // square to the contour's first element
        m_entryOpen = false;
        moveHeldEnd(nextStart);
        return flush();
    }
    double turn = 0;
    const auto kind = detail::classifyCorner(m_heldProgrammed, next, left(), m_rules.tangentTolerance,
                                             m_rules.reversalOutsideArcIsInside, &turn);
    if (kind == detail::CornerKind::Tangent)
        return flush();
    const bool intersect =
        kind == detail::CornerKind::Inside || (m_outsideIntersection && std::abs(turn) <= m_intersectionLimitRad);
    if (intersect) {
        const auto point =
            detail::cornerPoint(m_heldProgrammed, next, left(), m_radius, kind == detail::CornerKind::Inside);
        const std::string where = "the tool (radius " + mm(m_radius) + " mm) does not fit into the inside corner at " +
                                  detail::formatPoint(vertex);
        if (!point) {
            report(Severity::Error, where + ": the offsets do not meet (gouge)");
        } else if (kind == detail::CornerKind::Inside &&
                   !detail::keepsDirection(m_heldOffset, m_heldProgrammed, *point)) {
            report(Severity::Error, where + ": the element before it is shorter than the tool needs (gouge)");
        } else {
            moveHeldEnd(*point);
            return flush();
        }
        if (kind == detail::CornerKind::Inside)
            return flush();  // reported: the path goes on from the untrimmed end
    }
    flush();
    // Outside: an arc about the corner from one offset to the next (a rapid goes straight: the
    // trace has no arc at rapid traverse).
    if (std::holds_alternative<Rapid>(record)) {
        emit(Rapid{withXy(m_tool, nextStart)}, m_source);
    } else {
        Arc around;
        around.to = withXy(m_tool, nextStart);
        around.center = withXy(m_tool, vertex);
        around.normal = {0, 0, 1};
        around.clockwise = left();
        around.feedMmPerMin = feedOf(record);  // the corner is the next move's: its feed and kind
        around.feedKind = feedKindOf(record);
        emit(around, m_source);
    }
    m_tool = withXy(m_tool, nextStart);
}

void CutterCompensation::continueWith(const Record& record, Vec3 to, const CompElement& next)
{
    const Vec2 from = m_tool.xy();
    if (next.arc) {
        const auto offset = detail::offsetElement(next, left(), m_radius);
        if (!offset) {
            report(Severity::Error, "the tool radius " + mm(m_radius) + " mm is not smaller than the radius " +
                                        mm(distance(next.end, next.center)) +
                                        " mm of the inside arc: the tool cannot follow it (gouge); the arc is traced "
                                        "as programmed and compensation starts again");
            passProgrammed(record, to);
            m_state = State::Starting;
            return;
        }
        m_heldOffset = CompElement{true, from, offset->end, next.center, next.clockwise};
        if (!next.fullCircle()) {
            const double programmedSweep = detail::arcTravel(next.center, next.start, next.end, next.clockwise);
            const double remaining = detail::arcTravel(next.center, from, offset->end, next.clockwise);
            if (remaining > programmedSweep + 1e-9 && remaining > std::numbers::pi + programmedSweep / 2)
                report(Severity::Error, "the tool (radius " + mm(m_radius) +
                                            " mm) trims this arc past its end at an inside corner (gouge)");
        }
        hold(record, next, withXy(to, offset->end));
        m_programmed = to;
        return;
    }
    const Vec2 dir = detail::startTangent(next);
    const Vec2 end = to.xy() + detail::sideNormal(dir, left()) * m_radius;
    if ((end - from).dot(dir) <= 0)
        report(Severity::Error,
               "the tool (radius " + mm(m_radius) + " mm) trims this line past its end at an inside corner (gouge)");
    m_heldOffset = CompElement{false, from, end, {}, false};
    hold(record, next, withXy(to, end));
    m_programmed = to;
}

void CutterCompensation::cutterComp(const CutterComp& r)
{
    if (r.side == CutterCompSide::Off) {
        const bool wasActive = m_state != State::Off && m_radiusKnown && m_radius > 0;
        m_entryOpen = false;  // the entry move stays square to itself
        flush();
        pass(r);
        m_state = State::Off;
        m_side = CutterCompSide::Off;
        m_leaving = wasActive;
        return;
    }
    flush();
    m_entryOpen = false;
    pass(r);
    if (uncompensated())
        m_tool = m_programmed;  // moves without compensation track only the programmed position
    m_side = r.side;
    m_state = State::Starting;
    m_radiusKnown = m_nextRadius.has_value();
    m_radius = m_nextRadius.value_or(0);
    m_what = m_nextWhat;
    m_warnedUnknown = false;
    m_leaving = false;
}

void CutterCompensation::cycle(const Cycle& r)
{
    m_entryOpen = false;
    flush();
    pass(r);
    if (!r.holes.empty()) {
        const Vec3 last = r.holes.back();
        m_programmed = m_tool = {last.x, last.y, r.returnToClearance ? r.clearanceZ : r.retractZ};
    }
}

void CutterCompensation::toolAxisMove(const ToolAxisMove& r)
{
    m_entryOpen = false;
    flush();
    pass(r);
    m_programmed = m_tool = r.tip;
}

void CutterCompensation::end()
{
    m_entryOpen = false;
    flush();
    m_out.end();
}

}  // namespace camwb::nc
