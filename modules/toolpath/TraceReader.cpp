#include "toolpath/TraceReader.h"

#include "toolpath/ClText.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/RecordNames.h"

#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <tuple>

namespace camwb::toolpath {

namespace {

struct Token {
    std::string text;
    int column = 0;
    bool quoted = false;
};

// Splits a line at blanks; "..." is one token (with \" and \\ inside, as the writer escapes them).
std::optional<std::vector<Token>> tokenize(std::string_view line, int& badColumn)
{
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] == ' ' || line[i] == '\t') {
            ++i;
            continue;
        }
        Token token{{}, static_cast<int>(i) + 1, line[i] == '"'};
        if (token.quoted) {
            std::size_t j = i + 1;
            for (; j < line.size() && line[j] != '"'; ++j) {
                if (line[j] == '\\' && j + 1 < line.size())
                    ++j;
                token.text += line[j];
            }
            if (j >= line.size()) {
                badColumn = token.column;
                return std::nullopt;
            }
            i = j + 1;
        } else {
            const std::size_t end = std::min(line.find_first_of(" \t", i), line.size());
            token.text = std::string(line.substr(i, end - i));
            i = end;
        }
        tokens.push_back(std::move(token));
    }
    return tokens;
}

class LineParser {
public:
    LineParser(std::vector<Token> tokens, int line, std::size_t length, const std::string& file) :
        m_tokens(std::move(tokens)),
        m_line(line),
        m_endColumn(static_cast<int>(length) + 1),
        m_file(file)
    {
    }

    bool failed() const { return m_error.has_value(); }
    const base::Error& error() const { return *m_error; }

