#include "service/servicelog.h"

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>

#include <sys/stat.h>

namespace mbscope::app {

namespace {

// syslog(3) priorities: LOG_ERR 3, LOG_WARNING 4, LOG_NOTICE 5, LOG_INFO 6, LOG_DEBUG 7.
int priority(ServiceLog::Level level)
{
    return 3 + int(level);
}

// systemd sets JOURNAL_STREAM to "DEVICE:INODE" of the stream it connected to the journal; it is
// ours only while standard error still is that stream (systemd.exec(5)).
bool stderrIsJournal(std::FILE *stream)
{
    const QByteArray journal = qgetenv("JOURNAL_STREAM");
    if (journal.isEmpty())
        return false;
    struct stat st = {};
    if (::fstat(fileno(stream), &st) != 0)
        return false;
    return journal == QByteArray::number(quint64(st.st_dev)) + ':' + QByteArray::number(quint64(st.st_ino));
}

} // namespace

ServiceLog::ServiceLog(std::FILE *stream)
    : m_stream(stream)
    , m_journal(stderrIsJournal(stream))
{
}

void ServiceLog::write(Level level, const QString &message)
{
    if (int(level) > int(m_level))
        return;
    QByteArray line;
    if (m_journal)
        line = '<' + QByteArray::number(priority(level)) + '>';
    else
        line = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toLatin1() + ' ';
    line += levelName(level);
    line += ": ";
    line += message.toUtf8();
    line += '\n';
    std::fwrite(line.constData(), 1, size_t(line.size()), m_stream);
    std::fflush(m_stream);
}

bool ServiceLog::parseLevel(const QString &text, Level *level)
{
    for (const Level l : {Level::Error, Level::Warning, Level::Notice, Level::Info, Level::Debug}) {
        if (text == QLatin1String(levelName(l))) {
            *level = l;
            return true;
        }
    }
    return false;
}

const char *ServiceLog::levelName(Level level)
{
    switch (level) {
    case Level::Error:
        return "error";
    case Level::Warning:
        return "warning";
    case Level::Notice:
        return "notice";
    case Level::Info:
        return "info";
    case Level::Debug:
        return "debug";
    }
    return "info";
}

} // namespace mbscope::app
