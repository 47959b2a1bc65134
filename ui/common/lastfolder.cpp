#include "lastfolder.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QSettings>

namespace mbscope {

QString LastFolder::folder()
{
    const QString stored = QSettings().value(QLatin1String(kSettingsKey)).toString();
    if (!stored.isEmpty() && QFileInfo(stored).isDir())
        return stored;
    return QDir::homePath();
}

QString LastFolder::start(const QString &fileName)
{
    if (fileName.isEmpty())
        return folder();
    if (QFileInfo(fileName).isAbsolute())
        return fileName;
    return QDir(folder()).filePath(fileName);
}

void LastFolder::remember(const QString &path)
{
    if (path.isEmpty())
        return;
    const QFileInfo info(path);
    const QString where = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
    QSettings().setValue(QLatin1String(kSettingsKey), QDir::cleanPath(where));
}

} // namespace mbscope
