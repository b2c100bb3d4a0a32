#include "gui/tasks/PreviewRunner.h"

#include "document/OperationGeometry.h"
#include "gui/view3d/View3D.h"
#include "sim/TurningCheck.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace camwb::gui {

namespace {

constexpr int kProgressPollMs = 50;

// Computes as the job will, keeping the resolved heights for the panel's "auto" fields.
std::shared_ptr<const PreviewOutcome> compute(const document::Job& job, int index, const occ::Model& model,
                                              const ops::Progress& progress)
{
    QElapsedTimer clock;
    clock.start();
    auto outcome = std::make_shared<PreviewOutcome>();
    std::optional<ops::Heights> heights;
    auto result = document::computeOperation(job, index, model, progress, &heights);
    if (heights) {
        outcome->heights = *heights;
        outcome->heightsKnown = true;
    }
    if (progress.cancelled()) {
        outcome->cancelled = true;
    } else if (!result) {
        outcome->error = result.error().toString();
    } else {
        outcome->ok = true;
        outcome->result = std::move(result.value());
        // A lathe gives no Y: its path is drawn in the turning plane (Y = 0), as the checks read it.
        outcome->turning = document::isTurningKind(job.operations[static_cast<std::size_t>(index)].kind());
        outcome->scene = View3D::prepareToolpath(outcome->turning ? sim::inTurningPlane(outcome->result.toolpath)
                                                                  : outcome->result.toolpath);
    }
    outcome->seconds = clock.nsecsElapsed() * 1e-9;
    return outcome;
}

}  // namespace

struct PreviewRunner::Run {
    std::atomic<bool> cancel{false};
    std::atomic<int> percent{0};
    int shownPercent = -1;
};

PreviewRunner::PreviewRunner(QObject* parent) : QObject(parent)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDefaultDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &PreviewRunner::start);
    // Progress is polled from the run's atomic: the worker never touches a QObject.
    auto* poll = new QTimer(this);
    poll->setInterval(kProgressPollMs);
    connect(poll, &QTimer::timeout, this, [this] {
        if (m_running && m_running->percent != m_running->shownPercent) {
            m_running->shownPercent = m_running->percent;
            emit progress(m_running->shownPercent);
        }
    });
    poll->start();
}

PreviewRunner::~PreviewRunner()
{
    if (m_running)
        m_running->cancel = true;
}

void PreviewRunner::request(document::Job job, int index, occ::Model model)
{
    m_job = std::move(job);
    m_index = index;
    m_model = std::move(model);
    if (m_running)
        m_running->cancel = true;  // its result would be stale: stop it now, not after the delay
    m_running = nullptr;
    m_debounce.start();
}

void PreviewRunner::cancel()
{
    const bool active = m_debounce.isActive() || m_running;
    m_debounce.stop();
    if (m_running)
        m_running->cancel = true;
    m_running = nullptr;
    if (active)
        emit cancelled();
}

void PreviewRunner::start()
{
    if (m_index < 0 || m_index >= static_cast<int>(m_job.operations.size()))
        return;
    auto run = std::make_shared<Run>();
    m_running = run;
    emit started();
    ops::Progress progress;
    progress.cancel = &run->cancel;
    progress.report = [run](double fraction) { run->percent = std::clamp(static_cast<int>(fraction * 100), 0, 100); };
    auto* watcher = new QFutureWatcher<std::shared_ptr<const PreviewOutcome>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, run] {
        watcher->deleteLater();
        done(run, watcher->result());
    });
    watcher->setFuture(QtConcurrent::run([job = m_job, index = m_index, model = m_model, progress, run] {
        return compute(job, index, model, progress);
    }));
}

void PreviewRunner::done(const std::shared_ptr<Run>& run, std::shared_ptr<const PreviewOutcome> outcome)
{
    if (run != m_running)
        return;  // superseded or cancelled: a newer request owns the panel
    m_running = nullptr;
    if (outcome->cancelled)
        return;
    m_last = std::move(outcome);
    emit finished();
}

}  // namespace camwb::gui
