#pragma once

#include "linerule.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>

namespace mbscope {

class JsonReader;

// Reads a profile's "delimited" object (docs/profiles.md, "Delimited protocols"), recording
// problems in the reader: patterns that are not regular expressions (with the character at
// fault), templates naming a capture the pattern does not have, tables that do not exist.
class LineTableReader
{
public:
    [[nodiscard]] static LineTable read(JsonReader &reader, const QJsonValue &value, const QString &path);
};

} // namespace mbscope
