#pragma once

#include "link/linkcontroller.h"

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

private:
    QLabel *m_stateLabel = nullptr;
    QLabel *m_countersLabel = nullptr;
};

} // namespace mbscope
