// Placeholder until the sinumerik interpreter lands: says so instead of tracing nothing.
#include "nc/detail/Dialects.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view, const InterpretOptions& options, toolpath::MachineSink&)
{
    InterpretResult result;
    result.files.push_back(options.fileName);
    result.diagnostics.push_back({Severity::Error, options.fileName, 0, 0, "the sinumerik interpreter is not built yet"});
    return result;
}

}  // namespace camwb::nc::detail
