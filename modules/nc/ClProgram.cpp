// A CL file read back as a program: its importer turns the text into records, which go to the
// sink as an interpreter's would, each at its statement's line, so the inspector, the program
// information, `nc trace` and the simulator take CL where they take NC.
#include "nc/detail/Dialects.h"

#include "base/LineReader.h"
#include "toolpath/ForwardingSink.h"

namespace camwb::nc::detail {

namespace {

// Passes records on at their statement's line: the importers number each record with the line
// it came from (SourceRef::recordIndex), where readers of a program look at SourceRef::line.
class AtStatementLine : public toolpath::ForwardingSink {
public:
    using ForwardingSink::ForwardingSink;
    void setSource(const toolpath::SourceRef& source) override
    {
        toolpath::SourceRef at = source;
        at.file = 0;
        at.line = source.recordIndex;
        ForwardingSink::setSource(at);
    }
};

}  // namespace

// What the importer cannot read stops it: one error at its line and no records, as a fatal NC
// error does. What it leaves out comes as warnings at their lines.
InterpretResult importCl(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    const std::string file = options.fileName.empty() ? "<input>" : options.fileName;
    result.files.push_back(file);
    base::LineReader lines(text);
    auto read = toolpath::readCl(lines, *options.clFormat, file);
    if (!read) {
        const base::Error& e = read.error();
        result.diagnostics.push_back({Severity::Error, e.file.empty() ? file : e.file, e.line, e.column, e.message});
        return result;
    }
    for (Diagnostic& warning : read.value().warnings) {
        if (result.diagnostics.size() < options.maxDiagnostics)
            result.diagnostics.push_back(std::move(warning));
        else
            ++result.diagnosticsDropped;
    }
    AtStatementLine atLine(sink);
    toolpath::play(read.value().toolpath, atLine);
    result.blocksExecuted = static_cast<std::int64_t>(read.value().toolpath.size());
    result.completed = true;
    return result;
}

}  // namespace camwb::nc::detail
