// Playing CL records through a post: each record becomes a handler call, or for moves without a
// handler a C++ block template. The kernel's policies apply on the way: arcs are split, or
// linearised where the post cannot write them; cycles the post does not write are expanded into
// moves; five-axis moves are refused by three-axis posts; cutter compensation must change on a
// straight move and works in XY.
#include "base/NumberFormat.h"
#include "kinematics/PoseSolver.h"
#include "post/detail/FiveAxisWriter.h"
#include "post/detail/ScriptRun.h"
#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/MachineSink.h"
#include "toolpath/PlaneFrames.h"
#include "toolpath/RecordNames.h"

#include <cmath>
#include <map>

namespace camwb::post {

using namespace toolpath;

namespace {

QString qs(const std::string& text) { return QString::fromStdString(text); }

int compCode(CutterCompSide side)
{
    return side == CutterCompSide::Left ? 41 : side == CutterCompSide::Right ? 42 : 40;
}

// The feed kind as block templates take it (toolpath::FeedKind's value).
template <typename Move> int feedKindOf(const Move& move) { return static_cast<int>(move.feedKind); }

// A message once per run for something that happened `count` times, first at `first`.
struct Tally {
    long long first = -1;
    int count = 0;
    void add(long long record)
    {
        if (count++ == 0)
            first = record;
    }
};

}  // namespace

class ScriptSink : public MachineSink {
public:
    explicit ScriptSink(ScriptRun& run) : m_run(run), m_caps(run.m_capabilities) {}

