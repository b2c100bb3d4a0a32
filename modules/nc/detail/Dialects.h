// The per-dialect interpreters behind nc::interpret (each in its own folder).
#pragma once

#include "nc/Interpreter.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);
InterpretResult interpretHeidenhain(std::string_view text, const InterpretOptions& options,
                                    toolpath::MachineSink& sink);
InterpretResult interpretIso(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);

}  // namespace camwb::nc::detail
