// Klartext cycles: CYCL DEF 7 (datum shift), 9 (dwell), 19 (tilted plane: Planes.cpp), the drilling
// cycles 200-209 and 240 and the old 1/2/17 as one toolpath::Cycle record per call; 204 (back
// boring) and 208 (bore milling) expanded into moves here, because no CycleKind describes them.
#include "nc/heidenhain/Machine.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

bool traced(int n)
{
    switch (n) {
    case 1:
    case 2:
    case 17:
    case 200:
    case 201:
    case 202:
    case 203:
    case 204:
    case 205:
    case 206:
    case 207:
    case 208:
    case 209:
    case 240:
        return true;
    default:
        return false;
    }
}

}  // namespace

void Machine::cycleDef(const Block& b)
{
    if (b.a == 7 || b.a == 19) {
        if (b.b == 0)
            return;
        BlockWords w;
        if (!gather(b, w, false))
            return;
        if (b.a == 7) {
            // Absolute values from the workpiece datum, incremental ones from the last shift.
            for (int i = 0; i < 3; ++i) {
                const auto& absolute = w.axes[static_cast<std::size_t>(i)];
                const auto& incremental = w.axes[static_cast<std::size_t>(9 + i)];
                double& s = i == 0 ? m_shift.x : (i == 1 ? m_shift.y : m_shift.z);
                if (absolute)
                    s = *absolute * m_scale;
                if (incremental)
                    s += *incremental * m_scale;
            }
            if (w.rotary)
                report(Severity::Warning, b.line, b.column, "datum shift of rotary axes is not traced");
            return;
        }
        return workingPlaneCycle(b, w);
    }
    if (b.a == 247)
        return datumSetting(b);
    if (b.a == 10)
        return rotationCycle(b);
    const Program& p = program();
    if (b.a < 200 && b.b > 0) {
        // One line of an old multi-block cycle (9.1 DWELL 1.5, 1.2 DEPTH -20 ...): its last value.
        if (b.wordCount == 0)
            return;
        const auto v = eval(p.words[static_cast<std::size_t>(b.firstWord)].expr);
        if (!v)
            return;
        if (b.a == 9) {
            if (*v < 0 || *v > 3600) {
                report(Severity::Error, b.line, b.column, "dwell time out of range (0..3600 s)");
                return;
            }
            m_sink.dwell(Dwell{*v});
            return;
        }
        if (m_cycle.defined && m_cycle.number == b.a && b.b < 10) {
            m_cycle.q[static_cast<std::size_t>(b.b)] = *v;
            m_cycle.set.set(static_cast<std::size_t>(b.b));
        }
        return;
    }
    if (b.a == 9)
        return;  // 9.0 DWELL TIME: the title
    m_cycle = CycleDefinition{};
    m_cycle.number = b.a;
    m_cycle.line = b.line;
    m_cycle.defined = true;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key != Key::QSet)
            continue;
        double value = 0;
        if (word.expr == -3) {
            value = m_autoFeed / m_feedScale;
        } else if (word.expr == -2) {
            report(Severity::Warning, word.line, word.column, "FMAX as a cycle feed: traced with feed 0");
        } else {
            const auto v = eval(word.expr);
            if (!v)
                continue;
            value = *v;
        }
        m_params.q[static_cast<std::size_t>(word.param)] = value;  // cycle parameters are global Q parameters
        if (word.param >= 200 && word.param < 600) {
            m_cycle.q[static_cast<std::size_t>(word.param - 200)] = value;
            m_cycle.set.set(static_cast<std::size_t>(word.param - 200));
        }
    }
    if (!traced(b.a))
        report(Severity::Warning, b.line, b.column,
               "cycle " + std::to_string(b.a) + " is not traced: its calls move nothing");
}

