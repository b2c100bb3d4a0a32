// Canned cycles of the APT reader: CYCLE/<type>,<couplets> ... holes ... CYCLE/OFF become Cycle
// records, one per run of holes with equal parameters. The semantics are in AptReader.h.
#include "toolpath/AptReader.h"

#include "toolpath/ClArcs.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <cmath>

namespace camwb::toolpath {

namespace {

constexpr double kMmPerInch = 25.4;

bool sameParameters(const Cycle& a, const Cycle& b)
{
    return a.kind == b.kind && a.clearanceZ == b.clearanceZ && a.retractZ == b.retractZ && a.topZ == b.topZ &&
           a.bottomZ == b.bottomZ && a.peckMm == b.peckMm && a.dwellSeconds == b.dwellSeconds &&
           a.feedMmPerMin == b.feedMmPerMin && a.returnToClearance == b.returnToClearance;
}

bool isFeedUnit(const AptItem& item)
{
    return item.isWord("MMPM") || item.isWord("IPM") || item.isWord("MMPR") || item.isWord("IPR");
}

}  // namespace

base::Status AptReader::cycle(const AptStatement& s, const Items& items)
{
    if (items.empty() || items[0].kind != AptItem::Kind::Word)
        return m_out.error("CYCLE needs a type (DRILL, DEEP, BRKCHP, TAP, BORE), ON or OFF",
                           items.empty() ? s.argsPos : items[0].pos);
    const std::string& type = items[0].word;
    if (type == "OFF") {
        if (items.size() > 1)
            return m_out.error("CYCLE/OFF takes no further values", items[1].pos);
        if (!m_cycleActive)
            m_out.warn("CYCLE/OFF without an active cycle", s.wordPos);
        endCycle(s.line, false);
        return {};
    }
    CycleDefinition def;
    std::size_t first = 1;
    if (type == "ON") {
        if (!m_cycleDef)
            return m_out.error("CYCLE/ON without an earlier cycle to resume", items[0].pos);
        def = *m_cycleDef;
    } else if (type == "DRILL" || type == "FACE" || type == "CSINK") {
        def.kind = CycleKind::Drill;
        if (type == "DRILL" && items.size() > 1 && (items[1].isWord("DEEP") || items[1].isWord("BRKCHP"))) {
            def.kind = items[1].word == "DEEP" ? CycleKind::Peck : CycleKind::ChipBreak;
            first = 2;
        }
    } else if (type == "DEEP") {
        def.kind = CycleKind::Peck;
    } else if (type == "BRKCHP") {
        def.kind = CycleKind::ChipBreak;
    } else if (type == "TAP" || type == "RIGID") {
        def.kind = CycleKind::Tap;
    } else if (type == "BORE" || type == "REAM") {
        def.kind = CycleKind::Bore;
    } else {
        return m_out.error("CYCLE/" + type + " is not supported", items[0].pos);
    }
    def.line = s.line;
    if (auto status = cycleCouplets(items, first, def); !status)
        return status;
    if (!def.depthMm)
        return m_out.error("CYCLE needs a depth (DEPTH or FEDTO)", items[0].pos);
    if ((def.kind == CycleKind::Peck || def.kind == CycleKind::ChipBreak) && !(def.peckMm && *def.peckMm > 0))
        return m_out.error("CYCLE/" + type + " needs a peck depth (STEP or INCR)", items[0].pos);

    flushCycleRun();
    m_cycleActive = true;
    m_cycleDef = def;
    m_cycleStartZ = m_position ? std::optional<double>(m_position->z) : std::nullopt;
    return {};
}

base::Status AptReader::cycleCouplets(const Items& items, std::size_t first, CycleDefinition& def)
{
    int positional = 0;
    bool lastWasPositionalFeed = false;
    std::optional<double> rawFeed;
    FeedMode feedMode = m_feedMode;
    double feedScale = m_mmPerUnit;
    bool unitGiven = false;
    for (std::size_t i = first; i < items.size(); ++i) {
        const AptItem& item = items[i];
        const bool previousWasFeed = lastWasPositionalFeed;
        lastWasPositionalFeed = false;
        if (item.kind == AptItem::Kind::Group)
            return m_out.error("CYCLE: unexpected (" + item.word + "/...)", item.pos);
        if (item.kind == AptItem::Kind::Number) {
            // Classic positional form: depth, feed, clearance.
            if (positional == 0)
                def.depthMm = length(std::abs(item.number));
            else if (positional == 1) {
                rawFeed = item.number;
                lastWasPositionalFeed = true;
            } else if (positional == 2)
                def.clearMm = length(item.number);
            else
                return m_out.error("CYCLE: unexpected value", item.pos);
            ++positional;
            continue;
        }
        auto value = [&]() -> base::Result<double> {
            if (i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number)
                return items[++i].number;
            return m_out.error("CYCLE: " + item.word + " needs a value", item.pos);
        };
        const std::string& w = item.word;
        if (isFeedUnit(item)) {
            feedMode = (w == "MMPM" || w == "IPM") ? FeedMode::PerMinute : FeedMode::PerRevolution;
            feedScale = w[0] == 'I' ? kMmPerInch : 1.0;
            unitGiven = true;
            // "f, MMPM" (Creo's fixed form) names the unit of the feed just given; otherwise the
            // unit comes first and the feed follows. "d, c, MMPM, f" could be either: refuse it
            // rather than guess which value is the feed.
            const bool numberFollows = i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number;
            if (previousWasFeed && numberFollows)
                return m_out.error("CYCLE: ambiguous values around " + w +
                                       ": write the depth and distances as couplets (DEPTH, CLEAR, RAPTO)",
                                   item.pos);
            if (!previousWasFeed) {
                auto f = value();
                if (!f)
                    return f.error();
                rawFeed = f.value();
                positional = std::max(positional, 2);
            }
        } else if (w == "DEPTH" || w == "FEDTO") {
            auto v = value();
            if (!v)
                return v.error();
            def.depthMm = length(std::abs(v.value()));
            positional = std::max(positional, 1);
        } else if (w == "STEP" || w == "INCR") {
            auto v = value();
            if (!v)
                return v.error();
            def.peckMm = length(std::abs(v.value()));
        } else if (w == "CLEAR" || w == "RAPTO") {
            auto v = value();
            if (!v)
                return v.error();
            (w == "CLEAR" ? def.clearMm : def.raptoMm) = length(v.value());
        } else if (w == "RTRCTO" || w == "RETURN") {
            if (i + 1 < items.size() && items[i + 1].isWord("AUTO")) {
                ++i;
                def.ret = CycleReturn::Clearance;
            } else if (i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number) {
                const double e = items[++i].number;
                def.ret = e == 0 ? CycleReturn::Clearance : CycleReturn::Distance;
                def.returnMm = length(e);
            } else {
                return m_out.error("CYCLE: " + w + " expects a distance or AUTO",
                                   i + 1 < items.size() ? items[i + 1].pos : item.pos);
            }
        } else if (w == "DWELL") {
            auto v = value();
            if (!v)
                return v.error();
            if (v.value() < 0)
                return m_out.error("CYCLE: negative DWELL", items[i].pos);
            def.dwellSeconds = v.value();
        } else {
            // BACK, TIMES, ORIENT, MINSTP, PITCH, REV, ...: parameters the Cycle record has no field for.
            m_out.warn("CYCLE: " + w + " ignored", item.pos);
            if (i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number)
                ++i;
        }
    }
    if (rawFeed) {
        if (*rawFeed < 0)
            return m_out.error("CYCLE: negative feed", items[first].pos);
        def.feed = *rawFeed * feedScale;
        def.feedMode = feedMode;
    } else if (unitGiven) {
        return m_out.error("CYCLE: feed unit without a feed", items[first].pos);
    }
    return {};
}

base::Status AptReader::hole(const Vec3& top, const Vec3& axis, const AptStatement& s)
{
    if (!isPlusZ(axis))
        return m_out.error("CYCLE holes along a tool axis other than +Z are not supported", s.wordPos);
    m_rapidNext = false;
    const CycleDefinition& def = *m_cycleDef;
    Cycle c;
    c.kind = def.kind == CycleKind::Drill && def.dwellSeconds.value_or(0) > 0 ? CycleKind::DrillDwell : def.kind;
    c.topZ = top.z;
    c.retractZ = top.z + (def.raptoMm ? *def.raptoMm : def.clearMm.value_or(0));
    c.bottomZ = top.z - *def.depthMm;
    c.peckMm = def.peckMm.value_or(0);
    c.dwellSeconds = def.dwellSeconds.value_or(0);
    FeedMode mode = m_feedMode;
    if (def.feed) {
        c.feedMmPerMin = *def.feed;
        mode = def.feedMode;
    } else {
        if (!m_feedSet && !m_warnedNoFeed) {
            m_out.warn("CYCLE without a feed and no FEDRAT before it: its feed is 0", def.line);
            m_warnedNoFeed = true;
        }
        c.feedMmPerMin = m_feed;
    }
    if (!m_cycleStartZ) {
        m_out.warn("no tool position before the CYCLE: its clearance plane is taken as the R plane", def.line);
        m_cycleStartZ = c.retractZ;
    }
    c.clearanceZ = *m_cycleStartZ;
    c.returnToClearance = def.ret != CycleReturn::RPlane;
    if (def.ret == CycleReturn::Distance) {
        const double returnZ = top.z + def.returnMm;
        if (std::abs(returnZ - c.retractZ) < 1e-9)
            c.returnToClearance = false;
        else
            c.clearanceZ = returnZ;
    }
    if (const std::optional<std::string> why = tooManyPecks(c))  // as the NC interpreters refuse it
        return m_out.error(*why, def.line);
    c.holes = {top};
    if (m_run && m_run->feedMode == mode && sameParameters(m_run->cycle, c)) {
        m_run->cycle.holes.push_back(top);
    } else {
        flushCycleRun();
        if (c.returnToClearance && c.clearanceZ < c.retractZ - 1e-9)
            m_out.warn("the cycle's clearance plane Z" + formatForMessage(c.clearanceZ) + " is below its R plane Z" +
                           formatForMessage(c.retractZ),
                       s.line);
        m_run = CycleRun{c, mode, s.line};
    }
    const double returnZ = c.returnToClearance ? std::max(c.clearanceZ, c.retractZ) : c.retractZ;
    m_position = Vec3{top.x, top.y, returnZ};
    m_lastDirection.reset();
    m_toolChangeRecord.reset();
    return {};
}

void AptReader::flushCycleRun()
{
    if (!m_run)
        return;
    CycleRun run = std::move(*m_run);
    m_run.reset();
    // A cycle's own per-revolution feed must not change how the following moves read theirs.
    const bool switchMode = run.feedMode != m_feedMode;
    if (switchMode)
        m_out.add(FeedModeChange{run.feedMode}, run.line);
    m_out.add(std::move(run.cycle), run.line);
    if (switchMode)
        m_out.add(FeedModeChange{m_feedMode}, run.line);
}

void AptReader::endCycle(int line, bool warnIfActive)
{
    flushCycleRun();
    if (m_cycleActive && warnIfActive)
        m_out.warn("CYCLE is still on (no CYCLE/OFF): it ends here", line);
    m_cycleActive = false;
}

}  // namespace camwb::toolpath
