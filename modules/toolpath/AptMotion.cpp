// Motion statements of the APT reader: GOTO, GODLTA, FROM, GOHOME, TLAXIS, NX's CIRCLE + GOTO and
// CATIA's INDIRV + TLON,GOFWD/(CIRCLE/...),ON,(LINE/...). The semantics are in AptReader.h.
#include "toolpath/AptReader.h"

#include "toolpath/ClArcs.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::toolpath {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The numbers of `items`, or the position of the first item that is not one.
std::optional<TextPos> firstNonNumber(const std::vector<AptItem>& items, std::size_t begin, std::size_t end)
{
    for (std::size_t i = begin; i < end && i < items.size(); ++i) {
        if (items[i].kind != AptItem::Kind::Number)
            return items[i].pos;
    }
    return std::nullopt;
}

}  // namespace

base::Status AptReader::gotoStatement(const AptStatement& s, const Items& items, bool relative)
{
    const std::string& word = s.words.front();
    for (const AptItem& item : items) {
        if (item.kind != AptItem::Kind::Number)
            return m_out.error(word + " expects numbers, found " + describeItem(item), item.pos);
    }
    const TextPos where = items.empty() ? s.argsPos : items.front().pos;
    Vec3 to;
    Vec3 axis = m_toolAxis;
    if (!relative) {
        if (items.size() != 3 && items.size() != 6)
            return m_out.error("GOTO needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found " + std::to_string(items.size()),
                               where);
        to = point(items[0].number, items[1].number, items[2].number);
        if (items.size() == 6) {
            const auto unit = unitVector({items[3].number, items[4].number, items[5].number});
            if (!unit)
                return m_out.error("GOTO: the tool axis i,j,k is zero", items[3].pos);
            axis = *unit;
        }
    } else {
        if (!m_position)
            return m_out.error("GODLTA needs a known position (a GOTO or FROM before it)", s.wordPos);
        if (items.size() == 3 || items.size() == 6)
            to = *m_position + point(items[0].number, items[1].number, items[2].number);
        else if (items.size() == 1)
            to = *m_position + m_toolAxis * length(items[0].number);
        else
            return m_out.error("GODLTA needs 3 values (dx,dy,dz), 6 (dx,dy,dz,i,j,k) or 1 (along the tool axis), "
                               "found " +
                                   std::to_string(items.size()),
                               where);
        if (items.size() == 6) {
            const auto unit = unitVector({items[3].number, items[4].number, items[5].number});
            if (!unit)
                return m_out.error("GODLTA: the tool axis i,j,k is zero", items[3].pos);
            axis = *unit;
        }
    }
    if (m_circle) {
        m_toolAxis = axis;
        m_pointsFollow = false;
        return finishCircle(to, s);
    }
    m_pointsFollow = m_rapidNext;
    if (m_cycleActive)
        return hole(to, axis, s);
    return moveTo(to, axis, s);
}

base::Status AptReader::pointLine(const AptStatement& s)
{
    if (!m_pointsFollow)
        return m_out.error("a line of values without a GOTO before it", s.wordPos);
    if (auto parsed = tokenizeArguments(s.args, m_out, m_items); !parsed)
        return parsed;
    const Items& items = m_items;
    for (const AptItem& item : items) {
        if (item.kind != AptItem::Kind::Number)
            return m_out.error("GOTO point expects numbers, found " + describeItem(item), item.pos);
    }
    if (items.size() != 3 && items.size() != 6)
        return m_out.error("a GOTO point needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found " +
                               std::to_string(items.size()),
                           items.front().pos);
    const Vec3 to = point(items[0].number, items[1].number, items[2].number);
    Vec3 axis = m_toolAxis;
    if (items.size() == 6) {
        const auto unit = unitVector({items[3].number, items[4].number, items[5].number});
        if (!unit)
            return m_out.error("GOTO: the tool axis i,j,k is zero", items[3].pos);
        axis = *unit;
    }
    if (m_openArc) {
        // Creo's POINTS_&_ARC: every point lies on the arc and the last one ends it.
        OpenArc& open = *m_openArc;
        Arc& arc = std::get<Arc>(m_out.record(open.record));
        open.sweep += forwardAngle(arc, open.last, to);
        open.last = to;
        arc.to = to;
        arc.turns = std::max(0, static_cast<int>(std::ceil(open.sweep / kTwoPi - 1e-9)) - 1);
        for (const std::string& problem : arcRadiusProblems(to, arc, open.radiusMm, 0.001 * m_mmPerUnit)) {
            if (problem.find("ends") != std::string::npos)
                m_out.warn(problem, s.line);
        }
        m_toolAxis = axis;
        m_position = to;
        m_lastDirection = unitVector(arcEndTangent(arc));
        return {};
    }
    m_rapidNext = *m_pointsFollow;
    if (m_cycleActive)
        return hole(to, axis, s);
    return moveTo(to, axis, s);
}

