#include "common/readyfile.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>

namespace mbscope::app {

ReadyFile::~ReadyFile()
{
    if (m_published)
        QFile::remove(m_path);
}

bool ReadyFile::prepare(const QString &path, QString *error)
{
    const QFileInfo info(path);
    const QFileInfo folder(info.absolutePath());
    if (path.isEmpty() || info.fileName().isEmpty()) {
        *error = QStringLiteral("--ready-file: no file name given");
        return false;
    }
    if (!folder.isDir()) {
        *error = QStringLiteral("--ready-file %1: the folder %2 does not exist").arg(path, QDir::toNativeSeparators(folder.filePath()));
        return false;
    }
    if (info.isDir()) {
        *error = QStringLiteral("--ready-file %1: is a folder, not a file").arg(path);
        return false;
    }
    if (info.exists() && !QFile::remove(path)) {
        *error = QStringLiteral("--ready-file %1: a file left by an earlier run cannot be removed").arg(path);
        return false;
    }
    // Created now and removed, so that a folder where nothing can be written fails before any
    // port is bound rather than after.
    QFile probe(path);
    if (!probe.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("--ready-file %1: cannot be created (%2)").arg(path, probe.errorString());
        return false;
    }
    probe.close();
    probe.remove();
    m_path = path;
    return true;
}

bool ReadyFile::publish(const QStringList &lines, QString *error)
{
    if (m_path.isEmpty())
        return true;
    QSaveFile file(m_path);
    if (!file.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("--ready-file %1: cannot be written (%2)").arg(m_path, file.errorString());
        return false;
    }
    for (const QString &line : lines)
        file.write(line.toUtf8() + '\n');
    if (!file.commit()) {
        *error = QStringLiteral("--ready-file %1: cannot be written (%2)").arg(m_path, file.errorString());
        return false;
    }
    m_published = true;
    return true;
}

} // namespace mbscope::app
