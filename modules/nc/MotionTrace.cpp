#include "nc/MotionTrace.h"

#include "base/NumberFormat.h"
#include "toolpath/RecordNames.h"

#include <filesystem>
#include <type_traits>

namespace camwb::nc {

namespace {

using namespace camwb::toolpath;

std::string num(double v) { return base::formatFixed(v, 4); }

struct State {
    Vec3 position;
    double rpm = 0;
    bool spindleCw = true;
    double surfaceSpeed = 0;
    int tool = 0;
    FeedMode feedMode = FeedMode::PerMinute;
};

// One trace entry, written as text or JSON by the same code so both always carry the same fields.
class EntryWriter {
public:
    EntryWriter(std::string& out, TraceFormat format) : m_out(out), m_format(format) {}

    void begin(const std::string& where, int line, const char* kind)
    {
        if (m_format == TraceFormat::Text) {
            m_out += where;
            m_out += ' ';
            m_out += kind;
        } else {
            m_out += "{\"file\":\"" + json(where) + "\",\"line\":" + std::to_string(line) + ",\"kind\":\"" + kind + '"';
        }
    }
    void word(const char* text)  // a bare word in text ("cw"), a boolean-ish string field in JSON
    {
        if (m_format == TraceFormat::Text) {
            m_out += ' ';
            m_out += text;
        }
    }
    void field(const char* textKey, const char* jsonKey, const std::string& value, bool quote = false)
    {
        if (m_format == TraceFormat::Text) {
            if (*textKey) {
                m_out += ' ';
                m_out += textKey;
            }
            m_out += ' ' + value;
        } else {
            m_out += std::string(",\"") + jsonKey + "\":" + (quote ? '"' + value + '"' : value);
        }
    }
    void point(const char* textKey, const char* jsonKey, const Vec3& p)
    {
        if (m_format == TraceFormat::Text) {
            if (*textKey) {
                m_out += ' ';
                m_out += textKey;
            }
            m_out += ' ' + num(p.x) + ' ' + num(p.y) + ' ' + num(p.z);
        } else {
            m_out += std::string(",\"") + jsonKey + "\":[" + num(p.x) + ',' + num(p.y) + ',' + num(p.z) + ']';
        }
    }
    void end() { m_out += m_format == TraceFormat::Text ? "\n" : "}\n"; }

private:
    static std::string json(const std::string& s)
    {
        std::string out;
        for (char c : s) {
            if (c == '"' || c == '\\')
                out += '\\';
            if (static_cast<unsigned char>(c) < 0x20)
                continue;
            out += c;
        }
        return out;
    }
    std::string& m_out;
    TraceFormat m_format;
};

class Tracer {
public:
    Tracer(const std::vector<std::string>& files, TraceFormat format, std::string& out) :
        m_files(files),
        m_format(format),
        m_w(out, format)
    {
    }

    void record(const Record& record, const SourceRef& source)
    {
        m_source = source;
        std::visit([this](const auto& r) { visit(r); }, record);
    }

private:
    std::string where() const
    {
        const std::string line = std::to_string(m_source.line);
        if (m_source.file <= 0 || m_source.file >= static_cast<int>(m_files.size()))
            return m_format == TraceFormat::Text ? line : fileName(0);
        return m_format == TraceFormat::Text ? fileName(m_source.file) + ':' + line : fileName(m_source.file);
    }
    std::string fileName(int index) const
    {
        if (index >= static_cast<int>(m_files.size()))
            return "<input>";
        return std::filesystem::path(m_files[index]).filename().string();
    }
    void begin(const char* kind) { m_w.begin(where(), m_source.line, kind); }
    void state(double feed, bool withFeed)
    {
        if (withFeed) {
            const char* key = m_state.feedMode == FeedMode::PerMinute       ? "f"
                              : m_state.feedMode == FeedMode::PerRevolution ? "fr"
                                                                            : "fi";
            m_w.field(key, "feed", num(feed));
            if (m_format == TraceFormat::Jsonl)
                m_w.field("", "feedMode", name(m_state.feedMode), true);
        }
        m_w.field("s", "spindle", num(m_state.rpm));
        if (m_format == TraceFormat::Text) {
            if (m_state.rpm > 0 && !m_state.spindleCw)
                m_w.word("ccw");
        } else {
            m_w.field("", "spindleCw", m_state.spindleCw ? "true" : "false");
        }
        if (m_state.surfaceSpeed > 0)
            m_w.field("css", "surfaceSpeed", num(m_state.surfaceSpeed));
        m_w.field("t", "tool", std::to_string(m_state.tool));
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
        if (m_format == TraceFormat::Text)
            m_w.word(r.clockwise ? "cw" : "ccw");
        m_w.point("", "to", r.to);
        m_w.point("c", "center", r.center);
        m_w.point("n", "normal", r.normal);
        if (m_format == TraceFormat::Jsonl)
            m_w.field("", "cw", r.clockwise ? "true" : "false");
        m_w.field("turns", "turns", std::to_string(r.turns));
        state(r.feedMmPerMin, true);
        m_state.position = r.to;
    }
    void visit(const Cycle& r)
    {
        for (const Vec3& hole : r.holes) {
            begin("cycle");
            if (m_format == TraceFormat::Text)
                m_w.word(name(r.kind));
            else
                m_w.field("", "cycle", name(r.kind), true);
            m_w.point("", "to", hole);
            m_w.field("bottom", "bottom", num(r.bottomZ));
            m_w.field("top", "top", num(r.topZ));
            m_w.field("r", "retract", num(r.retractZ));
            m_w.field("clear", "clearance", num(r.clearanceZ));
            if (r.peckMm > 0)
                m_w.field("peck", "peck", num(r.peckMm));
            if (r.dwellSeconds > 0)
                m_w.field("dwell", "dwell", num(r.dwellSeconds));
            m_w.field("return", "return", r.returnToClearance ? "clear" : "retract", true);
            state(r.feedMmPerMin, true);
            m_state.position = {hole.x, hole.y, r.returnToClearance ? std::max(r.clearanceZ, r.retractZ) : r.retractZ};
        }
    }
    void visit(const Dwell& r)
    {
        begin("dwell");
        m_w.field("", "seconds", num(r.seconds));
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

    const std::vector<std::string>& m_files;
    TraceFormat m_format;
    EntryWriter m_w;
    State m_state;
    SourceRef m_source;
};

}  // namespace

std::string motionTrace(const toolpath::Toolpath& program, const std::vector<std::string>& files, TraceFormat format)
{
    std::string out;
    Tracer tracer(files, format, out);
    for (std::size_t i = 0; i < program.size(); ++i)
        tracer.record(program.record(i), program.source(i));
    return out;
}

}  // namespace camwb::nc
