#include "rollingcapture.h"

#include "trafficmetadata.h"

#include <QtCore/QCoreApplication>

#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QMutexLocker>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace mbscope {

namespace {

// The window's log keeps what the traffic list may need again in memory; the journal keeps all.
TrafficLog::Limits windowLimits()
{
    TrafficLog::Limits limits;
    limits.maxEntries = 200'000;
    limits.maxBytes = quint64(32) << 20;
    return limits;
}

} // namespace

RollingCapture::RollingCapture(const CaptureDirectory &directory, const Policy &policy)
    : m_directory(directory)
    , m_partsDirectory(directory)
    , m_policy(policy)
    , m_log(windowLimits())
{
    // The window's watches and scans write into it beside the composer's engine.
    m_log.setShared(true);
}

RollingCapture::~RollingCapture()
{
    finish();
}

bool RollingCapture::start(const QString &target, QString *error, const Describe &describe)
{
    if (!m_directory.ensureExists(error))
        return false;
    m_target = target;
    m_start = QDateTime::currentDateTime();
    m_part = 1;
    const QString path = m_directory.newJournalPath(m_start, m_target, m_part);
    if (!CaptureDirectory::markOpen(path, error))
        return false;
    // What the journal holds, for analyze and replay of it alone: the window, its target.
    TrafficMetadata metadata = TrafficMetadata::forCommand(QStringLiteral("window"), QCoreApplication::arguments().mid(1),
                                                           QCoreApplication::applicationVersion());
    metadata.target = target;
    if (describe)
        describe(metadata);
    TrafficJournalWriter::Options options;
    options.metadata = metadata.toUtf8();
    if (!m_log.openJournal(path, options, false, error)) {
        CaptureDirectory::markClosed(path);
        return false;
    }
    {
        const QMutexLocker lock(&m_mutex);
        m_path = path;
    }
    m_log.setJournalRotation(m_policy.rotateBytes, [this](const QString &closed) { return nextPart(closed); });
    m_directory.enforceQuota(m_policy.keepBytes, {path});
    return true;
}

QString RollingCapture::nextPart(const QString &closedPath)
{
    // In the engine's thread: the part just closed is whole, its marker goes (the writer's own
    // name for it is stale after a move).
    Q_UNUSED(closedPath);
    CaptureDirectory::markClosed(currentPath());
    CaptureDirectory parts;
    {
        const QMutexLocker lock(&m_mutex);
        parts = m_partsDirectory;
    }
    const QString path = parts.newJournalPath(m_start, m_target, ++m_part);
    // Without its marker the part is still tried: the journal's own open then says what is wrong
    // with the place ("cannot create ...: No such file or directory"), which the window shows.
    CaptureDirectory::markOpen(path);
    {
        const QMutexLocker lock(&m_mutex);
        m_path = path;
    }
    m_directory.enforceQuota(m_policy.keepBytes, {path});
    return path;
}

QString RollingCapture::currentPath() const
{
    const QMutexLocker lock(&m_mutex);
    return m_path;
}

bool RollingCapture::moveTo(const QString &path, QString *error)
{
    const QString from = currentPath();
    if (from.isEmpty()) {
        if (error)
            *error = QStringLiteral("nothing is being recorded");
        return false;
    }
    if (QFile::exists(path)) {
        if (error)
            *error = QStringLiteral("%1 exists: a journal is never overwritten").arg(path);
        return false;
    }
    // rename(2), not QFile::rename: that one copies across file systems, and the writer would go
    // on into the old file. A rename keeps the open file: what comes next lands at path.
    if (std::rename(QFile::encodeName(from).constData(), QFile::encodeName(path).constData()) != 0) {
        if (error)
            *error = QStringLiteral("cannot move %1 to %2: %3").arg(from, path, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    CaptureDirectory::markClosed(from);
    CaptureDirectory::markOpen(path);
    const QMutexLocker lock(&m_mutex);
    m_partsDirectory = CaptureDirectory(QFileInfo(path).absolutePath());
    m_path = path;
    return true;
}

void RollingCapture::finish()
{
    const QString path = currentPath();
    if (path.isEmpty())
        return;
    m_log.setJournalRotation(0, {});
    m_log.closeJournal();
    CaptureDirectory::markClosed(path);
    {
        const QMutexLocker lock(&m_mutex);
        m_path.clear();
    }
    m_directory.enforceQuota(m_policy.keepBytes);
}

} // namespace mbscope
