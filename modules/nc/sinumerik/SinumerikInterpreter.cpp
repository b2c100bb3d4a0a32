// Entry of the SINUMERIK 828D/840D interpreter (nc::interpret with Dialect::Sinumerik).
#include "nc/detail/Dialects.h"
#include "nc/sinumerik/Machine.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    sinumerik::Machine machine(options, sink, result);
    machine.run(text);
    return result;
}

}  // namespace camwb::nc::detail
