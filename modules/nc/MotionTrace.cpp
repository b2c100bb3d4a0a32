#include "nc/MotionTrace.h"

#include "base/NumberFormat.h"
#include "nc/detail/TraceText.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/RecordNames.h"
#include "toolpath/ToolpathRecorder.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace camwb::nc {

namespace {

using namespace camwb::toolpath;
using detail::NumberCache;
using detail::TextBuffer;

struct State {
    KnownPosition position;  // nothing known at the start, as on the control
    double rpm = 0;
    bool spindleCw = true;
    double surfaceSpeed = 0;
    int tool = 0;
    FeedMode feedMode = FeedMode::PerMinute;
};

// One trace entry, written as text or JSON by the same calls so both always carry the same
// fields. Everything is appended in place: a million-line program is traced at the
// interpreter's pace, not the allocator's.
class EntryWriter {
public:
    EntryWriter(TextBuffer& out, TraceFormat format) : m_out(out), m_text(format == TraceFormat::Text)
    {
        m_number.decimals = 4;
    }

    // Text: "<where> <kind>"; JSON: {"file":"<file>","line":n,"kind":"<kind>".
    void begin(std::string_view file, bool showFile, int line, std::string_view kind)
    {
        if (m_text) {
            if (showFile) {
                m_out += file;
                m_out += ':';
            }
            integer(line);
            m_out += ' ';
            m_out += kind;
        } else {
            m_out += "{\"file\":\"";
            m_out += file;  // a file name without quotes or controls (see Tracer::jsonName)
            m_out += "\",\"line\":";
            integer(line);
            m_out += ",\"kind\":\"";
            m_out += kind;
            m_out += '"';
        }
    }
    void word(std::string_view text)  // a bare word in the text only ("cw"); JSON says it by field
    {
        if (m_text) {
            m_out += ' ';
            m_out += text;
        }
    }
    CAMWB_TRACE_INLINE void key(std::string_view textKey, std::string_view jsonKey)
    {
        if (m_text) {
            if (!textKey.empty()) {
                m_out += ' ';
                m_out += textKey;
            }
            m_out += ' ';
        } else {
            m_out += ",\"";
            m_out += jsonKey;
            m_out += "\":";
        }
    }
    CAMWB_TRACE_INLINE void number(std::string_view textKey, std::string_view jsonKey, double value)
    {
        key(textKey, jsonKey);
        number(value);
    }
    CAMWB_TRACE_INLINE void integerField(std::string_view textKey, std::string_view jsonKey, int value)
    {
        key(textKey, jsonKey);
        integer(value);
    }
    void text(std::string_view textKey, std::string_view jsonKey, std::string_view value)
    {
        key(textKey, jsonKey);
        if (m_text) {
            m_out += value;
        } else {
            m_out += '"';
            m_out += value;
            m_out += '"';
        }
    }
    // Axis names: text "x y z", JSON "axes":["x","y","z"].
    void axisNames(AxisMask axes)
    {
        key("", "axes");
        if (m_text) {
            m_out += toolpath::axisNames(axes);
            return;
        }
        m_out += '[';
        bool first = true;
        for (int axis = 0; axis < 3; ++axis) {
            if (!axes.has(axis))
                continue;
            if (!first)
                m_out += ',';
            first = false;
            const char name[] = {'"', static_cast<char>('x' + axis), '"'};
            m_out += std::string_view(name, 3);
        }
        m_out += ']';
    }
    void boolean(std::string_view jsonKey, bool value)  // JSON only
    {
        if (!m_text) {
            key("", jsonKey);
            m_out += value ? std::string_view("true") : std::string_view("false");
        }
    }
    CAMWB_TRACE_INLINE void point(std::string_view textKey, std::string_view jsonKey, const Vec3& p)
    {
        key(textKey, jsonKey);
        const char separator = m_text ? ' ' : ',';
        if (!m_text)
            m_out += '[';
        number(p.x);
        m_out += separator;
        number(p.y);
        m_out += separator;
        number(p.z);
        if (!m_text)
            m_out += ']';
    }
    // The target of a straight move while some axis is unknown: text names the known axes
    // ("z 5.0000"), JSON gives null for the others; never a coordinate the program did not give.
    void knownPoint(std::string_view jsonKey, const KnownPosition& p)
    {
        key("", jsonKey);
        if (!m_text)
            m_out += '[';
        bool first = true;
        for (int axis = 0; axis < 3; ++axis) {
            if (m_text && !p.known(axis))
                continue;
            if (!first)
                m_out += m_text ? ' ' : ',';
            first = false;
            if (m_text) {
                m_out += static_cast<char>('x' + axis);
                m_out += ' ';
            }
            if (p.known(axis))
                number(p.value(axis));
            else
                m_out += std::string_view("null");
        }
        if (!m_text)
            m_out += ']';
    }
    void end()
    {
        if (!m_text)
            m_out += '}';
        m_out += '\n';
    }
    bool isText() const { return m_text; }
    // The text written since size() was `start`, and a copy of such text.
    std::size_t size() const { return m_out.size(); }
    std::string_view since(std::size_t start) const { return m_out.view().substr(start); }
    void raw(std::string_view text) { m_out += text; }

private:
    CAMWB_TRACE_INLINE void number(double value)
    {
        char* at = m_out.room(base::NumberFormat::kBufferSize);
        std::size_t length = m_cache.find(value, at);
        if (length == 0) {
            length = m_number.formatTo(value, at);
            m_cache.store(value, at, length);
        }
        m_out.commit(at + length);
    }
    CAMWB_TRACE_INLINE void integer(int value)
    {
        char* at = m_out.room(16);
        m_out.commit(std::to_chars(at, at + 16, value).ptr);
    }

