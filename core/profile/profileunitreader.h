#pragma once

#include "deviceprofile.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

class JsonReader;

// Reads one unit of a device profile (format in docs/profiles.md): identity, function codes,
// response delay, tables (ProfileTableReader), FIFOs, files, device identification, server id.
class ProfileUnitReader
{
public:
    [[nodiscard]] static std::optional<UnitProfile> read(JsonReader &reader, const QJsonValue &value,
                                                         const QString &path);

private:
    // "sharedTables" (after the tables, whose entries it checks) and "gapReads".
    static void readSharedTables(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static void readFunctions(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static void readFifos(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static void readFiles(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static void readDeviceId(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static void readServerId(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);
    static QList<quint16> readWords(JsonReader &reader, const QJsonValue &value, const QString &path,
                                    qsizetype maxCount);
};

} // namespace mbscope
