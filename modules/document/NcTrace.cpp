#include "document/NcTrace.h"

#include "nc/tools/ErrorRecords.h"
#include "toolpath/MachineSink.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace camwb::document {

namespace {

// Records what the interpreter sends, and where subprogram runs start. After cancellation it
// drops everything, so a superseded run of a huge program costs only the parsing.
class TraceRecorder : public toolpath::MachineSink {
public:
    TraceRecorder(NcTrace& trace, const std::atomic<bool>* cancel) : m_trace(trace), m_cancel(cancel) {}

    void setSource(const toolpath::SourceRef& source) override
    {
        // The interpreters announce the calling block before entering a called program
        // (Interpreter.h), so the last main-program line seen is the call.
        if (source.file == 0)
            m_mainLine = source.line;
        m_source = source;
    }

    void rapid(const toolpath::Rapid& r) override { add(r); }
    void linear(const toolpath::Linear& r) override { add(r); }
    void arc(const toolpath::Arc& r) override { add(r); }
    void toolChange(const toolpath::ToolChange& r) override { add(r); }
    void spindle(const toolpath::Spindle& r) override { add(r); }
    void coolant(const toolpath::Coolant& r) override { add(r); }
    void feedMode(const toolpath::FeedModeChange& r) override { add(r); }
    void workOffset(const toolpath::WorkOffset& r) override { add(r); }
    void dwell(const toolpath::Dwell& r) override { add(r); }
    void cycle(const toolpath::Cycle& r) override { add(r); }
    void toolAxisMove(const toolpath::ToolAxisMove& r) override { add(r); }
    void cutterComp(const toolpath::CutterComp& r) override { add(r); }
    void comment(const toolpath::Comment&) override {}  // comments are in the editor already
    void sectionBegin(const toolpath::SectionBegin& r) override { add(r); }
    void sectionEnd(const toolpath::SectionEnd& r) override { add(r); }
    void programStop(const toolpath::ProgramStop& r) override { add(r); }
    void passThrough(const toolpath::PassThrough& r) override { add(r); }
    void workingPlane(const toolpath::WorkingPlane& r) override { add(r); }
    void unknownAxes(const toolpath::UnknownAxes& r) override { add(r); }

    bool cancelled() const { return m_cancelled; }

private:
    template <class R> void add(const R& record)
    {
        if (m_cancelled || (m_cancel != nullptr && m_cancel->load(std::memory_order_relaxed))) {
            m_cancelled = true;
            return;
        }
        const auto index = static_cast<std::uint32_t>(m_trace.program.size());
        if (m_source.file > 0 && m_previousFile == 0)
            m_trace.subprogramRuns.emplace_back(index, m_mainLine);
        m_previousFile = m_source.file;
        m_trace.program.add(record, m_source);
    }