    TextBuffer& m_out;
    bool m_text;
    base::NumberFormat m_number;
    NumberCache m_cache;
};

// The text a part of an entry had the last time, copied while what it shows stays the same (the
// state that ends an entry, an arc's normal): far cheaper than writing it again.
template <class Key> class RepeatedPart {
public:
    template <class WriteIt> void write(EntryWriter& w, const Key& key, WriteIt&& writeIt)
    {
        if (m_key && *m_key == key) {
            w.raw(m_text);
            return;
        }
        const std::size_t start = w.size();
        writeIt();
        m_key = key;
        m_text.assign(w.since(start));
    }

private:
    std::optional<Key> m_key;
    std::string m_text;
};

// Turns records into entries, keeping the state they carry (feed mode, spindle, tool). The one
// formatter of the trace: motionTrace() feeds it a recorded toolpath, MotionTraceWriter the
// interpreter's records as they come.
class Tracer {
public:
    Tracer(const std::vector<std::string>& files, TraceFormat format, TextBuffer& out) : m_w(out, format)
    {
        setFiles(files);
    }

    // The names entries of each SourceRef::file carry.
    void setFiles(const std::vector<std::string>& files)
    {
        m_names.clear();
        for (const std::string& file : files)
            m_names.push_back(jsonName(std::filesystem::path(file).filename().string()));
        if (m_names.empty())
            m_names.push_back("<input>");
    }

    void record(const Record& record, const SourceRef& source)
    {
        m_source = source;
        std::visit([this](const auto& r) { visit(r); }, record);
    }
    template <class T> void record(const T& record, const SourceRef& source)
    {
        m_source = source;
        visit(record);
    }

private:
    // File names go into JSON strings as they are; drop what would need escaping.
    static std::string jsonName(const std::string& name)
    {
        std::string out;
        for (char c : name)
            if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20)
                out += c;
        return out;
    }
    void begin(std::string_view kind)
    {
        const bool called = m_source.file > 0 && m_source.file < static_cast<int>(m_names.size());
        // The text names only called programs' files; JSON names every entry's file.
        m_w.begin(m_names[called ? m_source.file : 0], called, m_source.line, kind);
    }
    // What ends an entry: feed, spindle, tool. It repeats until the program changes one of them
    // (writing it was a third of the trace's time).
    struct StateKey {
        std::uint64_t feed, rpm, surfaceSpeed;
        int tool;
        FeedMode feedMode;
        bool withFeed, spindleCw;
        bool operator==(const StateKey&) const = default;
    };
    void state(double feed, bool withFeed)
    {
        const StateKey key{withFeed ? std::bit_cast<std::uint64_t>(feed) : 0,
                           std::bit_cast<std::uint64_t>(m_state.rpm),
                           std::bit_cast<std::uint64_t>(m_state.surfaceSpeed),
                           m_state.tool,
                           m_state.feedMode,
                           withFeed,
                           m_state.spindleCw};
        m_stateText.write(m_w, key, [&] { writeState(feed, withFeed); });
    }
    void writeState(double feed, bool withFeed)
    {
        if (withFeed) {
            const std::string_view key = m_state.feedMode == FeedMode::PerMinute       ? "f"
                                         : m_state.feedMode == FeedMode::PerRevolution ? "fr"
                                                                                       : "fi";
            m_w.number(key, "feed", feed);
            if (!m_w.isText())
                m_w.text("", "feedMode", name(m_state.feedMode));
        }
        m_w.number("s", "spindle", m_state.rpm);
        if (m_w.isText()) {
            if (m_state.rpm > 0 && !m_state.spindleCw)
                m_w.word("ccw");
        } else {
            m_w.boolean("spindleCw", m_state.spindleCw);
        }
        if (m_state.surfaceSpeed > 0)
            m_w.number("css", "surfaceSpeed", m_state.surfaceSpeed);
        m_w.integerField("t", "tool", m_state.tool);
        m_w.end();
    }

