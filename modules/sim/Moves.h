// The simulator's input: a program (CL or NC read back) as straight pieces of tool motion in the
// workpiece frame, each with the state the simulator needs (feed on the tip, tool, spindle, the
// record it came from). Arcs are split within a chord tolerance, canned cycles expanded as a
// control makes them, working planes (3+2) applied, five-axis moves carry the tool axis at both
// ends. Motion in time, stock removal, the checks and the simulator dock all read this one list.
#pragma once

#include "base/Vec.h"
#include "kinematics/KinematicChain.h"
#include "toolpath/ClRecords.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sim {

using base::Vec3;

enum class MoveKind : std::uint8_t {
    Rapid,       // at the machine's rapid rate
    Feed,        // at feedMmPerMin on the tip, or in `minutes` (inverse time)
    Dwell,       // the tool stands for `seconds`
    ToolChange,  // the tool stands while the changer works (kinematics::Machine says how long)
    Stop,        // program stop (M0/M1): the tool stands; no time is counted
};

// The tool's axis at both ends of a move and the machine's rotary positions where the source gave
// them: what only moves that tilt or turn the tool need. A move of a vertical tool without rotary
// positions, as a three-axis program's all are, holds none of it (ToolTurnBox): a long program's
// moves are half the size.
struct ToolTurn {
    Vec3 fromAxis{0, 0, 1};  // unit, tip towards spindle, workpiece frame
    Vec3 toAxis{0, 0, 1};
    toolpath::RotaryAxes fromMachine{};
    toolpath::RotaryAxes toMachine{};
};

// A ToolTurn on the heap, copied with its move; empty: the vertical tool, no rotary positions.
class ToolTurnBox {
public:
    ToolTurnBox() = default;
    ToolTurnBox(const ToolTurnBox& other) : m_turn(other.m_turn ? std::make_unique<ToolTurn>(*other.m_turn) : nullptr)
    {
    }
    ToolTurnBox(ToolTurnBox&&) noexcept = default;
    ToolTurnBox& operator=(const ToolTurnBox& other)
    {
        if (this != &other)
            m_turn = other.m_turn ? std::make_unique<ToolTurn>(*other.m_turn) : nullptr;
        return *this;
    }
    ToolTurnBox& operator=(ToolTurnBox&&) noexcept = default;

    const ToolTurn& get() const { return m_turn ? *m_turn : kNone; }
    // The turn to change, made where there is none; nullptr where there is none and the value to
    // set is the default (`isDefault`): setting a default costs nothing.
    ToolTurn* edit(bool isDefault)
    {
        if (!m_turn && isDefault)
            return nullptr;
        if (!m_turn)
            m_turn = std::make_unique<ToolTurn>();
        return m_turn.get();
    }

private:
    static inline const ToolTurn kNone{};
    std::unique_ptr<ToolTurn> m_turn;
};

// One straight piece of motion (or a pause at `to` for the kinds that stand). The tip goes
// straight from `from` to `to` and the tool axis turns evenly from fromAxis() to toAxis() (a
// control's tool-tip control), unless `jointInterpolated`: then the machine moves its axes
// evenly from fromMachine() to toMachine() and MoveList has split the move so that the tip's
// curve stays within the chord tolerance of its pieces. Where the tool's axis changes between two
// moves (a new working plane, three-axis moves after five-axis ones), MoveList puts a turn about
// the standing tip between them: a Rapid with from == to, so its time and axis speeds count.
struct Move {
    Vec3 from;
    Vec3 to;
    MoveKind kind = MoveKind::Feed;
    bool fromArc = false;            // a piece of a split arc or helix
    bool fiveAxis = false;           // from a ToolAxisMove (the axis may turn)
    bool jointInterpolated = false;  // see above
    bool positionKnown = true;       // false: a pause before any move (from, to mean nothing)
    int tool = 0;                    // tool number in use (0: none yet); MoveList::tools has it
    std::uint32_t record = 0;        // index of the toolpath record it came from
    double feedMmPerMin = 0;         // Feed, per minute mode (per revolution: times the rpm)
    double minutes = 0;              // Feed in inverse time: the time this piece takes; else 0
    double seconds = 0;              // Dwell
    double spindleRpm = 0;           // 0: stopped
    // A piece of an arc or helix about the workpiece's Z axis: both ends lie on the circle of
    // arcRadius round arcCentre, and the tip follows the arc between them (the straight piece is
    // its chord). 0: not such a piece. The stock sweeps the arc itself, so that a block's pieces
    // cut one by one and the block cut in one pass leave the same stock (Stock::cutArcRun).
    base::Vec2 arcCentre;
    double arcRadius = 0;

