#pragma once

#include "dissection.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {

// The two ways a dissection leaves mbscope as text: an aligned table for people and JSON for
// scripts. Both are used by `mbscope decode` and by the golden tests.
class DissectionFormat
{
public:
    // {"framing", "direction", "framing_reason", "direction_reason", "note", "summary", "valid",
    //  "fields": [{"key", "name", "offset", "length", "raw", "value", "display", "severity",
    //              "message", "children"}]}
    [[nodiscard]] static QJsonObject toJson(const Dissection &dissection);

    // Offset, bytes, field, value (with meaning), problems; children indented under parents.
    // Long raw byte runs are shortened to maxRawBytes with their count.
    [[nodiscard]] static QString toTable(const Dissection &dissection, int maxRawBytes = 8);
};

} // namespace mbscope
