// The cut stock while the simulator plays: a worker thread cuts the moves up to the playback
// position (a partial move up to the tool's tip), remeshes and hands the mesh to the GUI, which
// never waits for it. Going back restores a copy kept every so many moves and cuts forward from
// there. At the program's end it compares the stock with the design model (the deviation map).
#pragma once

#include "gui/sim/Timeline.h"
#include "sim/Stock.h"

#include <QObject>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

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
    // Returns at once: a cut under way finishes on the worker, which then ends by itself.
    ~StockAnimation() override;

    void setTarget(const MovePoint& point);
    // The last frame delivered (null before the first); frameReady says when it changes.
    std::shared_ptr<const StockFrame> frame() const;
    // The worker has cut up to the target and delivered that frame.
    bool isCaughtUp() const;

signals:
    void frameReady();

private:
    struct Shared;
    class Worker;
    std::shared_ptr<Shared> m_shared;
};

}  // namespace camwb::gui