    void rapid(const Rapid& r) override;
    void linear(const Linear& r) override
    {
        if (!fiveAxis())
            straight(Handler::Linear, r.to, r.axes, r.feedMmPerMin, feedKindOf(r));
    }
    void arc(const Arc& r) override;
    void cycle(const Cycle& r) override;
    void toolChange(const ToolChange& r) override
    {
        m_toolRadius = r.tool.diameterMm / 2;
        handle(Handler::ToolChange, {toolObject(r.tool)});
        // The tool changer moves the machine where the post cannot know: no axis is known until
        // a move gives it, and the first rapid goes over in X/Y before it moves Z (rapid()).
        m_run.m_kernel->forgetPosition();
        m_afterToolChange = true;
    }
    void spindle(const Spindle& r) override
    {
        m_spindle = {r.rpm, r.clockwise};
        // Under constant surface speed (a lathe's G96) rpm is the limit and the third argument the
        // surface speed in m/min; 0 otherwise.
        handle(Handler::Spindle, {r.rpm, r.clockwise, r.surfaceSpeedMPerMin});
    }
    void coolant(const Coolant& r) override { handle(Handler::Coolant, {QString(toolpath::name(r.mode))}); }
    void feedMode(const FeedModeChange& r) override
    {
        m_inverseTime = r.mode == FeedMode::InverseTime;
        handle(Handler::FeedMode, {QString(toolpath::name(r.mode))});
    }
    void workOffset(const WorkOffset& r) override { handle(Handler::WorkOffset, {r.index}); }
    void dwell(const Dwell& r) override { handle(Handler::Dwell, {r.seconds}); }
    void toolAxisMove(const ToolAxisMove& r) override
    {
        if (fiveAxis())
            return;
        // Along +Z: a three-axis move, outside the five-axis sections of a machine's chain too.
        if (alongZ(r.axis) && (m_caps.maxAxes < 5 || m_five)) {
            straight(r.feedMmPerMin > 0 ? Handler::Linear : Handler::Rapid, r.tip, {}, r.feedMmPerMin);
            return;
        }
        if (m_caps.maxAxes < 5) {
            m_run.fail("five-axis move (tool axis " + base::formatFixed(r.axis.x, 6) + ", " +
                       base::formatFixed(r.axis.y, 6) + ", " + base::formatFixed(r.axis.z, 6) + ") but post " +
                       m_run.m_postId + " drives " + std::to_string(m_caps.maxAxes) + " axes");
            return;
        }
        if (!m_run.has(Handler::Linear5D)) {
            m_run.fail("five-axis move but " +
                       (m_run.m_machine ? "machine " + m_run.m_machine->id + " has no five-axis kinematic chain"
                                        : std::string("no machine is given")) +
                       ": post " + m_run.m_postId + " writes five-axis moves through the machine's kinematics");
            return;
        }
        m_afterToolChange = false;
        handle(Handler::Linear5D, {r.tip.x, r.tip.y, r.tip.z, r.axis.x, r.axis.y, r.axis.z, r.feedMmPerMin});
        m_run.m_kernel->setPosition(r.tip);
    }
    void cutterComp(const CutterComp& r) override
    {
        m_compChanged = m_compChanged || r.side != m_comp;
        m_comp = r.side;
        handle(Handler::CutterComp, {QString(toolpath::name(r.side))});
    }
    void comment(const Comment& r) override { handle(Handler::Comment, {qs(r.text)}); }
    void sectionBegin(const SectionBegin& r) override
    {
        QJSValue section = engine().newObject();
        section.setProperty("operationName", qs(r.operationName));
        section.setProperty("strategy", qs(r.strategy));
        section.setProperty("toolNumber", r.toolNumber);
        section.setProperty("operationIndex", m_operation);
        QJSValue feeds = engine().newObject();
        feeds.setProperty("cutting", r.feeds.cuttingMmPerMin);
        feeds.setProperty("plunge", r.feeds.plungeMmPerMin);
        feeds.setProperty("entry", r.feeds.entryMmPerMin);
        feeds.setProperty("exit", r.feeds.exitMmPerMin);
        feeds.setProperty("finishing", r.feeds.finishingMmPerMin);
        section.setProperty("feeds", feeds);
        // section.parameters.R3 etc.: the strategy's inputs, for a post that writes the strategy itself.
        QJSValue parameters = engine().newObject();
        for (const auto& [name, value] : r.strategyParameters)
            parameters.setProperty(qs(name), value);
        section.setProperty("parameters", parameters);
        if (!m_run.setSectionProperties(r.postProperties))
            return;
        handle(Handler::Section, {section});
    }
    // The operation's own property values hold through onSectionEnd, then the job's again.
    void sectionEnd(const SectionEnd&) override
    {
        handle(Handler::SectionEnd, {});
        m_run.setSectionProperties({});
    }
    void programStop(const ProgramStop& r) override { handle(Handler::Stop, {r.optional}); }
    void passThrough(const PassThrough& r) override { handle(Handler::PassThrough, {qs(r.text)}); }
    // Read back from NC (an untraced M140 MB MAX, G53 or SUPA move): no post can write a move to a
    // place the CL does not give, and leaving it out would run the next moves from the wrong place.
    void unknownAxes(const UnknownAxes& r) override
    {
        m_run.fail("the CL moves " + toolpath::axisNames(r.axes, 'X') +
                   " to a place it does not give (a retract or a machine-coordinate " +
                   "move read back from NC): post " + m_run.m_postId + " cannot write that move");
    }
    void workingPlane(const WorkingPlane& r) override
    {
        if (!m_run.has(Handler::WorkingPlane)) {
            if (r.tilted())
                m_run.fail("3+2 working plane (tool axis " + base::NumberFormat{6, true}.format(r.zAxis.x) + ", " +
                           base::NumberFormat{6, true}.format(r.zAxis.y) + ", " +
                           base::NumberFormat{6, true}.format(r.zAxis.z) + ") but post " + m_run.m_postId +
                           " has no onWorkingPlane: it cannot tilt the working plane");
            return;
        }
        auto vector = [this](const Vec3& v) {
            QJSValue o = engine().newObject();
            o.setProperty("x", v.x);
            o.setProperty("y", v.y);
            o.setProperty("z", v.z);
            return o;
        };
        QJSValue plane = engine().newObject();
        plane.setProperty("origin", vector(r.origin));
        plane.setProperty("xAxis", vector(r.xAxis));
        plane.setProperty("yAxis", vector(r.yAxis()));
        plane.setProperty("zAxis", vector(r.zAxis));
        plane.setProperty("tilted", r.tilted());
        // The spatial angles of the rotation (toolpath/PlaneFrames.h: about the fixed X, Y, Z).
        const std::array<double, 3> angles = toolpath::spatialAngles(r);
        plane.setProperty("spatialA", angles[0]);
        plane.setProperty("spatialB", angles[1]);
        plane.setProperty("spatialC", angles[2]);
        // The machine's pose for the plane, as the kinematics chooses it without a previous pose
        // (the preferred branch): a post writes the branch the control should take (SEQ, _DIR).
        const kinematics::Machine* machine = m_run.m_machine ? &*m_run.m_machine : nullptr;
        if (r.tilted() && machine != nullptr && machine->kinematics.fiveAxis()) {
            auto pose = kinematics::PoseSolver(*machine).solve({r.origin, r.zAxis}, nullptr);
            if (!pose) {
                m_run.fail("working plane with tool axis (" + base::NumberFormat{6, true}.format(r.zAxis.x) + ", " +
                           base::NumberFormat{6, true}.format(r.zAxis.y) + ", " +
                           base::NumberFormat{6, true}.format(r.zAxis.z) + "): " + pose.error().message);
                return;
            }
            QJSValue rotary = engine().newObject();
            for (int j = 0; j < 2; ++j)
                rotary.setProperty(QString::fromStdString(machine->kinematics.joints[j].axis).toLower(),
                                   pose->pose.rotaryDeg[j]);
            rotary.setProperty("branch", pose->branch);
            // A control that tilts by the machine's axis angles (CYCL DEF 19) sets up the machine's
            // X as the table carries it: the plane's X lies this many degrees from it about the
            // tool axis (counter-clockwise seen from +Z), which the post turns by (CYCL DEF 10).
            const kinematics::TiltedAxes tilted = kinematics::tiltedAxes(machine->kinematics, pose->pose.rotaryDeg);
            rotary.setProperty("rotation", std::atan2(tilted.x.cross(r.xAxis).dot(r.zAxis), tilted.x.dot(r.xAxis)) *
                                               180 / std::acos(-1.0));
            plane.setProperty("machine", rotary);
        }
        handle(Handler::WorkingPlane, {plane});
        // The coordinates that follow are in another frame: no axis value written before means
        // anything there, so every axis is written again, and the first rapid goes over in X/Y
        // before it goes down, as after a tool change.
        m_run.m_kernel->forgetPosition();
        m_afterToolChange = true;
    }
    void setSource(const SourceRef& source) override
    {
        m_operation = source.operationIndex;
        m_run.m_kernel->mainWriter().setOperation(source.operationIndex);
    }

