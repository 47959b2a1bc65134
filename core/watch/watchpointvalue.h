#pragma once

#include <QtCore/QList>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// The value of one named bit field of a register: "mode" = 3 ("auto").
struct WatchBitFieldValue {
    QString name;
    quint32 value = 0;
    QString state; // the field's state name for the value; empty when it has none

    friend bool operator==(const WatchBitFieldValue &, const WatchBitFieldValue &) = default;
};

// One value of a watch's answer as WatchDecoder reads it: a point of the definition, or an address
// no point names (shown as u16, a 32-bit value in an Enron watch, or 0/1 for bits).
struct WatchPointValue {
    quint16 address = 0;
    int width = 1;         // addresses the value occupies (a u32 in a 16-bit table: 2)
    int point = -1;        // index in WatchDefinition::points; -1: an address no point names
    QString name;          // the point's name (empty for unnamed addresses)
    QString unit;
    quint64 raw = 0;       // the value's bits, byte order undone (RegisterValue::bits), or the bit
    double value = 0;      // raw as a number, times scale plus offset
    QString text;          // the value as shown: the format's text unscaled, else the scaled number
    QList<WatchBitFieldValue> bitFields;

    friend bool operator==(const WatchPointValue &, const WatchPointValue &) = default;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::WatchPointValue)