// Cycle 247 DATUM SETTING is active as soon as it is defined: preset Q339 of the preset table
// becomes the datum (a WorkOffset record), and the machining cycle defined before it stays the
// one CYCL CALL and M99 run.
void Machine::datumSetting(const Block& b)
{
    const Program& p = program();
    std::optional<double> preset;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key != Key::QSet || word.expr < 0)
            continue;
        const auto v = eval(word.expr);
        if (!v)
            return;
        m_params.q[static_cast<std::size_t>(word.param)] = *v;  // cycle parameters are global Q parameters
        if (word.param == 339)
            preset = *v;
    }
    if (!preset) {
        report(Severity::Error, b.line, b.column, "cycle 247 needs the datum number Q339");
        return;
    }
    if (*preset < 0 || *preset > 65535 || *preset != std::floor(*preset)) {
        report(Severity::Error, b.line, b.column,
               "cycle 247: datum number Q339 " + mm(*preset) + " is not a preset table line (0..65535)");
        return;
    }
    m_sink.workOffset(WorkOffset{static_cast<int>(*preset)});
}

void Machine::cycleCall(const Block& b)
{
    BlockWords w;
    if (!gather(b, w, false))
        return;
    applySpindleAndCoolant(b, w);
    m_modalCycleCall = false;  // CYCL CALL ends M89, as M99 does
    Vec2 hole = m_pos.xy();
    if (b.kind == BlockKind::CycleCallPos) {
        AxisMask given;
        if (!checkKnown(b, w, given))
            return;
        const auto t = target(b, w, m_pos, false);
        if (!t)
            return;
        m_pos = *t;
        m_known.give(given);
        m_sink.rapid(Rapid{m_pos, m_known.mask()});
        hole = t->xy();
    }
    runCycle(b, hole);
    applyStop(b, w, false);
}

void Machine::runCycle(const Block& b, Vec2 hole)
{
    if (!m_cycle.defined) {
        report(Severity::Error, b.line, b.column, "cycle call without a cycle definition (CYCL DEF)");
        return;
    }
    if (!traced(m_cycle.number))
        return;
    checkToolAlongPlane(b);
    if (m_five.active() && m_five.fiveAxisMove()) {
        report(Severity::Error, b.line, b.column,
               "a cycle called with the rotary axes turned is not traced (drill in a tilted working plane with "
               "PLANE or CYCL DEF 19); nothing moves");
        return;
    }
    // The hole is where the tool is; the old cycles and 204/208 start from its Z, too.
    const bool fromZ = m_cycle.number < 200 || m_cycle.number == 204 || m_cycle.number == 208;
    if (!needKnown(b, fromZ ? AxisMask{} : kXyAxes, kNoAxes, kNoAxes, "the cycle call"))
        return;
    if (m_cycle.number == 208)
        return boreMilling(b, hole);
    if (m_cycle.number == 204)
        return backBoring(b, hole);
    cycleRecord(b, hole);
}