base::Status AptReader::moveTo(const Vec3& to, const Vec3& axis, const AptStatement& s)
{
    m_toolAxis = axis;
    const bool rapid = m_rapidNext;
    m_rapidNext = false;
    if (!rapid && !m_feedSet && !m_warnedNoFeed) {
        m_out.warn("feed motion before any FEDRAT: its feed is 0", s.wordPos);
        m_warnedNoFeed = true;
    }
    const double feed = rapid ? 0.0 : m_feed;
    if (isPlusZ(axis)) {
        if (rapid)
            emit(Rapid{to}, s.line);
        else
            emit(Linear{to, feed}, s.line);
    } else {
        emit(ToolAxisMove{to, axis, feed}, s.line);
    }
    if (m_position) {
        if (const auto direction = unitVector(to - *m_position))
            m_lastDirection = direction;
    }
    m_position = to;
    m_toolChangeRecord.reset();
    return {};
}

base::Status AptReader::from(const AptStatement& s, const Items& items)
{
    if (auto bad = firstNonNumber(items, 0, items.size()))
        return m_out.error("FROM expects numbers", *bad);
    if (items.size() != 3 && items.size() != 6)
        return m_out.error("FROM needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found " + std::to_string(items.size()),
                           items.empty() ? s.argsPos : items.front().pos);
    if (items.size() == 6) {
        const auto unit = unitVector({items[3].number, items[4].number, items[5].number});
        if (!unit)
            return m_out.error("FROM: the tool axis i,j,k is zero", items[3].pos);
        m_toolAxis = *unit;
    }
    m_position = point(items[0].number, items[1].number, items[2].number);
    m_from = m_position;
    m_lastDirection.reset();
    return {};
}

base::Status AptReader::gohome(const AptStatement& s)
{
    if (!m_from)
        return m_out.error("GOHOME without a FROM point to go back to", s.wordPos);
    m_rapidNext = true;
    return moveTo(*m_from, m_toolAxis, s);
}

base::Status AptReader::tlaxis(const AptStatement& s, const Items& items)
{
    if (items.size() != 3 || firstNonNumber(items, 0, 3))
        return m_out.error("TLAXIS expects i,j,k", items.empty() ? s.argsPos : items.front().pos);
    const auto unit = unitVector({items[0].number, items[1].number, items[2].number});
    if (!unit)
        return m_out.error("TLAXIS: the tool axis is zero", items.front().pos);
    m_toolAxis = *unit;
    return {};
}

base::Status AptReader::indirection(const AptStatement& s, const Items& items, bool towardsPoint)
{
    const std::string& word = s.words.front();
    if (items.size() != 3 || firstNonNumber(items, 0, 3))
        return m_out.error(word + " expects three values", items.empty() ? s.argsPos : items.front().pos);
    Vec3 v{items[0].number, items[1].number, items[2].number};
    if (towardsPoint) {
        if (!m_position)
            return m_out.error("INDIRP needs a known position", s.wordPos);
        v = point(v.x, v.y, v.z) - *m_position;
    }
    const auto unit = unitVector(v);
    if (!unit)
        return m_out.error(word + ": the direction is zero", items.front().pos);
    m_startDirection = unit;
    return {};
}

base::Status AptReader::circle(const AptStatement& s, const Items& items)
{
    if (m_cycleActive)
        return m_out.error("CIRCLE inside a CYCLE (no CYCLE/OFF before it)", s.wordPos);
    if (!m_position)
        return m_out.error("CIRCLE needs a known start position (a GOTO or FROM before it)", s.wordPos);
    std::vector<double> values;
    int turns = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const AptItem& item = items[i];
        if (item.kind == AptItem::Kind::Number) {
            values.push_back(item.number);
        } else if (item.isWord("TIMES") && i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number) {
            const double laps = items[++i].number;
            if (laps < 1 || laps != std::floor(laps) || laps > 1e6)
                return m_out.error("CIRCLE: TIMES needs a whole number of laps >= 1", items[i].pos);
            turns = static_cast<int>(laps) - 1;
        } else {
            return m_out.error("CIRCLE: unexpected " + describeItem(item), item.pos);
        }
    }
    if (values.size() < 7)
        return m_out.error("CIRCLE needs cx,cy,cz,i,j,k,r", items.empty() ? s.argsPos : items.front().pos);
    const auto axis = unitVector({values[3], values[4], values[5]});
    if (!axis)
        return m_out.error("CIRCLE: the axis i,j,k is zero", items[3].pos);
    if (values[6] <= 0)
        return m_out.error("CIRCLE: the radius must be > 0", items[6].pos);
    m_circle =
        PendingCircle{point(values[0], values[1], values[2]), *axis, length(values[6]), turns, s.line, s.wordPos};
    return {};
}