    QJSValue toolObject(const Tool& t)
    {
        QJSValue tool = engine().newObject();
        tool.setProperty("number", t.number);
        tool.setProperty("name", qs(t.name));
        tool.setProperty("kind", qs(t.kind));
        tool.setProperty("diameter", t.diameterMm);
        tool.setProperty("cornerRadius", t.cornerRadiusMm);
        tool.setProperty("fluteLength", t.fluteLengthMm);
        tool.setProperty("length", t.lengthMm);
        tool.setProperty("flutes", t.flutes);
        tool.setProperty("pointAngle", t.pointAngleDeg);
        tool.setProperty("holder", qs(t.holder));
        return tool;
    }

    // The five-axis sections of the program, planned before it is played.
    void startFiveAxis(FiveAxisPlan plan) { m_five.emplace(m_run, std::move(plan)); }

    // Warnings for what this run could not write as the CL said, once per kind.
    void report(std::vector<base::Diagnostic>& messages) const
    {
        if (m_five)
            m_five->report(messages);
        auto warn = [&messages, &file = m_run.m_postFile](std::string text) {
            messages.push_back(base::warningDiagnostic(std::move(text), file));
        };
        for (const auto& [what, count] : m_unhandled)
            warn("post " + m_run.m_postId + " has no handler for " + what + "; " + counted(count, "record", "records") +
                 " not output");
        if (m_missingFeed.count > 0)
            warn(counted(m_missingFeed.count, "feed move", "feed moves") +
                 " without a feed rate: F not written (first: CL record " + std::to_string(m_missingFeed.first) + ")");
        if (m_shortCompEntry.count > 0)
            warn(counted(m_shortCompEntry.count, "cutter compensation entry move", "cutter compensation entry moves") +
                 " not longer than the tool radius: the control may refuse it (first: CL record " +
                 std::to_string(m_shortCompEntry.first) + ")");
        for (const auto& [reason, tally] : m_linearised)
            warn(counted(tally.count, "arc", "arcs") + " " + reason + ": written as lines within " +
                 base::NumberFormat{6, true}.format(m_caps.toleranceMm) + " mm (first: CL record " +
                 std::to_string(tally.first) + ")");
    }

private:
    QJSEngine& engine() { return m_run.m_engine; }

