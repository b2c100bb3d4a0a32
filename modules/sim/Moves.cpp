#include "sim/Moves.h"

#include "base/Prefault.h"
#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/MachineSink.h"
#include "toolpath/Toolpath.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace camwb::sim {

using toolpath::AxisMask;
using toolpath::KnownPosition;

namespace {

constexpr double kMaxArcStepDeg = 10;
constexpr int kMaxPiecesPerArc = 200000;
constexpr int kMaxJointPieces = 4096;
constexpr double kPi = 3.14159265358979323846;

// Follows the records as a control would, turning motion into Moves.
class MoveBuilder : public toolpath::MachineSink {
public:
    MoveBuilder(MoveList& out, const MoveOptions& options) : m_out(out), m_options(options) {}

    void setRecord(std::uint32_t record, bool inError)
    {
        m_record = record;
        m_inError = inError;
    }
    void finish() { closeSection(); }

    void rapid(const toolpath::Rapid& r) override { straight(r.to, r.axes, MoveKind::Rapid, 0); }
    void linear(const toolpath::Linear& l) override { straight(l.to, l.axes, MoveKind::Feed, l.feedMmPerMin); }
    void arc(const toolpath::Arc& a) override;
    void toolChange(const toolpath::ToolChange& c) override
    {
        m_tool = c.tool.number;
        m_out.tools[c.tool.number] = c.tool;
        m_toolLengthMm = c.tool.lengthMm;
        pause(MoveKind::ToolChange, 0);
    }
    void spindle(const toolpath::Spindle& s) override
    {
        m_rpm = s.rpm;
        m_spindleCw = s.clockwise;
    }
    void coolant(const toolpath::Coolant&) override {}
    void feedMode(const toolpath::FeedModeChange& f) override { m_feedMode = f.mode; }
    void workOffset(const toolpath::WorkOffset&) override {}
    void dwell(const toolpath::Dwell& d) override { pause(MoveKind::Dwell, d.seconds); }
    void cycle(const toolpath::Cycle& c) override;
    void toolAxisMove(const toolpath::ToolAxisMove& m) override;
    void cutterComp(const toolpath::CutterComp&) override {}
    void comment(const toolpath::Comment&) override {}
    void sectionBegin(const toolpath::SectionBegin& s) override
    {
        closeSection();
        m_section = MoveSection{s.operationName, s.toolNumber, m_out.moves.size(), m_out.moves.size()};
        m_inSection = true;
    }
    void sectionEnd(const toolpath::SectionEnd&) override { closeSection(); }
    void programStop(const toolpath::ProgramStop&) override { pause(MoveKind::Stop, 0); }
    void passThrough(const toolpath::PassThrough&) override {}
    // Nothing is cut or timed from an unknown place; the move that makes the position whole again
    // is cut where it ends (straight(), toolAxisMove()).
    void unknownAxes(const toolpath::UnknownAxes& u) override { m_local.forget(u.axes); }
    void workingPlane(const toolpath::WorkingPlane& plane) override
    {
        if (const auto p = m_local.point())
            m_local.set(plane.toLocal(m_plane.toWorkpiece(*p)));  // the same point in the new frame
        else
            m_local.forget();  // a partly known point cannot be carried into a turned frame
        m_plane = plane;
        turnTo(plane.zAxis);
    }

private:
    void closeSection()
    {
        if (!m_inSection)
            return;
        m_section.endMove = m_out.moves.size();
        if (m_section.tool == 0)
            m_section.tool = m_tool;
        m_out.sections.push_back(m_section);
        m_inSection = false;
    }

    Move base(MoveKind kind) const
    {
        Move m;
        m.kind = kind;
        m.tool = m_tool;
        m.record = m_record;
        m.spindleRpm = m_rpm;
        m.setAxis(m_axis);
        m.setFromMachine(m_machine);
        m.setToMachine(m_machine);
        return m;
    }