    std::string word()
    {
        if (const Token* t = next("a word"))
            return t->text;
        return {};
    }
    void keyword(std::string_view expected)
    {
        const Token* t = next(std::string("'") + std::string(expected) + "'");
        if (t && t->text != expected)
            fail("expected '" + std::string(expected) + "', found '" + std::string(t->text) + "'", t->column);
    }
    double number()
    {
        const Token* t = next("a number");
        if (!t)
            return 0;
        const std::optional<double> value = parseNumber(t->text);
        if (!value)
            fail("expected a number, found '" + std::string(t->text) + "'", t->column);
        return value.value_or(0);
    }
    int integer()
    {
        const Token* t = m_index < m_tokens.size() ? &m_tokens[m_index] : nullptr;
        const double value = number();
        // Range first: converting a double outside int's range is undefined (found by fuzz.trace).
        const bool representable = value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
        if (t && !failed() && (!representable || value != static_cast<int>(value)))
            fail("expected an integer, found '" + std::string(t->text) + "'", t->column);
        return representable ? static_cast<int>(value) : 0;
    }
    Vec3 point() { return {number(), number(), number()}; }
    // A straight move's target: "x y z", or the axes it gives by name in order ("z 20", "x 1 y 2").
    Vec3 target(AxisMask& axes)
    {
        Vec3 to;
        axes = AxisMask{0};
        for (int axis; (axis = nextAxis(axes)) >= 0;) {
            axes.bits = static_cast<unsigned char>(axes.bits | 1 << axis);
            setAxisValue(to, axis, number());
        }
        if (axes.none() && !failed()) {
            axes = AxisMask{};
            return point();
        }
        return to;
    }
    // Axis names in order, at least one ("z", "x y z"): the axes of an "unknown" record.
    AxisMask axisNames()
    {
        AxisMask axes{0};
        for (int axis; (axis = nextAxis(axes)) >= 0;)
            axes.bits = static_cast<unsigned char>(axes.bits | 1 << axis);
        if (axes.none() && !failed())
            fail("expected the axes made unknown (x, y, z)", atEnd() ? m_endColumn : m_tokens[m_index].column);
        return axes;
    }
    std::string text()
    {
        const Token* t = next("a quoted text");
        if (t && !t->quoted)
            fail("expected a quoted text, found '" + std::string(t->text) + "'", t->column);
        return t ? std::string(t->text) : std::string();
    }
    template <class Enum, std::size_t N> Enum choice(const std::array<Enum, N>& values)
    {
        const Token* t = next("a name");
        if (!t)
            return values[0];
        for (Enum v : values)
            if (t->text == name(v))
                return v;
        fail("unknown name '" + std::string(t->text) + "'", t->column);
        return values[0];
    }
    // The feed kind a move may name after its feed ("f 150 plunge"); none: unspecified.
    FeedKind optionalFeedKind()
    {
        if (failed() || atEnd())
            return FeedKind::Unspecified;
        const Token& t = m_tokens[m_index++];
        const std::optional<FeedKind> kind = t.quoted ? std::nullopt : feedKindNamed(t.text);
        if (!kind)
            fail("unknown feed kind '" + t.text + "' (cutting, plunge, entry, exit or finishing)", t.column);
        return kind.value_or(FeedKind::Unspecified);
    }
    bool atEnd() const { return m_index >= m_tokens.size(); }
    // The next word when it is one of `names` (an optional field's key), consumed; else "".
    std::string optionalKey(std::initializer_list<const char*> names)
    {
        if (failed() || atEnd() || m_tokens[m_index].quoted)
            return {};
        for (const char* name : names)
            if (m_tokens[m_index].text == name) {
                ++m_index;
                return name;
            }
        return {};
    }
    // Fails on a word left over; `where` says what may end the line ("(flutes N, ...)").
    void end(const std::string& where = "at the end of the line")
    {
        if (!failed() && !atEnd())
            fail("unexpected '" + std::string(m_tokens[m_index].text) + "' " + where, m_tokens[m_index].column);
    }
    void fail(const std::string& message, int column)
    {
        if (!m_error)
            m_error = base::makeError(message, m_file, m_line, column);
    }

private:
    // The next token as an axis name after those in `seen`, consumed; -1 (nothing consumed) when it
    // is no axis name.
    int nextAxis(AxisMask seen)
    {
        if (failed() || atEnd())
            return -1;
        const Token& t = m_tokens[m_index];
        if (t.quoted || t.text.size() != 1 || t.text[0] < 'x' || t.text[0] > 'z')
            return -1;
        const int axis = t.text[0] - 'x';
        if (seen.bits >> axis) {  // this axis or a later one already given
            fail("axis '" + t.text + "' out of order or given twice (x, y, z)", t.column);
            return -1;
        }
        ++m_index;
        return axis;
    }
    const Token* next(const std::string& what)
    {
        if (failed())
            return nullptr;
        if (m_index >= m_tokens.size()) {
            fail("expected " + what + " at the end of the line", m_endColumn);
            return nullptr;
        }
        return &m_tokens[m_index++];
    }

    std::vector<Token> m_tokens;
    std::size_t m_index = 0;
    int m_line;
    int m_endColumn;
    const std::string& m_file;
    std::optional<base::Error> m_error;
};

constexpr std::array kCoolants{CoolantMode::Off, CoolantMode::Flood, CoolantMode::Mist, CoolantMode::ThroughTool};
constexpr std::array kFeedModes{FeedMode::PerMinute, FeedMode::PerRevolution, FeedMode::InverseTime};
constexpr std::array kCycles{CycleKind::Drill,     CycleKind::DrillDwell, CycleKind::Peck,
                             CycleKind::ChipBreak, CycleKind::Tap,        CycleKind::Bore};
constexpr std::array kSides{CutterCompSide::Off, CutterCompSide::Left, CutterCompSide::Right};

}  // namespace

base::Result<ClImport> readTrace(std::string_view text, const std::string& fileName)
{
    base::LineReader lines(text);
    return readTrace(lines, fileName);
}

