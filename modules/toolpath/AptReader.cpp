#include "toolpath/AptReader.h"

#include <cmath>
#include <set>

namespace camwb::toolpath {

namespace {

constexpr double kMmPerInch = 25.4;

// Statements that describe the CL file itself (post selection, tolerances, multi-axis mode) and
// carry nothing the CL model needs.
const std::set<std::string, std::less<>> kNothingToCarry = {"MACHIN", "INTOL",  "OUTTOL", "TOLER",
                                                            "AUTOPS", "MULTAX", "CLPRNT"};
// Motions defined by APT geometry (drive, part and check surfaces): only an APT processor can
// compute them, and skipping a motion would corrupt every move after it.
const std::set<std::string, std::less<>> kGeometryMotions = {"GOLFT",  "GORGT", "GOBACK", "GOUP",
                                                             "GODOWN", "GO",    "PSIS"};
// Every statement the reader acts on (a missing '/' after one of these is an Error).
const std::set<std::string, std::less<>> kKnownStatements = {
    "UNITS",  "FEDRAT", "SPINDL", "COOLNT", "CUTCOM", "DELAY",  "MSYS",   "FROM",       "TLAXIS", "CIRCLE",
    "CYCLE",  "GOTO",   "GODLTA", "CUTTER", "TLDATA", "LOADTL", "LOAD",   "INDIRV",     "INDIRP", "GOFWD",
    "RAPID",  "END",    "FINI",   "STOP",   "OPSTOP", "GOHOME", "PAINT",  "SELECT",     "TOOLNO", "ORIGIN",
    "MACHIN", "INTOL",  "OUTTOL", "TOLER",  "AUTOPS", "MULTAX", "CLPRNT", "END-OF-PATH"};
// Statements that may stand between an NX CIRCLE and the GOTO that ends it.
const std::set<std::string, std::less<>> kAllowedInsideCircle = {"GOTO",   "FEDRAT", "PAINT", "INTOL",
                                                                 "OUTTOL", "TOLER",  "MULTAX"};

std::string joinWords(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : ",") + w;
    return out;
}

}  // namespace

base::Result<ClImport> readAptSource(std::string_view text, const std::string& fileName)
{
    base::LineReader lines(text);
    return readAptSource(lines, fileName);
}

base::Result<ClImport> readAptSource(base::LineReader& lines, const std::string& fileName)
{
    return AptReader(lines, fileName).read();
}

AptReader::AptReader(base::LineReader& lines, std::string fileName) :
    m_out(std::move(fileName)),
    m_scanner(lines, m_out)
{
    m_out.expectText(lines.sizeBytes());
}

base::Result<ClImport> AptReader::read()
{
    bool any = false;
    while (!m_finished) {
        auto next = m_scanner.next(m_unit);
        if (!next)
            return next.error();
        if (!next.value())
            break;
        any = true;
        if (auto status = unit(m_unit); !status)
            return status.error();
    }
    std::optional<TextPos> afterFini;
    if (m_finished) {
        auto rest = m_scanner.skipToEnd();
        if (!rest)
            return rest.error();
        afterFini = rest.value();
    }
    const int lastLine = m_scanner.lineCount();
    if (m_finished) {
        if (afterFini)
            m_out.warn("text after FINI is ignored", *afterFini);
    } else {
        if (auto status = endOfInput(lastLine); !status)
            return status.error();
        if (any)
            m_out.warn("no FINI at the end of the file: it may be truncated", lastLine);
    }
    return m_out.finish(lastLine);
}

base::Status AptReader::unit(const AptUnit& u)
{
    switch (u.kind) {
    case AptUnit::Kind::Remark: {
        // CATIA opens each operation with "$$ OPERATION NAME : <name>".
        const std::string upper = toUpper(u.body);
        if (upper.rfind("OPERATION NAME", 0) == 0) {
            const std::string_view rest = trim(std::string_view(u.body).substr(14));
            if (!rest.empty() && rest.front() == ':') {
                if (m_circle)
                    return m_out.error("CIRCLE at line " + std::to_string(m_circle->line) +
                                           " is not followed by the GOTO that ends it",
                                       u.start);
                endCycle(u.line, true);
                m_toolChangeRecord.reset();
                SectionBegin section;
                section.operationName = std::string(trim(rest.substr(1)));
                m_out.beginSection(std::move(section), u.line);
                return {};
            }
        }
        if (!u.body.empty())
            emit(Comment{u.body}, u.line);
        return {};
    }
    case AptUnit::Kind::Text:
        if (u.keyword == "INSERT") {
            if (m_circle)
                return m_out.error("INSERT between CIRCLE and the GOTO that ends it", u.start);
            emit(PassThrough{u.body}, u.line);
        } else {
            emit(Comment{u.body}, u.line);
        }
        return {};
    case AptUnit::Kind::Statement:
        break;
    }
    if (auto split = splitStatement(u, m_out, m_statement); !split)
        return split;
    return statement(m_statement);
}

