#include "watchlogwriter.h"

#include "watch/watchcsvlog.h"

#include <QtCore/QDateTime>

namespace mbscope {

namespace {

QString rowsText(quint64 rows)
{
    return QStringLiteral("%1 %2").arg(rows).arg(rows == 1 ? QStringLiteral("row") : QStringLiteral("rows"));
}

} // namespace

WatchLogWriter::WatchLogWriter(qint64 queueBytes, QObject *parent)
    : QObject(parent)
    , m_queue(queueBytes)
{
}

WatchLogWriter::~WatchLogWriter()
{
    close();
}

void WatchLogWriter::wake()
{
    QMetaObject::invokeMethod(this, &WatchLogWriter::onQueued, Qt::QueuedConnection);
}

void WatchLogWriter::offerStarted(const SessionWatches &watches)
{
    if (m_queue.pushStarted(watches))
        wake();
}

void WatchLogWriter::offerSamples(const QList<WatchSample> &samples)
{
    if (m_logging.load(std::memory_order_relaxed) && m_queue.pushSamples(samples))
        wake();
}

void WatchLogWriter::offerEvent(const WatchRuleEvent &event)
{
    if (m_logging.load(std::memory_order_relaxed) && m_queue.pushEvent(event))
        wake();
}

void WatchLogWriter::offerStopped()
{
    if (m_queue.pushStopped())
        wake();
}

void WatchLogWriter::drain()
{
    write(m_queue.size());
}

void WatchLogWriter::onQueued()
{
    // A turn of the thread's event loop every 64 entries, so that configure() (logging turned
    // off, say) need not wait for a queue the polls keep full.
    if (!write(64))
        wake();
}

bool WatchLogWriter::write(qsizetype entries)
{
    for (qsizetype n = 0; n < entries; ++n) {
        std::optional<WatchLogQueue::Entry> e = m_queue.take();
        if (!e)
            break;
        switch (e->kind) {
        case WatchLogQueue::Entry::Kind::Started:
            watchesStarted(e->watches);
            break;
        case WatchLogQueue::Entry::Kind::Samples:
            append(e->samples);
            break;
        case WatchLogQueue::Entry::Kind::RuleEvent:
            appendEvent(e->event);
            break;
        case WatchLogQueue::Entry::Kind::Stopped:
            watchesStopped();
            break;
        }
        takeDrops();
    }
    takeDrops();
    if (!m_queue.isEmpty())
        return false;
    // Everything queued is written: the log has caught up with the polls.
    endDropping(QStringLiteral("the log caught up"));
    return true;
}

void WatchLogWriter::takeDrops()
{
    const QMap<int, quint64> drops = m_queue.takeDropped();
    if (drops.isEmpty())
        return;
    const bool first = m_droppingNow.isEmpty();
    if (first)
        m_droppingSinceMs = QDateTime::currentMSecsSinceEpoch();
    for (auto it = drops.cbegin(); it != drops.cend(); ++it) {
        if (it.key() < 0 || it.key() >= m_watches.watches.size())
            continue;
        const bool newWatch = !m_droppingNow.contains(it.key());
        m_droppingNow[it.key()] += it.value();
        m_dropped[it.key()] += it.value();
        if (m_log)
            m_droppedSinceOpen += it.value();
        Q_EMIT droppedRows(it.key(), m_dropped.value(it.key()));
        // The events file says where the gap starts; the row that ends it says how many.
        if (newWatch && m_log) {
            QString error;
            const bool ok = m_log->appendNote(it.key(), m_droppingSinceMs, QStringLiteral("overflow"), m_droppingNow.value(it.key()),
                                              QStringLiteral("the log cannot keep up with the polls: rows are dropped until it catches up"),
                                              &error);
            said(it.key(), ok, error);
        }
    }
    if (first && !m_droppingNow.isEmpty()) {
        Q_EMIT dropping(QStringLiteral("the log cannot keep up with the polls: rows are dropped until it catches up "
                                       "(at most %1 MiB wait to be written)")
                            .arg(m_queue.capacityBytes() / (1024 * 1024)));
    }
}

void WatchLogWriter::endDropping(const QString &why)
{
    if (m_droppingNow.isEmpty())
        return;
    const QString since = QDateTime::fromMSecsSinceEpoch(m_droppingSinceMs, Qt::UTC).toString(Qt::ISODateWithMs);
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    quint64 total = 0;
    for (auto it = m_droppingNow.cbegin(); it != m_droppingNow.cend(); ++it) {
        total += it.value();
        if (!m_log)
            continue;
        QString error;
        const bool ok = m_log->appendNote(it.key(), now, QStringLiteral("dropped"), it.value(),
                                          QStringLiteral("%1 not logged since %2: the log could not keep up with the polls")
                                              .arg(rowsText(it.value()), since),
                                          &error);
        said(it.key(), ok, error);
    }
    m_droppingNow.clear();
    Q_EMIT caughtUp(total, QStringLiteral("%1: %2 dropped since %3").arg(why, rowsText(total), since));
}

void WatchLogWriter::configure(const std::optional<WatchLogSettings> &settings, const QString &baseDirectory)
{
    // What was queued under the old settings is theirs.
    drain();
    std::optional<WatchLogSettings> wanted = settings && settings->enabled ? settings : std::nullopt;
    m_logging = wanted.has_value();
    if (wanted == m_settings && baseDirectory == m_base)
        return;
    close();
    m_settings = std::move(wanted);
    m_base = baseDirectory;
    if (m_running)
        open();
}

void WatchLogWriter::watchesStarted(const SessionWatches &watches)
{
    close();
    m_watches = watches;
    m_dropped.clear();
    m_running = true;
    open();
}

void WatchLogWriter::watchesStopped()
{
    m_running = false;
    close();
    Q_EMIT drained();
}

void WatchLogWriter::open()
{
    if (!m_settings)
        return;
    auto log = std::make_unique<WatchCsvLog>(*m_settings, m_base);
    QString error;
    if (!log->open(m_watches.watches, &error)) {
        Q_EMIT failed(error);
        return;
    }
    m_log = std::move(log);
    m_failing.clear();
    m_droppedSinceOpen = 0;
    Q_EMIT opened(m_log->directory());
}

void WatchLogWriter::close()
{
    takeDrops();
    endDropping(QStringLiteral("the log closed"));
    if (!m_log)
        return;
    m_log->close();
    Q_EMIT closed(m_log->directory(), m_log->files(), m_log->lostRows() + m_droppedSinceOpen, m_droppedSinceOpen);
    m_log.reset();
    m_droppedSinceOpen = 0;
}

void WatchLogWriter::said(int watch, bool ok, const QString &error)
{
    // Said once while it lasts (a full disk would say it at every poll, a folder that cannot be
    // made at every watch's roll while the others still write to their open files), and again
    // should it come back after every failing watch wrote again.
    if (ok) {
        m_failing.remove(watch);
        return;
    }
    if (m_failing.isEmpty())
        Q_EMIT failed(error);
    m_failing.insert(watch);
}

void WatchLogWriter::append(const QList<WatchSample> &samples)
{
    if (!m_log)
        return;
    for (const WatchSample &s : samples) {
        QString error;
        const bool ok = m_log->append(s.watch, s.timeMs, watchSampleStatusName(s.status), s.values, s.error, &error);
        said(s.watch, ok, error);
    }
}

void WatchLogWriter::appendEvent(const WatchRuleEvent &event)
{
    if (!m_log)
        return;
    QString error;
    const bool ok = m_log->appendEvent(event, &error);
    said(event.watch, ok, error);
}

} // namespace mbscope

#include "moc_watchlogwriter.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