    void handle(Handler handler, const QJSValueList& args)
    {
        if (!m_run.has(handler)) {
            ++m_unhandled[std::string(m_run.m_recordName) + " (" + handlerName(handler) + ")"];
            return;
        }
        m_run.call(handler, args);
    }

    // A straight move to the axes `axes` gives; the others stay, and stay unwritten while unknown.
    void straight(Handler handler, const Vec3& to, AxisMask axes, double feed, int feedKind = 0);
    // An inverse-time feed says in how many minutes the whole move takes: each of n pieces is n times faster.
    double pieceFeed(double feed, std::size_t pieces) const
    {
        return m_inverseTime ? feed * static_cast<double>(pieces) : feed;
    }
    void arcPiece(const ArcPiece& piece, const Arc& arc, int pieceIndex, int pieces);
    // What a template could not write: a value beyond its format stops the run (false), a missing
    // feed is counted for the warning at the end.
    bool handleIssues(const BlockTemplate::Issues& issues)
    {
        if (issues.missingFeed)
            m_missingFeed.add(m_run.m_recordIndex);
        if (issues.beyondMax.empty())
            return true;
        m_run.fail(issues.beyondMax);
        return false;
    }
    void expandHole(const Cycle& cycle, const Vec3& hole);
    // A move of a five-axis section goes to FiveAxisWriter (true); after the section's last the
    // machine stands where the post's onFiveAxisEnd left it: unknown, as after a tool change.
    bool fiveAxis()
    {
        if (!m_five || !m_five->owns(m_run.m_recordIndex))
            return false;
        m_afterToolChange = false;
        if (m_five->writeRecord(m_comp != CutterCompSide::Off)) {
            m_run.m_kernel->forgetPosition();
            m_afterToolChange = true;
        }
        return true;
    }