base::Status AptReader::arguments(const AptStatement& s)
{
    if (!s.hasSlash)
        return m_out.error(s.words.front() + " needs '/' and its values", s.argsPos);
    return tokenizeArguments(s.args, m_out, m_items);
}

void AptReader::emit(Record record, int line)
{
    flushCycleRun();
    m_out.add(std::move(record), line);
}

base::Status AptReader::statement(const AptStatement& s)
{
    if (m_circle && (s.pointLine || !(s.words.size() == 1 && kAllowedInsideCircle.count(s.words.front()))))
        return m_out.error("CIRCLE at line " + std::to_string(m_circle->line) +
                               " is not followed by the GOTO that ends it",
                           s.wordPos);
    if (s.pointLine)
        return pointLine(s);
    // Point lines continue only the GOTO right before them.
    m_pointsFollow.reset();
    m_openArc.reset();

    const std::string& word = s.words.front();
    if (s.junkPos) {
        if (s.words.size() == 1 && kKnownStatements.count(word))
            return m_out.error("expected '/' after " + word, *s.junkPos);
        m_out.warn("unknown statement " + joinWords(s.words) + " ignored", s.wordPos);
        return {};
    }
    if (s.words.size() > 1) {
        if (s.words.back() == "GOFWD") {
            for (std::size_t i = 0; i + 1 < s.words.size(); ++i) {
                if (s.words[i] != "TLON")
                    return m_out.error(s.words[i] + " (tool offset from the drive circle) is not supported; only TLON",
                                       s.wordPos);
            }
            if (auto parsed = arguments(s); !parsed)
                return parsed;
            return gofwd(s, m_items);
        }
        m_out.warn("unknown statement " + joinWords(s.words) + " ignored", s.wordPos);
        return {};
    }

    // Statements without arguments.
    if (word == "RAPID" || word == "END" || word == "FINI" || word == "STOP" || word == "OPSTOP" ||
        word == "END-OF-PATH" || word == "GOHOME") {
        if (s.hasSlash)
            return m_out.error(word + " takes no values", s.argsPos);
        if (word == "RAPID") {
            m_rapidNext = true;
        } else if (word == "STOP" || word == "OPSTOP") {
            emit(ProgramStop{word == "OPSTOP"}, s.line);
        } else if (word == "END-OF-PATH") {
            endCycle(s.line, true);
            if (!m_out.endSection(s.line))
                m_out.warn("END-OF-PATH without an open TOOL PATH", s.wordPos);
        } else if (word == "GOHOME") {
            return gohome(s);
        } else {
            if (auto status = endOfInput(s.line); !status)
                return status;
            m_out.endSection(s.line);
            m_finished = word == "FINI";
        }
        return {};
    }
    if (kNothingToCarry.count(word))
        return {};
    if (word == "GOFWD") {
        if (auto parsed = arguments(s); !parsed)
            return parsed;
        return gofwd(s, m_items);
    }
    if (kGeometryMotions.count(word))
        return m_out.error(word + " needs an APT geometry processor and is not supported", s.wordPos);
    if (word == "PAINT") {
        m_out.warn("PAINT (display statement) ignored", s.wordPos);
        return {};
    }
    if (word == "SELECT") {
        m_out.warn("SELECT (tool preselection) ignored: the CL model has no preselection", s.wordPos);
        return {};
    }
    if (word == "TOOLNO") {
        m_out.warn("TOOLNO ignored: the tool change is read from LOADTL", s.wordPos);
        return {};
    }
    if (word == "ORIGIN") {
        m_out.warn("ORIGIN (NC axis system) is not applied: coordinates are read as written", s.wordPos);
        return {};
    }
    if (word == "TOOL PATH")
        return toolPath(s);
    if (!kKnownStatements.count(word)) {
        m_out.warn("unknown statement " + word + " ignored", s.wordPos);
        return {};
    }

    if (auto parsed = arguments(s); !parsed)
        return parsed;
    const Items& items = m_items;
    if (word == "UNITS")
        return units(s, items);
    if (word == "FEDRAT")
        return fedrat(s, items);
    if (word == "SPINDL")
        return spindl(s, items);
    if (word == "COOLNT")
        return coolnt(s, items);
    if (word == "CUTCOM")
        return cutcom(s, items);
    if (word == "DELAY")
        return delay(s, items);
    if (word == "MSYS")
        return msys(s, items);
    if (word == "FROM")
        return from(s, items);
    if (word == "TLAXIS")
        return tlaxis(s, items);
    if (word == "CIRCLE")
        return circle(s, items);
    if (word == "CYCLE")
        return cycle(s, items);
    if (word == "GOTO" || word == "GODLTA")
        return gotoStatement(s, items, word == "GODLTA");
    if (word == "CUTTER" || word == "TLDATA")
        return cutter(s, items, word == "TLDATA");
    if (word == "LOADTL")
        return loadTool(s, items, 0);
    if (word == "LOAD") {
        if (items.empty() || !items.front().isWord("TOOL")) {
            m_out.warn("LOAD other than LOAD/TOOL ignored", s.wordPos);
            return {};
        }
        return loadTool(s, items, 1);
    }
    return indirection(s, items, word == "INDIRP");
}

