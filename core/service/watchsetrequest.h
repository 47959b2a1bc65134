#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// A write asked for over MQTT (PREFIX/WATCH/set), read against the watch's definition. The payload
// is a JSON object of points and values:
//   {"setpoint": 21.5}                     a number in the point's engineering unit: scale and
//                                          offset undone, then encoded in the point's format
//   {"setpoint": "0x00D7"}                 a text in the point's format, raw (RegisterValue::fromText)
//   {"pump": true}                         a coil: true/false or 1/0
// A point is named by its name (or its address, "0x0079" or "121"), and must be marked writable
// in the watch, in a table that can be written (holding registers, coils). All or nothing: one
// bad entry refuses the message, and error says which and why.
struct WatchSetRequest {
    struct Write {
        QString point;          // as the payload named it
        quint16 address = 0;
        QList<quint16> words;   // registers in wire order; a coil: one word, 0 or 1
    };
    QList<Write> writes;
    QString error;

    [[nodiscard]] bool isOk() const { return error.isEmpty(); }
    [[nodiscard]] static WatchSetRequest parse(const WatchDefinition &watch, const QByteArray &payload);
};

} // namespace mbscope
