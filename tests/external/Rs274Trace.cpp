#include "Rs274Trace.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <set>

namespace camwb::external {

using namespace toolpath;

namespace {

// Calls that change nothing the CL model describes (units, overrides, blending, resets, ...).
const std::set<std::string_view> kIgnoredCalls = {"USE_LENGTH_UNITS",
                                                  "SET_G92_OFFSET",
                                                  "SET_XY_ROTATION",
                                                  "SET_FEED_REFERENCE",
                                                  "ON_RESET",
                                                  "SELECT_TOOL",
                                                  "START_CHANGE",
                                                  "SET_MOTION_CONTROL_MODE",
                                                  "SET_NAIVECAM_TOLERANCE",
                                                  "DISABLE_FEED_OVERRIDE",
                                                  "ENABLE_FEED_OVERRIDE",
                                                  "DISABLE_SPEED_OVERRIDE",
                                                  "ENABLE_SPEED_OVERRIDE",
                                                  "SET_SPINDLE_MODE",
                                                  "SET_FEED_MODE"};  // the feed mode comes from its comment

struct Call {
    std::string_view name;
    std::string_view args;  // between the parentheses
};

// "   12 N..... NAME(args)" -> name and args.
std::optional<Call> splitCall(std::string_view line)
{
    const std::size_t marker = line.find("N..... ");
    if (marker == std::string_view::npos)
        return std::nullopt;
    std::string_view rest = line.substr(marker + 7);
    const std::size_t open = rest.find('(');
    const std::size_t close = rest.rfind(')');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
        return std::nullopt;
    return Call{rest.substr(0, open), rest.substr(open + 1, close - open - 1)};
}

// Numbers of an argument list; commas and blanks both separate (USE_TOOL_LENGTH_OFFSET mixes them).
std::optional<std::vector<double>> numbers(std::string_view args)
{
    std::vector<double> values;
    std::size_t i = 0;
    while (i < args.size()) {
        if (args[i] == ',' || args[i] == ' ') {
            ++i;
            continue;
        }
        double value = 0;
        const auto [end, error] = std::from_chars(args.data() + i, args.data() + args.size(), value);
        if (error != std::errc())
            return std::nullopt;
        values.push_back(value);
        i = static_cast<std::size_t>(end - args.data());
    }
    return values;
}

// The text of COMMENT("...") and MESSAGE("...").
std::string quoted(std::string_view args)
{
    if (args.size() >= 2 && args.front() == '"' && args.back() == '"')
        args = args.substr(1, args.size() - 2);
    return std::string(args);
}

class TraceReader {
public:
    base::Status read(std::string_view trace);
    Rs274Program take() { return std::move(m_program); }

private:
    base::Status call(const Call& call, int line);
    base::Status motion(std::string_view name, const std::vector<double>& v);
    void spindleState(double rpm, bool clockwise);
    void coolantState();
    void feedModeComment(std::string_view text);