base::Status AptReader::units(const AptStatement& s, const Items& items)
{
    if (items.size() == 1 && (items[0].isWord("MM") || items[0].isWord("INCHES") || items[0].isWord("INCH"))) {
        m_mmPerUnit = items[0].isWord("MM") ? 1.0 : kMmPerInch;
        return {};
    }
    return m_out.error("UNITS expects MM or INCHES", items.empty() ? s.argsPos : items[0].pos);
}

base::Status AptReader::fedrat(const AptStatement& s, const Items& items)
{
    std::optional<double> value;
    std::optional<FeedMode> mode;
    double mmPerUnit = m_mmPerUnit;
    TextPos valuePos;
    for (const AptItem& item : items) {
        if (item.kind == AptItem::Kind::Number) {
            if (value)
                return m_out.error("FEDRAT has more than one value", item.pos);
            value = item.number;
            valuePos = item.pos;
        } else if (item.isWord("MMPM") || item.isWord("IPM") || item.isWord("MMPR") || item.isWord("IPR")) {
            mode = (item.word == "MMPM" || item.word == "IPM") ? FeedMode::PerMinute : FeedMode::PerRevolution;
            mmPerUnit = item.word[0] == 'I' ? kMmPerInch : 1.0;
        } else if (item.isWord("PERMIN") || item.isWord("PERREV")) {
            // Per minute / per revolution in the file's own length unit (CATIA's APT import lists them).
            mode = item.word == "PERMIN" ? FeedMode::PerMinute : FeedMode::PerRevolution;
            mmPerUnit = m_mmPerUnit;
        } else {
            return m_out.error("FEDRAT: unknown word " + describeItem(item) +
                                   " (expected MMPM, IPM, MMPR, IPR, PERMIN or PERREV)",
                               item.pos);
        }
    }
    if (!value)
        return m_out.error("FEDRAT needs a feed value", s.argsPos);
    if (*value < 0)
        return m_out.error("FEDRAT: negative feed", valuePos);
    m_feed = *value * mmPerUnit;
    m_feedSet = true;
    const FeedMode newMode = mode.value_or(m_feedMode);
    if (newMode != m_feedMode) {
        m_feedMode = newMode;
        emit(FeedModeChange{newMode}, s.line);
    }
    return {};
}

