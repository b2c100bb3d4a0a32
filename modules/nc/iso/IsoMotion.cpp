// Straight moves of the ISO machine: G0 and G1 targets from the axis words (units, absolute or
// incremental), feeds and their checks. Rotary and UVW axes are read but not traced.
#include "nc/iso/IsoMachine.h"

#include <cmath>

namespace camwb::nc::iso {

using namespace camwb::toolpath;

namespace {

constexpr double kTravelLimitMm = 1e6;  // a kilometre of travel is a typing error, not a program

}  // namespace

AxisMask axisWords(const Block& block)
{
    return AxisMask{static_cast<unsigned char>((block.has('X') ? AxisMask::kX : 0) |
                                               (block.has('Y') ? AxisMask::kY : 0) |
                                               (block.has('Z') ? AxisMask::kZ : 0))};
}

Vec3 Machine::target(const Block& block) const
{
    Vec3 to = m_state.position;
    const bool absolute = m_state.absolute;
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

bool Machine::needKnown(const Block& block, AxisMask before, AxisMask after, AxisMask given, const char* need)
{
    const int axis = m_state.known.missing(before, after, given);
    if (axis < 0)
        return true;
    error(block, static_cast<char>('X' + axis), unknownAxisMessage(axis, need));
    return false;
}

// The axes of a block that may move: an incremental word on an unknown axis, an arc, a cycle or
// compensation from an unknown start are errors; a move gives the axes written in absolute terms.
bool Machine::checkKnown(const Block& block, int mode, AxisMask& given)
{
    const AxisMask words = axisWords(block);
    const bool absolute = m_state.absolute;
    given = absolute ? words : kNoAxes;
    if (!absolute && !needKnown(block, words, kNoAxes, kNoAxes, "an incremental move"))
        return false;
    if (mode == 20 || mode == 30)
        return needKnown(block, planeMask(m_state.plane / 10), AxisMask{}, given, "the arc");
    if (mode != 0 && mode != 10)
        return needKnown(block, axisBit(2), kXyAxes, given, "the canned cycle");
    return m_state.comp == CutterCompSide::Off || needKnown(block, kXyAxes, AxisMask{}, given, "cutter compensation");
}

double Machine::feedFor(const Block& block, const char* what)
{
    if (m_state.feedMode == FeedMode::InverseTime && !block.has('F'))
        m_reporter.error(m_line, 0, std::string(what) + " under G93 (inverse time) needs an F word in the block");
    else if (m_state.feed <= 0)
        m_reporter.error(m_line, 0, std::string(what) + " with feed rate 0: set F first");
    return m_state.feed;
}

// Most blocks of a posted program are axis words, centre words and F with at most a G0..G3:
// they skip the modal-group bookkeeping of execute(). False: the block needs the full path.
bool Machine::executeMotionOnly(const Block& block)
{
    constexpr std::uint32_t kMotionLetters = (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A')) |
                                             (1u << ('I' - 'A')) | (1u << ('J' - 'A')) | (1u << ('K' - 'A')) |
                                             (1u << ('F' - 'A'));
    constexpr std::uint32_t kXyz = (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A'));
    if (block.mCount != 0 || block.gCount > 1 || (block.present & ~kMotionLetters) || !block.comments.empty())
        return false;
    const int g = block.gCount ? block.g[0].code10 : -1;
    if (g != -1 && g != 0 && g != 10 && g != 20 && g != 30)
        return false;
    const int mode = g == -1 ? m_state.motion : g;
    constexpr std::uint32_t kCentre = (1u << ('I' - 'A')) | (1u << ('J' - 'A')) | (1u << ('K' - 'A'));
    const bool moves = (block.present & kXyz) || ((mode == 20 || mode == 30) && (block.present & kCentre));
    if ((block.has('F') && block.get('F') < 0) || (moves && mode == 800))
        return false;  // the full path says what is wrong
    if (block.has('F'))
        m_state.feed = m_state.feedMode == FeedMode::InverseTime ? block.get('F') : block.get('F') * m_state.unit;
    if (g != -1)
        m_state.motion = m_state.lastMotion = g;
    if (moves)
        motion(block, mode);
    return true;
}

void Machine::motion(const Block& block, int mode)
{
    checkAxes(block);
    constexpr std::uint32_t kXyz = (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A'));
    if ((mode == 0 || mode == 10) && !(block.present & kXyz))
        return;  // rotary or UVW words only: nothing moves in the three-axis trace
    AxisMask given;
    if (!checkKnown(block, mode, given))
        return;
    const Vec3 to = target(block);
    if (!(std::abs(to.x) < kTravelLimitMm && std::abs(to.y) < kTravelLimitMm && std::abs(to.z) < kTravelLimitMm)) {
        m_reporter.error(m_line, 0, "target out of range (more than 1000 m from the origin)");
        return;
    }
    if (mode == 0 || mode == 10 || mode == 20 || mode == 30)
        m_state.cycleSequence = false;
    switch (mode) {
    case 0:
        m_state.known.give(given);
        source();
        m_sink.rapid(Rapid{to, m_state.known.mask()});
        m_state.position = to;
        return;
    case 10: {
        const double feed = feedFor(block, "G1");
        m_state.known.give(given);
        source();
        m_sink.linear(Linear{to, feed, m_state.known.mask()});
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

// G53 X.. Y.. Z..: machine coordinates, whose place in the work offset's frame the trace does not
// know (the offsets are the control's: LinuxCNC's var file, a Fanuc's offset page). The axes the
// block gives are unknown after it until a block gives them again; nothing is drawn meanwhile, as
// SINUMERIK's SUPA is read. A machine's top of Z taken as work Z0 would draw a rapid into the part.
void Machine::moveInMachineCoordinates(const Block& block, int column)
{
    checkAxes(block);
    m_state.cycleSequence = false;
    if (!m_warnedG53) {
        m_warnedG53 = true;
        m_reporter.warning(m_line, column,
                           "G53: a move in machine coordinates is not traced (the work offset is the control's); "
                           "the axes it gives are unknown until a block gives them");
    }
    source();
    m_state.known.lose(axisWords(block), m_sink);
}

}  // namespace camwb::nc::iso