    // The tool axis at the ends (unit, tip towards spindle, workpiece frame; vertical unless set)
    // and the machine's rotary positions where the source gave them (none unless set).
    const Vec3& fromAxis() const { return m_turn.get().fromAxis; }
    const Vec3& toAxis() const { return m_turn.get().toAxis; }
    const toolpath::RotaryAxes& fromMachine() const { return m_turn.get().fromMachine; }
    const toolpath::RotaryAxes& toMachine() const { return m_turn.get().toMachine; }
    void setFromAxis(const Vec3& axis)
    {
        if (ToolTurn* t = m_turn.edit(isVertical(axis)))
            t->fromAxis = axis;
    }
    void setToAxis(const Vec3& axis)
    {
        if (ToolTurn* t = m_turn.edit(isVertical(axis)))
            t->toAxis = axis;
    }
    void setAxis(const Vec3& axis) { setFromAxis(axis), setToAxis(axis); }  // both ends
    void setFromMachine(const toolpath::RotaryAxes& r)
    {
        if (ToolTurn* t = m_turn.edit(isNone(r)))
            t->fromMachine = r;
    }
    void setToMachine(const toolpath::RotaryAxes& r)
    {
        if (ToolTurn* t = m_turn.edit(isNone(r)))
            t->toMachine = r;
    }

    double lengthMm() const { return base::distance(from, to); }
    // The tool axis at `u` (0..1) of the move: turned evenly (the angle grows with u) from
    // fromAxis to toAxis. Opposite ends have no even turn between them: fromAxis, not a guess.
    Vec3 axisAt(double u) const;
    bool moves() const { return kind == MoveKind::Rapid || kind == MoveKind::Feed; }
    // Descends along Z more than it travels across (a vertical tool's plunge: a tool that does
    // not cut at its centre must not make it into material).
    bool plunges() const
    {
        const double down = from.z - to.z, dx = to.x - from.x, dy = to.y - from.y;
        return down > 0 && down * down > dx * dx + dy * dy;
    }
    // The tip at `u` (0..1) of the move: along the arc for an arc piece, else on the chord; the
    // ends are `from` and `to` exactly.
    Vec3 pointAt(double u) const;

private:
    // The defaults bit for bit (a -0 is kept: an angle worked out from it may differ).
    static bool zero(double v) { return v == 0 && !std::signbit(v); }
    static bool isVertical(const Vec3& a) { return zero(a.x) && zero(a.y) && a.z == 1; }
    static bool isNone(const toolpath::RotaryAxes& r)
    {
        return r.known == 0 && zero(r.aDeg) && zero(r.bDeg) && zero(r.cDeg);
    }
    ToolTurnBox m_turn;
};

// True when `next` goes on from `piece` along the same arc or helix about Z (same block, circle,
// tool and kind, vertical tool) and neither plunges: the pieces a stock may cut as one
// (Stock::cutArcRun) and the checks judge as one.
inline bool continuesArc(const Move& piece, const Move& next)
{
    auto onArc = [](const Move& m) {
        return m.arcRadius > 0 && m.kind == MoveKind::Feed && !m.plunges() && !m.fiveAxis &&
               m.fromAxis() == Vec3{0, 0, 1} && m.toAxis() == Vec3{0, 0, 1};
    };
    return onArc(piece) && onArc(next) && next.from == piece.to && next.record == piece.record &&
           next.tool == piece.tool && next.arcCentre == piece.arcCentre && next.arcRadius == piece.arcRadius &&
           next.spindleRpm == piece.spindleRpm;
}

// continuesArc(), and both pieces level: the pieces of a level arc, which a stock may sweep as
// one annular sector.
inline bool continuesLevelArc(const Move& piece, const Move& next)
{
    return continuesArc(piece, next) && piece.from.z == piece.to.z && next.from.z == next.to.z;
}

// An operation's span of moves (from SectionBegin to SectionEnd), for per-operation figures.
struct MoveSection {
    std::string name;
    int tool = 0;
    std::size_t firstMove = 0;
    std::size_t endMove = 0;  // one past the last
};

struct MoveOptions {
    double chordToleranceMm = 0.005;  // arcs and joint-interpolated moves split within this
    // The machine's chain: joint-interpolated five-axis moves are split through it; a
    // three-axis chain leaves such moves straight (nothing else knows how the tip curves).
    const kinematics::KinematicChain* chain = nullptr;
};

// A record whose way cannot be followed: a move that starts where an axis is not known yet (a
// program that gives only Z before its first X and Y, or the moves after an untraced one,
// UnknownAxes), or a canned cycle's hole with no height known above it. It sets what it knows
// and makes no motion; the one that makes the position whole stands at its end (a Move with
// from == to) so that the stock there is checked.
struct UntracedMove {
    std::uint32_t record = 0;
    MoveKind kind = MoveKind::Rapid;  // Feed: it would cut along a way no one knows
    toolpath::AxisMask unknownAxes;   // where it starts
    std::size_t nextMove = 0;         // the index in MoveList::moves of the first move after it
};

struct MoveList {
    std::vector<Move> moves;
    std::map<int, toolpath::Tool> tools;  // every tool changed to, by number
    std::vector<MoveSection> sections;
    std::vector<UntracedMove> untraced;  // in record order

    const toolpath::Tool* tool(int number) const;
};

// The moves of `program`. Records flagged in `recordsInError` (nc::recordsInError) move the
// position but make no motion: what such a block claims is not what the machine would do.
MoveList buildMoves(const toolpath::Toolpath& program, const MoveOptions& options = {},
                    const std::vector<bool>& recordsInError = {});

}  // namespace camwb::sim
