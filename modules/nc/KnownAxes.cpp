#include "nc/KnownAxes.h"

#include "kinematics/Machine.h"
#include "nc/Interpreter.h"

namespace camwb::nc {

KnownAxes knownAtStart(const InterpretOptions& options)
{
    KnownAxes known;
    if (options.start)
        known.give(toolpath::AxisMask{});
    else if (options.machine && !options.machine->axes.empty() && !options.machine->axis("Y"))
        known.give(axisBit(1));
    return known;
}

std::string unknownAxisMessage(int axis, std::string_view need)
{
    const char letter = static_cast<char>('X' + axis);
    std::string message(1, letter);
    message += " is unknown here: no absolute ";
    message += letter;
    message += " has been programmed yet, and ";
    message.append(need);
    message += " needs it; nothing moves";
    return message;
}

}  // namespace camwb::nc