base::Status AptReader::spindl(const AptStatement& s, const Items& items)
{
    std::optional<double> rpm;
    std::optional<bool> clockwise;
    bool off = false;
    bool on = false;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const AptItem& item = items[i];
        if (item.kind == AptItem::Kind::Number) {
            if (rpm)
                return m_out.error("SPINDL has more than one speed", item.pos);
            if (item.number < 0)
                return m_out.error("SPINDL: negative speed", item.pos);
            rpm = item.number;
        } else if (item.isWord("RPM")) {
        } else if (item.isWord("CLW") || item.isWord("CCLW")) {
            clockwise = item.word == "CLW";
        } else if (item.isWord("OFF")) {
            off = true;
        } else if (item.isWord("ON")) {
            on = true;
        } else if (item.isWord("SFM") || item.isWord("SMM")) {
            m_out.warn("SPINDL with surface speed (" + item.word + ") is not supported: ignored", item.pos);
            return {};
        } else if (item.kind == AptItem::Kind::Word) {
            m_out.warn("SPINDL: " + item.word + " ignored", item.pos);
            if (i + 1 < items.size() && items[i + 1].kind == AptItem::Kind::Number)
                ++i;  // its value (RANGE,n; MAXRPM,n) is not the speed
        } else {
            return m_out.error("SPINDL: unexpected " + describeItem(item), item.pos);
        }
    }
    if (off) {
        emit(Spindle{0, m_spindle.clockwise}, s.line);
        return {};
    }
    if (clockwise)
        m_spindle.clockwise = *clockwise;
    if (rpm) {
        m_spindle.rpm = *rpm;
        m_spindleSet = true;
    } else if (!on && !clockwise) {
        return m_out.error("SPINDL needs a speed, ON or OFF", s.argsPos);
    } else if (!m_spindleSet) {
        m_out.warn("SPINDL without a speed before any speed was set: ignored", s.wordPos);
        return {};
    }
    emit(m_spindle, s.line);
    return {};
}

base::Status AptReader::coolnt(const AptStatement& s, const Items& items)
{
    if (items.empty() || items[0].kind != AptItem::Kind::Word)
        return m_out.error("COOLNT needs ON, FLOOD, MIST, THRU or OFF", items.empty() ? s.argsPos : items[0].pos);
    const std::string& mode = items[0].word;
    if (mode == "ON" || mode == "FLOOD")
        emit(Coolant{CoolantMode::Flood}, s.line);
    else if (mode == "MIST")
        emit(Coolant{CoolantMode::Mist}, s.line);
    else if (mode == "THRU")
        emit(Coolant{CoolantMode::ThroughTool}, s.line);
    else if (mode == "OFF")
        emit(Coolant{CoolantMode::Off}, s.line);
    else
        m_out.warn("COOLNT/" + mode + " is not supported: ignored", items[0].pos);
    return {};
}

base::Status AptReader::cutcom(const AptStatement& s, const Items& items)
{
    bool on = false;
    for (const AptItem& item : items) {
        if (item.isWord("LEFT") || item.isWord("RIGHT") || item.isWord("OFF")) {
            const CutterCompSide side = item.word == "LEFT"    ? CutterCompSide::Left
                                        : item.word == "RIGHT" ? CutterCompSide::Right
                                                               : CutterCompSide::Off;
            emit(CutterComp{side}, s.line);
            return {};
        }
        on = on || item.isWord("ON");
    }
    if (on) {
        m_out.warn("CUTCOM/ON without LEFT or RIGHT ignored", s.wordPos);
        return {};
    }
    return m_out.error("CUTCOM needs LEFT, RIGHT or OFF", s.argsPos);
}

base::Status AptReader::cutter(const AptStatement& s, const Items& items, bool tldata)
{
    std::size_t first = 0;
    std::string kind;
    if (tldata) {
        if (items.empty() || !(items[0].isWord("MILL") || items[0].isWord("DRILL"))) {
            m_out.warn("TLDATA other than MILL or DRILL ignored", s.wordPos);
            return {};
        }
        kind = items[0].word == "DRILL" ? "drill" : "";
        first = 1;
    }
    std::vector<double> values;
    for (std::size_t i = first; i < items.size(); ++i) {
        if (items[i].kind != AptItem::Kind::Number) {
            m_out.warn(s.words.front() + " with " + items[i].word + " is not supported: ignored", items[i].pos);
            return {};
        }
        values.push_back(items[i].number);
    }
    if (values.empty() || values[0] <= 0)
        return m_out.error(s.words.front() + " needs a diameter > 0", values.empty() ? s.argsPos : items[first].pos);
    const double d = length(values[0]);
    const double r = values.size() > 1 && kind.empty() ? length(values[1]) : 0;
    if (kind.empty())
        kind = r <= 0 ? "flat" : std::abs(r - d / 2) < 1e-6 ? "ball" : "bull";
    m_cutter = Tool{};
    m_cutterFresh = true;
    m_cutter.kind = kind;
    m_cutter.diameterMm = d;
    m_cutter.cornerRadiusMm = r;
    if (!tldata && values.size() >= 7)
        m_cutter.fluteLengthMm = length(values[6]);
    if (tldata && kind != "drill" && values.size() >= 3)
        m_cutter.lengthMm = length(values[2]);
    if (m_toolChangeRecord) {
        // The load before had no geometry of its own: this describes that tool.
        Tool& loaded = std::get<ToolChange>(m_out.record(*m_toolChangeRecord)).tool;
        const int number = loaded.number;
        const std::string name = loaded.name;
        const double lengthMm = loaded.lengthMm;
        loaded = m_cutter;
        loaded.number = number;
        loaded.name = name;
        if (loaded.lengthMm == 0)
            loaded.lengthMm = lengthMm;
        m_knownTools[number] = loaded;
        m_cutterFresh = false;
    }
    return {};
}

