// Computes one operation's live preview off the GUI thread: requests are debounced (the user is
// still typing), a new request stops the running computation through its cancel flag, progress
// comes back queued to the GUI thread, and only the newest request's outcome is delivered.
#pragma once

#include "document/Job.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>
#include <string>

namespace camwb::gui {

class ToolpathScene;

struct PreviewOutcome {
    bool ok = false;
    bool cancelled = false;
    std::string error;  // computeOperation's message ("pocket \"Pocket 1\": ...")
    ops::OpResult result;
    std::shared_ptr<const ToolpathScene> scene;  // the 3D view's data, built on the worker
    bool turning = false;                        // a lathe operation's: in the XZ plane
    bool heightsKnown = false;                   // false when the geometry did not resolve
    ops::Heights heights;                        // derived, with the user's overrides applied
    double seconds = 0;
};

class PreviewRunner : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultDebounceMs = 150;

    explicit PreviewRunner(QObject* parent = nullptr);
    ~PreviewRunner() override;  // cancels; a worker still running finishes on its own copies

    void setDebounceMs(int ms) { m_debounce.setInterval(ms); }
    // Previews operations[index] of `job` after the debounce delay; supersedes a running one.
    void request(document::Job job, int index, occ::Model model);
    // Stops the running computation and forgets a pending request (cancelled() follows).
    void cancel();
    bool isRunning() const { return m_running != nullptr; }
    bool isPending() const { return m_debounce.isActive(); }
    const std::shared_ptr<const PreviewOutcome>& lastOutcome() const { return m_last; }

signals:
    void started();
    void progress(int percent);
    void finished();   // lastOutcome() holds the result (ok or error)
    void cancelled();  // the user's cancel, not a superseded run

private:
    struct Run;
    void start();
    void done(const std::shared_ptr<Run>& run, std::shared_ptr<const PreviewOutcome> outcome);

    QTimer m_debounce;
    document::Job m_job;
    int m_index = -1;
    occ::Model m_model;
    std::shared_ptr<Run> m_running;  // the newest started run while it computes
    std::shared_ptr<const PreviewOutcome> m_last;
};

}  // namespace camwb::gui
