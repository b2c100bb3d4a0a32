#include "gui/sim/StockAnimation.h"

#include "gui/sim/SimRun.h"
#include "sim/HeightField.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace camwb::gui {

namespace {

using Clock = std::chrono::steady_clock;

// Cutting stops for a frame after this much work, so the view follows a long catch-up.
constexpr auto kFrameBudget = std::chrono::milliseconds(30);

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

StockAnimation::StockAnimation(std::shared_ptr<const SimRun> run, QObject* parent) :
    QObject(parent),
    m_run(std::move(run))
{
    m_end = m_run->timeline.pointAt(m_run->timeline.total());
    // At most 16 copies (a dexel stock's copy is megabytes): going back re-cuts at most 1/16 of
    // the program, or 64 moves.
    m_checkpointEvery = std::max<std::size_t>(64, m_run->moves.moves.size() / 16);
    m_thread = std::thread([this] { work(); });
}

StockAnimation::~StockAnimation()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void StockAnimation::setTarget(const MovePoint& point)
{
    {
        std::lock_guard lock(m_mutex);
        if (point == m_target && m_frame)
            return;
        m_target = point;
        m_caughtUp = false;
    }
    m_wake.notify_all();
}

std::shared_ptr<const StockFrame> StockAnimation::frame() const
{
    std::lock_guard lock(m_mutex);
    return m_frame;
}

bool StockAnimation::isCaughtUp() const
{
    std::lock_guard lock(m_mutex);
    return m_caughtUp;
}

void StockAnimation::work()
{
    std::unique_ptr<sim::Stock> stock = m_run->stock->clone();
    m_checkpoints.emplace_back(0, stock->clone());
    bool first = true;
    for (;;) {
        MovePoint target;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || first || !(m_target == m_done); });
            if (m_stop)
                return;
            target = m_target;
        }
        first = false;
        const auto cutStart = Clock::now();
        if (target < m_done)
            restoreBefore(target, stock);
        const bool reached = cutToward(target, *stock);
        auto frame = std::make_shared<StockFrame>();
        frame->at = m_done;
        frame->cutSeconds = secondsSince(cutStart);
        const auto meshStart = Clock::now();
        remesh(*stock, *frame);
        if (m_done == m_end && m_run->hasDesign)
            frame->deviation = stock->compare();
        frame->meshSeconds = secondsSince(meshStart);
        {
            std::lock_guard lock(m_mutex);
            m_frame = std::move(frame);
            m_caughtUp = reached && m_target == m_done;
        }
        QMetaObject::invokeMethod(
            this, [this] { emit frameReady(); }, Qt::QueuedConnection);
    }
}

// Cuts from where the stock is toward `target`, a frame's budget at a time; true when there.
bool StockAnimation::cutToward(const MovePoint& target, sim::Stock& stock)
{
    const auto start = Clock::now();
    const auto& moves = m_run->moves.moves;
    while (m_done < target) {
        const std::size_t i = m_done.move;
        const double to = i < target.move ? 1.0 : target.fraction;
        const sim::Move& move = moves[i];
        auto shape = m_run->toolShapes.find(move.tool);
        if (move.moves() && move.positionKnown && shape != m_run->toolShapes.end() && to > m_done.fraction)
            stock.cut(partOf(move, m_done.fraction, to), i, *shape->second);
        m_done = i < target.move ? MovePoint{i + 1, 0.0} : target;
        if (m_done.fraction == 0 && m_done.move % m_checkpointEvery == 0 && m_checkpoints.back().first < m_done.move)
            m_checkpoints.emplace_back(m_done.move, stock.clone());
        if (Clock::now() - start > kFrameBudget)
            break;
    }
    return m_done == target;
}

// Back to the last copy at or before `target`.
void StockAnimation::restoreBefore(const MovePoint& target, std::unique_ptr<sim::Stock>& stock)
{
    while (m_checkpoints.size() > 1 && m_checkpoints.back().first > target.move)
        m_checkpoints.pop_back();
    stock = m_checkpoints.back().second->clone();
    m_done = {m_checkpoints.back().first, 0.0};
    m_triangles = nullptr;
}

// A height field rewrites only the heights of the columns cut since the last frame; any other
// stock (tri-dexels) is meshed whole.
void StockAnimation::remesh(sim::Stock& stock, StockFrame& frame)
{
    auto* field = dynamic_cast<sim::HeightField*>(&stock);
    if (field != nullptr && m_triangles) {
        const sim::ColumnRect changed = field->takeChanged();
        if (!changed.empty())
            field->updateMesh(m_mesh, changed);
    } else {
        m_mesh = stock.mesh();
        if (field != nullptr)
            field->takeChanged();
        m_triangles = std::make_shared<const std::vector<std::uint32_t>>(m_mesh.triangles);
    }
    frame.positions = std::make_shared<const std::vector<float>>(m_mesh.positions);
    frame.triangles = field != nullptr ? m_triangles : std::exchange(m_triangles, nullptr);
}

}  // namespace camwb::gui
