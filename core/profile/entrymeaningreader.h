#pragma once

#include "deviceprofile.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

class JsonReader;

// Reads what a register map says of a table entry besides its numbers (docs/profiles.md, "What a
// register map says"): "kind", "min"/"max", "scaleRegister", "bits", "enum", "length"/"padding"
// and "notImplemented". Each problem names the entry's path and the key ("...holding[3].bits.17:
// bit 17 is beyond a u16 (bits 0-15)"). Called after the entry's type and scale are read.
class EntryMeaningReader
{
public:
    // The keys it reads, for checkKeys: bits tables take only "kind".
    [[nodiscard]] static QList<const char *> keys(bool bits);
    static void read(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry);
    // Resolves scaleRegister into the entry's scale (10 to the power of the i16 the register
    // holds at start), checking that it names a one-register integer entry of the same table
    // among known (the entries without a scaleRegister, read first). False on a problem.
    static bool resolveScaleRegister(JsonReader &reader, const QList<TableEntry> &known, const QString &path,
                                     TableEntry *entry);
};

} // namespace mbscope