    // The feed of a move of `lengthMm` at programmed `feed` in the current mode.
    void setFeed(Move& m, double feed, double fraction) const
    {
        if (m.kind != MoveKind::Feed)
            return;
        switch (m_feedMode) {
        case toolpath::FeedMode::PerMinute:
            m.feedMmPerMin = feed;
            break;
        case toolpath::FeedMode::PerRevolution:
            m.feedMmPerMin = feed * m_rpm;
            break;
        case toolpath::FeedMode::InverseTime:
            m.minutes = feed > 0 ? fraction / feed : 0;
            break;
        }
    }

    void pause(MoveKind kind, double seconds)
    {
        if (m_inError)
            return;
        const auto p = m_local.point();
        Move m = base(kind);
        m.positionKnown = p.has_value();  // the time counts even before the first move
        if (p)
            m.from = m.to = m_plane.toWorkpiece(*p);
        m.seconds = seconds;
        m_out.moves.push_back(std::move(m));
    }

    void push(const Vec3& fromLocal, const Vec3& toLocal, MoveKind kind, double feed, double fraction, bool fromArc)
    {
        Move m = base(kind);
        m.from = m_plane.toWorkpiece(fromLocal);
        m.to = m_plane.toWorkpiece(toLocal);
        m.fromArc = fromArc;
        setFeed(m, feed, fraction);
        m_out.moves.push_back(std::move(m));
    }

    void straight(const Vec3& to, AxisMask axes, MoveKind kind, double feed)
    {
        turnTo(m_plane.zAxis);
        const std::optional<Vec3> from = m_local.point();
        const toolpath::AxisMask unknownBefore = unknownAxes();
        m_local.moveTo(to, axes);
        const std::optional<Vec3> end = m_local.point();
        if (!from) {
            untraced(kind, unknownBefore);
            if (!end)
                return;
            // The move that makes the position whole (the program's first, or the first after an
            // untraced move) leaves the tool standing at `end`, wherever it came from: that pose is
            // a move of its own (from == to), so a rapid that ends in the stock is the crash it is.
            // The way there is not known and not cut.
            if (!m_inError)
                push(*end, *end, kind, feed, 1.0, false);
            return;
        }
        if (m_inError || base::distance(*from, *end) < 1e-12)
            return;
        push(*from, *end, kind, feed, 1.0, false);
    }

    // The axes not known yet, in the working plane's frame.
    toolpath::AxisMask unknownAxes() const
    {
        return toolpath::AxisMask{static_cast<unsigned char>(toolpath::AxisMask::kAll & ~m_local.known().bits)};
    }

    // Names the record in MoveList::untraced (one in error is reported as such already).
    void untraced(MoveKind kind, toolpath::AxisMask unknown)
    {
        if (!m_inError)
            m_out.untraced.push_back({m_record, kind, unknown, m_out.moves.size()});
    }

    // The tool's axis becomes `axis` (a new working plane, or three-axis moves after five-axis
    // ones). The machine turns its rotary axes for that before the next move; where the tool is
    // known that turn is a move of its own, about the standing tip, so that its time and its
    // axis speeds count (a jump would be an infinite speed). The rotary positions are unknown
    // from there until a move gives them again.
    void turnTo(const Vec3& axis)
    {
        const Vec3 to = axis.normalized();
        if (m_axis.angleTo(to) < 1e-9)
            return;
        const std::optional<Vec3> p = m_local.point();
        if (p && !m_inError) {
            Move m = base(MoveKind::Rapid);
            m.from = m.to = m_plane.toWorkpiece(*p);
            m.setToAxis(to);
            m.fiveAxis = true;
            m.setToMachine({});
            m_out.moves.push_back(std::move(m));
        }
        m_axis = to;
        m_machine = {};
    }

    void splitJoint(const toolpath::ToolAxisMove& m, Move piece, const Vec3& fromTip);

