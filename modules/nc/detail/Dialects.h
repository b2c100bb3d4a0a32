// The per-dialect interpreters behind nc::interpret (each in its own folder), and the CL import
// that stands in for them when InterpretOptions::clFormat is set (ClProgram.cpp).
#pragma once

#include "nc/Interpreter.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);
InterpretResult interpretHeidenhain(std::string_view text, const InterpretOptions& options,
                                    toolpath::MachineSink& sink);
InterpretResult interpretIso(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);
InterpretResult importCl(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);

}  // namespace camwb::nc::detail
