#include "toolpath/RecordNames.h"

#include <array>
#include <iterator>

namespace camwb::toolpath {

const char* name(CutterCompSide side)
{
    switch (side) {
    case CutterCompSide::Left:
        return "left";
    case CutterCompSide::Right:
        return "right";
    case CutterCompSide::Off:
        break;
    }
    return "off";
}

const char* name(CoolantMode mode)
{
    switch (mode) {
    case CoolantMode::Flood:
        return "flood";
    case CoolantMode::Mist:
        return "mist";
    case CoolantMode::ThroughTool:
        return "throughTool";
    case CoolantMode::Off:
        break;
    }
    return "off";
}

const char* name(FeedMode mode)
{
    switch (mode) {
    case FeedMode::PerRevolution:
        return "perRevolution";
    case FeedMode::InverseTime:
        return "inverseTime";
    case FeedMode::PerMinute:
        break;
    }
    return "perMinute";
}

const char* name(CycleKind kind)
{
    switch (kind) {
    case CycleKind::DrillDwell:
        return "drillDwell";
    case CycleKind::Peck:
        return "peck";
    case CycleKind::ChipBreak:
        return "chipBreak";
    case CycleKind::Tap:
        return "tap";
    case CycleKind::Bore:
        return "bore";
    case CycleKind::Drill:
        break;
    }
    return "drill";
}

const char* name(FeedKind kind)
{
    switch (kind) {
    case FeedKind::Cutting:
        return "cutting";
    case FeedKind::Plunge:
        return "plunge";
    case FeedKind::Entry:
        return "entry";
    case FeedKind::Exit:
        return "exit";
    case FeedKind::Finishing:
        return "finishing";
    case FeedKind::Unspecified:
        break;
    }
    return "";
}

std::optional<FeedKind> feedKindNamed(std::string_view word)
{
    static constexpr std::array kinds{FeedKind::Cutting, FeedKind::Plunge, FeedKind::Entry, FeedKind::Exit,
                                      FeedKind::Finishing};
    for (FeedKind kind : kinds)
        if (word == name(kind))
            return kind;
    return std::nullopt;
}

std::string axisNames(AxisMask axes, char first)
{
    std::string out;
    for (int axis = 0; axis < 3; ++axis) {
        if (!axes.has(axis))
            continue;
        if (!out.empty())
            out += ' ';
        out += static_cast<char>(first + axis);
    }
    return out;
}

const char* recordName(const Record& record)
{
    static constexpr const char* names[] = {
        "Rapid",      "Linear",      "Arc",         "ToolChange",   "Spindle",    "Coolant", "FeedModeChange",
        "WorkOffset", "Dwell",       "Cycle",       "ToolAxisMove", "CutterComp", "Comment", "SectionBegin",
        "SectionEnd", "ProgramStop", "PassThrough", "WorkingPlane", "UnknownAxes"};
    static_assert(std::size(names) == std::variant_size_v<Record>, "a name for every CL record");
    return names[record.index()];
}

}  // namespace camwb::toolpath
