// The cut stock while the simulator plays: a worker thread cuts the moves up to the playback
// position (a partial move up to the tool's tip), remeshes and hands the mesh to the GUI, which
// never waits for it. Going back restores a copy kept every so many moves and cuts forward from
// there. At the program's end it compares the stock with the design model (the deviation map).
#pragma once

#include "gui/sim/Timeline.h"
#include "sim/Stock.h"

#include <QObject>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace camwb::gui {

struct SimRun;

struct StockFrame {
    // The stock's surface; `triangles` is the same object as the frame before's while only the
    // heights changed (a height field remeshes in place), so the view updates its points only.
    std::shared_ptr<const std::vector<float>> positions;
    std::shared_ptr<const std::vector<std::uint32_t>> triangles;
    std::optional<sim::Deviation> deviation;  // at the program's end, with a design model
    MovePoint at;                             // the stock after cutting up to here
    double cutSeconds = 0;                    // worker time for this frame
    double meshSeconds = 0;
};

class StockAnimation : public QObject {
    Q_OBJECT
public:
    // `run` must have a stock.
    explicit StockAnimation(std::shared_ptr<const SimRun> run, QObject* parent = nullptr);
    ~StockAnimation() override;

    void setTarget(const MovePoint& point);
    // The last frame delivered (null before the first); frameReady says when it changes.
    std::shared_ptr<const StockFrame> frame() const;
    // The worker has cut up to the target and delivered that frame.
    bool isCaughtUp() const;

signals:
    void frameReady();

private:
    void work();
    bool cutToward(const MovePoint& target, sim::Stock& stock);
    void restoreBefore(const MovePoint& target, std::unique_ptr<sim::Stock>& stock);
    void remesh(sim::Stock& stock, StockFrame& frame);

    std::shared_ptr<const SimRun> m_run;
    MovePoint m_end;
    std::size_t m_checkpointEvery = 64;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    MovePoint m_target;
    MovePoint m_done;  // worker only
    bool m_stop = false;
    bool m_caughtUp = false;
    std::shared_ptr<const StockFrame> m_frame;
    std::vector<std::pair<std::size_t, std::unique_ptr<sim::Stock>>> m_checkpoints;  // worker only
    sim::TriangleMesh m_mesh;  // worker only: the mesh a height field updates in place
    std::shared_ptr<const std::vector<std::uint32_t>> m_triangles;  // worker only; null: remesh all
    std::thread m_thread;
};

}  // namespace camwb::gui
