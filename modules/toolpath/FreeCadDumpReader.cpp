#include "toolpath/FreeCadDumpReader.h"

#include "toolpath/ClArcs.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <cmath>

namespace camwb::toolpath {

namespace {

constexpr double kSecondsPerMinute = 60;  // FreeCAD feeds are mm/s

// "G81" -> {'G', 81}; nullopt for names that are not a letter and a whole number.
std::optional<std::pair<char, int>> splitName(std::string_view name)
{
    if (name.size() < 2)
        return std::nullopt;
    const char letter = name[0] >= 'a' && name[0] <= 'z' ? static_cast<char>(name[0] - 'a' + 'A') : name[0];
    if (name.size() <= 4 && std::all_of(name.begin() + 1, name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        int code = 0;  // the usual "G1", "G01", "M6": digits only
        for (char c : name.substr(1))
            code = code * 10 + (c - '0');
        return std::pair<char, int>{letter, code};
    }
    const auto number = parseNumber(name.substr(1));
    if (!number || *number < 0 || *number > 999 || *number != std::floor(*number))
        return std::nullopt;
    return std::pair<char, int>{letter, static_cast<int>(*number)};
}

bool sameParameters(const Cycle& a, const Cycle& b)
{
    return a.kind == b.kind && a.clearanceZ == b.clearanceZ && a.retractZ == b.retractZ && a.topZ == b.topZ &&
           a.bottomZ == b.bottomZ && a.peckMm == b.peckMm && a.dwellSeconds == b.dwellSeconds &&
           a.feedMmPerMin == b.feedMmPerMin && a.returnToClearance == b.returnToClearance;
}

}  // namespace

base::Result<ClImport> readFreeCadDump(std::string_view text, const std::string& fileName)
{
    base::LineReader lines(text);
    return readFreeCadDump(lines, fileName);
}

base::Result<ClImport> readFreeCadDump(base::LineReader& lines, const std::string& fileName)
{
    return FreeCadDumpReader(lines, fileName).read();
}

FreeCadDumpReader::FreeCadDumpReader(base::LineReader& lines, std::string fileName) :
    m_lines(lines),
    m_out(std::move(fileName)),
    m_scanner(lines, m_out)
{
    m_out.expectText(lines.sizeBytes());
}

base::Result<ClImport> FreeCadDumpReader::read()
{
    while (true) {
        const base::Result<bool> more = m_scanner.next(m_entry);
        if (!more)
            return more.error();
        if (!more.value())
            break;
        if (auto status = entry(m_entry); !status)
            return status.error();
    }
    flushCycleRun();
    const int lastLine = m_lines.lineNumber();
    if (m_cycleMode)
        m_out.warn("canned cycle still active at the end of the dump (no G80)", lastLine);
    return m_out.finish(lastLine);
}

void FreeCadDumpReader::emit(Record record, int line)
{
    flushCycleRun();
    m_out.add(std::move(record), line);
}

void FreeCadDumpReader::flushCycleRun()
{
    if (!m_run)
        return;
    m_out.add(std::move(m_run->cycle), m_run->line);
    m_run.reset();
}

void FreeCadDumpReader::warnNoFeed(int line)
{
    if (!m_feedSet && !m_warnedNoFeed) {
        m_out.warn("feed motion before any F: its feed is 0", line);
        m_warnedNoFeed = true;
    }
}

base::Status FreeCadDumpReader::entry(const DumpEntry& e)
{
    const std::optional<std::string> justOpened = std::move(m_justOpened);
    m_justOpened.reset();
    if (e.kind == DumpEntry::Kind::Note) {
        if (e.name.rfind("Path:", 0) == 0) {
            // Each path object of the job starts afresh: no cycle mode carries over.
            flushCycleRun();
            m_cycleMode = false;
            m_cycleZ = m_cycleR = m_cycleQ = m_cycleP = std::nullopt;
            SectionBegin section;
            section.operationName = std::string(trim(std::string_view(e.name).substr(5)));
            m_justOpened = section.operationName;
            m_out.beginSection(std::move(section), e.line);
        } else {
            emit(Comment{e.name}, e.line);
        }
        return {};
    }
    if (e.name.empty()) {
        m_out.warn("Command without a name ignored", e.namePos);
        return {};
    }
    if (e.name.front() == '(') {
        std::string text(trim(std::string_view(e.name).substr(1, e.name.size() - 2)));
        // FreeCAD starts every object's path with its label as a comment: right after the
        // "(Path: label)" note that opened the section, it names the section a second time.
        if (justOpened && *justOpened == text)
            return {};
        emit(Comment{std::move(text)}, e.line);
        return {};
    }
    const auto name = splitName(e.name);
    if (name && name->first == 'G')
        return gCode(e, name->second);
    if (name && name->first == 'M')
        return mCode(e, name->second);
    m_out.warn("unknown command " + e.name + " ignored", e.namePos);
    return {};
}

base::Status FreeCadDumpReader::gCode(const DumpEntry& e, int code)
{
    switch (code) {
    case 0:
    case 1:
        return move(e, code == 0);
    case 2:
    case 3:
        return arc(e, code == 2);
    case 4: {
        const DumpParameter* p = e.find('P');
        if (!p || p->value < 0)
            return m_out.error("G4 needs P (the dwell in seconds, >= 0)", p ? p->pos : e.namePos);
        emit(Dwell{p->value}, e.line);
        return {};
    }
    case 17:
        m_planeNormal = {0, 0, 1};
        return {};
    case 18:
        m_planeNormal = {0, 1, 0};
        return {};
    case 19:
        m_planeNormal = {1, 0, 0};
        return {};
    case 20:
        return m_out.error("inch units (G20) are not supported in a FreeCAD dump: FreeCAD paths are in mm", e.namePos);
    case 21:
    case 90:
        return {};
    case 91:
        return m_out.error("incremental CL (G91) is not supported", e.namePos);
    case 40:
        emit(CutterComp{CutterCompSide::Off}, e.line);
        return {};
    case 41:
        emit(CutterComp{CutterCompSide::Left}, e.line);
        return {};
    case 42:
        emit(CutterComp{CutterCompSide::Right}, e.line);
        return {};
    case 73:
        return hole(e, CycleKind::ChipBreak);
    case 80:
        flushCycleRun();
        m_cycleMode = false;
        m_cycleZ = m_cycleR = m_cycleQ = m_cycleP = std::nullopt;
        return {};
    case 81:
        return hole(e, CycleKind::Drill);
    case 82:
        return hole(e, CycleKind::DrillDwell);
    case 83:
        return hole(e, CycleKind::Peck);
    case 84:
        return hole(e, CycleKind::Tap);
    case 85:
        return hole(e, CycleKind::Bore);
    case 98:
    case 99:
        m_returnToClearance = code == 98;
        return {};
    default:
        if (code >= 54 && code <= 59) {
            emit(WorkOffset{code - 53}, e.line);
            return {};
        }
        m_out.warn("unknown command " + e.name + " ignored", e.namePos);
        return {};
    }
}

base::Status FreeCadDumpReader::mCode(const DumpEntry& e, int code)
{
    switch (code) {
    case 0:
    case 1:
        emit(ProgramStop{code == 1}, e.line);
        return {};
    case 2:
    case 30:
        return {};
    case 3:
    case 4: {
        if (const DumpParameter* s = e.find('S')) {
            if (s->value < 0)
                return m_out.error("negative spindle speed", s->pos);
            m_spindle.rpm = s->value;
            m_spindleSet = true;
        } else if (!m_spindleSet) {
            return m_out.error(e.name + " without S and no speed before it", e.namePos);
        }
        m_spindle.clockwise = code == 3;
        emit(m_spindle, e.line);
        return {};
    }
    case 5:
        emit(Spindle{0, m_spindle.clockwise}, e.line);
        return {};
    case 6: {
        const DumpParameter* t = e.find('T');
        if (!t || t->value < 0 || t->value != std::floor(t->value) || t->value > 1e9)
            return m_out.error("M6 needs T (a whole tool number >= 0)", t ? t->pos : e.namePos);
        Tool tool;
        tool.number = static_cast<int>(t->value);
        emit(ToolChange{tool}, e.line);
        return {};
    }
    case 7:
        emit(Coolant{CoolantMode::Mist}, e.line);
        return {};
    case 8:
        emit(Coolant{CoolantMode::Flood}, e.line);
        return {};
    case 9:
        emit(Coolant{CoolantMode::Off}, e.line);
        return {};
    default:
        m_out.warn("unknown command " + e.name + " ignored", e.namePos);
        return {};
    }
}

base::Status FreeCadDumpReader::noRotaryAxes(const DumpEntry& e) const
{
    for (const char key : {'A', 'B', 'C'}) {
        if (const DumpParameter* p = e.find(key))
            return m_out.error(
                std::string("rotary axis ") + key + " is not supported (it needs the machine's kinematics)", p->pos);
    }
    return {};
}

std::optional<double> FreeCadDumpReader::feedOf(const DumpEntry& e)
{
    const DumpParameter* f = e.find('F');
    if (!f)
        return std::nullopt;
    m_feed = f->value * kSecondsPerMinute;
    m_feedSet = true;
    return m_feed;
}

Vec3 FreeCadDumpReader::target(const DumpEntry& e, AxisMask& given) const
{
    Vec3 to;
    given = AxisMask{0};
    for (int axis = 0; axis < 3; ++axis) {
        if (const DumpParameter* p = e.find(static_cast<char>('X' + axis))) {
            setAxisValue(to, axis, p->value);
            given.bits = static_cast<unsigned char>(given.bits | 1 << axis);
        } else if (m_position.known(axis)) {
            setAxisValue(to, axis, m_position.value(axis));
        }
    }
    return to;
}

base::Status FreeCadDumpReader::move(const DumpEntry& e, bool rapid)
{
    if (auto status = noRotaryAxes(e); !status)
        return status;
    if (!rapid)
        feedOf(e);
    m_cycleMode = false;
    AxisMask given;
    Vec3 to = target(e, given);
    if (given.none()) {
        if (rapid)
            m_out.warn("G0 without X, Y or Z ignored", e.namePos);
        return {};
    }
    // Only the axes the command gives: the others stay where they are, which the dump may not
    // have said yet ("G0 Z20" before the first X/Y), and the records never guess them.
    for (int axis = 0; axis < 3; ++axis) {
        if (!given.has(axis))
            setAxisValue(to, axis, 0);
    }
    if (rapid) {
        emit(Rapid{to, given}, e.line);
    } else {
        warnNoFeed(e.line);
        emit(Linear{to, m_feed, given}, e.line);
    }
    m_position.moveTo(to, given);
    return {};
}

base::Status FreeCadDumpReader::arc(const DumpEntry& e, bool clockwise)
{
    if (auto status = noRotaryAxes(e); !status)
        return status;
    if (const DumpParameter* r = e.find('R'))
        return m_out.error("arcs with R are not supported (FreeCAD writes I, J, K)", r->pos);
    if (!m_position.complete())
        return m_out.error("arc from an unknown position (no move with X, Y and Z before it)", e.namePos);
    m_cycleMode = false;
    const Vec3 start = m_position.value();
    feedOf(e);
    warnNoFeed(e.line);
    AxisMask given;
    const Vec3 to = target(e, given);  // complete: the start is
    auto value = [&](char key) {
        const DumpParameter* p = e.find(key);
        return p ? p->value : 0.0;
    };
    Vec3 offset{value('I'), value('J'), value('K')};
    offset = offset - m_planeNormal * offset.dot(m_planeNormal);
    if (offset.length() < 1e-12)
        return m_out.error("arc without a centre: I, J, K are 0 in the arc's plane", e.namePos);
    int turns = 0;
    if (const DumpParameter* p = e.find('P')) {
        if (p->value < 1 || p->value != std::floor(p->value) || p->value > 1e6)
            return m_out.error("P (turns) must be a whole number >= 1", p->pos);
        turns = static_cast<int>(p->value) - 1;
    }
    const Arc a = makeArc(start, to, start + offset, m_planeNormal, !clockwise, turns, m_feed);
    // The dumper rounds to 5 significant digits: allow for that at the size of the coordinates.
    const double magnitude = std::max(
        {std::abs(start.x), std::abs(start.y), std::abs(start.z), std::abs(to.x), std::abs(to.y), std::abs(to.z)});
    for (const std::string& problem : arcRadiusProblems(start, a, std::nullopt, 0.01 + 1e-4 * magnitude))
        m_out.warn(problem, e.line);
    emit(a, e.line);
    m_position.set(to);
    return {};
}

base::Status FreeCadDumpReader::hole(const DumpEntry& e, CycleKind kind)
{
    if (auto status = noRotaryAxes(e); !status)
        return status;
    feedOf(e);
    warnNoFeed(e.line);
    double xy[2] = {0, 0};
    for (int axis = 0; axis < 2; ++axis) {
        const DumpParameter* p = e.find(static_cast<char>('X' + axis));
        if (!p && !m_position.known(axis))
            return m_out.error(e.name + std::string(" needs ") + static_cast<char>('X' + axis) +
                                   " (no position before it)",
                               e.namePos);
        xy[axis] = p ? p->value : m_position.value(axis);
    }
    // Z, R, Q and P are modal within the cycle mode, as on the controls FreeCAD writes for.
    auto modal = [&](char key, std::optional<double>& slot, bool required, const char* what) -> base::Status {
        if (const DumpParameter* p = e.find(key))
            slot = p->value;
        if (required && !slot)
            return m_out.error(e.name + " needs " + key + " (" + what + ")", e.namePos);
        return {};
    };
    const bool pecks = kind == CycleKind::Peck || kind == CycleKind::ChipBreak;
    if (auto s = modal('Z', m_cycleZ, true, "the hole bottom"); !s)
        return s;
    if (auto s = modal('R', m_cycleR, true, "the R plane"); !s)
        return s;
    if (auto s = modal('Q', m_cycleQ, pecks, "the peck depth"); !s)
        return s;
    if (auto s = modal('P', m_cycleP, kind == CycleKind::DrillDwell, "the dwell in seconds"); !s)
        return s;
    if (pecks && !(*m_cycleQ > 0))
        return m_out.error(e.name + ": Q must be > 0", e.find('Q') ? e.find('Q')->pos : e.namePos);
    if (kind == CycleKind::DrillDwell && *m_cycleP < 0)
        return m_out.error(e.name + ": P must be >= 0", e.find('P') ? e.find('P')->pos : e.namePos);
    if (kind != CycleKind::DrillDwell && e.find('P'))
        m_out.warn("P ignored on " + e.name, e.find('P')->pos);

    Cycle c;
    c.kind = kind;
    c.retractZ = *m_cycleR;
    c.topZ = *m_cycleR;
    c.bottomZ = *m_cycleZ;
    c.peckMm = pecks ? *m_cycleQ : 0;
    c.dwellSeconds = kind == CycleKind::DrillDwell ? *m_cycleP : 0;
    c.feedMmPerMin = m_feed;
    c.returnToClearance = m_returnToClearance;
    if (const std::optional<std::string> why = tooManyPecks(c))  // as the NC interpreters refuse it
        return m_out.error(e.name + ": " + *why, e.find('Q') ? e.find('Q')->pos : e.namePos);
    const Vec3 hole{xy[0], xy[1], c.topZ};
    bool extends = false;
    if (m_run) {
        // The previous hole left the tool at its return plane; the run keeps its first clearance.
        c.clearanceZ = m_run->cycle.clearanceZ;
        extends = sameParameters(m_run->cycle, c);
    }
    if (extends) {
        m_run->cycle.holes.push_back(hole);
    } else {
        flushCycleRun();
        if (m_position.known(2)) {
            c.clearanceZ = m_position.value(2);
        } else {
            m_out.warn("no Z before the cycle: its clearance plane is taken as the R plane", e.namePos);
            c.clearanceZ = c.retractZ;
        }
        if (c.returnToClearance && c.clearanceZ < c.retractZ)
            m_out.warn("the cycle's clearance plane Z" + formatForMessage(c.clearanceZ) + " is below its R plane Z" +
                           formatForMessage(c.retractZ),
                       e.line);
        c.holes = {hole};
        m_run = CycleRun{c, e.line};
    }
    m_cycleMode = true;
    const Cycle& run = m_run->cycle;
    m_position.set({hole.x, hole.y, run.returnToClearance ? std::max(run.clearanceZ, run.retractZ) : run.retractZ});
    return {};
}

}  // namespace camwb::toolpath
