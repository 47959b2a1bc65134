#include "watchlogwriter.h"

#include "watch/watchcsvlog.h"

namespace mbscope {

WatchLogWriter::WatchLogWriter(QObject *parent)
    : QObject(parent)
{
}

WatchLogWriter::~WatchLogWriter()
{
    close();
}

void WatchLogWriter::configure(const std::optional<WatchLogSettings> &settings, const QString &baseDirectory)
{
    std::optional<WatchLogSettings> wanted = settings && settings->enabled ? settings : std::nullopt;
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
    Q_EMIT opened(m_log->directory());
}

void WatchLogWriter::close()
{
    if (!m_log)
        return;
    m_log->close();
    Q_EMIT closed(m_log->directory(), m_log->files(), m_log->lostRows());
    m_log.reset();
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
