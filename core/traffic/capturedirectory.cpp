#include "capturedirectory.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QSysInfo>

#include <algorithm>

#if defined(Q_OS_UNIX)
#include <cerrno>
#include <csignal>
#include <unistd.h>
#endif

namespace mbscope {

namespace {

QString markerOf(const QString &journal)
{
    return journal + QLatin1String(CaptureDirectory::kMarkerSuffix);
}

// "rtu-tcp://127.0.0.1:4001" -> "rtu-tcp_127.0.0.1_4001": letters, digits, '.', '-' kept.
QString fileSafe(const QString &target)
{
    QString out;
    for (const QChar c : target) {
        if (c.isLetterOrNumber() || c == u'.' || c == u'-')
            out += c;
        else if (!out.endsWith(u'_'))
            out += u'_';
    }
    while (out.endsWith(u'_'))
        out.chop(1);
    return out.left(80);
}

bool processAlive(qint64 pid)
{
#if defined(Q_OS_UNIX)
    if (pid <= 0)
        return false;
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
#else
    Q_UNUSED(pid);
    return true;
#endif
}

qint64 ownPid()
{
#if defined(Q_OS_UNIX)
    return qint64(::getpid());
#else
    return 0;
#endif
}

// The marker's process id, when it was written on this host; 0 otherwise.
qint64 markerPid(const QString &marker)
{
    QFile file(marker);
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> lines = file.readAll().split('\n');
    if (lines.size() < 2 || QString::fromUtf8(lines.at(1)) != QSysInfo::machineHostName())
        return 0;
    return lines.at(0).toLongLong();
}

} // namespace

CaptureDirectory::CaptureDirectory(QString path)
    : m_path(std::move(path))
{
}

bool CaptureDirectory::ensureExists(QString *error) const
{
    if (QDir().mkpath(m_path))
        return true;
    if (error)
        *error = QStringLiteral("%1: cannot create the capture folder").arg(m_path);
    return false;
}

QString CaptureDirectory::newJournalPath(const QDateTime &start, const QString &target, int part) const
{
    QString base = start.toString(QStringLiteral("yyyyMMdd-HHmmss"));
    if (const QString safe = fileSafe(target); !safe.isEmpty())
        base += u'-' + safe;
    if (part > 1)
        base += QStringLiteral("-part%1").arg(part);
    const QDir dir(m_path);
    QString candidate = dir.filePath(base + QLatin1String(kSuffix));
    for (int n = 2; QFileInfo::exists(candidate) || QFileInfo::exists(markerOf(candidate)); ++n)
        candidate = dir.filePath(base + QStringLiteral("-%1").arg(n) + QLatin1String(kSuffix));
    return candidate;
}

QList<CaptureDirectory::Journal> CaptureDirectory::journals() const
{
    QList<Journal> out;
    const QFileInfoList files = QDir(m_path).entryInfoList({QStringLiteral("*") + QLatin1String(kSuffix)}, QDir::Files);
    for (const QFileInfo &f : files)
        out.append(Journal{f.absoluteFilePath(), f.size(), f.lastModified()});
    std::sort(out.begin(), out.end(), [](const Journal &a, const Journal &b) {
        return a.modified != b.modified ? a.modified < b.modified : a.path < b.path;
    });
    return out;
}

QStringList CaptureDirectory::enforceQuota(qint64 maxBytes, const QStringList &keep) const
{
    QList<Journal> all = journals();
    qint64 total = 0;
    for (const Journal &j : all)
        total += j.bytes;
    QStringList deleted;
    for (const Journal &j : all) {
        if (total <= maxBytes)
            break;
        const QString marker = markerOf(j.path);
        if (keep.contains(j.path) || (QFileInfo::exists(marker) && processAlive(markerPid(marker))))
            continue;
        if (QFile::remove(j.path)) {
            QFile::remove(marker);
            total -= j.bytes;
            deleted.append(j.path);
        }
    }
    return deleted;
}

bool CaptureDirectory::markOpen(const QString &journal, QString *error)
{
    QFile marker(markerOf(journal));
    if (!marker.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        if (error)
            *error = QStringLiteral("%1: cannot write the recording marker: %2").arg(marker.fileName(), marker.errorString());
        return false;
    }
    marker.write(QByteArray::number(ownPid()) + '\n' + QSysInfo::machineHostName().toUtf8() + '\n');
    return true;
}

void CaptureDirectory::markClosed(const QString &journal)
{
    QFile::remove(markerOf(journal));
}

QStringList CaptureDirectory::abandoned() const
{
    QStringList out;
    const QList<Journal> all = journals();
    for (auto it = all.crbegin(); it != all.crend(); ++it) {
        const QString marker = markerOf(it->path);
        if (QFileInfo::exists(marker) && !processAlive(markerPid(marker)))
            out.append(it->path);
    }
    return out;
}

} // namespace mbscope