base::Status AptReader::finishCircle(const Vec3& to, const AptStatement& s)
{
    const PendingCircle c = *m_circle;
    m_circle.reset();
    if (m_rapidNext)
        return m_out.error("RAPID before the GOTO that ends a CIRCLE: an arc cannot be a rapid", s.wordPos);
    if (!m_feedSet && !m_warnedNoFeed) {
        m_out.warn("feed motion before any FEDRAT: its feed is 0", c.line);
        m_warnedNoFeed = true;
    }
    const Vec3 start = *m_position;
    const Arc arc = makeArc(start, to, c.center, c.axis, true, c.turns, m_feed);
    checkArc(start, arc, c.radiusMm, c.line);
    emit(arc, c.line);
    // Start == end is a whole lap; TIMES adds the others.
    double sweep = forwardAngle(arc, start, to);
    if (sweep == 0)
        sweep = kTwoPi;
    m_openArc = OpenArc{m_out.size() - 1, c.radiusMm, sweep + kTwoPi * c.turns, to, c.line};
    m_position = to;
    m_lastDirection = unitVector(arcEndTangent(arc));
    m_toolChangeRecord.reset();
    return {};
}

void AptReader::checkArc(const Vec3& start, const Arc& arc, std::optional<double> radiusMm, int line)
{
    // APT writers print 4 or 5 decimals; a thousandth of the file's unit is far above that.
    for (const std::string& problem : arcRadiusProblems(start, arc, radiusMm, 0.001 * m_mmPerUnit))
        m_out.warn(problem, line);
}

