#pragma once

#include <QtCore/QtGlobal>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

class QJSEngine;

namespace mbscope {

// Interrupts a script call that runs past its time limit: a thread of its own waits for the
// deadline of each armed call and then calls QJSEngine::setInterrupted(true) (documented as
// thread-safe), which stops the JavaScript at its next instruction. The engine's thread arms it
// before a call and disarms it after; disarm() says whether it fired and clears the interrupt so
// that the next call runs.
class ScriptWatchdog
{
public:
    explicit ScriptWatchdog(QJSEngine *engine);
    ~ScriptWatchdog();
    ScriptWatchdog(const ScriptWatchdog &) = delete;
    ScriptWatchdog &operator=(const ScriptWatchdog &) = delete;

    void arm(qint64 limitNs);
    // True when the limit interrupted the call.
    bool disarm();

private:
    void run();

    QJSEngine *m_engine;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::chrono::steady_clock::time_point m_deadline;
    bool m_armed = false;
    bool m_fired = false;
    bool m_quit = false;
    bool m_timing = false; // the thread waits for a deadline
    std::thread m_thread; // last: starts once the rest is set up
};

} // namespace mbscope
