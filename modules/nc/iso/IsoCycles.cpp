// Canned cycles G73, G81..G86, G89 of the ISO machine as toolpath::Cycle records, one per hole
// (LinuxCNC "G80-G89 Canned Cycles"): R, Z, P and Q kept from one cycle block to the next, L
// repeats (moving by X/Y each time under G91), R measured from the start Z and Z from R under
// G91. A record's hole is (X, Y, R): LinuxCNC measures pecks from the R plane, so the R plane is
// the top; clearance is the Z before the cycle's first hole, and G98 returns to the higher of it
// and R, as cycleReturnZ() does. Also G28/G30: the intermediate point, then the stored position in
// machine coordinates, which leaves the axes it moves unknown.
#include "nc/iso/IsoMachine.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <cmath>

namespace camwb::nc::iso {

using namespace camwb::toolpath;

namespace {

constexpr int kMaxRepeats = 100000;  // L beyond this is a typing error

CycleKind kindOf(int mode)
{
    switch (mode) {
    case 730:
        return CycleKind::ChipBreak;
    case 820:
        return CycleKind::DrillDwell;
    case 830:
        return CycleKind::Peck;
    case 840:
        return CycleKind::Tap;
    case 850:
    case 860:
    case 890:
        return CycleKind::Bore;
    default:
        return CycleKind::Drill;
    }
}

}  // namespace

void Machine::cycle(const Block& block, int mode)
{
    const std::string name = "G" + std::to_string(mode / 10);
    if (m_state.plane != 170) {
        m_reporter.error(m_line, 0, name + " outside G17: only cycles along Z are traced");
        return;
    }
    if (m_state.feedMode == FeedMode::InverseTime) {
        m_reporter.error(m_line, 0, name + " under G93 (inverse time): LinuxCNC refuses it");
        return;
    }
    int repeats = 1;
    if (block.has('L')) {
        const double l = block.get('L');
        if (l < 0 || l != std::floor(l) || l > kMaxRepeats) {
            error(block, 'L', "L (repeats) must be a whole number from 0 to 100000");
            return;
        }
        repeats = static_cast<int>(l);
    }
    const double unit = m_state.unit;
    if (block.has('R')) {
        m_state.cycleR = block.get('R') * unit;
        m_state.haveCycleR = true;
    }
    if (block.has('Z')) {
        m_state.cycleZ = block.get('Z') * unit;
        m_state.haveCycleZ = true;
    }
    if (block.has('P'))
        m_state.cycleP = block.get('P');
    if (block.has('Q'))
        m_state.cycleQ = block.get('Q') * unit;
    if (!m_state.haveCycleR || !m_state.haveCycleZ) {
        m_reporter.error(m_line, 0, name + " needs " + (m_state.haveCycleR ? "Z" : "R") + " (given once, then kept)");
        return;
    }
    if ((mode == 730 || mode == 830) && m_state.cycleQ <= 0) {
        m_reporter.error(m_line, block.has('Q') ? block.col('Q') : 0, name + " needs Q > 0 (peck depth)");
        return;
    }
    if (m_state.cycleP < 0) {
        m_reporter.error(m_line, block.has('P') ? block.col('P') : 0, name + " with a negative dwell P");
        return;
    }
    const double oldZ = m_state.position.z;
    const double r = m_state.absolute ? m_state.cycleR : oldZ + m_state.cycleR;
    const double bottom = m_state.absolute ? m_state.cycleZ : r + m_state.cycleZ;
    if (r < bottom) {
        m_reporter.error(m_line, block.has('R') ? block.col('R') : 0, name + " R plane is below the bottom Z");
        return;
    }
    if (mode == 860)
        m_reporter.warning(m_line, 0, "G86 (spindle stop, rapid out) is traced as a bore cycle with dwell");
    if (mode == 840 && m_state.spindle <= 0)
        m_reporter.warning(m_line, 0, "G84 (tapping) without the spindle turning clockwise (M3)");
    const double feed = feedFor(block, name.c_str());

    // A cycle's clearance is the Z before its first hole: a block naming the cycle starts anew.
    bool named = false;
    for (int i = 0; i < block.gCount; ++i)
        named = named || block.g[i].code10 == mode;
    if (named || !m_state.cycleSequence)
        m_state.cycleStartZ = oldZ;
    const double clear = m_state.retractToR ? r : std::max(r, oldZ);
    const double dx = block.has('X') ? block.get('X') * unit : 0.0;
    const double dy = block.has('Y') ? block.get('Y') * unit : 0.0;
    double x = m_state.absolute && block.has('X') ? dx : m_state.position.x;
    double y = m_state.absolute && block.has('Y') ? dy : m_state.position.y;

    Cycle record;
    record.kind = kindOf(mode);
    record.clearanceZ = m_state.cycleStartZ;
    record.retractZ = r;
    record.topZ = r;
    record.bottomZ = bottom;
    record.peckMm = mode == 730 || mode == 830 ? m_state.cycleQ : 0;
    record.dwellSeconds = mode == 820 || mode == 840 || mode == 860 || mode == 890 ? m_state.cycleP : 0;
    record.feedMmPerMin = feed;
    record.returnToClearance = !m_state.retractToR;
    if (const std::optional<std::string> why = toolpath::tooManyPecks(record))
        m_reporter.error(m_line, block.has('Q') ? block.col('Q') : 0, name + ": " + *why);
    for (int i = 0; i < repeats; ++i) {
        if (!m_state.absolute) {
            x += dx;
            y += dy;
        }
        record.holes.assign(1, Vec3{x, y, r});
        source();
        m_sink.cycle(record);
    }
    if (repeats > 0) {
        m_state.position = Vec3{x, y, clear};
        m_state.known.give(AxisMask{});  // Z was known, X and Y known or given (checkKnown)
    }
    m_state.cycleSequence = true;
}

void Machine::referenceReturn(const Block& block, int code)
{
    checkAxes(block);
    const bool any = block.has('X') || block.has('Y') || block.has('Z');
    AxisMask given;
    if (!checkKnown(block, 0, given))
        return;
    if (any) {
        const Vec3 via = target(block);
        m_state.known.give(given);
        source();
        m_sink.rapid(Rapid{via, m_state.known.mask()});
        m_state.position = via;
    }
    // The stored position (#5161.. or #5181..) is in machine coordinates, like G53's: where it lies
    // in the work offset's frame is the control's knowledge, so the axes going there become unknown.
    m_reporter.warning(m_line, 0,
                       std::string(code == 280 ? "G28" : "G30") + " goes to the stored position #" +
                           std::to_string(code == 280 ? 5161 : 5181) +
                           ".. in machine coordinates: not traced; the axes it moves are unknown until a block "
                           "gives them");
    source();
    m_state.known.lose(any ? axisWords(block) : AxisMask{}, m_sink);
    m_state.cycleSequence = false;
}

}  // namespace camwb::nc::iso