void Machine::cycleRecord(const Block& b, Vec2 hole)
{
    const CycleDefinition& d = m_cycle;
    const int n = d.number;
    const bool old = n < 200;
    // The old cycles (1, 2, 17) start at set-up clearance above the surface and return there.
    const double setup = (old ? d.get(1) : d.get(200)) * m_scale;
    const double top = old ? m_pos.z - setup : m_shift.z + d.get(203) * m_scale;
    const double second = old ? setup : d.get(204) * m_scale;
    double depth = (old ? d.get(2) : d.get(201)) * m_scale;
    if (depth == 0) {
        report(Severity::Warning, b.line, b.column, "cycle depth 0: the control skips the cycle");
        return;
    }
    if (depth > 0) {
        if (!m_cycle.depthWarned)
            report(Severity::Warning, b.line, b.column,
                   "cycle depth is positive: traced as the same depth below the surface "
                   "(the control machines upwards or refuses it, depending on its machine parameters)");
        m_cycle.depthWarned = true;
        depth = -depth;
    }
    Cycle c;
    c.topZ = top;
    c.bottomZ = top + depth;
    c.retractZ = top + setup;
    c.clearanceZ = top + second;
    c.returnToClearance = true;
    c.feedMmPerMin = d.get(206) * m_feedScale;
    c.dwellSeconds = d.get(211);
    const double peck = d.get(202) * m_scale;
    const bool pecking = peck > 0 && peck < std::abs(depth) - 1e-9;
    switch (n) {
    case 200:
    case 205:
        c.kind = pecking ? CycleKind::Peck : (c.dwellSeconds > 0 ? CycleKind::DrillDwell : CycleKind::Drill);
        c.peckMm = pecking ? peck : 0;
        break;
    case 203:
        c.kind = pecking ? (d.get(213) > 0 ? CycleKind::ChipBreak : CycleKind::Peck)
                         : (c.dwellSeconds > 0 ? CycleKind::DrillDwell : CycleKind::Drill);
        c.peckMm = pecking ? peck : 0;
        break;
    case 201:
    case 202:
        c.kind = CycleKind::Bore;
        break;
    case 240:
        c.kind = c.dwellSeconds > 0 ? CycleKind::DrillDwell : CycleKind::Drill;
        break;
    case 206:
    case 207:
    case 209:
        c.kind = CycleKind::Tap;
        if (n != 206)
            c.feedMmPerMin = std::abs(d.get(239)) * m_scale * m_rpm;  // pitch times speed
        if (n != 206)
            c.dwellSeconds = 0;
        break;
    case 1: {
        const double oldPeck = d.get(3) * m_scale;
        const bool oldPecking = oldPeck > 0 && oldPeck < std::abs(depth) - 1e-9;
        c.kind = oldPecking ? CycleKind::Peck : CycleKind::Drill;
        c.peckMm = oldPecking ? oldPeck : 0;
        c.dwellSeconds = d.get(4);
        c.feedMmPerMin = d.get(5) * m_feedScale;
        if (c.dwellSeconds > 0 && !oldPecking)
            c.kind = CycleKind::DrillDwell;
        break;
    }
    case 2:
        c.kind = CycleKind::Tap;
        c.dwellSeconds = d.get(3);
        c.feedMmPerMin = d.get(4) * m_feedScale;
        break;
    case 17:
        c.kind = CycleKind::Tap;
        c.dwellSeconds = 0;
        c.feedMmPerMin = std::abs(d.get(3)) * m_scale * m_rpm;
        break;
    default:
        break;
    }
    if (c.kind != CycleKind::DrillDwell && c.kind != CycleKind::Peck && c.kind != CycleKind::ChipBreak &&
        c.kind != CycleKind::Bore && c.kind != CycleKind::Tap)
        c.dwellSeconds = 0;
    if (const std::optional<std::string> why = toolpath::tooManyPecks(c))
        report(Severity::Error, b.line, b.column, "cycle " + std::to_string(n) + ": " + *why);
    c.holes.push_back({hole.x, hole.y, top});
    m_sink.cycle(c);
    m_pos = {hole.x, hole.y, std::max(c.clearanceZ, c.retractZ)};
    m_known.give(AxisMask{});  // X and Y were known, the cycle ends at a programmed height
}

// Cycle 208: a helix on the bore's diameter down to depth, a full circle at the bottom, back to
// the centre and up. The tool radius comes from TOOL DEF ... R (0 when unknown).
void Machine::boreMilling(const Block& b, Vec2 hole)
{
    const CycleDefinition& d = m_cycle;
    const double top = m_shift.z + d.get(203) * m_scale;
    const double setup = d.get(200) * m_scale;
    const double second = d.get(204) * m_scale;
    double depth = d.get(201) * m_scale;
    if (depth == 0) {
        report(Severity::Warning, b.line, b.column, "cycle depth 0: the control skips the cycle");
        return;
    }
    if (depth > 0)
        depth = -depth;
    const double feed = d.get(206) * m_feedScale;
    double toolRadius = 0;
    if (auto r = m_toolRadius.find(m_tool); r != m_toolRadius.end())
        toolRadius = r->second;
    else
        warnOnce(kWarnCycleRadius, b, "cycle 208: tool radius unknown (no TOOL DEF R): traced on the bore diameter");
    const double radius = d.get(335) * m_scale / 2 - toolRadius;
    const double startZ = top + setup;
    const double bottom = top + depth;

    const Vec3 over{hole.x, hole.y, std::max(m_pos.z, startZ)};
    if (distance(m_pos.xy(), hole) > 1e-9)
        m_sink.rapid(Rapid{over});
    m_sink.rapid(Rapid{{hole.x, hole.y, startZ}});
    if (radius <= 1e-6) {
        m_sink.linear(Linear{{hole.x, hole.y, bottom}, feed});
    } else {
        const double pitch = d.get(334) * m_scale;
        const double height = startZ - bottom;
        const double laps = std::clamp(pitch > 0 ? height / pitch : 1.0, 0.0, 1000.0);
        if (pitch <= 0)
            report(Severity::Warning, b.line, b.column, "cycle 208: infeed per helix Q334 <= 0: one lap traced");
        // Climb milling inside a bore turns counter-clockwise with a clockwise spindle.
        const bool ccw = (d.get(351, 1) >= 0) == m_spindleCw;
        const double sweep = laps * 2 * std::numbers::pi;
        const Vec3 start{hole.x + radius, hole.y, startZ};
        m_sink.linear(Linear{start, feed});
        Arc helix;
        const double a = ccw ? sweep : -sweep;
        const bool whole = std::abs(laps - std::round(laps)) < 1e-12;
        helix.to = whole ? Vec3{start.x, start.y, bottom}
                         : Vec3{hole.x + radius * std::cos(a), hole.y + radius * std::sin(a), bottom};
        helix.center = {hole.x, hole.y, startZ};
        helix.clockwise = !ccw;
        helix.turns = std::max(0, static_cast<int>(std::ceil(laps - 1e-9)) - 1);
        helix.feedMmPerMin = feed;
        m_sink.arc(helix);
        Arc circle = helix;
        circle.center.z = bottom;
        circle.turns = 0;  // to == start: one full circle
        m_sink.arc(circle);
        m_sink.linear(Linear{{hole.x, hole.y, bottom}, feed});
    }
    m_sink.rapid(Rapid{{hole.x, hole.y, startZ}});
    m_pos = {hole.x, hole.y, startZ};
    if (second > setup) {
        m_pos.z = top + second;
        m_sink.rapid(Rapid{m_pos});
    }
}

