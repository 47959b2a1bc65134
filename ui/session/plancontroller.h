#pragma once

#include "sessionmetatypes.h"
#include "exchange/trafficentry.h"
#include "session/planresult.h"
#include "session/sessiondocument.h"

#include <QtCore/QObject>
#include <QtCore/QString>

#include <optional>

class QThread;

namespace mbscope {

class LinkController;
class PlanResultModel;
class PlanWorker;

// Runs a session's test plan from the window, as `mbscope run` does (the core's PlanRunner, in
// a thread of its own through PlanWorker), against the connected target or else the session's
// own; lists each step as it ends (results()), sums them up and writes JUnit XML.
class PlanController : public QObject
{
    Q_OBJECT
public:
    explicit PlanController(LinkController *link, QObject *parent = nullptr);
    ~PlanController() override;

    // False with *error when it cannot start: no plan, no target, a poll running, a run running.
    // The window's link is closed first (a serial port takes one client).
    bool run(const SessionDocument &document, QString *error);
    void stop();
    [[nodiscard]] bool isRunning() const { return m_worker != nullptr; }
    [[nodiscard]] PlanResultModel *results() const { return m_results; }
    [[nodiscard]] const std::optional<PlanResult> &lastResult() const { return m_last; }
    // "16 steps: 15 passed, 1 failed, 0 errors, 0 skipped in 1.234 s against tcp://..."
    [[nodiscard]] QString summary() const { return m_summary; }
    [[nodiscard]] static QString summaryOf(const PlanResult &result);
    // The last run's results as JUnit XML in path; false with *error.
    bool exportJUnit(const QString &path, QString *error) const;

Q_SIGNALS:
    void started(const QString &plan, const QString &target);
    void stepFinished(const mbscope::StepResult &step);
    void finished(const QString &summary, bool passed);
    void runningChanged(bool running);
    // The frames of the plan's run, as its engine logs them, for the traffic list.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);

private:
    void onStep(const StepResult &step);
    void onFinished(const PlanResult &result);

    LinkController *m_link;
    PlanResultModel *m_results;
    QThread *m_thread = nullptr;
    PlanWorker *m_worker = nullptr;
    std::optional<PlanResult> m_last;
    QString m_summary;
};

} // namespace mbscope
