#include "gui/sim/StockAnimation.h"

#include "gui/sim/SimRun.h"
#include "sim/HeightField.h"
#include "sim/MakeStock.h"

#include <QCoreApplication>
#include <QPointer>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <utility>

namespace camwb::gui {

namespace {

using Clock = std::chrono::steady_clock;

// Cutting stops for a frame after this much work, so the view follows a long catch-up.
constexpr auto kFrameBudget = std::chrono::milliseconds(30);

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

// What the GUI and the worker share, under the mutex. The worker holds it alive after the
// animation is gone, until it notices `stop`.
struct StockAnimation::Shared {
    std::shared_ptr<const SimRun> run;
    std::mutex mutex;
    std::condition_variable wake;
    MovePoint target;
    bool stop = false;
    bool caughtUp = false;
    std::shared_ptr<const StockFrame> frame;
};

// The worker's own state: the stock, its copies, where it has cut to and its mesh.
class StockAnimation::Worker {
public:
    Worker(std::shared_ptr<Shared> shared, QPointer<StockAnimation> owner) :
        m_shared(std::move(shared)),
        m_owner(std::move(owner)),
        m_run(*m_shared->run)
    {
        m_end = m_run.timeline.pointAt(m_run.timeline.total());
        // At most 16 copies besides the start's, and together no more than an eighth of the
        // computer's memory (a dexel stock's copy is megabytes, a fine height field's gigabytes):
        // going back re-cuts at most that share of the program, or 64 moves.
        const double copy = double(std::max<std::size_t>(1, m_run.stock->memoryBytes()));
        const auto copies = std::size_t(std::clamp(0.25 * sim::stockMemoryBudget() / copy, 1.0, 16.0));
        m_checkpointEvery = std::max<std::size_t>(64, m_run.moves.moves.size() / copies + 1);
    }

    void run();

private:
    bool cutToward(const MovePoint& target);
    void restoreBefore(const MovePoint& target);
    void remesh(StockFrame& frame);

    std::shared_ptr<Shared> m_shared;
    QPointer<StockAnimation> m_owner;  // read on the GUI thread only
    const SimRun& m_run;
    MovePoint m_end;
    std::size_t m_checkpointEvery = 64;
    std::unique_ptr<sim::Stock> m_stock;
    MovePoint m_done;
    std::vector<std::pair<std::size_t, std::unique_ptr<sim::Stock>>> m_checkpoints;
    sim::TriangleMesh m_mesh;                                       // a height field updates it in place
    std::shared_ptr<const std::vector<std::uint32_t>> m_triangles;  // null: remesh all
};

StockAnimation::StockAnimation(std::shared_ptr<const SimRun> run, QObject* parent) :
    QObject(parent),
    m_shared(std::make_shared<Shared>())
{
    m_shared->run = std::move(run);
    std::thread([worker = std::make_shared<Worker>(m_shared, QPointer<StockAnimation>(this))] {
        worker->run();
    }).detach();
}

StockAnimation::~StockAnimation()
{
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->stop = true;
    }
    m_shared->wake.notify_all();
}

void StockAnimation::setTarget(const MovePoint& point)
{
    {
        std::lock_guard lock(m_shared->mutex);
        if (point == m_shared->target && m_shared->frame)
            return;
        m_shared->target = point;
        m_shared->caughtUp = false;
    }
    m_shared->wake.notify_all();
}

std::shared_ptr<const StockFrame> StockAnimation::frame() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->frame;
}

bool StockAnimation::isCaughtUp() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->caughtUp;
}

void StockAnimation::Worker::run()
{
    m_stock = m_run.stock->clone();
    m_checkpoints.emplace_back(0, m_stock->clone());
    bool first = true;
    for (;;) {
        MovePoint target;
        {
            std::unique_lock lock(m_shared->mutex);
            m_shared->wake.wait(lock, [&] { return m_shared->stop || first || !(m_shared->target == m_done); });
            if (m_shared->stop)
                return;
            target = m_shared->target;
        }
        first = false;
        const auto cutStart = Clock::now();
        if (target < m_done)
            restoreBefore(target);
        const bool reached = cutToward(target);
        auto frame = std::make_shared<StockFrame>();
        frame->at = m_done;
        frame->cutSeconds = secondsSince(cutStart);
        const auto meshStart = Clock::now();
        remesh(*frame);
        if (m_done == m_end && m_run.hasDesign)
            frame->deviation = m_stock->compare();
        frame->meshSeconds = secondsSince(meshStart);
        {
            std::lock_guard lock(m_shared->mutex);
            if (m_shared->stop)
                return;
            m_shared->frame = std::move(frame);
            m_shared->caughtUp = reached && m_shared->target == m_done;
        }
        // Posted to the application: the animation may be gone by the time it runs.
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [owner = m_owner] {
                if (owner)
                    emit owner->frameReady();
            },
            Qt::QueuedConnection);
    }
}

// Cuts from where the stock is toward `target`, a frame's budget at a time; true when there.
bool StockAnimation::Worker::cutToward(const MovePoint& target)
{
    const auto start = Clock::now();
    const auto& moves = m_run.moves.moves;
    while (m_done < target) {
        const std::size_t i = m_done.move;
        const double to = i < target.move ? 1.0 : target.fraction;
        const sim::Move& move = moves[i];
        auto shape = m_run.toolShapes.find(move.tool);
        if (move.moves() && move.positionKnown && shape != m_run.toolShapes.end() && to > m_done.fraction)
            m_stock->cut(partOf(move, m_done.fraction, to), i, *shape->second);
        m_done = i < target.move ? MovePoint{i + 1, 0.0} : target;
        if (m_done.fraction == 0 && m_done.move % m_checkpointEvery == 0 && m_checkpoints.back().first < m_done.move)
            m_checkpoints.emplace_back(m_done.move, m_stock->clone());
        if (Clock::now() - start > kFrameBudget)
            break;
    }
    return m_done == target;
}

// Back to the last copy at or before `target`.
void StockAnimation::Worker::restoreBefore(const MovePoint& target)
{
    while (m_checkpoints.size() > 1 && m_checkpoints.back().first > target.move)
        m_checkpoints.pop_back();
    m_stock = m_checkpoints.back().second->clone();
    m_done = {m_checkpoints.back().first, 0.0};
    m_triangles = nullptr;
}

// A height field rewrites only the heights of the columns cut since the last frame; any other
// stock (tri-dexels) is meshed whole.
void StockAnimation::Worker::remesh(StockFrame& frame)
{
    auto* field = dynamic_cast<sim::HeightField*>(m_stock.get());
    if (field != nullptr && m_triangles) {
        const sim::ColumnRect changed = field->takeChanged();
        if (!changed.empty())
            field->updateMesh(m_mesh, changed);
    } else {
        m_mesh = m_stock->mesh();
        if (field != nullptr)
            field->takeChanged();
        m_triangles = std::make_shared<const std::vector<std::uint32_t>>(m_mesh.triangles);
    }
    frame.positions = std::make_shared<const std::vector<float>>(m_mesh.positions);
    frame.triangles = field != nullptr ? m_triangles : std::exchange(m_triangles, nullptr);
}

}  // namespace camwb::gui