    ScriptRun& m_run;
    const PostCapabilities& m_caps;
    std::map<std::string, int> m_unhandled;
    std::map<std::string, Tally> m_linearised;  // by reason
    Tally m_missingFeed;
    SpindleState m_spindle;
    CutterCompSide m_comp = CutterCompSide::Off;
    double m_toolRadius = 0;
    Tally m_shortCompEntry;
    bool m_inverseTime = false;
    bool m_compChanged = false;      // since the last straight move
    bool m_afterToolChange = false;  // no motion since the last tool change
    int m_operation = -1;
    std::optional<FiveAxisWriter> m_five;
};

void ScriptSink::rapid(const Rapid& r)
{
    if (fiveAxis())
        return;
    // After a tool change the machine stands where the changer left it, at a height the post does
    // not know: a first rapid that gives X or Y and Z moves X/Y at that height and only then Z,
    // never diagonally down from the tool change position. A CL whose first move gives Z alone
    // (a retract to its clearance plane) or X/Y alone already says the order, and keeps it.
    constexpr unsigned char kXY = AxisMask::kX | AxisMask::kY;
    if (std::exchange(m_afterToolChange, false) && r.axes.has(2) && (r.axes.bits & kXY)) {
        straight(Handler::Rapid, r.to, AxisMask{static_cast<unsigned char>(r.axes.bits & kXY)}, 0);
        if (!m_run.m_failure)
            straight(Handler::Rapid, r.to, AxisMask{AxisMask::kZ}, 0);
        return;
    }
    straight(Handler::Rapid, r.to, r.axes, 0);
}

void ScriptSink::straight(Handler handler, const Vec3& to, AxisMask axes, double feed, int feedKind)
{
    ScriptKernel& kernel = *m_run.m_kernel;
    m_afterToolChange = false;
    KnownPosition end = kernel.position();
    end.moveTo(to, axes);
    const std::optional<Vec3> start = kernel.position().point();
    if (m_compChanged && m_comp != CutterCompSide::Off && start && end.complete()) {
        // The control offsets the tool along the entry move: one no longer than the radius fails.
        const Vec3 entry = end.value() - *start;
        if (std::hypot(entry.x, entry.y) <= m_toolRadius)
            m_shortCompEntry.add(m_run.m_recordIndex);
    }
    const bool isLinear = handler == Handler::Linear;
    if (m_run.has(handler)) {
        // An axis nobody has given yet is null: VariableObject.format(null) writes no word.
        auto axis = [&](int index) {
            return end.known(index) ? QJSValue(end.value(index)) : QJSValue(QJSValue::NullValue);
        };
        if (isLinear)
            m_run.call(handler, {axis(0), axis(1), axis(2), feed});
        else
            m_run.call(handler, {axis(0), axis(1), axis(2)});
    } else if (std::optional<BlockTemplate>& block = isLinear ? m_run.m_templates.linear : m_run.m_templates.rapid) {
        MoveValues move;
        move.start = start.value_or(end.value());
        move.end = end.value();
        move.known = end.known();
        move.feed = feed;
        move.motion = isLinear ? 1 : 0;
        move.comp = compCode(m_comp);
        move.feedKind = feedKind;
        m_run.m_templates.writeBeforeMove(kernel.writer());
        BlockTemplate::Issues issues;
        if (block->write(move, kernel.writer(), issues))
            m_run.m_templates.finishMove(block->axisBits(), move.start, move.end, kernel.writer());
        handleIssues(issues);
    } else {
        ++m_unhandled[std::string(m_run.m_recordName) + " (" + handlerName(handler) + ")"];
    }
    m_compChanged = false;
    kernel.setPosition(end);  // getCurrentPosition() is the start point inside a handler
}

void ScriptSink::arc(const Arc& r)
{
    if (fiveAxis())
        return;
    ScriptKernel& kernel = *m_run.m_kernel;
    m_afterToolChange = false;
    const std::optional<Vec3> start = kernel.position().point();
    if (!start) {
        m_run.fail("arc with an unknown start point: no motion gave X, Y and Z before it (since the start or the "
                   "last tool change)");
        return;
    }
    if (m_compChanged) {
        m_run.fail("cutter compensation changes on an arc; controls need a straight move to start or end it");
        return;
    }
    const std::string plane = arcPlane(r.normal);
    if (m_comp != CutterCompSide::Off && plane != "XY") {
        m_run.fail("arc outside the XY plane with cutter compensation on: compensation works in XY");
        return;
    }
    // Splitting first also rejects degenerate arcs and gives the radius and helix test.
    const double maxSweep = m_caps.arcRadiusWords ? std::min(m_caps.maxArcSweepDeg, 359.9) : m_caps.maxArcSweepDeg;
    std::vector<ArcPiece> pieces = splitArc(*start, r, maxSweep);
    if (pieces.empty()) {
        m_run.fail("degenerate arc: zero radius");
        return;
    }
    if (pieces.front().helical && m_caps.maxHelixSweepDeg > maxSweep)  // helices in fewer, longer pieces
        pieces = splitArc(*start, r, m_caps.maxHelixSweepDeg);
    std::string reason;
    if (plane.empty())
        reason = "in an oblique plane";
    else if (std::find(m_caps.arcPlanes.begin(), m_caps.arcPlanes.end(), plane) == m_caps.arcPlanes.end())
        reason = "in the " + plane + " plane, which the post does not write";
    else if (pieces.front().helical && !m_caps.writesHelix(plane))
        reason = "helical in the " + plane + " plane, which the post does not write";
    else if (pieces.front().radius < m_caps.minArcRadiusMm || pieces.front().radius > m_caps.maxArcRadiusMm)
        reason = "outside the post's arc radius range";
    if (!reason.empty()) {
        m_linearised[reason].add(m_run.m_recordIndex);
        const std::vector<Vec3> points = linearizeArc(*start, r, m_caps.toleranceMm);
        for (const Vec3& point : points)
            straight(Handler::Linear, point, {}, pieceFeed(r.feedMmPerMin, points.size()), feedKindOf(r));
        return;
    }
    for (std::size_t i = 0; i < pieces.size() && !m_run.m_failure; ++i)
        arcPiece(pieces[i], r, static_cast<int>(i), static_cast<int>(pieces.size()));
    kernel.setPosition(r.to);
}

void ScriptSink::arcPiece(const ArcPiece& p, const Arc& arc, int pieceIndex, int pieces)
{
    ScriptKernel& kernel = *m_run.m_kernel;
    kernel.setPosition(p.start);
    // Radius words: a negative radius selects the arc longer than a half circle.
    const double radius = m_caps.arcRadiusWords && p.sweepDeg > 180 + 1e-9 ? -p.radius : p.radius;
    const std::string plane = arcPlane(p.normal);
    if (m_run.has(Handler::Circular)) {
        QJSValue info = engine().newObject();
        info.setProperty("plane", qs(plane));
        info.setProperty("normal", scriptPoint(engine(), p.normal));
        info.setProperty("helical", p.helical);
        info.setProperty("sweep", p.sweepDeg);
        info.setProperty("radius", radius);
        info.setProperty("start", scriptPoint(engine(), p.start));
        info.setProperty("turns", arc.turns);
        info.setProperty("piece", pieceIndex);
        info.setProperty("pieces", pieces);
        m_run.call(Handler::Circular, {p.clockwise, p.center.x, p.center.y, p.center.z, p.end.x, p.end.y, p.end.z,
                                       pieceFeed(arc.feedMmPerMin, static_cast<std::size_t>(pieces)), info});
    } else if (ArcBlocks* blocks = m_run.m_templates.arcBlocks(BlockTemplates::planeIndex(plane), p.helical)) {
        MoveValues move;
        move.start = p.start;
        move.end = p.end;
        if (p.sweepDeg < 360 - 1e-6 && blocks->back().endsWhereItStarts(move, BlockTemplates::planeIndex(plane))) {
            // Written as an arc it would read back as start = end, a full circle: a short straight move.
            straight(Handler::Linear, p.end, {}, pieceFeed(arc.feedMmPerMin, static_cast<std::size_t>(pieces)),
                     feedKindOf(arc));
            return;
        }
        move.center = p.center;
        move.radius = radius;
        move.feed = pieceFeed(arc.feedMmPerMin, static_cast<std::size_t>(pieces));
        move.feedKind = feedKindOf(arc);
        move.sweepDeg = p.sweepDeg;
        move.motion = p.clockwise ? 2 : 3;
        move.plane = 17 + BlockTemplates::planeIndex(plane);
        move.comp = compCode(m_comp);
        move.helical = p.helical;
        m_run.m_templates.writeBeforeMove(kernel.writer());
        BlockTemplate::Issues issues;
        unsigned boundAxes = 0;
        for (BlockTemplate& block : *blocks)
            if (block.write(move, kernel.writer(), issues))
                boundAxes |= block.axisBits();
            else if (!issues.beyondMax.empty())
                break;
        if (!handleIssues(issues))
            return;
        m_run.m_templates.finishMove(boundAxes, p.start, p.end, kernel.writer());
    } else if (pieceIndex == 0) {  // one count per arc, not per piece
        ++m_unhandled[std::string(m_run.m_recordName) + " (onCircular)"];
    }
    kernel.setPosition(p.end);
}

void ScriptSink::expandHole(const Cycle& cycle, const Vec3& hole)
{
    const KnownPosition& from = m_run.m_kernel->position();
    if (!from.known(2)) {
        m_run.fail("canned cycle from an unknown height: no motion gave Z before it (since the start or the last "
                   "tool change)");
        return;
    }
    if (const std::optional<std::string> why = tooManyPecks(cycle)) {
        m_run.fail(*why);
        return;
    }
    for (const Record& record : expandCycleHole(cycle, hole, from, m_spindle)) {
        if (m_run.m_failure)
            return;
        dispatch(record, *this);
    }
}

void ScriptSink::cycle(const Cycle& c)
{
    m_afterToolChange = false;
    const std::string kind = toolpath::name(c.kind);
    const bool native =
        m_caps.cyclesDeclared ? m_caps.writesCycle(kind) : m_run.has(Handler::Cycle) || m_run.has(Handler::CyclePoint);
    if (!native) {
        for (const Vec3& hole : c.holes)
            expandHole(c, hole);
        return;
    }
    QJSValue cycle = engine().newObject();
    cycle.setProperty("kind", qs(kind));
    cycle.setProperty("clearanceZ", c.clearanceZ);
    cycle.setProperty("retractZ", c.retractZ);
    cycle.setProperty("returnZ", cycleReturnZ(c));
    cycle.setProperty("returnToClearance", c.returnToClearance);
    cycle.setProperty("topZ", c.topZ);
    cycle.setProperty("bottomZ", c.bottomZ);
    cycle.setProperty("peck", c.peckMm);
    cycle.setProperty("dwell", c.dwellSeconds);
    cycle.setProperty("feed", c.feedMmPerMin);
    cycle.setProperty("spindleRpm", m_spindle.rpm);
    cycle.setProperty("spindleClockwise", m_spindle.clockwise);
    cycle.setProperty("peckClearance", kPeckClearanceMm);  // what the kernel's expansion uses
    QJSValue holes = engine().newArray(static_cast<uint>(c.holes.size()));
    for (std::size_t i = 0; i < c.holes.size(); ++i)
        holes.setProperty(static_cast<quint32>(i), scriptPoint(engine(), c.holes[i]));
    cycle.setProperty("holes", holes);

    ScriptKernel& kernel = *m_run.m_kernel;
    if (!m_run.call(Handler::Cycle, {cycle}))
        return;
    for (const Vec3& hole : c.holes) {
        if (m_run.has(Handler::CyclePoint)) {
            kernel.setCycleExpander([this, &c](const Vec3& point) { expandHole(c, point); });
            const bool ok = m_run.call(Handler::CyclePoint, {hole.x, hole.y, hole.z});
            kernel.setCycleExpander({});
            if (!ok)
                return;
        }
        // After each hole the tool stands over it at the return plane.
        kernel.setPosition(Vec3{hole.x, hole.y, cycleReturnZ(c)});
    }
    m_run.call(Handler::CycleEnd, {cycle});
}

base::Status ScriptRun::play(const Toolpath& toolpath, const ProgramSummary& summary)
{
    ScriptSink sink(*this);
    QJSValue program = m_engine.newObject();
    program.setProperty("workOffset", summary.firstWorkOffset);
    QJSValue tools = m_engine.newArray(static_cast<uint>(summary.tools.size()));
    for (std::size_t i = 0; i < summary.tools.size(); ++i)
        tools.setProperty(static_cast<quint32>(i), sink.toolObject(summary.tools[i]));
    program.setProperty("tools", tools);
    if (summary.hasMotion) {
        QJSValue extents = m_engine.newObject();
        QJSValue min = scriptPoint(m_engine, summary.min);
        QJSValue max = scriptPoint(m_engine, summary.max);
        for (int axis = 0; axis < 3; ++axis) {
            if (!summary.extentAxes.has(axis)) {  // no move gave this axis: no extent, not 0
                const QString name = QString(QChar('x' + axis));
                min.setProperty(name, QJSValue(QJSValue::NullValue));
                max.setProperty(name, QJSValue(QJSValue::NullValue));
            }
        }
        extents.setProperty("min", min);
        extents.setProperty("max", max);
        program.setProperty("extents", extents);
    } else {
        program.setProperty("extents", QJSValue(QJSValue::NullValue));
    }

    if (m_capabilities.maxAxes >= 5 && m_machine && m_machine->kinematics.fiveAxis()) {
        auto plan = planFiveAxis(toolpath, *m_machine, m_fiveAxis.options, m_capabilities.toleranceMm);
        if (!plan)
            return base::makeError(plan.error().message, m_postFile);
        sink.startFiveAxis(std::move(plan).value());
    }
    m_recordIndex = -1;
    call(Handler::Open, {program});
    for (std::size_t i = 0; i < toolpath.size() && !m_failure; ++i) {
        m_recordIndex = static_cast<long long>(i);
        m_recordName = toolpath::recordName(toolpath.record(i));
        sink.setSource(toolpath.source(i));
        dispatch(toolpath.record(i), sink);
    }
    m_recordIndex = -1;
    m_kernel->mainWriter().setOperation(-1);
    if (!m_failure)
        call(Handler::Close, {});
    if (!m_failure && !m_kernel->openCompanion().empty())
        fail("openFile(\"" + m_kernel->openCompanion() + "\") was never closed: closeFile() before the run ends");
    if (m_failure)
        return *m_failure;
    sink.report(m_kernel->messages());
    return {};
}

}  // namespace camwb::post
