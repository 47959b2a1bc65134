#pragma once

#include "sessionmetatypes.h"
#include "replay/replayoutcome.h"
#include "replay/replayresult.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>

#include <memory>

namespace mbscope {

class ReplayRunner;
class ReplayScript;

// One replay against a live target, run by the core's ReplayRunner (what `mbscope replay
// --target` runs) in a thread of its own: the runner waits in local event loops for pacing and
// answers, which must not be the GUI's. Move it to a QThread, start run() there; stop() is a
// queued call its local loops deliver. A link failure ends the run, as in the CLI.
class ReplayWorker : public QObject
{
    Q_OBJECT
public:
    // sendWrites: the recording's writes are sent too (ReplayRunner::setSendWrites).
    ReplayWorker(std::shared_ptr<const ReplayScript> script, const LinkUrl &target, double speed, bool sendWrites,
                 int timeoutMs = -1);
    ~ReplayWorker() override;

public Q_SLOTS:
    void run();
    // Stops after the request in flight (its thread's event, delivered by the runner's loops).
    void stop();

Q_SIGNALS:
    void outcomeReady(const mbscope::ReplayOutcome &outcome);
    // linkProblem: what the link said when nothing reached the device (the run ended early).
    void finished(const mbscope::ReplayResult &result, const QString &linkProblem);

private:
    std::shared_ptr<const ReplayScript> m_script;
    LinkUrl m_target;
    double m_speed;
    bool m_sendWrites;
    int m_timeoutMs;
    bool m_stopRequested = false;
    ReplayRunner *m_runner = nullptr; // while run() runs
};

} // namespace mbscope
