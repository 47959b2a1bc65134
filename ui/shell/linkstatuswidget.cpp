#include "linkstatuswidget.h"

#include "common/severitystyle.h"

#include <QtCore/QEvent>
#include <QtCore/QLocale>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>

namespace mbscope {

LinkStatusWidget::LinkStatusWidget(QWidget *parent)
    : QWidget(parent)
    , m_stateLabel(new QLabel(this))
    , m_countersLabel(new QLabel(this))
    , m_watchLabel(new QLabel(this))
{
    m_watchLabel->setObjectName(QStringLiteral("watchTrafficLabel"));
    m_watchLabel->setToolTip(tr("What the watches of the Watches tab sent and received on their own links"));
    m_watchLabel->hide(); // until the watches poll
    m_stateLabel->setObjectName(QStringLiteral("linkStateLabel"));
    m_countersLabel->setObjectName(QStringLiteral("linkCountersLabel"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stateLabel);
    layout->addSpacing(16);
    layout->addWidget(m_countersLabel);
    layout->addSpacing(16);
    layout->addWidget(m_watchLabel);
    setState(LinkController::State::Disconnected, {});
    setCounters({});
}

void LinkStatusWidget::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    // Another theme: the state word's colour is written into its text, so the text is made again.
    if (event->type() == QEvent::ApplicationPaletteChange || event->type() == QEvent::PaletteChange)
        setState(m_state, m_message);
}

void LinkStatusWidget::setState(LinkController::State state, const QString &message)
{
    m_state = state;
    m_message = message;
    QString word;
    QColor colour; // none: the palette's text colour, whatever the theme becomes
    switch (state) {
    case LinkController::State::Disconnected: word = tr("Not connected"); break;
    case LinkController::State::Ready: word = tr("Connecting"); colour = SeverityStyle::textColor(Severity::Info); break;
    case LinkController::State::Connected: word = tr("Connected"); colour = SeverityStyle::goodColor(); break;
    case LinkController::State::Failed: word = tr("Link failed"); colour = SeverityStyle::textColor(Severity::Error); break;
    }
    // The state word is coloured; the detail (the link's words) stays readable text. Connected,
    // the target is in the connection bar already: here only in the tooltip, so the status bar
    // keeps room for its messages at 1024 px (issue 31: a poll's summary was cut).
    const bool withDetail = state == LinkController::State::Ready || state == LinkController::State::Failed;
    const QString detail = withDetail ? message : QString();
    m_stateLabel->setText(QStringLiteral("<b%1>\u25CF %2</b>%3")
                              .arg(colour.isValid() ? QStringLiteral(" style=\"color:%1\"").arg(colour.name()) : QString(),
                                   word.toHtmlEscaped(),
                                   detail.isEmpty() ? QString() : QStringLiteral("&nbsp; ") + detail.toHtmlEscaped()));
    m_stateLabel->setToolTip(state == LinkController::State::Disconnected ? QString() : message);
}

void LinkStatusWidget::setCounters(const EngineCounters &counters)
{
    const QLocale locale;
    QString text = tr("TX %1 B  RX %2 B  \u00B7  %3")
                       .arg(locale.toString(counters.bytesOut), locale.toString(counters.bytesIn),
                            counters.requestsSent == 1 ? tr("1 request")
                                                       : tr("%1 requests").arg(locale.toString(counters.requestsSent)));
    if (counters.linkErrors > 0)
        text += counters.linkErrors == 1 ? tr("  \u00B7  1 link error")
                                         : tr("  \u00B7  %1 link errors").arg(locale.toString(counters.linkErrors));
    m_countersLabel->setText(text);
    m_countersLabel->setToolTip(tr("This connection's traffic since Connect: bytes sent (TX) and received (RX), "
                                   "requests sent and link errors. A new connection counts from zero."));
}

void LinkStatusWidget::addWatchTraffic(const QList<WatchSample> &samples)
{
    if (samples.isEmpty())
        return;
    for (const WatchSample &sample : samples) {
        ++m_watchPolls;
        if (!sample.isOk())
            ++m_watchFailures;
        m_watchBytesOut += sample.requestBytes;
        m_watchBytesIn += sample.answerBytes;
    }
    const QLocale locale;
    QString text = tr("Watches: TX %1 B  RX %2 B  \u00B7  %3")
                       .arg(locale.toString(m_watchBytesOut), locale.toString(m_watchBytesIn),
                            m_watchPolls == 1 ? tr("1 poll") : tr("%1 polls").arg(locale.toString(m_watchPolls)));
    if (m_watchFailures > 0)
        text += m_watchFailures == 1 ? tr("  \u00B7  1 failed") : tr("  \u00B7  %1 failed").arg(locale.toString(m_watchFailures));
    m_watchLabel->setText(text);
    m_watchLabel->show();
}

QString LinkStatusWidget::watchTrafficText() const
{
    return m_watchLabel->text();
}

QString LinkStatusWidget::stateText() const
{
    return m_stateLabel->text();
}

QString LinkStatusWidget::countersText() const
{
    return m_countersLabel->text();
}

} // namespace mbscope
