#include "procstat.h"

#include <QtCore/QByteArray>
#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QString>

#include <unistd.h>

namespace mbscope::testcli {

double processCpuSeconds(qint64 pid, bool withChildren)
{
    QFile file(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray stat = file.readAll();
    // proc(5): the fields after the command's closing parenthesis; utime, stime, cutime and
    // cstime are fields 14 to 17.
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 15)
        return -1;
    double ticks = fields.at(11).toDouble() + fields.at(12).toDouble();
    if (withChildren)
        ticks += fields.at(13).toDouble() + fields.at(14).toDouble();
    return ticks / double(::sysconf(_SC_CLK_TCK));
}

qint64 processRssKiB(qint64 pid)
{
    QFile file(QStringLiteral("/proc/%1/status").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith("VmRSS:")) // "VmRSS:     12345 kB"
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

} // namespace mbscope::testcli