    MoveList& m_out;
    const MoveOptions& m_options;
    KnownPosition m_local;  // in the working plane's frame
    toolpath::WorkingPlane m_plane;
    Vec3 m_axis{0, 0, 1};
    toolpath::RotaryAxes m_machine{};
    toolpath::FeedMode m_feedMode = toolpath::FeedMode::PerMinute;
    double m_rpm = 0;
    bool m_spindleCw = true;
    int m_tool = 0;
    double m_toolLengthMm = 0;
    std::uint32_t m_record = 0;
    bool m_inError = false;
    MoveSection m_section;
    bool m_inSection = false;
};

void MoveBuilder::arc(const toolpath::Arc& a)
{
    turnTo(m_plane.zAxis);
    const std::optional<Vec3> from = m_local.point();
    if (!from) {
        untraced(MoveKind::Feed, unknownAxes());
        m_local.moveTo(a.to, AxisMask{});
        return;
    }
    m_local.set(a.to);
    if (m_inError)
        return;
    const std::vector<Vec3> points =
        toolpath::linearizeArc(*from, a, m_options.chordToleranceMm, kMaxArcStepDeg, kMaxPiecesPerArc);
    double total = 0;
    Vec3 p = *from;
    for (const Vec3& q : points) {
        total += base::distance(p, q);
        p = q;
    }
    // About the workpiece's Z and round (not a spiral between unequal radii): the stock may
    // sweep the arc itself rather than its chords.
    const Vec3 centre = m_plane.toWorkpiece(a.center);
    const Vec3 normal = m_plane.direction(a.normal);
    const double radius = base::distance(m_plane.toWorkpiece(*from).xy(), centre.xy());
    auto onCircle = [&](const Vec3& local) {
        return std::abs(base::distance(m_plane.toWorkpiece(local).xy(), centre.xy()) - radius) <= 1e-9 * (1 + radius);
    };
    const bool aboutZ = std::abs(normal.x) < 1e-12 && std::abs(normal.y) < 1e-12 && normal.z != 0 && radius > 1e-9 &&
                        std::all_of(points.begin(), points.end(), onCircle);
    const std::size_t first = m_out.moves.size();
    p = *from;
    for (const Vec3& q : points) {
        const double fraction = total > 0 ? base::distance(p, q) / total : 1.0 / points.size();
        if (base::distance(p, q) >= 1e-12)
            push(p, q, MoveKind::Feed, a.feedMmPerMin, fraction, true);
        p = q;
    }
    if (aboutZ)
        for (std::size_t k = first; k < m_out.moves.size(); ++k)
            m_out.moves[k].arcCentre = centre.xy(), m_out.moves[k].arcRadius = radius;
}

void MoveBuilder::cycle(const toolpath::Cycle& c)
{
    for (const Vec3& hole : c.holes) {
        if (!m_local.known(2)) {
            untraced(MoveKind::Feed, unknownAxes());  // nothing says how high the tool is over the hole
            continue;
        }
        for (const toolpath::Record& r : toolpath::expandCycleHole(c, hole, m_local, {m_rpm, m_spindleCw}))
            toolpath::dispatch(r, *this);
    }
}

void MoveBuilder::toolAxisMove(const toolpath::ToolAxisMove& m)
{
    // Five-axis moves are in the workpiece frame whatever plane was set before.
    const std::optional<Vec3> fromLocal = m_local.point();
    const std::optional<Vec3> from = fromLocal ? std::optional<Vec3>(m_plane.toWorkpiece(*fromLocal)) : std::nullopt;
    const toolpath::AxisMask unknownBefore = unknownAxes();
    const Vec3 fromAxis = m_axis;
    const toolpath::RotaryAxes fromMachine = m_machine;
    m_local.set(m_plane.toLocal(m.tip));
    m_axis = m.axis.normalized();
    m_machine = m.machine;
    Move piece = base(m.feedMmPerMin > 0 ? MoveKind::Feed : MoveKind::Rapid);
    piece.fiveAxis = true;
    piece.to = m.tip;
    if (!from) {  // the tool stands at the end of the way no one knows (as in straight())
        untraced(piece.kind, unknownBefore);
        if (!m_inError) {
            piece.from = piece.to;
            setFeed(piece, m.feedMmPerMin, 1.0);
            m_out.moves.push_back(std::move(piece));
        }
        return;
    }
    if (m_inError)
        return;
    piece.from = *from;
    piece.setFromAxis(fromAxis);
    piece.setToAxis(m_axis);
    piece.setFromMachine(fromMachine);
    piece.setToMachine(m.machine);
    setFeed(piece, m.feedMmPerMin, 1.0);
    if (m.jointInterpolated) {
        splitJoint(m, piece, *from);
        return;
    }
    if (base::distance(piece.from, piece.to) < 1e-12 && fromAxis.angleTo(m_axis) < 1e-12)
        return;
    m_out.moves.push_back(std::move(piece));
}

// The machine moves its joints evenly: the tip curves through the chain. Pieces double until the
// middle of each lies within the chord tolerance of its chord.
void MoveBuilder::splitJoint(const toolpath::ToolAxisMove& m, Move piece, const Vec3& fromTip)
{
    const kinematics::KinematicChain* chain = m_options.chain;
    piece.jointInterpolated = true;
    const bool known = chain && chain->fiveAxis() &&
                       std::all_of(chain->joints.begin(), chain->joints.end(), [&](const kinematics::RotaryJoint& j) {
                           return piece.fromMachine().of(j.axis) && piece.toMachine().of(j.axis);
                       });
    if (!known) {
        m_out.moves.push_back(std::move(piece));  // straight: nothing here knows how the tip curves
        return;
    }
    kinematics::MachinePose a, b;
    for (int i = 0; i < 2; ++i) {
        a.rotaryDeg[i] = *piece.fromMachine().of(chain->joints[i].axis);
        b.rotaryDeg[i] = *piece.toMachine().of(chain->joints[i].axis);
    }
    a.linear = kinematics::linearAxesFor(*chain, fromTip, a.rotaryDeg, m_toolLengthMm);
    b.linear = kinematics::linearAxesFor(*chain, m.tip, b.rotaryDeg, m_toolLengthMm);
    auto at = [&](double t) {
        kinematics::MachinePose p;
        p.linear = a.linear + (b.linear - a.linear) * t;
        for (int i = 0; i < 2; ++i)
            p.rotaryDeg[i] = a.rotaryDeg[i] + (b.rotaryDeg[i] - a.rotaryDeg[i]) * t;
        return kinematics::forwardKinematics(*chain, p, m_toolLengthMm);
    };
    int pieces = 1;
    std::vector<kinematics::ToolPose> poses;
    for (;;) {
        poses.clear();
        double worst = 0;
        for (int i = 0; i <= pieces; ++i)
            poses.push_back(at(double(i) / pieces));
        for (int i = 0; i < pieces; ++i) {
            const Vec3 mid = at((i + 0.5) / pieces).tip;
            worst = std::max(worst, base::distance(mid, (poses[i].tip + poses[i + 1].tip) * 0.5));
        }
        if (worst <= m_options.chordToleranceMm || pieces >= kMaxJointPieces)
            break;
        pieces *= 2;
    }
    const Move whole = piece;
    for (int i = 0; i < pieces; ++i) {
        Move p = whole;
        p.from = poses[i].tip;
        p.to = poses[i + 1].tip;
        p.setFromAxis(poses[i].axis);
        p.setToAxis(poses[i + 1].axis);
        p.minutes = whole.minutes / pieces;
        toolpath::RotaryAxes fromMachine = p.fromMachine(), toMachine = p.toMachine();
        for (int j = 0; j < 2; ++j) {
            const std::string& axis = chain->joints[j].axis;
            fromMachine.set(axis, a.rotaryDeg[j] + (b.rotaryDeg[j] - a.rotaryDeg[j]) * double(i) / pieces);
            toMachine.set(axis, a.rotaryDeg[j] + (b.rotaryDeg[j] - a.rotaryDeg[j]) * double(i + 1) / pieces);
        }
        p.setFromMachine(fromMachine);
        p.setToMachine(toMachine);
        m_out.moves.push_back(std::move(p));
    }
}

}  // namespace