// Cycle 204: the tool enters off centre (Q251 in the direction Q214) through the bore to set-up
// clearance below the lower edge, centres, counterbores upwards by Q249 and leaves the same way.
void Machine::backBoring(const Block& b, Vec2 hole)
{
    const CycleDefinition& d = m_cycle;
    const double top = m_shift.z + d.get(203) * m_scale;
    const double setup = d.get(200) * m_scale;
    const double second = d.get(204) * m_scale;
    const double thickness = d.get(250) * m_scale;
    const double counterbore = d.get(249) * m_scale;
    const double offset = d.get(251) * m_scale;
    const double prePosition = d.get(253) * m_feedScale;
    const double boreFeed = d.get(254) * m_feedScale;
    const double dwell = d.get(255);
    if (thickness <= 0) {
        report(Severity::Error, b.line, b.column, "cycle 204: material thickness Q250 must be positive");
        return;
    }
    Vec2 off = hole;
    const double direction = d.get(214);
    switch (direction >= 0 && direction <= 4 ? static_cast<int>(direction) : 0) {
    case 1:
        off.x -= offset;
        break;
    case 2:
        off.y -= offset;
        break;
    case 3:
        off.x += offset;
        break;
    case 4:
        off.y += offset;
        break;
    default:
        break;
    }
    const double below = top - thickness - setup;
    const double startZ = top + setup;
    if (distance(m_pos.xy(), hole) > 1e-9)
        m_sink.rapid(Rapid{{hole.x, hole.y, std::max(m_pos.z, startZ)}});
    m_sink.rapid(Rapid{{hole.x, hole.y, startZ}});
    m_sink.rapid(Rapid{{off.x, off.y, startZ}});
    m_sink.linear(Linear{{off.x, off.y, below}, prePosition});
    m_sink.linear(Linear{{hole.x, hole.y, below}, prePosition});
    m_sink.linear(Linear{{hole.x, hole.y, top - thickness + std::abs(counterbore)}, boreFeed});
    if (dwell > 0)
        m_sink.dwell(Dwell{dwell});
    m_sink.linear(Linear{{hole.x, hole.y, below}, prePosition});
    m_sink.linear(Linear{{off.x, off.y, below}, prePosition});
    m_sink.rapid(Rapid{{off.x, off.y, startZ}});
    m_sink.rapid(Rapid{{hole.x, hole.y, startZ}});
    m_pos = {hole.x, hole.y, startZ};
    if (second > setup) {
        m_pos.z = top + second;
        m_sink.rapid(Rapid{m_pos});
    }
}

}  // namespace camwb::nc::heidenhain
