#include "post/detail/ScriptWatchdog.h"

#include <algorithm>

namespace camwb::post {

std::chrono::nanoseconds ScriptWatchdog::steadyNow()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch());
}

ScriptWatchdog::ScriptWatchdog(QJSEngine& engine, std::chrono::milliseconds budget, Clock clock) :
    m_engine(engine),
    m_budget(budget),
    m_clock(std::move(clock)),
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
        // At least 1: a deadline of 0 means "not armed".
        m_deadline.store(std::max<long long>(1, (m_clock() + m_budget).count()));
}

bool ScriptWatchdog::expired() const
{
    const long long deadline = m_deadline.load();
    return deadline != 0 && m_clock().count() > deadline;
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
        if (deadline != 0 && m_clock().count() > deadline && m_deadline.compare_exchange_strong(deadline, 0)) {
            m_engine.setInterrupted(true);
            m_fired.store(true);
        }
    }
}

}  // namespace camwb::post
