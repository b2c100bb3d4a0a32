#include "nc/KnownAxes.h"

namespace camwb::nc {

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
