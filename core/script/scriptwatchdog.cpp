#include "scriptwatchdog.h"

#include <QtQml/QJSEngine>

namespace mbscope {

ScriptWatchdog::ScriptWatchdog(QJSEngine *engine)
    : m_engine(engine), m_thread([this] { run(); })
{
}

ScriptWatchdog::~ScriptWatchdog()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_quit = true;
    }
    m_wake.notify_one();
    m_thread.join();
}

void ScriptWatchdog::arm(qint64 limitNs)
{
    bool wake = false;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_deadline = std::chrono::steady_clock::now() + std::chrono::nanoseconds(limitNs);
        m_armed = true;
        m_fired = false;
        // A thread still waiting for an earlier call's deadline wakes then and waits on for this
        // one: no wake-up (a thread switch) per call when calls come fast.
        wake = !m_timing;
    }
    if (wake)
        m_wake.notify_one();
}

bool ScriptWatchdog::disarm()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_armed = false;
    const bool fired = m_fired;
    m_fired = false;
    if (fired)
        m_engine->setInterrupted(false);
    return fired;
}

void ScriptWatchdog::run()
{
    std::unique_lock<std::mutex> lock(m_mutex);
    while (!m_quit) {
        if (!m_armed) {
            m_wake.wait(lock);
            continue;
        }
        const auto deadline = m_deadline;
        m_timing = true;
        const bool timedOut = m_wake.wait_until(lock, deadline) == std::cv_status::timeout;
        m_timing = false;
        if (timedOut && m_armed && !m_quit && std::chrono::steady_clock::now() >= m_deadline) {
            m_engine->setInterrupted(true);
            m_fired = true;
            m_armed = false;
        }
    }
}

} // namespace mbscope