base::Status AptReader::gofwd(const AptStatement& s, const Items& items)
{
    if (m_cycleActive)
        return m_out.error("circular move inside a CYCLE (no CYCLE/OFF before it)", s.wordPos);
    if (!m_position)
        return m_out.error("circular move needs a known start position (a GOTO or FROM before it)", s.wordPos);
    if (m_rapidNext)
        return m_out.error("RAPID before a circular move: an arc cannot be a rapid", s.wordPos);

    // (CIRCLE/[CANON,]cx,cy,cz[,i,j,k],r), ON, [n, INTOF,] (LINE/x1,y1,z1,x2,y2,z2)
    if (items.empty() || items[0].kind != AptItem::Kind::Group || items[0].word != "CIRCLE")
        return m_out.error("GOFWD is supported with (CIRCLE/...) only", items.empty() ? s.argsPos : items[0].pos);
    const AptItem& circleItem = items[0];
    std::size_t first = !circleItem.items.empty() && circleItem.items[0].isWord("CANON") ? 1 : 0;
    const std::size_t count = circleItem.items.size() - first;
    if ((count != 4 && count != 7) || firstNonNumber(circleItem.items, first, circleItem.items.size()))
        return m_out.error("CIRCLE needs cx,cy,cz,r or cx,cy,cz,i,j,k,r", circleItem.pos);
    std::vector<double> cv;
    for (std::size_t i = first; i < circleItem.items.size(); ++i)
        cv.push_back(circleItem.items[i].number);
    const Vec3 center = point(cv[0], cv[1], cv[2]);
    const auto axis = count == 7 ? unitVector({cv[3], cv[4], cv[5]}) : std::optional<Vec3>(Vec3{0, 0, 1});
    if (!axis)
        return m_out.error("CIRCLE: the axis i,j,k is zero", circleItem.pos);
    const double radius = length(cv.back());
    if (radius <= 0)
        return m_out.error("CIRCLE: the radius must be > 0", circleItem.items.back().pos);

    std::size_t i = 1;
    if (i >= items.size() || !items[i].isWord("ON"))
        return m_out.error("expected ON after the CIRCLE (TO, PAST and TANTO are not supported)",
                           i < items.size() ? items[i].pos : s.argsPos);
    ++i;
    int crossing = 1;
    if (i + 1 < items.size() && items[i].kind == AptItem::Kind::Number && items[i + 1].isWord("INTOF")) {
        const double n = items[i].number;
        if (n < 1 || n != std::floor(n) || n > 1e6)
            return m_out.error("INTOF needs a whole number >= 1", items[i].pos);
        crossing = static_cast<int>(n);
        i += 2;
    }
    if (i >= items.size() || items[i].kind != AptItem::Kind::Group || items[i].word != "LINE")
        return m_out.error("expected (LINE/x1,y1,z1,x2,y2,z2) as the check line",
                           i < items.size() ? items[i].pos : s.argsPos);
    const AptItem& lineItem = items[i];
    if (lineItem.items.size() != 6 || firstNonNumber(lineItem.items, 0, 6))
        return m_out.error("LINE needs x1,y1,z1,x2,y2,z2", lineItem.pos);
    if (i + 1 < items.size())
        return m_out.error("unexpected " + describeItem(items[i + 1]) + " after the LINE", items[i + 1].pos);
    const auto& lv = lineItem.items;
    const Vec3 p1 = point(lv[0].number, lv[1].number, lv[2].number);
    const Vec3 p2 = point(lv[3].number, lv[4].number, lv[5].number);

    const std::optional<Vec3> direction = m_startDirection ? m_startDirection : m_lastDirection;
    m_startDirection.reset();
    if (!direction)
        return m_out.error("circular move without a start direction (INDIRV) or a previous move", s.wordPos);

    const Vec3 n = *axis;
    const Vec3 start = *m_position;
    const double tolerance = 0.001 * m_mmPerUnit;
    const Vec3 radial = (start - center) - n * (start - center).dot(n);
    const auto u = unitVector(radial);
    if (!u)
        return m_out.error("the circular move starts on the circle's axis", s.wordPos);
    const Vec3 v = n.cross(*u);
    const Vec3 d = *direction - n * direction->dot(n);
    const double along = d.dot(v);
    if (d.length() < 1e-9 || std::abs(along) < 1e-9 * d.length())
        return m_out.error("the start direction (INDIRV) does not say which way round the circle to go", s.wordPos);
    const bool ccw = along > 0;

    // Crossings of the check line (projected into the circle's plane) with the circle.
    auto project = [&](const Vec3& p) { return p - n * (p - center).dot(n); };
    const Vec3 q1 = project(p1);
    const Vec3 q2 = project(p2);
    const Vec3 l = q2 - q1;
    const double a = l.dot(l);
    if (a < 1e-18)
        return m_out.error("the LINE's points coincide in the circle's plane", lineItem.pos);
    const Vec3 f = q1 - center;
    const double tClosest = -f.dot(l) / a;
    const double distance = (f + l * tClosest).length();
    if (distance > radius + tolerance)
        return m_out.error("the LINE does not meet the CIRCLE", lineItem.pos);
    const double halfChord = std::sqrt(std::max(0.0, radius * radius - distance * distance)) / std::sqrt(a);
    std::vector<std::pair<double, Vec3>> crossings;  // forward angle from the start, point
    for (const double t : {tClosest - halfChord, tClosest + halfChord}) {
        const Vec3 p = q1 + l * t;
        const Vec3 w = p - center;
        double theta = std::atan2(w.dot(v), w.dot(*u));
        if (!ccw)
            theta = -theta;
        if (theta < 0)
            theta += kTwoPi;
        // The start itself is not a crossing: the tool is already there.
        if ((w - *u * radius).length() < tolerance)
            theta = kTwoPi;
        if (crossings.empty() || std::abs(crossings.front().first - theta) > 1e-12)
            crossings.push_back({theta, p});
    }
    std::sort(crossings.begin(), crossings.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    const std::size_t k = static_cast<std::size_t>(crossing - 1);
    const auto& [angle, crossingPoint] = crossings[k % crossings.size()];
    const double sweep = angle + kTwoPi * static_cast<double>(k / crossings.size());
    const int turns = static_cast<int>(std::ceil(sweep / kTwoPi - 1e-12)) - 1;

    Vec3 to = crossingPoint;
    if (angle == kTwoPi)
        to = start;  // whole laps: exactly back at the start, so posts see a full circle
    else if ((crossingPoint - p2).length() < tolerance)
        to = p2;  // the file's own digits, not a recomputed intersection
    else if ((crossingPoint - p1).length() < tolerance)
        to = p1;

    if (!m_feedSet && !m_warnedNoFeed) {
        m_out.warn("feed motion before any FEDRAT: its feed is 0", s.wordPos);
        m_warnedNoFeed = true;
    }
    const Arc arc = makeArc(start, to, center, n, ccw, turns, m_feed);
    checkArc(start, arc, radius, s.line);
    const double offPlane = std::abs((start - center).dot(n));
    if (offPlane > tolerance)
        m_out.warn("the arc starts " + formatForMessage(offPlane) + " mm off its circle's plane", s.line);
    emit(arc, s.line);
    m_position = to;
    m_lastDirection = unitVector(arcEndTangent(arc));
    m_toolChangeRecord.reset();
    return {};
}

}  // namespace camwb::toolpath
