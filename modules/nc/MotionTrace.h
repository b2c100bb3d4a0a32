// The canonical trace of an interpreted NC program (`camwb-cli nc trace`, the NC goldens): one
// entry per motion (rapid, linear, arc, helix, one per cycle hole) and per dwell, with the
// program line that made it and the state it ran with: feed and its mode, spindle, tool.
// Text: "<line> <kind> <x> <y> <z> [...] f <feed> s <rpm> t <tool>", lines of called programs as
// "<file name>:<line>". JSONL: one object per entry with the same fields. Formats documented in
// docs/architecture.md; 4 decimals, no locale.
#pragma once

#include "toolpath/MachineSink.h"
#include "toolpath/Toolpath.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc {

enum class TraceFormat { Text, Jsonl };

// `program` holds records with SourceRef line/file as the interpreters set them; `files` names
// the files SourceRef::file indexes (InterpretResult::files).
std::string motionTrace(const toolpath::Toolpath& program, const std::vector<std::string>& files, TraceFormat format);

// The same text while the interpreter runs, without keeping the toolpath: a sink that formats each
// entry as it arrives and hands the text to `write` in chunks of about chunkBytes. A called
// program's entries carry its file name, which the run tells only at its end (InterpretResult::
// files): from the first record of another file on, records are kept and traced by finish().
class MotionTraceWriter : public toolpath::MachineSink {
public:
    // Receives the text in order; returns false when writing failed.
    using Write = std::function<bool(std::string_view)>;

    // `programPath`: the program's own file (InterpretOptions::fileName), entries of file 0.
    MotionTraceWriter(const std::string& programPath, TraceFormat format, Write write,
                      std::size_t chunkBytes = std::size_t(1) << 20);
    ~MotionTraceWriter() override;

    void setSource(const toolpath::SourceRef& source) override;
    void rapid(const toolpath::Rapid&) override;
    void linear(const toolpath::Linear&) override;
    void arc(const toolpath::Arc&) override;
    void toolChange(const toolpath::ToolChange&) override;
    void spindle(const toolpath::Spindle&) override;
    void coolant(const toolpath::Coolant&) override;
    void feedMode(const toolpath::FeedModeChange&) override;
    void workOffset(const toolpath::WorkOffset&) override;
    void dwell(const toolpath::Dwell&) override;
    void cycle(const toolpath::Cycle&) override;
    void toolAxisMove(const toolpath::ToolAxisMove&) override;
    void cutterComp(const toolpath::CutterComp&) override;
    void comment(const toolpath::Comment&) override;
    void sectionBegin(const toolpath::SectionBegin&) override;
    void sectionEnd(const toolpath::SectionEnd&) override;
    void programStop(const toolpath::ProgramStop&) override;
    void passThrough(const toolpath::PassThrough&) override;
    void workingPlane(const toolpath::WorkingPlane&) override;
    void unknownAxes(const toolpath::UnknownAxes&) override;

    // Traces what was kept with the run's files and hands over the rest of the text; false when a
    // write failed at any time.
    bool finish(const std::vector<std::string>& files);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace camwb::nc
