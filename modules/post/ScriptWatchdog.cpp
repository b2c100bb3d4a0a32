#include "post/detail/ScriptWatchdog.h"

#include <algorithm>

namespace camwb::post {

namespace {

long long nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

ScriptWatchdog::ScriptWatchdog(QJSEngine& engine, std::chrono::milliseconds budget) :
    m_engine(engine),
    m_budget(budget),
    m_thread([this] { watch(); })
{
}

ScriptWatchdog::~ScriptWatchdog()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void ScriptWatchdog::enter()
{
    if (m_depth++ == 0)
        m_deadline.store(nowNs() + std::chrono::duration_cast<std::chrono::nanoseconds>(m_budget).count());
}

bool ScriptWatchdog::leave()
{
    if (--m_depth > 0)
        return false;
    if (m_deadline.exchange(0) != 0)
        return false;  // still armed: the watcher did not fire
    // The watcher claimed this deadline: it has interrupted the engine or is about to.
    while (!m_fired.load())
        std::this_thread::yield();
    m_fired.store(false);
    m_engine.setInterrupted(false);
    return true;
}

void ScriptWatchdog::watch()
{
    // Checks a few times per budget (at least every 50 ms); a call is interrupted at most one
    // check interval after its deadline.
    const auto interval = std::clamp(m_budget / 8, std::chrono::milliseconds(1), std::chrono::milliseconds(50));
    std::unique_lock lock(m_mutex);
    while (!m_stop) {
        m_wake.wait_for(lock, interval);
        long long deadline = m_deadline.load();
        // Claiming the deadline first means a call that ends now cannot be confused with the next.
        if (deadline != 0 && nowNs() > deadline && m_deadline.compare_exchange_strong(deadline, 0)) {
            m_engine.setInterrupted(true);
            m_fired.store(true);
        }
    }
}

}  // namespace camwb::post
