#pragma once

#include "pollreport.h"
#include "pollsettings.h"

#include <QtCore/QObject>

namespace mbscope {

class EngineCore;
class Poller;

// Runs a poll once per interval, one after the other, in the engine's thread, collecting one
// PollRun per interval (a student's table of error rate against poll interval). A plain poll is
// a sweep of one interval. stop() ends the run in progress and skips the rest; finished() then
// delivers the runs so far.
class Sweep : public QObject
{
    Q_OBJECT
public:
    Sweep(EngineCore *core, const SweepSettings &settings, bool isSweep, QObject *parent = nullptr);
    ~Sweep() override;

    void start();
    void stop();
    [[nodiscard]] const PollReport &report() const { return m_report; }
    [[nodiscard]] bool isFinished() const { return m_finished; }

Q_SIGNALS:
    void finished(const mbscope::PollReport &report);

private:
    void startRun();
    void onRunFinished();

    EngineCore *m_core;
    SweepSettings m_settings;
    PollReport m_report;
    Poller *m_poller = nullptr;
    int m_next = 0;
    bool m_stopping = false;
    bool m_finished = false;
};

} // namespace mbscope