Vec3 Move::axisAt(double u) const
{
    const Vec3& a = fromAxis();
    const Vec3& b = toAxis();
    const double angle = a.angleTo(b);
    if (angle < 1e-12 || angle > kPi - 1e-9)
        return a;
    const double s = std::sin(angle);
    return a * (std::sin((1 - u) * angle) / s) + b * (std::sin(u * angle) / s);
}

namespace {

// About how many moves buildMoves() makes of `program`, to reserve at once: a list that grows by
// doubling copies itself into fresh pages each time (on the 20k-block benchmark program, 156k
// moves, 232 bytes each then, the copies were 20,000 of the command's 32,000 page faults). Each arc is
// counted from where the record before it ended, whatever axes it gave; a straight move, a pause
// and a new working plane (the turn to it) are one each, a five-axis move two (it may be followed
// by a turn back). Only joint-interpolated five-axis moves, split along the tip's curve, and
// drilling cycles with many pecks can make more. Capped, so that a wild guess reserves no more
// than a long program's worth.
std::size_t movesEstimate(const toolpath::Toolpath& program, const MoveOptions& options)
{
    std::size_t count = 0;
    Vec3 at;
    for (std::size_t i = 0; i < program.size(); ++i) {
        const toolpath::Record& r = program.record(i);
        if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            count += std::size_t(
                toolpath::linearizedPointCount(at, *a, options.chordToleranceMm, kMaxArcStepDeg, kMaxPiecesPerArc));
            at = a->to;
        } else if (const auto* c = std::get_if<toolpath::Cycle>(&r)) {
            count += 8 * c->holes.size();  // a drilling cycle's moves per hole, pecks aside
        } else if (const auto* m = std::get_if<toolpath::Linear>(&r)) {
            at = m->to;
            ++count;
        } else if (const auto* q = std::get_if<toolpath::Rapid>(&r)) {
            at = q->to;
            ++count;
        } else if (std::holds_alternative<toolpath::ToolAxisMove>(r)) {
            count += 2;
        } else if (std::holds_alternative<toolpath::ToolChange>(r) || std::holds_alternative<toolpath::Dwell>(r) ||
                   std::holds_alternative<toolpath::ProgramStop>(r) ||
                   std::holds_alternative<toolpath::WorkingPlane>(r)) {
            ++count;
        }
    }
    return std::min(count, 16 * program.size() + 1024);
}

}  // namespace

