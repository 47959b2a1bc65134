#pragma once

#include "conformancecheck.h"
#include "conformanceresult.h"
#include "conformancesettings.h"

#include <QtCore/QList>

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
    // Each result as it is decided (the CLI prints it), then the scorecard.
    [[nodiscard]] ConformanceResult run(const std::function<void(const CheckResult &)> &each = {});
    // The checks not run yet are not run (Ctrl-C); safe from a signal-driven event.
    void stop() { m_stop = true; }

private:
    // Why check cannot run here, or empty.
    [[nodiscard]] static QString skipReason(const ConformanceCheck &check, const class ConformanceContext &context);

    ConformanceSettings m_settings;
    TrafficLog *m_log = nullptr;
    std::atomic<bool> m_stop{false};
};

} // namespace mbscope
