#include "unitscanner.h"

#include "unitclassifier.h"

namespace mbscope {

UnitScanner::UnitScanner(QObject *parent)
    : QObject(parent)
    , m_channel(new ProbeChannel(this))
{
    connect(m_channel, &ProbeChannel::answered, this, &UnitScanner::onAnswered);
}

QByteArray UnitScanner::readPdu(quint8 function, quint16 address, quint16 quantity)
{
    QByteArray pdu(1, char(function));
    pdu.append(char(address >> 8)).append(char(address & 0xFF));
    pdu.append(char(quantity >> 8)).append(char(quantity & 0xFF));
    return pdu;
}

bool UnitScanner::start(const UnitScanSettings &settings)
{
    if (m_running || !settings.problem().isEmpty())
        return false;
    m_settings = settings;
    m_results.clear();
    m_channel->setTarget(settings.url);
    m_channel->setGapMs(settings.gapMs);
    m_nextUnit = settings.firstUnit;
    m_running = true;
    m_clock.start();
    Q_EMIT progressChanged(progress());
    // From the event loop: a scan whose time limit leaves room for no request at all ends at
    // once, and finished() must reach whoever waits for it after start() (a command's loop hung
    // forever, deaf to Ctrl-C, on `scan --units 1-3 --max-time 200ms`).
    QMetaObject::invokeMethod(this, &UnitScanner::next, Qt::QueuedConnection);
    return true;
}

void UnitScanner::stop()
{
    if (m_running)
        end(JobEnd::Stopped);
}

JobProgress UnitScanner::progress() const
{
    JobProgress p;
    p.total = m_settings.idCount();
    p.done = int(m_results.size());
    for (const UnitProbe &r : m_results)
        p.found += r.isPresent() ? 1 : 0;
    p.elapsedMs = m_clock.isValid() ? m_clock.elapsed() : 0;
    const int left = p.total - p.done;
    const qint64 perId = p.done > 0 ? p.elapsedMs / p.done : m_settings.timeoutMs + m_settings.gapMs;
    p.remainingMs = qMin<qint64>(qint64(left) * perId, qMax<qint64>(0, m_settings.maxDurationMs - p.elapsedMs));
    return p;
}

void UnitScanner::next()
{
    if (!m_running)
        return;
    if (m_nextUnit > m_settings.lastUnit) {
        end(JobEnd::Completed);
        return;
    }
    // The probe must fit in what is left of the time limit, or it is not sent.
    if (m_clock.elapsed() + m_settings.timeoutMs + m_settings.gapMs > m_settings.maxDurationMs) {
        end(JobEnd::TimeLimit);
        return;
    }
    m_current = m_nextUnit++;
    m_channel->probe(quint8(m_current),
                     readPdu(m_settings.function, m_settings.address, m_settings.quantity),
                     m_settings.timeoutMs);
}

void UnitScanner::onAnswered(const Transaction &transaction, const QByteArray &bytesRead)
{
    if (!m_running)
        return;
    const UnitProbe probe =
        UnitClassifier::classify(quint8(m_current), transaction, m_settings.url.framing(), bytesRead);
    m_results.append(probe);
    Q_EMIT probed(probe);
    Q_EMIT progressChanged(progress());
    if (probe.kind == UnitProbeKind::LinkError) {
        end(JobEnd::LinkError);
        return;
    }
    next();
}

void UnitScanner::end(JobEnd how)
{
    m_running = false;
    m_channel->cancel();
    Q_EMIT progressChanged(progress());
    Q_EMIT finished(how);
}

} // namespace mbscope

#include "moc_unitscanner.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
