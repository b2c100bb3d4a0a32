#include "nc/MotionTrace.h"

#include "base/NumberFormat.h"
#include "toolpath/RecordNames.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace camwb::nc {

namespace {

using namespace camwb::toolpath;

struct State {
    Vec3 position;
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
    EntryWriter(std::string& out, TraceFormat format) : m_out(out), m_text(format == TraceFormat::Text)
    {
        m_number.decimals = 4;
    }

    // Text: "<where> <kind>"; JSON: {"file":"<file>","line":n,"kind":"<kind>".
    void begin(const std::string& file, bool showFile, int line, const char* kind)
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
    void word(const char* text)  // a bare word in the text only ("cw"); JSON says it by field
    {
        if (m_text) {
            m_out += ' ';
            m_out += text;
        }
    }
    void key(const char* textKey, const char* jsonKey)
    {
        if (m_text) {
            if (*textKey) {
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
    void number(const char* textKey, const char* jsonKey, double value)
    {
        key(textKey, jsonKey);
        number(value);
    }
    void integerField(const char* textKey, const char* jsonKey, int value)
    {
        key(textKey, jsonKey);
        integer(value);
    }
    void text(const char* textKey, const char* jsonKey, const char* value)
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
    void boolean(const char* jsonKey, bool value)  // JSON only
    {
        if (!m_text) {
            key("", jsonKey);
            m_out += value ? "true" : "false";
        }
    }
    void point(const char* textKey, const char* jsonKey, const Vec3& p)
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
    void end() { m_out += m_text ? "\n" : "}\n"; }
    bool isText() const { return m_text; }

private:
    void number(double value)
    {
        char buffer[base::NumberFormat::kBufferSize];
        m_out.append(buffer, m_number.formatTo(value, buffer));
    }
    void integer(int value)
    {
        char buffer[16];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
        m_out.append(buffer, result.ptr);
    }

    std::string& m_out;
    bool m_text;
    base::NumberFormat m_number;
};

class Tracer {
public:
    Tracer(const std::vector<std::string>& files, TraceFormat format, std::string& out) : m_w(out, format)
    {
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
    void begin(const char* kind)
    {
        const bool called = m_source.file > 0 && m_source.file < static_cast<int>(m_names.size());
        // The text names only called programs' files; JSON names every entry's file.
        m_w.begin(m_names[called ? m_source.file : 0], called, m_source.line, kind);
    }
    void state(double feed, bool withFeed)
    {
        if (withFeed) {
            const char* key = m_state.feedMode == FeedMode::PerMinute       ? "f"
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

    void visit(const Rapid& r)
    {
        begin("rapid");
        m_w.point("", "to", r.to);
        state(0, false);
        m_state.position = r.to;
    }
    void visit(const Linear& r)
    {
        begin("linear");
        m_w.point("", "to", r.to);
        state(r.feedMmPerMin, true);
        m_state.position = r.to;
    }
    void visit(const Arc& r)
    {
        // A helix leaves the arc's plane: its end is not at the start's height along the normal.
        const Vec3 d = r.to - m_state.position;
        const bool helix = std::abs(d.x * r.normal.x + d.y * r.normal.y + d.z * r.normal.z) > 1e-9;
        begin(helix ? "helix" : "arc");
        m_w.word(r.clockwise ? "cw" : "ccw");
        m_w.point("", "to", r.to);
        m_w.point("c", "center", r.center);
        m_w.point("n", "normal", r.normal);
        m_w.boolean("cw", r.clockwise);
        m_w.integerField("turns", "turns", r.turns);
        state(r.feedMmPerMin, true);
        m_state.position = r.to;
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
            m_state.position = {hole.x, hole.y, r.returnToClearance ? std::max(r.clearanceZ, r.retractZ) : r.retractZ};
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
        m_w.point("axis", "axis", r.axis);
        state(r.feedMmPerMin, r.feedMmPerMin > 0);
        m_state.position = r.tip;
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
    SourceRef m_source;
};

}  // namespace

std::string motionTrace(const toolpath::Toolpath& program, const std::vector<std::string>& files, TraceFormat format)
{
    std::string out;
    out.reserve(program.size() * (format == TraceFormat::Text ? 80 : 160));
    Tracer tracer(files, format, out);
    for (std::size_t i = 0; i < program.size(); ++i)
        tracer.record(program.record(i), program.source(i));
    return out;
}

}  // namespace camwb::nc