    // A move that gives fewer axes keeps the others, as the control does; until every axis is
    // known (a program's first moves) the entry shows the known ones only.
    void moveStraight(const Vec3& to, AxisMask axes)
    {
        m_state.position.moveTo(to, axes);
        if (m_state.position.complete())
            m_w.point("", "to", m_state.position.value());
        else
            m_w.knownPoint("to", m_state.position);
    }
    void visit(const Rapid& r)
    {
        begin("rapid");
        moveStraight(r.to, r.axes);
        state(0, false);
    }
    void visit(const Linear& r)
    {
        begin("linear");
        moveStraight(r.to, r.axes);
        state(r.feedMmPerMin, true);
    }
    void visit(const Arc& r)
    {
        // A helix leaves the arc's plane: its end is not at the start's height along the normal.
        const Vec3 d = r.to - m_state.position.value();
        const bool helix = std::abs(d.x * r.normal.x + d.y * r.normal.y + d.z * r.normal.z) > 1e-9;
        begin(helix ? "helix" : "arc");
        m_w.word(r.clockwise ? "cw" : "ccw");
        m_w.point("", "to", r.to);
        m_w.point("c", "center", r.center);
        m_normalText.write(m_w, r.normal, [&] { m_w.point("n", "normal", r.normal); });
        m_w.boolean("cw", r.clockwise);
        m_w.integerField("turns", "turns", r.turns);
        state(r.feedMmPerMin, true);
        m_state.position.set(r.to);
    }
    void visit(const Cycle& r)
    {
        for (const Vec3& hole : r.holes) {
            begin("cycle");
            m_w.word(name(r.kind));
            if (!m_w.isText())
                m_w.text("", "cycle", name(r.kind));
            m_w.point("", "to", hole);
            m_w.number("bottom", "bottom", r.bottomZ);
            m_w.number("top", "top", r.topZ);
            m_w.number("r", "retract", r.retractZ);
            m_w.number("clear", "clearance", r.clearanceZ);
            if (r.peckMm > 0)
                m_w.number("peck", "peck", r.peckMm);
            if (r.dwellSeconds > 0)
                m_w.number("dwell", "dwell", r.dwellSeconds);
            m_w.text("return", "return", r.returnToClearance ? "clear" : "retract");
            state(r.feedMmPerMin, true);
            m_state.position.set(
                {hole.x, hole.y, r.returnToClearance ? std::max(r.clearanceZ, r.retractZ) : r.retractZ});
        }
    }
    void visit(const Dwell& r)
    {
        begin("dwell");
        m_w.number("", "seconds", r.seconds);
        m_w.end();
    }
    void visit(const ToolAxisMove& r)
    {
        begin(r.feedMmPerMin > 0 ? "linear5" : "rapid5");
        m_w.point("", "to", r.tip);
        // The tool vector (text "axis i j k", JSON "i" "j" "k") and the machine's rotary positions
        // where the interpreter knows them (a b c).
        if (m_w.isText()) {
            m_w.point("axis", "", r.axis);
        } else {
            m_w.number("", "i", r.axis.x);
            m_w.number("", "j", r.axis.y);
            m_w.number("", "k", r.axis.z);
        }
        if (r.machine.has(RotaryAxes::kA))
            m_w.number("a", "a", r.machine.aDeg);
        if (r.machine.has(RotaryAxes::kB))
            m_w.number("b", "b", r.machine.bDeg);
        if (r.machine.has(RotaryAxes::kC))
            m_w.number("c", "c", r.machine.cDeg);
        state(r.feedMmPerMin, r.feedMmPerMin > 0);
        m_state.position.set(r.tip);
    }
    void visit(const WorkingPlane& r)
    {
        begin("plane");
        m_w.point("", "origin", r.origin);
        m_w.point("x", "x", r.xAxis);
        m_w.point("z", "z", r.zAxis);
        m_w.end();
        // Coordinates after it are in the new frame: the moves' masks say which are known there.
        m_state.position.forget();
    }
    // The tool went somewhere the program does not say: the moves after it show the known axes only.
    void visit(const UnknownAxes& r)
    {
        begin("unknown");
        m_w.axisNames(r.axes);
        m_w.end();
        m_state.position.forget(r.axes);
    }
    void visit(const ToolChange& r) { m_state.tool = r.tool.number; }
    void visit(const Spindle& r)
    {
        m_state.rpm = r.rpm;
        m_state.spindleCw = r.clockwise;
        m_state.surfaceSpeed = r.surfaceSpeedMPerMin;
    }
    void visit(const FeedModeChange& r) { m_state.feedMode = r.mode; }
    template <class T> void visit(const T&) {}

