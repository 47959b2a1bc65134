#include "savedrequests.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QSettings>

namespace mbscope {

namespace {

const QString kKey = QStringLiteral("composer/savedRequests");

QString tr(const char *text)
{
    return QCoreApplication::translate("mbscope::SavedRequests", text);
}

} // namespace

SavedRequest SavedRequests::rosRaoRead()
{
    return {tr("RosRao read"), QStringLiteral("01 03 00 79 00 16 15 DD")};
}

QList<SavedRequest> SavedRequests::defaults()
{
    return {
        rosRaoRead(),
        {tr("Read 10 holding registers from 0 (RTU, unit 1)"), QStringLiteral("01 03 00 00 00 0A C5 CD")},
        {tr("Read 16 coils from 0 (RTU, unit 1)"), QStringLiteral("01 01 00 00 00 10 3D C6")},
        {tr("Read 10 holding registers from 0 (TCP, unit 1)"), QStringLiteral("00 01 00 00 00 06 01 03 00 00 00 0A")},
        {tr("Report server id (RTU, unit 1)"), QStringLiteral("01 11 C0 2C")},
    };
}

QList<SavedRequest> SavedRequests::load()
{
    QSettings settings;
    // An array is a group, which contains() does not see: its size key says it was stored.
    if (!settings.contains(kKey + QStringLiteral("/size")))
        return defaults();
    QList<SavedRequest> requests;
    const int size = settings.beginReadArray(kKey);
    for (int i = 0; i < size; ++i) {
        settings.setArrayIndex(i);
        requests.append({settings.value(QStringLiteral("name")).toString(), settings.value(QStringLiteral("hex")).toString()});
    }
    settings.endArray();
    return requests;
}

void SavedRequests::store(const QList<SavedRequest> &requests)
{
    QSettings settings;
    settings.remove(kKey);
    settings.beginWriteArray(kKey, int(requests.size()));
    for (int i = 0; i < requests.size(); ++i) {
        settings.setArrayIndex(i);
        settings.setValue(QStringLiteral("name"), requests.at(i).name);
        settings.setValue(QStringLiteral("hex"), requests.at(i).hex);
    }
    settings.endArray();
}

} // namespace mbscope
