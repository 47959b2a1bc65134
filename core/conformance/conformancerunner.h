#pragma once

#include "conformancecheck.h"
#include "conformanceresult.h"
#include "conformancesettings.h"

#include "exchange/trafficentry.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <atomic>
#include <functional>

namespace mbscope {

class TrafficLog;

// Runs the battery against one device: the survey, then every check in order, each skipped with
// its reason when the device or the link lacks what it needs. One request at a time through the
// engine (a TransactionEngine on a thread of its own); run() waits in local event loops, so call it
// from a thread with an event dispatcher (the CLI's main thread).
class ConformanceRunner
{
public:
    explicit ConformanceRunner(ConformanceSettings settings);

    // Every check of the battery, in the order it runs them.
    [[nodiscard]] static QList<ConformanceCheck> battery();

    void setTrafficLog(TrafficLog *log) { m_log = log; }
    // Every frame in and out as the engine logs it (ProbeChannel::framesLogged, with the link's
    // name): the window's traffic list takes the run's frames as it takes a scan's.
    using FramesLogged = std::function<void(const QList<TrafficFrame> &frames, const QString &link)>;
    void setFramesLogged(FramesLogged framesLogged) { m_framesLogged = std::move(framesLogged); }
    // Each result as it is decided (the CLI prints it), then the scorecard.
    [[nodiscard]] ConformanceResult run(const std::function<void(const CheckResult &)> &each = {});
    // The checks not run yet are not run (Ctrl-C); safe from a signal-driven event.
    void stop() { m_stop = true; }

private:
    // Why check cannot run here, or empty.
    [[nodiscard]] static QString skipReason(const ConformanceCheck &check, const class ConformanceContext &context);

    ConformanceSettings m_settings;
    TrafficLog *m_log = nullptr;
    FramesLogged m_framesLogged;
    std::atomic<bool> m_stop{false};
};

} // namespace mbscope
