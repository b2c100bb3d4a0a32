#include "IsoTestSupport.h"

#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

namespace camwb::nc::iso::test {

std::string IsoRun::diagnostics() const
{
    std::string out;
    for (const Diagnostic& d : result.diagnostics)
        out += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + severityName(d.severity) + ": " +
               d.message + "\n";
    return out;
}

IsoRun run(std::string_view program, InterpretOptions options)
{
    options.dialect = Dialect::Iso;
    toolpath::ToolpathRecorder recorder;
    IsoRun r;
    r.result = interpret(program, options, recorder);
    r.path = recorder.take();
    r.trace = motionTrace(r.path, r.result.files, TraceFormat::Text);
    return r;
}

}  // namespace camwb::nc::iso::test