    NcTrace& m_trace;
    const std::atomic<bool>* m_cancel;
    toolpath::SourceRef m_source;
    int m_mainLine = 0;
    int m_previousFile = 0;
    bool m_cancelled = false;
};

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::optional<toolpath::ClFormat> clFormatToRead(const std::string& path, std::optional<nc::Dialect> dialectChoice)
{
    return dialectChoice ? std::nullopt : toolpath::clFormatFromExtension(path);
}

NcTrace traceNc(const NcTraceRequest& request)
{
    NcTrace trace;
    trace.clFormat = clFormatToRead(request.path, request.dialect);
    trace.dialectGuessed = !request.dialect.has_value();
    trace.dialect = request.dialect ? *request.dialect : nc::guessDialect(request.text, request.path);

    nc::InterpretOptions options;
    options.dialect = trace.dialect;
    options.clFormat = trace.clFormat;
    options.fileName = request.path;
    options.cancel = request.cancel;
    options.machine = request.machine.get();
    options.checkLimits = request.checkLimits;
    options.toolTable = request.tools.get();
    if (!request.path.empty())
        options.resolveProgram = nc::resolverBeside(request.path, trace.dialect);

    // The first run of each main-program line keeps its modal words; equal states are stored once.
    options.onBlock = [&trace](const nc::BlockModal& words) {
        if (words.file != 0 || words.line < 1)
            return;
        auto& index = trace.wordsIndexOfLine;
        const auto line = static_cast<std::size_t>(words.line);
        if (line < index.size() && index[line] != NcTrace::kNoWords)
            return;
        if (trace.modalWords.empty() || !trace.modalWords.back().sameState(words))
            trace.modalWords.push_back(words);
        if (index.size() <= line)
            index.resize(line + 1, NcTrace::kNoWords);
        index[line] = static_cast<std::uint32_t>(trace.modalWords.size() - 1);
    };

    const auto start = std::chrono::steady_clock::now();
    // About a record per line: reserved at once, so that a long program is not regrown and copied.
    trace.program.reserve(static_cast<std::size_t>(std::count(request.text.begin(), request.text.end(), '\n')) + 1);
    TraceRecorder recorder(trace, request.cancel);
    trace.result = nc::interpret(request.text, options, recorder);
    trace.cancelled = recorder.cancelled() || trace.result.cancelled;
    trace.interpretSeconds = secondsSince(start);
    if (trace.cancelled)
        return trace;

    const auto indexStart = std::chrono::steady_clock::now();
    trace.lineRecords.reserve(trace.program.size());
    for (std::size_t i = 0; i < trace.program.size(); ++i) {
        const toolpath::SourceRef& source = trace.program.source(i);
        if (source.file == 0 && source.line > 0)
            trace.lineRecords.emplace_back(source.line, static_cast<std::uint32_t>(i));
    }
    // Mostly sorted already (lines run forward); loops and jumps make the rest.
    if (!std::is_sorted(trace.lineRecords.begin(), trace.lineRecords.end()))
        std::stable_sort(trace.lineRecords.begin(), trace.lineRecords.end());
    trace.modal = ModalStateTable(trace.program);
    trace.recordsInError = nc::recordsInError(trace.program, trace.result);
    trace.indexSeconds = secondsSince(indexStart);
    return trace;
}

std::vector<std::size_t> NcTrace::recordsOfLine(int line) const
{
    auto begin = std::lower_bound(lineRecords.begin(), lineRecords.end(), std::make_pair(line, std::uint32_t(0)));
    std::vector<std::size_t> records;
    for (auto it = begin; it != lineRecords.end() && it->first == line; ++it)
        records.push_back(it->second);
    return records;
}

const nc::BlockModal* NcTrace::wordsOfLine(int line) const
{
    for (int l = std::min(line, static_cast<int>(wordsIndexOfLine.size()) - 1); l >= 1; --l) {
        const std::uint32_t index = wordsIndexOfLine[static_cast<std::size_t>(l)];
        if (index != kNoWords)
            return &modalWords[index];
    }
    return nullptr;
}

LineState NcTrace::lineState(int line) const
{
    LineState state;
    state.line = line;
    if (const nc::BlockModal* words = wordsOfLine(line))
        state.words = *words;
    const std::vector<std::size_t> records = recordsOfLine(line);
    if (records.empty()) {
        auto next =
            std::lower_bound(lineRecords.begin(), lineRecords.end(), std::make_pair(line + 1, std::uint32_t(0)));
        const std::size_t at = next != lineRecords.end() ? next->second : program.size();
        state.before = stateBefore(at);
        state.after = state.before;
        return state;
    }
    state.records = records.size();
    // The first run: the records that follow each other without a gap.
    std::size_t last = records.front();
    state.runs = 1;
    for (std::size_t i = 1; i < records.size(); ++i) {
        if (records[i] != records[i - 1] + 1)
            ++state.runs;
        else if (state.runs == 1)
            last = records[i];
    }
    state.before = stateBefore(records.front());
    state.after = stateBefore(last + 1);
    // The move the block makes: its first motion record (else its first record of any kind).
    ModalState at = state.before;
    for (std::size_t r = records.front(); r <= last; ++r) {
        const std::string what = describeMove(at, program.record(r));
        const auto& record = program.record(r);
        const bool motion =
            std::holds_alternative<toolpath::Rapid>(record) || std::holds_alternative<toolpath::Linear>(record) ||
            std::holds_alternative<toolpath::Arc>(record) || std::holds_alternative<toolpath::Cycle>(record) ||
            std::holds_alternative<toolpath::ToolAxisMove>(record) ||
            std::holds_alternative<toolpath::UnknownAxes>(record);
        if (motion) {
            state.move = what;
            break;
        }
        if (state.move.empty())
            state.move = what;
        applyRecord(at, record);
    }
    return state;
}

bool NcTrace::isInSubprogram(std::size_t record) const
{
    return record < program.size() && program.source(record).file > 0;
}

int NcTrace::lineOfRecord(std::size_t record) const
{
    if (record >= program.size())
        return -1;
    const toolpath::SourceRef& source = program.source(record);
    if (source.file == 0)
        return source.line;
    auto after =
        std::upper_bound(subprogramRuns.begin(), subprogramRuns.end(), static_cast<std::uint32_t>(record),
                         [](std::uint32_t r, const std::pair<std::uint32_t, int>& run) { return r < run.first; });
    if (after == subprogramRuns.begin())
        return -1;
    return std::prev(after)->second > 0 ? std::prev(after)->second : -1;
}

std::string NcTrace::whereOf(std::size_t record) const
{
    if (record >= program.size())
        return {};
    const toolpath::SourceRef& source = program.source(record);
    if (source.file == 0)
        return std::to_string(source.line);
    const auto& files = result.files;
    const std::string name = source.file < static_cast<int>(files.size())
                                 ? std::filesystem::path(files[source.file]).filename().string()
                                 : "file " + std::to_string(source.file);
    return name + ":" + std::to_string(source.line);
}

}  // namespace camwb::document
