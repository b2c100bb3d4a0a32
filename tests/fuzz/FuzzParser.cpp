// libFuzzer target for one parser (chosen at compile time with CAMWB_FUZZ_PARSER): any bytes in,
// diagnostics or records out, never a crash, a hang or a sanitizer report. NC calls to other
// programs resolve to the input itself, so recursion limits are fuzzed too.
#include "nc/Interpreter.h"
#include "toolpath/ClImport.h"
#include "toolpath/ToolpathRecorder.h"
#include "toolpath/TraceReader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

enum class Parser { Sinumerik, Heidenhain, Iso, Apt, FreeCadDump, Trace };
constexpr Parser kParser = Parser::CAMWB_FUZZ_PARSER;

void interpretNc(std::string_view text, camwb::nc::Dialect dialect)
{
    camwb::nc::InterpretOptions options;
    options.dialect = dialect;
    options.fileName = "fuzz";
    options.maxBlocks = 20000;  // enough to reach every construct, small enough for many runs per second
    const std::string program(text);
    options.resolveProgram = [&program](std::string_view name) {
        return std::optional<camwb::nc::ProgramSource>(camwb::nc::ProgramSource{std::string(name), program});
    };
    camwb::toolpath::ToolpathRecorder recorder;
    (void)camwb::nc::interpret(text, options, recorder);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    switch (kParser) {
    case Parser::Sinumerik:
        interpretNc(text, camwb::nc::Dialect::Sinumerik);
        break;
    case Parser::Heidenhain:
        interpretNc(text, camwb::nc::Dialect::Heidenhain);
        break;
    case Parser::Iso:
        interpretNc(text, camwb::nc::Dialect::Iso);
        break;
    case Parser::Apt:
        (void)camwb::toolpath::readAptSource(text, "fuzz.apt");
        break;
    case Parser::FreeCadDump:
        (void)camwb::toolpath::readFreeCadDump(text, "fuzz.dump");
        break;
    case Parser::Trace:
        (void)camwb::toolpath::readTrace(text, "fuzz.trace");
        break;
    }
    return 0;
}
