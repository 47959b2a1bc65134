#include "recordingsettings.h"

#include <QtCore/QDir>
#include <QtCore/QSettings>
#include <QtCore/QStandardPaths>

namespace mbscope {

RecordingSettings RecordingSettings::load()
{
    const QSettings settings;
    RecordingSettings r;
    r.enabled = settings.value(QStringLiteral("recording/enabled"), r.enabled).toBool();
    r.folder = settings.value(QStringLiteral("recording/folder")).toString();
    r.rotateMiB = qBound(1, settings.value(QStringLiteral("recording/rotateMiB"), r.rotateMiB).toInt(), 4096);
    r.keepMiB = qBound(16, settings.value(QStringLiteral("recording/keepMiB"), r.keepMiB).toInt(), 1 << 20);
    return r;
}

void RecordingSettings::store() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("recording/enabled"), enabled);
    settings.setValue(QStringLiteral("recording/folder"), folder);
    settings.setValue(QStringLiteral("recording/rotateMiB"), rotateMiB);
    settings.setValue(QStringLiteral("recording/keepMiB"), keepMiB);
}

QString RecordingSettings::defaultFolder()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("captures"));
}

RollingCapture::Policy RecordingSettings::policy() const
{
    RollingCapture::Policy p;
    p.rotateBytes = qint64(rotateMiB) << 20;
    p.keepBytes = qint64(keepMiB) << 20;
    return p;
}

} // namespace mbscope
