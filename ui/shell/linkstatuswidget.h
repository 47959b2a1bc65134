#pragma once

#include "link/linkcontroller.h"

#include "fleet/watchsample.h"

#include <QtWidgets/QWidget>

class QLabel;

namespace mbscope {

// The status bar's view of the link: its state as a coloured word with the target, and what went
// over it (requests, bytes sent and received, errors), as the engine counts them.
class LinkStatusWidget : public QWidget
{
    Q_OBJECT
public:
    explicit LinkStatusWidget(QWidget *parent = nullptr);

    void setState(LinkController::State state, const QString &message);
    void setCounters(const EngineCounters &counters);
    [[nodiscard]] QString stateText() const;
    [[nodiscard]] QString countersText() const;
    // The watches' polls (Watches tab), counted beside the bench's link: they have links of
    // their own, which the bench's counters do not see.
    void addWatchTraffic(const QList<mbscope::WatchSample> &samples);
    [[nodiscard]] QString watchTrafficText() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    QLabel *m_stateLabel = nullptr;
    QLabel *m_countersLabel = nullptr;
    QLabel *m_watchLabel = nullptr;
    LinkController::State m_state = LinkController::State::Disconnected;
    QString m_message;
    quint64 m_watchPolls = 0;
    quint64 m_watchFailures = 0;
    qint64 m_watchBytesOut = 0;
    qint64 m_watchBytesIn = 0;
};

} // namespace mbscope
