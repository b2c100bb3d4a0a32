// Private: interrupts a post script that runs past its budget. Armed around each outermost call
// into the script (evaluation, one handler); a background thread checks the deadline and asks
// QJSEngine to interrupt. Arming is two atomic stores, so the per-move cost stays negligible.
#pragma once

#include <QJSEngine>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace camwb::post {

class ScriptWatchdog {
public:
    ScriptWatchdog(QJSEngine& engine, std::chrono::milliseconds budget);
    ~ScriptWatchdog();
    ScriptWatchdog(const ScriptWatchdog&) = delete;
    ScriptWatchdog& operator=(const ScriptWatchdog&) = delete;

    // Nested calls keep the outermost deadline.
    void enter();
    // Returns true when the call was interrupted (and lets the engine run again).
    bool leave();
    std::chrono::milliseconds budget() const { return m_budget; }

private:
    void watch();

    QJSEngine& m_engine;
    std::chrono::milliseconds m_budget;
    std::atomic<long long> m_deadline{0};  // steady_clock nanoseconds; 0 = not armed
    std::atomic<bool> m_fired{false};      // the engine was interrupted for the current call
    int m_depth = 0;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    std::thread m_thread;
};

}  // namespace camwb::post