Vec3 Move::pointAt(double u) const
{
    if (u <= 0)
        return from;
    if (u >= 1)
        return to;
    const double z = from.z + u * (to.z - from.z);
    if (arcRadius <= 0) {
        const Vec3 p = from + (to - from) * u;
        return {p.x, p.y, z};
    }
    const base::Vec2 a = from.xy() - arcCentre, b = to.xy() - arcCentre;
    const double angle = u * std::atan2(a.cross(b), a.dot(b));  // a piece turns less than half a turn
    const double c = std::cos(angle), s = std::sin(angle);
    return {arcCentre.x + c * a.x - s * a.y, arcCentre.y + s * a.x + c * a.y, z};
}

const toolpath::Tool* MoveList::tool(int number) const
{
    const auto it = tools.find(number);
    return it == tools.end() ? nullptr : &it->second;
}

MoveList buildMoves(const toolpath::Toolpath& program, const MoveOptions& options,
                    const std::vector<bool>& recordsInError)
{
    MoveList out;
    const std::size_t estimate = movesEstimate(program, options);
    out.moves.reserve(estimate);
    // Written all but whole: faulted in beside the building, not a fault per page in it.
    const base::PrefaultBeside ahead(out.moves.data(), estimate * sizeof(Move));
    MoveBuilder builder(out, options);
    builder.begin();
    for (std::size_t i = 0; i < program.size(); ++i) {
        builder.setRecord(static_cast<std::uint32_t>(i), i < recordsInError.size() && recordsInError[i]);
        toolpath::dispatch(program.record(i), builder);
    }
    builder.finish();
    builder.end();
    return out;
}

}  // namespace camwb::sim