    Rs274Program m_program;
    Vec3 m_position;  // rs274 starts at the origin
    double m_feed = 0;
    std::string m_plane = "XY";
    double m_rpm = 0;
    Spindle m_spindle{0, true};
    bool m_mist = false, m_flood = false;
    CoolantMode m_coolant = CoolantMode::Off;
    FeedMode m_feedMode = FeedMode::PerMinute;
    int m_workOffset = 1;
    bool m_afterToolChange = false;
};

base::Status TraceReader::read(std::string_view trace)
{
    int line = 0;
    std::size_t start = 0;
    while (start < trace.size() && !m_program.programEnd) {
        std::size_t end = trace.find('\n', start);
        if (end == std::string_view::npos)
            end = trace.size();
        const std::string_view text = trace.substr(start, end - start);
        start = end + 1;
        ++line;
        if (text.find_first_not_of(" \t\r") == std::string_view::npos)
            continue;
        const std::optional<Call> parsed = splitCall(text);
        if (!parsed)
            return base::makeError("not a canonical call: " + std::string(text), "rs274 trace", line);
        if (base::Status status = call(*parsed, line); !status.ok())
            return status;
    }
    return {};
}

base::Status TraceReader::call(const Call& c, int line)
{
    auto fail = [&](const std::string& why) {
        return base::makeError(why + ": " + std::string(c.name) + "(" + std::string(c.args) + ")", "rs274 trace", line);
    };
    if (c.name == "COMMENT") {
        const std::string text = quoted(c.args);
        if (text.rfind("interpreter: ", 0) == 0)
            feedModeComment(text);
        else
            m_program.motion.add(Comment{text});
        return {};
    }
    if (c.name == "MESSAGE") {
        m_program.messages.push_back(quoted(c.args));
        return {};
    }
    if (c.name == "SELECT_PLANE") {
        const std::string_view plane = c.args;
        if (plane == "CANON_PLANE_XY")
            m_plane = "XY";
        else if (plane == "CANON_PLANE_XZ")
            m_plane = "ZX";
        else if (plane == "CANON_PLANE_YZ")
            m_plane = "YZ";
        else
            return fail("unknown plane");
        return {};
    }
    if (kIgnoredCalls.count(c.name))
        return {};
    const std::optional<std::vector<double>> v = numbers(c.args);
    if (!v)
        return fail("malformed arguments");
    auto need = [&](std::size_t count) { return v->size() >= count; };

    if (c.name == "STRAIGHT_TRAVERSE" || c.name == "STRAIGHT_FEED" || c.name == "ARC_FEED") {
        if (!need(c.name == "ARC_FEED" ? 6 : 3))
            return fail("too few arguments");
        return motion(c.name, *v);
    }
    if (c.name == "SET_FEED_RATE" && need(1)) {
        m_feed = (*v)[0];
    } else if (c.name == "DWELL" && need(1)) {
        m_program.motion.add(Dwell{(*v)[0]});
    } else if (c.name == "SET_SPINDLE_SPEED" && need(2)) {
        m_rpm = (*v)[1];
    } else if (c.name == "START_SPINDLE_CLOCKWISE" || c.name == "START_SPINDLE_COUNTERCLOCKWISE") {
        spindleState(m_rpm, c.name == "START_SPINDLE_CLOCKWISE");
    } else if (c.name == "STOP_SPINDLE_TURNING") {
        spindleState(0, true);
    } else if (c.name == "MIST_ON" || c.name == "MIST_OFF") {
        m_mist = c.name == "MIST_ON";
        coolantState();
    } else if (c.name == "FLOOD_ON" || c.name == "FLOOD_OFF") {
        m_flood = c.name == "FLOOD_ON";
        coolantState();
    } else if (c.name == "CHANGE_TOOL" && need(1)) {
        m_program.motion.add(ToolChange{Tool{static_cast<int>(std::lround((*v)[0]))}});
        m_afterToolChange = true;
    } else if (c.name == "USE_TOOL_LENGTH_OFFSET" && need(3)) {
        if (m_afterToolChange)
            m_program.toolLengthOffsetsMm.push_back((*v)[2]);
        m_afterToolChange = false;
    } else if (c.name == "SET_G5X_OFFSET" && need(1)) {
        const int index = static_cast<int>(std::lround((*v)[0]));
        if (index != m_workOffset)
            m_program.motion.add(WorkOffset{index});
        m_workOffset = index;
    } else if (c.name == "PROGRAM_STOP" || c.name == "OPTIONAL_PROGRAM_STOP") {
        m_program.motion.add(ProgramStop{c.name == "OPTIONAL_PROGRAM_STOP"});
    } else if (c.name == "PROGRAM_END") {
        m_program.programEnd = true;
    } else {
        return fail("unknown canonical call or too few arguments");
    }
    return {};
}

// ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end, a, b, c): the plane's
// first/second axes are X/Y (XY), Z/X (XZ) and Y/Z (YZ); rotation > 0 is counter-clockwise about
// the plane's positive axis and |rotation| - 1 counts extra full turns.
base::Status TraceReader::motion(std::string_view name, const std::vector<double>& v)
{
    if (name == "STRAIGHT_TRAVERSE") {
        m_position = {v[0], v[1], v[2]};
        m_program.motion.add(Rapid{m_position});
        return {};
    }
    if (name == "STRAIGHT_FEED") {
        m_position = {v[0], v[1], v[2]};
        m_program.motion.add(Linear{m_position, m_feed});
        return {};
    }
    Arc arc;
    const double rotation = v[4];
    if (m_plane == "XY") {
        arc.to = {v[0], v[1], v[5]};
        arc.center = {v[2], v[3], m_position.z};
        arc.normal = {0, 0, 1};
    } else if (m_plane == "ZX") {
        arc.to = {v[1], v[5], v[0]};
        arc.center = {v[3], m_position.y, v[2]};
        arc.normal = {0, 1, 0};
    } else {
        arc.to = {v[5], v[0], v[1]};
        arc.center = {m_position.x, v[2], v[3]};
        arc.normal = {1, 0, 0};
    }
    arc.clockwise = rotation < 0;
    arc.turns = static_cast<int>(std::lround(std::abs(rotation))) - 1;
    arc.feedMmPerMin = m_feed;
    m_position = arc.to;
    m_program.motion.add(arc);
    return {};
}

void TraceReader::spindleState(double rpm, bool clockwise)
{
    const Spindle next{rpm, clockwise};
    const bool same =
        (next.rpm == 0 && m_spindle.rpm == 0) || (next.rpm == m_spindle.rpm && next.clockwise == m_spindle.clockwise);
    if (!same)
        m_program.motion.add(next);
    m_spindle = next;
}

void TraceReader::coolantState()
{
    // Both on is no CL mode; it shows as flood so that a missing M9 between M7 and M8 is seen.
    const CoolantMode mode = m_flood ? CoolantMode::Flood : m_mist ? CoolantMode::Mist : CoolantMode::Off;
    if (mode != m_coolant || (m_flood && m_mist))
        m_program.motion.add(Coolant{mode});
    m_coolant = mode;
}

void TraceReader::feedModeComment(std::string_view text)
{
    std::optional<FeedMode> mode;
    if (text == "interpreter: feed mode set to units per minute")
        mode = FeedMode::PerMinute;
    else if (text == "interpreter: feed mode set to units per revolution")
        mode = FeedMode::PerRevolution;
    else if (text == "interpreter: feed mode set to inverse time")
        mode = FeedMode::InverseTime;
    if (mode && *mode != m_feedMode)
        m_program.motion.add(FeedModeChange{*mode});
    if (mode)
        m_feedMode = *mode;
}

}  // namespace

base::Result<Rs274Program> readRs274Trace(std::string_view trace)
{
    TraceReader reader;
    if (base::Status status = reader.read(trace); !status.ok())
        return status.error();
    return reader.take();
}

}  // namespace camwb::external
