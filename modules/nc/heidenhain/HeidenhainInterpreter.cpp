// Entry point of the Heidenhain Klartext interpreter (iTNC 530 / TNC 640): parse once, then run
// the blocks with a program counter, driving the sink. Never throws: an allocation failure on
// absurd input is reported as an error.
#include "nc/detail/Dialects.h"
#include "nc/heidenhain/Machine.h"

#include <new>

namespace camwb::nc::detail {

InterpretResult interpretHeidenhain(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    try {
        heidenhain::Machine machine(options, sink, result);
        machine.run(text);
    } catch (const std::bad_alloc&) {
        result.completed = false;
        result.diagnostics.push_back({Severity::Error, options.fileName.empty() ? "<input>" : options.fileName, 0, 0,
                                      "out of memory while interpreting the program"});
    } catch (const std::exception& e) {
        result.completed = false;
        result.diagnostics.push_back({Severity::Error, options.fileName.empty() ? "<input>" : options.fileName, 0, 0,
                                      std::string("internal error: ") + e.what()});
    }
    if (result.files.empty())
        result.files.push_back(options.fileName);
    return result;
}

}  // namespace camwb::nc::detail