    EntryWriter m_w;
    std::vector<std::string> m_names;
    State m_state;
    RepeatedPart<StateKey> m_stateText;
    RepeatedPart<Vec3> m_normalText;
    SourceRef m_source;
};

}  // namespace

std::string motionTrace(const toolpath::Toolpath& program, const std::vector<std::string>& files, TraceFormat format)
{
    TextBuffer out;
    out.reserve(program.size() * (format == TraceFormat::Text ? 80 : 160));
    Tracer tracer(files, format, out);
    for (std::size_t i = 0; i < program.size(); ++i)
        tracer.record(program.record(i), program.source(i));
    return std::string(out.view());
}

struct MotionTraceWriter::Impl {
    Impl(const std::string& programPath, TraceFormat format, Write write, std::size_t chunkBytes) :
        tracer({programPath}, format, text),
        write(std::move(write)),
        chunkBytes(chunkBytes)
    {
        text.reserve(chunkBytes + 65536);
    }

    template <class T> void record(const T& r)
    {
        // A called program's entries are named by its file, which the run names only at its end.
        if (held || source.file != 0) {
            if (!held)
                held.emplace();
            held->setSource(source);
            toolpath::dispatch(r, *held);
            return;
        }
        tracer.record(r, source);
        if (text.size() >= chunkBytes)
            flush();
    }
    void flush()
    {
        if (!writeFailed && text.size() > 0 && !write(text.view()))
            writeFailed = true;
        text.clear();
    }

    TextBuffer text;
    Tracer tracer;
    Write write;
    std::size_t chunkBytes;
    SourceRef source;
    std::optional<ToolpathRecorder> held;
    bool writeFailed = false;
};

MotionTraceWriter::MotionTraceWriter(const std::string& programPath, TraceFormat format, Write write,
                                     std::size_t chunkBytes) :
    m_impl(std::make_unique<Impl>(programPath, format, std::move(write), chunkBytes))
{
}

MotionTraceWriter::~MotionTraceWriter() = default;

void MotionTraceWriter::setSource(const SourceRef& source) { m_impl->source = source; }
void MotionTraceWriter::rapid(const Rapid& r) { m_impl->record(r); }
void MotionTraceWriter::linear(const Linear& r) { m_impl->record(r); }
void MotionTraceWriter::arc(const Arc& r) { m_impl->record(r); }
void MotionTraceWriter::toolChange(const ToolChange& r) { m_impl->record(r); }
void MotionTraceWriter::spindle(const Spindle& r) { m_impl->record(r); }
void MotionTraceWriter::coolant(const Coolant& r) { m_impl->record(r); }
void MotionTraceWriter::feedMode(const FeedModeChange& r) { m_impl->record(r); }
void MotionTraceWriter::workOffset(const WorkOffset& r) { m_impl->record(r); }
void MotionTraceWriter::dwell(const Dwell& r) { m_impl->record(r); }
void MotionTraceWriter::cycle(const Cycle& r) { m_impl->record(r); }
void MotionTraceWriter::toolAxisMove(const ToolAxisMove& r) { m_impl->record(r); }
void MotionTraceWriter::cutterComp(const CutterComp& r) { m_impl->record(r); }
void MotionTraceWriter::comment(const Comment& r) { m_impl->record(r); }
void MotionTraceWriter::sectionBegin(const SectionBegin& r) { m_impl->record(r); }
void MotionTraceWriter::sectionEnd(const SectionEnd& r) { m_impl->record(r); }
void MotionTraceWriter::programStop(const ProgramStop& r) { m_impl->record(r); }
void MotionTraceWriter::passThrough(const PassThrough& r) { m_impl->record(r); }
void MotionTraceWriter::workingPlane(const WorkingPlane& r) { m_impl->record(r); }
void MotionTraceWriter::unknownAxes(const UnknownAxes& r) { m_impl->record(r); }

bool MotionTraceWriter::finish(const std::vector<std::string>& files)
{
    Impl& impl = *m_impl;
    if (impl.held) {
        impl.tracer.setFiles(files);
        const Toolpath& held = impl.held->toolpath();
        for (std::size_t i = 0; i < held.size(); ++i) {
            impl.tracer.record(held.record(i), held.source(i));
            if (impl.text.size() >= impl.chunkBytes)
                impl.flush();
        }
        impl.held.reset();
    }
    impl.flush();
    return !impl.writeFailed;
}

}  // namespace camwb::nc
