#include "session/capturesourcepath.h"

#include "session/capturerecovery.h"
#include "session/sessionreader.h"

#include <QtCore/QFile>
#include <QtCore/QFileInfo>

namespace mbscope {

bool CaptureSourcePath::isSessionDocument(const QString &source)
{
    QFile file(source);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    return file.read(64).trimmed().startsWith('{');
}

bool CaptureSourcePath::resolve(const QString &source, QString *path, QString *error)
{
    const QFileInfo info(source);
    if (!info.exists()) {
        *error = QStringLiteral("%1: no such file").arg(source);
        return false;
    }
    if (info.isDir()) {
        *error = QStringLiteral("%1: a directory, not a capture or journal").arg(source);
        return false;
    }
    if (!isSessionDocument(source)) {
        *path = source;
        return true;
    }
    const SessionLoadResult loaded = SessionReader::load(source);
    if (!loaded.ok()) {
        *error = QStringLiteral("%1: not a session document mbscope can read:\n%2").arg(source, loaded.errorText());
        return false;
    }
    const QString journal = CaptureRecovery::journalPath(*loaded.document, source);
    if (journal.isEmpty()) {
        *error = QStringLiteral("%1: the session holds no captured traffic (no \"capture\" naming a journal)").arg(source);
        return false;
    }
    if (!QFileInfo::exists(journal)) {
        *error = QStringLiteral("%1: the session's journal %2 does not exist").arg(source, journal);
        return false;
    }
    *path = journal;
    return true;
}

} // namespace mbscope
