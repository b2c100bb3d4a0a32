// Private: interrupts a post script that runs past its budget. Armed around each outermost call
// into the script (evaluation, one handler); a background thread checks the deadline and asks
// QJSEngine to interrupt. Arming is two atomic stores, so the per-move cost stays negligible.
// The clock is a parameter so that tests decide what time it is instead of measuring it.
#pragma once

#include <QJSEngine>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace camwb::post {

class ScriptWatchdog {
public:
    using Clock = std::function<std::chrono::nanoseconds()>;
    static std::chrono::nanoseconds steadyNow();

    ScriptWatchdog(QJSEngine& engine, std::chrono::milliseconds budget, Clock clock = steadyNow);
    ~ScriptWatchdog();
    ScriptWatchdog(const ScriptWatchdog&) = delete;
    ScriptWatchdog& operator=(const ScriptWatchdog&) = delete;

    // Nested calls keep the outermost deadline.
    void enter();
    // Returns true when the call was interrupted (and lets the engine run again).
    bool leave();
    std::chrono::milliseconds budget() const { return m_budget; }
    // Whether a call is in progress and past its deadline (the watcher interrupts it at its next check).
    bool expired() const;

private:
    void watch();

    QJSEngine& m_engine;
    std::chrono::milliseconds m_budget;
    Clock m_clock;
    std::atomic<long long> m_deadline{0};  // m_clock nanoseconds; 0 = not armed
    std::atomic<bool> m_fired{false};      // the engine was interrupted for the current call
    int m_depth = 0;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    std::thread m_thread;
};

}  // namespace camwb::post
