// Straight moves of the ISO machine: G0 and G1 targets from the axis words (units, absolute or
// incremental), feeds and their checks. Rotary and UVW axes are read but not traced.
#include "nc/iso/IsoMachine.h"

#include <cmath>

namespace camwb::nc::iso {

using namespace camwb::toolpath;

namespace {

constexpr double kTravelLimitMm = 1e6;  // a kilometre of travel is a typing error, not a program

}  // namespace

Vec3 Machine::target(const Block& block, bool machineCoordinates) const
{
    Vec3 to = m_state.position;
    const bool absolute = m_state.absolute || machineCoordinates;
    const double unit = m_state.unit;
    if (block.has('X'))
        to.x = absolute ? block.get('X') * unit : to.x + block.get('X') * unit;
    if (block.has('Y'))
        to.y = absolute ? block.get('Y') * unit : to.y + block.get('Y') * unit;
    if (block.has('Z'))
        to.z = absolute ? block.get('Z') * unit : to.z + block.get('Z') * unit;
    return to;
}

void Machine::checkAxes(const Block& block)
{
    constexpr std::uint32_t kOther = (1u << ('A' - 'A')) | (1u << ('B' - 'A')) | (1u << ('C' - 'A')) |
                                     (1u << ('U' - 'A')) | (1u << ('V' - 'A')) | (1u << ('W' - 'A'));
    if ((block.present & kOther) && !m_warnedRotary) {
        m_warnedRotary = true;
        int column = 0;
        for (const char letter : {'A', 'B', 'C', 'U', 'V', 'W'})
            if (block.has(letter) && (column == 0 || block.col(letter) < column))
                column = block.col(letter);
        m_reporter.warning(m_line, column,
                           "A, B, C, U, V and W words are not traced: a three-axis trace of a five-axis program");
    }
}

double Machine::feedFor(const Block& block, const char* what)
{
    if (m_state.feedMode == FeedMode::InverseTime && !block.has('F'))
        m_reporter.error(m_line, 0, std::string(what) + " under G93 (inverse time) needs an F word in the block");
    else if (m_state.feed <= 0)
        m_reporter.error(m_line, 0, std::string(what) + " with feed rate 0: set F first");
    return m_state.feed;
}

void Machine::motion(const Block& block, int mode, const Groups& groups)
{
    checkAxes(block);
    constexpr std::uint32_t kXyz = (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A'));
    if ((mode == 0 || mode == 10) && !(block.present & kXyz))
        return;  // rotary or UVW words only: nothing moves in the three-axis trace
    const Vec3 to = target(block, groups.g[0] == 530);
    if (!(std::abs(to.x) < kTravelLimitMm && std::abs(to.y) < kTravelLimitMm && std::abs(to.z) < kTravelLimitMm)) {
        m_reporter.error(m_line, 0, "target out of range (more than 1000 m from the origin)");
        return;
    }
    if (mode == 0 || mode == 10 || mode == 20 || mode == 30)
        m_state.cycleSequence = false;
    switch (mode) {
    case 0:
        source();
        m_sink.rapid(Rapid{to});
        m_state.position = to;
        return;
    case 10: {
        const double feed = feedFor(block, "G1");
        source();
        m_sink.linear(Linear{to, feed});
        m_state.position = to;
        return;
    }
    case 20:
    case 30:
        arc(block, mode == 20, to);
        return;
    default:
        if (m_state.comp != CutterCompSide::Off) {
            m_reporter.error(m_line, 0, "canned cycle with cutter compensation on (LinuxCNC refuses it)");
            return;
        }
        cycle(block, mode);
        return;
    }
}

}  // namespace camwb::nc::iso