base::Result<ClImport> readTrace(base::LineReader& lines, const std::string& fileName)
{
    ClImport out;
    int section = -1, sections = 0;
    while (const std::optional<std::string_view> raw = lines.next()) {
        const int lineNumber = lines.lineNumber();
        const std::string_view line = trimRight(*raw);
        if (trim(line).empty() || trim(line).front() == '#')
            continue;
        int badColumn = 0;
        auto tokens = tokenize(line, badColumn);
        if (!tokens)
            return base::makeError("unterminated quoted text", fileName, lineNumber, badColumn);
        LineParser in(std::move(*tokens), lineNumber, line.size(), fileName);
        const std::string kind = in.word();
        const int kindColumn = static_cast<int>(line.find_first_not_of(" \t")) + 1;
        Record record;
        if (kind == "rapid") {
            Rapid r;
            r.to = in.target(r.axes);
            record = r;
        } else if (kind == "linear") {
            Linear l;
            l.to = in.target(l.axes);
            in.keyword("f");
            l.feedMmPerMin = in.number();
            l.feedKind = in.optionalFeedKind();
            record = l;
        } else if (kind == "arc") {
            Arc a;
            a.clockwise = in.word() == "cw";
            a.to = in.point();
            in.keyword("c");
            a.center = in.point();
            in.keyword("n");
            a.normal = in.point();
            in.keyword("turns");
            a.turns = in.integer();
            in.keyword("f");
            a.feedMmPerMin = in.number();
            a.feedKind = in.optionalFeedKind();
            record = a;
        } else if (kind == "tool") {
            Tool t;
            t.number = in.integer();
            t.kind = in.word();
            in.keyword("d");
            t.diameterMm = in.number();
            in.keyword("r");
            t.cornerRadiusMm = in.number();
            in.keyword("flute");
            t.fluteLengthMm = in.number();
            in.keyword("len");
            t.lengthMm = in.number();
            t.name = in.text();
            // Optional fields, each written only when it is not its default.
            for (std::string key; !(key = in.optionalKey({"flutes", "angle", "holder"})).empty();) {
                if (key == "flutes")
                    t.flutes = in.integer();
                else if (key == "angle")
                    t.pointAngleDeg = in.number();
                else
                    t.holder = in.text();
            }
            in.end("(after a tool's name: flutes N, angle A, holder \"...\")");
            record = ToolChange{t};
        } else if (kind == "spindle") {
            Spindle s{in.number()};
            const std::string direction = in.word();
            if (direction != "cw" && direction != "ccw" && !in.failed())
                in.fail("expected cw or ccw", 0);
            s.clockwise = direction == "cw";
            if (!in.atEnd()) {
                if (in.word() != "css" && !in.failed())
                    in.fail("expected css", 0);
                s.surfaceSpeedMPerMin = in.number();
            }
            record = s;
        } else if (kind == "coolant") {
            record = Coolant{in.choice(kCoolants)};
        } else if (kind == "feedmode") {
            record = FeedModeChange{in.choice(kFeedModes)};
        } else if (kind == "workoffset") {
            record = WorkOffset{in.integer()};
        } else if (kind == "dwell") {
            record = Dwell{in.number()};
        } else if (kind == "cycle") {
            Cycle c;
            c.kind = in.choice(kCycles);
            in.keyword("clear");
            c.clearanceZ = in.number();
            in.keyword("retract");
            c.retractZ = in.number();
            in.keyword("top");
            c.topZ = in.number();
            in.keyword("bottom");
            c.bottomZ = in.number();
            in.keyword("peck");
            c.peckMm = in.number();
            in.keyword("dwell");
            c.dwellSeconds = in.number();
            in.keyword("f");
            c.feedMmPerMin = in.number();
            in.keyword("return");
            c.returnToClearance = in.word() == "clear";
            in.keyword("holes");
            const int holes = in.integer();
            in.end();
            if (in.failed())
                return in.error();
            if (const std::optional<std::string> why = tooManyPecks(c))  // as the NC interpreters refuse it
                return base::makeError(*why, fileName, lineNumber, kindColumn);
            for (int h = 0; h < holes; ++h) {
                const std::optional<std::string_view> next = lines.next();
                if (!next)
                    return base::makeError("the cycle announces " + std::to_string(holes) + " holes but the file ends",
                                           fileName, lineNumber, kindColumn);
                int column = 0;
                const std::string_view holeLine = trimRight(*next);
                auto holeTokens = tokenize(holeLine, column);
                LineParser hole(holeTokens.value_or(std::vector<Token>{}), lines.lineNumber(), holeLine.size(),
                                fileName);
                hole.keyword("hole");
                c.holes.push_back(hole.point());
                hole.end();
                if (hole.failed())
                    return hole.error();
            }
            record = c;
        } else if (kind == "move5") {
            ToolAxisMove m{in.point()};
            in.keyword("axis");
            m.axis = in.point();
            in.keyword("f");
            m.feedMmPerMin = in.number();
            // Known rotary positions, each at most once, in the order a b c.
            for (const auto& [key, bit, value] :
                 {std::tuple{"a", RotaryAxes::kA, &m.machine.aDeg}, std::tuple{"b", RotaryAxes::kB, &m.machine.bDeg},
                  std::tuple{"c", RotaryAxes::kC, &m.machine.cDeg}}) {
                if (in.optionalKey({key}).empty())
                    continue;
                *value = in.number();
                m.machine.known |= bit;
            }
            m.jointInterpolated = !in.optionalKey({"joint"}).empty();
            in.end("(after a five-axis move's feed: a A, b B, c C, joint)");
            record = m;
        } else if (kind == "comp") {
            record = CutterComp{in.choice(kSides)};
        } else if (kind == "comment") {
            record = Comment{in.text()};
        } else if (kind == "section") {
            SectionBegin s;
            s.operationName = in.text();
            s.strategy = in.word();
            if (s.strategy == "-")
                s.strategy.clear();
            in.keyword("tool");
            s.toolNumber = in.integer();
            in.keyword("cut");
            s.feeds.cuttingMmPerMin = in.number();
            in.keyword("plunge");
            s.feeds.plungeMmPerMin = in.number();
            for (std::string key; !(key = in.optionalKey({"entry", "exit", "finish"})).empty();)
                (key == "entry"  ? s.feeds.entryMmPerMin
                 : key == "exit" ? s.feeds.exitMmPerMin
                                 : s.feeds.finishingMmPerMin) = in.number();
            while (!in.optionalKey({"set"}).empty()) {
                std::string name = in.word();
                s.postProperties.emplace_back(std::move(name), in.text());
            }
            while (!in.optionalKey({"param"}).empty()) {
                std::string name = in.word();
                s.strategyParameters.emplace_back(std::move(name), in.number());
            }
            in.end("(after a section's plunge feed: entry F, exit F, finish F, set NAME \"value\", param NAME V)");
            record = s;
            section = sections++;
        } else if (kind == "endsection") {
            record = SectionEnd{};
        } else if (kind == "stop") {
            const bool optional = !in.atEnd();
            if (optional)
                in.keyword("optional");
            record = ProgramStop{optional};
        } else if (kind == "passthrough") {
            record = PassThrough{in.text()};
        } else if (kind == "plane") {
            WorkingPlane p{in.point()};
            in.keyword("x");
            p.xAxis = in.point();
            in.keyword("z");
            p.zAxis = in.point();
            if (std::abs(p.xAxis.length() - 1) > 1e-6 || std::abs(p.zAxis.length() - 1) > 1e-6 ||
                std::abs(p.xAxis.dot(p.zAxis)) > 1e-6)
                return base::makeError("plane: the x and z axes must be unit vectors at right angles", fileName,
                                       lineNumber, kindColumn);
            record = p;
        } else if (kind == "unknown") {
            record = UnknownAxes{in.axisNames()};
        } else if (!in.failed()) {
            return base::makeError("unknown trace record '" + kind + "'", fileName, lineNumber, kindColumn);
        }
        in.end();
        if (in.failed())
            return in.error();
        out.toolpath.add(std::move(record), {section, lineNumber});
        if (kind == "endsection")
            section = -1;
    }
    if (lines.readError())
        return *lines.readError();
    return out;
}

}  // namespace camwb::toolpath
