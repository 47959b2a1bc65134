#pragma once

#include "sessionmetatypes.h"
#include "exchange/trafficentry.h"
#include "session/planresult.h"
#include "session/sessiondocument.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>

namespace mbscope {

class PlanRunner;

// One run of a session's test plan by the core's PlanRunner (what `mbscope run` runs) in a
// thread of its own, since the runner waits in local event loops. Move it to a QThread, start
// run() there; stop() is a queued call its loops deliver (the steps left are reported skipped).
class PlanWorker : public QObject
{
    Q_OBJECT
public:
    PlanWorker(const SessionDocument &document, const LinkUrl &url);
    ~PlanWorker() override;

public Q_SLOTS:
    void run();
    void stop();

Q_SIGNALS:
    void stepFinished(const mbscope::StepResult &step);
    void finished(const mbscope::PlanResult &result);
    // Every frame the plan's engine sends and reads, batched (PlanRunner::setFramesObserver).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

private:
    SessionDocument m_document;
    LinkUrl m_url;
    bool m_stopRequested = false;
    PlanRunner *m_runner = nullptr; // while run() runs
};

} // namespace mbscope