base::Status AptReader::loadTool(const AptStatement& s, const Items& items, std::size_t numberIndex)
{
    if (items.size() <= numberIndex || items[numberIndex].kind != AptItem::Kind::Number)
        return m_out.error(s.words.front() + " needs a tool number",
                           items.size() > numberIndex ? items[numberIndex].pos : s.argsPos);
    const double number = items[numberIndex].number;
    if (number < 0 || number != std::floor(number) || number > 1e9)
        return m_out.error("tool number must be a whole number >= 0", items[numberIndex].pos);
    // Geometry is never taken from another tool: without a CUTTER/TLDATA since the last load it is
    // that of this tool number's earlier load, else unknown (0) until one follows the load.
    Tool tool;
    if (m_cutterFresh) {
        tool = m_cutter;
    } else if (const auto known = m_knownTools.find(static_cast<int>(number)); known != m_knownTools.end()) {
        tool = known->second;
    }
    tool.number = static_cast<int>(number);
    if (!m_nextToolName.empty() || m_cutterFresh)
        tool.name = m_nextToolName;
    m_nextToolName.clear();
    for (std::size_t i = numberIndex + 1; i + 1 < items.size(); ++i) {
        if (items[i].isWord("LENGTH") && items[i + 1].kind == AptItem::Kind::Number)
            tool.lengthMm = length(items[i + 1].number);
    }
    emit(ToolChange{tool}, s.line);
    m_knownTools[tool.number] = tool;
    if (m_cutterFresh)
        m_toolChangeRecord.reset();
    else
        m_toolChangeRecord = m_out.size() - 1;
    m_cutterFresh = false;
    return {};
}

base::Status AptReader::delay(const AptStatement& s, const Items& items)
{
    if (items.size() != 1 || items[0].kind != AptItem::Kind::Number || items[0].number < 0)
        return m_out.error("DELAY expects one time in seconds", items.empty() ? s.argsPos : items[0].pos);
    emit(Dwell{items[0].number}, s.line);
    return {};
}

base::Status AptReader::toolPath(const AptStatement& s)
{
    if (!s.hasSlash)
        return m_out.error("TOOL PATH needs '/' and the operation name", s.argsPos);
    // Operation and tool names are free text (NX allows characters the tokenizer would refuse).
    std::vector<std::string> parts;
    std::string_view rest = s.args.text();
    while (true) {
        const std::size_t comma = rest.find(',');
        parts.emplace_back(trim(rest.substr(0, comma)));
        if (comma == std::string_view::npos)
            break;
        rest.remove_prefix(comma + 1);
    }
    if (parts[0].empty())
        return m_out.error("TOOL PATH needs the operation name", s.argsPos);
    if (parts.size() >= 3 && toUpper(parts[1]) == "TOOL")
        m_nextToolName = parts[2];
    endCycle(s.line, true);
    m_toolChangeRecord.reset();
    SectionBegin section;
    section.operationName = parts[0];
    m_out.beginSection(std::move(section), s.line);
    return {};
}

base::Status AptReader::msys(const AptStatement& s, const Items& items)
{
    static const double identity[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    bool isIdentity = items.size() == 9;
    for (std::size_t i = 0; isIdentity && i < 9; ++i)
        isIdentity = items[i].kind == AptItem::Kind::Number && std::abs(items[i].number - identity[i]) < 1e-9;
    if (!isIdentity)
        m_out.warn("MSYS (machine coordinate system) is not applied: coordinates are read as written", s.wordPos);
    return {};
}

base::Status AptReader::endOfInput(int line)
{
    if (m_circle)
        return m_out.error("CIRCLE is not followed by the GOTO that ends it", m_circle->pos);
    endCycle(line, true);
    return {};
}

}  // namespace camwb::toolpath
