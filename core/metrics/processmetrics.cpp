#include "processmetrics.h"

#include <QtCore/QDir>
#include <QtCore/QFile>

#ifdef Q_OS_LINUX
#include <unistd.h>
#endif

namespace mbscope {

ProcessMetrics::ProcessMetrics(MetricsRegistry &registry)
    : m_resident(registry.gauge(QStringLiteral("process_resident_memory_bytes"), QStringLiteral("Resident memory size in bytes.")))
    , m_virtual(registry.gauge(QStringLiteral("process_virtual_memory_bytes"), QStringLiteral("Virtual memory size in bytes.")))
    , m_cpu(registry.counter(QStringLiteral("process_cpu_seconds_total"), QStringLiteral("Total user and system CPU time spent in seconds.")))
    , m_start(registry.gauge(QStringLiteral("process_start_time_seconds"),
                             QStringLiteral("Start time of the process since unix epoch in seconds.")))
    , m_fds(registry.gauge(QStringLiteral("process_open_fds"), QStringLiteral("Number of open file descriptors.")))
{
}

void ProcessMetrics::update()
{
#ifdef Q_OS_LINUX
    QFile stat(QStringLiteral("/proc/self/stat"));
    if (!stat.open(QIODevice::ReadOnly))
        return;
    const QByteArray line = stat.readAll();
    // proc(5): the command name (field 2) is in parentheses and may hold spaces; fields after it
    // are counted from the last ')'. utime 14, stime 15, starttime 22, vsize 23, rss 24.
    const qsizetype close = line.lastIndexOf(')');
    if (close < 0)
        return;
    const QList<QByteArray> fields = line.mid(close + 2).split(' ');
    const auto field = [&](int number) { return fields.value(number - 3).toDouble(); };
    const double ticks = double(::sysconf(_SC_CLK_TCK));
    const double page = double(::sysconf(_SC_PAGESIZE));
    m_cpu.set({}, (field(14) + field(15)) / ticks);
    m_virtual.set({}, field(23));
    m_resident.set({}, field(24) * page);

    QFile uptime(QStringLiteral("/proc/stat"));
    if (uptime.open(QIODevice::ReadOnly)) {
        for (const QByteArray &l : uptime.readAll().split('\n')) {
            if (l.startsWith("btime "))
                m_start.set({}, l.mid(6).trimmed().toDouble() + field(22) / ticks);
        }
    }
    m_fds.set({}, double(QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot).size()));
#endif
}

} // namespace mbscope
