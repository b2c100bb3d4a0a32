#include "gui/sim/Timeline.h"

#include <algorithm>

namespace camwb::gui {

namespace {

base::Vec3 lerp(const base::Vec3& a, const base::Vec3& b, double f) { return a + (b - a) * f; }

base::Vec3 axisBetween(const base::Vec3& a, const base::Vec3& b, double f)
{
    const base::Vec3 axis = lerp(a, b, f).normalized();
    return axis.length() > 0 ? axis : a;
}

}  // namespace

Timeline::Timeline(const sim::MoveList* moves, const sim::MotionPlan& plan) : m_moves(moves), m_planned(plan.moves)
{
    m_start.reserve(m_planned.size());
    m_length.reserve(m_planned.size());
    for (const sim::PlannedMove& move : m_planned) {
        m_start.push_back(move.start);
        m_length.push_back(move.end() - move.start);
    }
    m_total = m_planned.empty() ? 0.0 : std::max(plan.totalSeconds, m_start.back() + m_length.back());
}

MovePoint Timeline::pointAt(double position) const
{
    if (m_start.empty())
        return {};
    position = std::clamp(position, 0.0, m_total);
    // The last move starting at or before the position; at a move's very end, that move (so the
    // end of the program shows the last move done, not a pause after it).
    auto it = std::upper_bound(m_start.begin(), m_start.end(), position);
    std::size_t move = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - m_start.begin() - 1));
    while (move > 0 && m_length[move] == 0 && m_start[move] == position && m_length[move - 1] > 0)
        --move;
    const double length = m_length[move];
    if (length <= 0)
        return {move, 1.0};
    const double local = position - m_start[move];
    // In time: the pause first (dwell, tool change, spindle ramp), then the velocity profile.
    const sim::PlannedMove& planned = m_planned[move];
    const double moving = local - planned.pauseSeconds;
    if (moving <= 0)
        return {move, 0.0};
    if (planned.length > 0)
        return {move, std::clamp(planned.distanceAt(moving) / planned.length, 0.0, 1.0)};
    return {move, planned.moveSeconds > 0 ? std::clamp(moving / planned.moveSeconds, 0.0, 1.0) : 1.0};
}

ToolPose Timeline::poseAt(const MovePoint& point) const
{
    if (!m_moves || point.move >= m_moves->moves.size())
        return {};
    // A pause before any known position means nothing: look back for a move that knows.
    std::size_t i = point.move;
    while (i > 0 && !m_moves->moves[i].positionKnown)
        --i;
    const sim::Move& move = m_moves->moves[i];
    if (!move.positionKnown)
        return {};
    const double f = i == point.move ? point.fraction : 1.0;
    return {move.pointAt(f), axisBetween(move.fromAxis(), move.toAxis(), f), m_moves->moves[point.move].tool, true};
}

int Timeline::lineOf(std::size_t move) const
{
    if (!m_moves || move >= m_moves->moves.size())
        return -1;
    const auto record = m_moves->moves[move].record;
    return m_lineOf ? m_lineOf(record) : static_cast<int>(record);
}

std::size_t Timeline::runStart(std::size_t move) const
{
    const int line = lineOf(move);
    while (move > 0 && lineOf(move - 1) == line)
        --move;
    return move;
}

double Timeline::nextBlock(double position) const
{
    if (m_start.empty())
        return 0;
    const MovePoint here = pointAt(position);
    const int line = lineOf(here.move);
    for (std::size_t i = here.move + 1; i < m_start.size(); ++i)
        if (lineOf(i) != line)
            return m_start[i];
    return m_total;
}

double Timeline::previousBlock(double position) const
{
    if (m_start.empty())
        return 0;
    MovePoint here = pointAt(position);
    // At the very start of a move that opens a block, "here" is that block's start already.
    std::size_t first = runStart(here.move);
    if (position > m_start[first] + 1e-9)
        return m_start[first];
    if (first == 0)
        return 0;
    return m_start[runStart(first - 1)];
}

std::size_t Timeline::firstMoveOfRecord(std::size_t record) const
{
    if (!m_moves)
        return 0;
    const auto& moves = m_moves->moves;
    auto it = std::lower_bound(moves.begin(), moves.end(), record,
                               [](const sim::Move& m, std::size_t r) { return m.record < r; });
    return static_cast<std::size_t>(it - moves.begin());
}

sim::Move partOf(const sim::Move& move, double from, double to)
{
    sim::Move part = move;
    part.from = move.pointAt(from);  // on the arc for an arc's piece: the stock sweeps the arc
    part.to = move.pointAt(to);
    part.setFromAxis(axisBetween(move.fromAxis(), move.toAxis(), from));
    part.setToAxis(axisBetween(move.fromAxis(), move.toAxis(), to));
    return part;
}

}  // namespace camwb::gui
