#pragma once

#include "deviceprofile.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

class JsonReader;

// Reads the "tables" object of a unit in a device profile (format in docs/profiles.md): the
// entries of each table with their types, scaling, initial values and generators, and checks
// that entries do not overlap and that copy generators name an existing value.
class ProfileTableReader
{
public:
    // Appends the entries to unit->entries, sorted by table then address.
    static void readTables(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit);

    // The keys of "tables" and of a copy's "table" are simTableKey's (simtable.h).

private:
    // known: the entries read so far (a scaleRegister's source is among them).
    static std::optional<TableEntry> readEntry(JsonReader &reader, const QJsonValue &value, const QString &path,
                                               SimTable table, const QList<TableEntry> &known);
    static bool readInitialValues(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry);
    static std::optional<GeneratorSpec> readGenerator(JsonReader &reader, const QJsonValue &value,
                                                      const QString &path, const TableEntry &entry);
};

} // namespace mbscope
