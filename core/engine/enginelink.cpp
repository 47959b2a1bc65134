#include "enginecore.h"

#include "protocol/streamframer.h"
#include "transport/monotonicclock.h"
#include "transport/networklink.h"

namespace mbscope {

void EngineCore::closeLink()
{
    m_deferPump = true;
    failInFlight(QStringLiteral("%1: closed on request").arg(m_url.toString()));
    if (m_link && m_link->state() != Link::State::Closed) {
        m_closingQuietly = true;
        m_link->close();
        m_closingQuietly = false;
    }
    m_opening = false;
    m_openTimer.stop();
    resetFramer();
    m_deferPump = false;
}

void EngineCore::openLink()
{
    if (m_link && m_link->state() == Link::State::Open) {
        Q_EMIT linkOpened();
        return;
    }
    ensureLink();
}

void EngineCore::ensureLink()
{
    if (!m_link) {
        m_link = m_factory ? m_factory(m_url, this) : Link::create(m_url, this);
        if (!m_link) {
            failHead(QStringLiteral("%1: no link can be made for this target").arg(m_url.toString()));
            schedulePump();
            return;
        }
        m_link->setReceiver(this);
        updateBroadcastWait();
        connect(m_link, &Link::opened, this, &EngineCore::onOpened);
        connect(m_link, &Link::closed, this, &EngineCore::onClosed);
        connect(m_link, &Link::errorOccurred, this, &EngineCore::onLinkError);
        connect(m_link, &Link::bytesWritten, this, &EngineCore::onBytesWritten);
        connect(m_link, &Link::bytesReceived, this, &EngineCore::onBytesReceived);
    }
    if (m_link->state() == Link::State::Closed && !m_opening) {
        m_opening = true;
        ++m_counters.connects;
        // The link enforces the connect timeout; this one only guards against a link that never answers.
        m_openTimer.start(m_url.connectTimeoutMs + 2000);
        m_link->open();
    }
}

void EngineCore::onOpened()
{
    m_opening = false;
    m_openTimer.stop();
    if (const auto *network = qobject_cast<const NetworkLink *>(m_link))
        m_recorder->noteEndpoints(network->localEndpoint(), network->peerEndpoint());
    resetFramer();
    if (m_options.warmUp.count() > 0) // the device's warm-up: its first request waits (lineQuiet)
        m_lineQuietNs = qMax(m_lineQuietNs, monotonicNowNs() + qint64(m_options.warmUp.count()));
    Q_EMIT linkOpened();
    schedulePump();
}

void EngineCore::onLinkError(const LinkError &error)
{
    ++m_counters.linkErrors;
    m_openTimer.stop();
    const bool wasOpening = m_opening;
    m_opening = false;
    m_deferPump = true;
    Q_EMIT linkMessage(error.message);
    m_linkLost = true;
    const qint64 held = flushPartial();
    m_linkLost = false;
    // Some errors leave the link open (UDP "port unreachable", a serial write error); a lost
    // link says so with closed() after this.
    const bool stillOpen = m_link && m_link->state() == Link::State::Open;
    if (!stillOpen)
        resetFramer();
    QString problem = error.message;
    if (held > 0)
        problem += QStringLiteral(" (after %1 bytes of an unfinished answer)").arg(held);
    if (wasOpening && m_scheduler.inFlight().isEmpty())
        failHead(problem);
    else
        failInFlight(problem);
    m_deferPump = false;
    schedulePump();
}

void EngineCore::onClosed(const QString &reason)
{
    if (m_closingQuietly)
        return;
    m_deferPump = true;
    const bool wasOpening = m_opening;
    m_opening = false;
    m_openTimer.stop();
    m_linkLost = true;
    const qint64 held = flushPartial();
    m_linkLost = false;
    QString problem = QStringLiteral("%1: the link closed: %2").arg(m_url.toString(), reason);
    if (held > 0)
        problem += QStringLiteral(" (after %1 bytes of an unfinished answer)").arg(held);
    if (!m_scheduler.inFlight().isEmpty() || wasOpening) {
        ++m_counters.linkErrors;
        Q_EMIT linkMessage(problem);
    }
    resetFramer();
    if (wasOpening && m_scheduler.inFlight().isEmpty())
        failHead(problem);
    else
        failInFlight(problem);
    m_deferPump = false;
    schedulePump();
}

void EngineCore::failInFlight(const QString &problem)
{
    while (!m_scheduler.inFlight().isEmpty())
        finish(0, TransactionStatus::LinkError, problem);
}

void EngineCore::failHead(const QString &problem)
{
    if (!m_scheduler.hasQueued())
        return;
    const InFlightRequest head = InFlightRequest::unsent(m_scheduler.takeHead());
    // Never written, so no send time; the moment it failed places it in the traffic list.
    const qint64 failedNs = monotonicNowNs();
    record(head.toTransaction(TransactionStatus::LinkError, problem, {}, 0, failedNs), head.out.tag);
}

} // namespace mbscope
