#include "nc/iso/IsoMachine.h"

#include <array>
#include <cmath>
#include <string>

namespace camwb::nc::iso {

using namespace camwb::toolpath;

namespace {

// Modal groups of the G codes LinuxCNC 2.9 knows (x10). Group -2: known, but its motion is not
// traced (splines, threading, probing, back boring); -3: G70/G71 inch/mm of Fanuc-style controls.
struct GroupOf {
    int code10;
    int group;
};
constexpr GroupOf kGroups[] = {
    {40, 0},   {100, 0},  {280, 0},  {281, 0},  {300, 0},  {301, 0},  {530, 0},  {920, 0},  {921, 0},
    {922, 0},  {923, 0},  {0, 1},    {10, 1},   {20, 1},   {30, 1},   {730, 1},  {800, 1},  {810, 1},
    {820, 1},  {830, 1},  {840, 1},  {850, 1},  {860, 1},  {890, 1},  {170, 2},  {180, 2},  {190, 2},
    {900, 3},  {910, 3},  {901, 4},  {911, 4},  {930, 5},  {940, 5},  {950, 5},  {200, 6},  {210, 6},
    {400, 7},  {410, 7},  {420, 7},  {430, 8},  {431, 8},  {432, 8},  {490, 8},  {980, 10}, {990, 10},
    {540, 12}, {550, 12}, {560, 12}, {570, 12}, {580, 12}, {590, 12}, {591, 12}, {592, 12}, {593, 12},
    {610, 13}, {611, 13}, {640, 13}, {960, 14}, {970, 14}, {70, 15},  {80, 15},  {50, -2},  {51, -2},
    {330, -2}, {331, -2}, {381, -2}, {382, -2}, {383, -2}, {384, -2}, {385, -2}, {740, -2}, {760, -2},
    {870, -2}, {880, -2}, {171, -2}, {181, -2}, {191, -2}, {411, 7},  {421, 7},  {700, -3}, {710, -3},
};

constexpr auto kGroupTable = [] {
    std::array<signed char, 1000> table{};
    for (signed char& group : table)
        group = -1;
    for (const GroupOf& g : kGroups)
        table[static_cast<std::size_t>(g.code10)] = static_cast<signed char>(g.group);
    return table;
}();

// Modal group of a G code (x10); -1 = unknown.
int gGroup(int code) { return code >= 0 && code < 1000 ? kGroupTable[static_cast<std::size_t>(code)] : -1; }

std::string gName(int code10)
{
    return "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
}

// T, M61 Q and the D of G41/G42: a whole number >= 0 that fits an int (tested before any cast:
// converting a double beyond int's range is undefined).
bool isToolNumber(double v) { return v >= 0 && v == std::floor(v) && v <= 1e9; }

}  // namespace

void Machine::error(const Block& block, char letter, std::string message)
{
    m_reporter.error(m_line, letter && block.has(letter) ? block.col(letter) : 0, std::move(message));
}

bool Machine::classify(const Block& block, Groups& groups)
{
    for (int i = 0; i < 16; ++i)
        groups.g[i] = -1;
    for (int i = 0; i < block.gCount; ++i) {
        const Code& c = block.g[i];
        const int group = gGroup(c.code10);
        if (group == -1) {
            // Codes of other ISO controls (Fanuc G5.1, Hurco G5.3...) rarely move anything: say so, go on.
            m_reporter.warning(m_line, c.column, "unknown G code " + gName(c.code10) + " ignored");
            continue;
        }
        if (group == -3) {
            m_reporter.warning(m_line, c.column,
                               gName(c.code10) + " read as " + (c.code10 == 700 ? "inch" : "millimetre") +
                                   " units (Fanuc/Hurco style; LinuxCNC writes " + (c.code10 == 700 ? "G20" : "G21") +
                                   ")");
            if (groups.g[6] != -1) {
                m_reporter.error(m_line, c.column, "two G codes of the same modal group: units");
                return false;
            }
            groups.g[6] = c.code10 == 700 ? 200 : 210;
            groups.gColumn[6] = c.column;
            continue;
        }
        if (group == -2) {
            m_reporter.error(m_line, c.column, gName(c.code10) + " is not supported by this interpreter");
            return false;
        }
        if (groups.g[group] != -1) {
            m_reporter.error(m_line, c.column,
                             "two G codes of the same modal group: " + gName(groups.g[group]) + " and " +
                                 gName(c.code10));
            return false;
        }
        groups.g[group] = c.code10;
        groups.gColumn[group] = c.column;
    }
    for (int i = 0; i < block.mCount; ++i) {
        const Code& c = block.m[i];
        const int m = c.code10 / 10;
        int* slot = nullptr;
        switch (m) {
        case 0:
        case 1:
        case 2:
        case 30:
        case 60:
            slot = &groups.stop;
            groups.stopColumn = c.column;
            break;
        case 6:
        case 61:
            slot = &groups.toolChange;
            break;
        case 3:
        case 4:
        case 5:
            slot = &groups.spindle;
            break;
        case 7:
        case 8:
        case 9:
            // M7 and M8 may share a block (both coolants on); M9 with either is a conflict.
            for (int k = 0; k < groups.coolantCount; ++k) {
                if (groups.coolant[k] == m || groups.coolant[k] == 9 || m == 9) {
                    m_reporter.error(m_line, c.column, "two M codes of the same modal group (coolant)");
                    return false;
                }
            }
            groups.coolant[groups.coolantCount++] = m;
            continue;
        case 48:
        case 49:
        case 50:
        case 51:
        case 52:
        case 53:
        case 62:
        case 63:
        case 64:
        case 65:
        case 66:
        case 67:
        case 68:
        case 70:
        case 71:
        case 72:
        case 73:
            continue;  // overrides, I/O and modal state: no motion to trace
        default:
            if (m == 128 || m == 129) {
                m_reporter.warning(m_line, c.column,
                                   "M" + std::to_string(m) + " (five-axis tool centre point) is not traced");
                continue;
            }
            if (m >= 100 && m <= 199) {
                m_reporter.warning(m_line, c.column, "user M code M" + std::to_string(m) + " is not traced");
                continue;
            }
            // Another control's M code (M13, M25...): it switches something, it moves nothing.
            m_reporter.warning(m_line, c.column, "unknown M code M" + std::to_string(m) + " ignored");
            continue;
        }
        if (*slot != -1) {
            m_reporter.error(m_line, c.column,
                             "two M codes of the same modal group: M" + std::to_string(*slot) + " and M" +
                                 std::to_string(m));
            return false;
        }
        *slot = m;
    }
    return true;
}

void Machine::setSpindle(double rpm, int direction)
{
    const bool running = m_state.spindle != 0;
    if (direction == 0) {
        m_state.spindle = 0;
        if (running) {
            source();
            m_sink.spindle(Spindle{0, true, 0});
        }
        return;
    }
    if (running && direction == m_state.spindle && rpm == m_state.runningRpm)
        return;
    m_state.spindle = direction;
    m_state.runningRpm = rpm;
    source();
    m_sink.spindle(Spindle{rpm, direction > 0, 0});
}

void Machine::setCoolant(bool mist, bool flood)
{
    if (mist == m_state.mist && flood == m_state.flood)
        return;
    source();
    if (!mist && !flood) {
        m_sink.coolant(Coolant{CoolantMode::Off});
    } else {
        if (mist && !m_state.mist)
            m_sink.coolant(Coolant{CoolantMode::Mist});
        if (flood && !m_state.flood)
            m_sink.coolant(Coolant{CoolantMode::Flood});
    }
    m_state.mist = mist;
    m_state.flood = flood;
}

BlockOutcome Machine::execute(const Block& block, int line, int fileIndex)
{
    m_line = line;
    m_file = fileIndex;
    if (executeMotionOnly(block))
        return BlockOutcome::Continue;
    for (const std::string_view text : block.comments) {
        source();
        m_sink.comment(Comment{std::string(text)});
    }
    Groups groups;
    if (!classify(block, groups))
        return BlockOutcome::Continue;
    // LinuxCNC's order of execution; a step that finds an error reports it and ends the block.
    applyFeedMode(groups);
    applyUnits(groups);  // before F: the block's F is in the block's units
    if (!applyFeedRate(block) || !applySpindleSpeed(block, groups) || !applyToolSelection(block) ||
        !applyToolChange(block, groups))
        return BlockOutcome::Continue;
    applySpindle(groups);
    applyCoolant(groups);
    if (!applyDwell(block, groups))
        return BlockOutcome::Continue;
    applyPlane(groups);
    applyCompensation(block, groups);
    applyWorkOffset(groups);
    applyDistanceModes(groups);
    applyRetractMode(groups);
    if (!applyMotion(block, groups))
        return BlockOutcome::Continue;
    return applyStop(groups);
}

void Machine::applyFeedMode(const Groups& groups)
{
    const int mode5 = groups.g[5];
    if (mode5 == -1)
        return;
    const FeedMode mode = mode5 == 930   ? FeedMode::InverseTime
                          : mode5 == 950 ? FeedMode::PerRevolution
                                         : FeedMode::PerMinute;
    if (mode != m_state.feedMode) {
        m_state.feedMode = mode;
        source();
        m_sink.feedMode(FeedModeChange{mode});
    }
    m_state.feed = 0;  // LinuxCNC wants a new F after a feed mode change
}

void Machine::applyUnits(const Groups& groups)
{
    if (groups.g[6] != -1)
        m_state.unit = groups.g[6] == 200 ? 25.4 : 1.0;
}

bool Machine::applyFeedRate(const Block& block)
{
    if (!block.has('F'))
        return true;
    const double f = block.get('F');
    if (f < 0) {
        error(block, 'F', "negative feed rate");
        return false;
    }
    m_state.feed = m_state.feedMode == FeedMode::InverseTime ? f : f * m_state.unit;
    return true;
}

bool Machine::applySpindleSpeed(const Block& block, const Groups& groups)
{
    if (!block.has('S'))
        return true;
    const double s = block.get('S');
    if (s < 0) {
        error(block, 'S', "negative spindle speed");
        return false;
    }
    if (m_state.spindle != 0 && groups.spindle == -1)
        setSpindle(s, m_state.spindle);
    m_state.rpm = s;
    return true;
}

bool Machine::applyToolSelection(const Block& block)
{
    if (!block.has('T'))
        return true;
    const double t = block.get('T');
    if (!isToolNumber(t)) {
        error(block, 'T', "tool number must be a whole number >= 0");
        return false;
    }
    m_state.selectedTool = static_cast<int>(t);
    return true;
}

bool Machine::applyToolChange(const Block& block, const Groups& groups)
{
    if (groups.toolChange != 6 && groups.toolChange != 61)
        return true;
    if (groups.toolChange == 61) {
        if (!block.has('Q')) {
            m_reporter.error(m_line, 0, "M61 needs Q with the tool number");
            return false;
        }
        const double q = block.get('Q');
        if (!isToolNumber(q)) {
            error(block, 'Q', "M61 needs Q to be a tool number (a whole number >= 0)");
            return false;
        }
        m_state.selectedTool = static_cast<int>(q);
    } else if (m_state.spindle != 0) {
        setSpindle(0, 0);  // M6 stops the spindle (LinuxCNC's manual tool change)
    }
    m_state.tool = m_state.selectedTool;
    Tool tool;
    tool.number = m_state.tool;
    source();
    m_sink.toolChange(ToolChange{tool});
    return true;
}

void Machine::applySpindle(const Groups& groups)
{
    if (groups.spindle == 3 || groups.spindle == 4)
        setSpindle(m_state.rpm, groups.spindle == 3 ? 1 : -1);
    else if (groups.spindle == 5)
        setSpindle(0, 0);
}

void Machine::applyCoolant(const Groups& groups)
{
    if (groups.coolantCount == 0)
        return;
    bool mist = m_state.mist, flood = m_state.flood;
    for (int k = 0; k < groups.coolantCount; ++k) {
        if (groups.coolant[k] == 9)
            mist = flood = false;
        else if (groups.coolant[k] == 7)
            mist = true;
        else
            flood = true;
    }
    setCoolant(mist, flood);
}

bool Machine::applyDwell(const Block& block, const Groups& groups)
{
    if (groups.g[0] != 40)
        return true;
    if (!block.has('P') || block.get('P') < 0) {
        m_reporter.error(m_line, groups.gColumn[0], "G4 needs P with the dwell in seconds (P >= 0)");
        return false;
    }
    source();
    m_sink.dwell(Dwell{block.get('P')});
    return true;
}

void Machine::applyPlane(const Groups& groups)
{
    if (groups.g[2] != -1)
        m_state.plane = groups.g[2];
}

void Machine::applyCompensation(const Block& block, const Groups& groups)
{
    const int code = groups.g[7];
    if (code == -1)
        return;
    const CutterCompSide side = code == 410 || code == 411   ? CutterCompSide::Left
                                : code == 420 || code == 421 ? CutterCompSide::Right
                                                             : CutterCompSide::Off;
    if (side != CutterCompSide::Off && m_state.comp != CutterCompSide::Off) {
        m_reporter.error(m_line, groups.gColumn[7], "cutter compensation is already on: G40 first");
    } else if (side != m_state.comp) {
        if (side != CutterCompSide::Off)
            setCompensationRadius(block, code);
        m_state.comp = side;
        m_state.compCode = code;
        source();
        m_sink.cutterComp(CutterComp{side});
    }
}

// LinuxCNC: G41.1/G42.1 D<diameter>; G41/G42 D<tool> take that tool's diameter from the tool
// table, without D the diameter of the tool in the spindle.
void Machine::setCompensationRadius(const Block& block, int code)
{
    if (code == 411 || code == 421) {
        if (!block.has('D') || block.get('D') < 0) {
            error(block, 'D', gName(code) + " needs D with the tool diameter (D >= 0)");
            m_compensation.setRadius(std::nullopt, "the tool (no D)");
            return;
        }
        m_compensation.setRadius(block.get('D') * m_state.unit / 2, gName(code) + " D");
        return;
    }
    int tool = m_state.tool;
    if (block.has('D')) {
        const double d = block.get('D');
        if (!isToolNumber(d)) {
            error(block, 'D', gName(code) + " needs D to be a tool number (a whole number >= 0)");
            m_compensation.setRadius(std::nullopt, "the tool");
            return;
        }
        tool = static_cast<int>(d);
    }
    const std::string what = "tool " + std::to_string(tool);
    m_compensation.setRadius(m_toolTable ? m_toolTable->radiusOf(tool) : std::nullopt, what);
}

void Machine::applyWorkOffset(const Groups& groups)
{
    const int code = groups.g[12];
    if (code == -1)
        return;
    const int index = code >= 591 ? 6 + (code - 590) : (code - 540) / 10 + 1;
    if (m_state.comp != CutterCompSide::Off) {
        m_reporter.error(m_line, groups.gColumn[12], "work offset change with cutter compensation on");
    } else if (index != m_state.workOffset) {
        m_state.workOffset = index;
        source();
        m_sink.workOffset(WorkOffset{index});
    }
}

void Machine::applyDistanceModes(const Groups& groups)
{
    if (groups.g[3] != -1)
        m_state.absolute = groups.g[3] == 900;
    if (groups.g[4] != -1)
        m_state.arcAbsolute = groups.g[4] == 901;
}

void Machine::applyRetractMode(const Groups& groups)
{
    if (groups.g[10] != -1)
        m_state.retractToR = groups.g[10] == 990;
    if (groups.g[14] == 960)
        m_reporter.warning(m_line, groups.gColumn[14], "G96 constant surface speed is traced as a fixed speed");
}

// Group 0 codes that take the axis words (G28/G30, G10/G92...), then the motion mode.
bool Machine::applyMotion(const Block& block, const Groups& groups)
{
    const int* g = groups.g;
    const bool axisWords = (block.present & ((1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A')) |
                                             (1u << ('A' - 'A')) | (1u << ('B' - 'A')) | (1u << ('C' - 'A')) |
                                             (1u << ('U' - 'A')) | (1u << ('V' - 'A')) | (1u << ('W' - 'A')))) != 0;
    bool axesTaken = false;
    if (g[0] == 280 || g[0] == 300) {
        referenceReturn(block, g[0]);
        axesTaken = true;
    } else if (g[0] == 100 || g[0] == 920 || g[0] == 921 || g[0] == 922 || g[0] == 923 || g[0] == 281 || g[0] == 301) {
        m_reporter.warning(m_line, groups.gColumn[0],
                           gName(g[0]) + " (offsets and stored positions) is not traced: coordinates stay in the "
                                         "work offset's frame");
        axesTaken = true;
    }
    if (g[1] == 800 && axisWords && !axesTaken) {
        m_reporter.error(m_line, groups.gColumn[1], "axis words with G80 and no other motion");
        return false;
    }
    if (g[1] != -1)
        m_state.motion = g[1];
    if (g[1] == 0 || g[1] == 10 || g[1] == 20 || g[1] == 30)
        m_state.lastMotion = g[1];
    if (g[1] == 800)
        m_state.cycleSequence = false;
    if (axisWords && !axesTaken) {
        int mode = m_state.motion;
        if (mode == 800) {
            if (m_state.lastMotion < 0) {
                m_reporter.error(m_line, 0, "axis words without a motion mode (G80 is active): add G0, G1, G2 or G3");
                return false;
            }
            // Fanuc keeps G0/G1 through G80 (cycles are a group of their own there); LinuxCNC refuses.
            mode = m_state.lastMotion;
            if (!m_warnedG80) {
                m_warnedG80 = true;
                m_reporter.warning(m_line, 0,
                                   "axis words under G80: moving with " + gName(mode) +
                                       " as Fanuc-style controls do (LinuxCNC wants the G word again)");
            }
        }
        if (g[0] == 530)
            moveInMachineCoordinates(block, groups.gColumn[0]);
        else
            motion(block, mode);
    } else if (g[1] != -1 && g[1] != 0 && g[1] != 10 && g[1] != 20 && g[1] != 30 && g[1] != 800 && !axesTaken) {
        m_reporter.error(m_line, groups.gColumn[1], gName(g[1]) + " without X, Y or Z: no hole to drill");
        return false;
    } else if ((m_state.motion == 20 || m_state.motion == 30) && !axesTaken &&
               (block.has('I') || block.has('J') || block.has('K') || block.has('R'))) {
        motion(block, m_state.motion);  // a full circle needs no axis word
    }
    return true;
}

BlockOutcome Machine::applyStop(const Groups& groups)
{
    if (groups.stop == 0 || groups.stop == 1 || groups.stop == 60) {
        source();
        m_sink.programStop(ProgramStop{groups.stop == 1});
    } else if (groups.stop == 2 || groups.stop == 30) {
        programEnd();
        return BlockOutcome::ProgramEnd;
    }
    return BlockOutcome::Continue;
}

void Machine::reportModal(const BlockObserver& observer) const
{
    static const char* const kOffsets[] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};
    BlockModal m;
    m.file = m_file;
    m.line = m_line;
    m.distance = m_state.absolute ? BlockModal::Distance::Absolute : BlockModal::Distance::Incremental;
    m.distanceWord = m_state.absolute ? "G90" : "G91";
    m.inch = m_state.unit != 1.0;
    m.unitsWord = m.inch ? "G20" : "G21";
    m.plane = m_state.plane / 10;
    m.planeWord = m_state.plane == 180 ? "G18" : m_state.plane == 190 ? "G19" : "G17";
    m.compensation = m_state.comp;
    m.compensationWord = m_state.comp == CutterCompSide::Off    ? "G40"
                         : m_state.compCode == 411              ? "G41.1"
                         : m_state.compCode == 421              ? "G42.1"
                         : m_state.comp == CutterCompSide::Left ? "G41"
                                                                : "G42";
    m.feedMode = m_state.feedMode;
    m.feedModeWord = m_state.feedMode == FeedMode::InverseTime     ? "G93"
                     : m_state.feedMode == FeedMode::PerRevolution ? "G95"
                                                                   : "G94";
    if (m_state.workOffset >= 1 && m_state.workOffset <= 9)
        m.workOffset = kOffsets[m_state.workOffset - 1];
    observer(m);
}

void Machine::programEnd()
{
    // LinuxCNC's M2/M30: spindle and coolant off, G54, G17, G90, G94, G40, G80, G98 ... kept.
    setSpindle(0, 0);
    setCoolant(false, false);
    if (m_state.workOffset != 1) {
        m_state.workOffset = 1;
        source();
        m_sink.workOffset(WorkOffset{1});
    }
    if (m_state.feedMode != FeedMode::PerMinute) {
        m_state.feedMode = FeedMode::PerMinute;
        source();
        m_sink.feedMode(FeedModeChange{FeedMode::PerMinute});
    }
    if (m_state.comp != CutterCompSide::Off) {
        m_state.comp = CutterCompSide::Off;
        source();
        m_sink.cutterComp(CutterComp{CutterCompSide::Off});
    }
    m_state.plane = 170;
    m_state.absolute = true;
    m_state.motion = 10;
}

}  // namespace camwb::nc::iso
