#pragma once

#include "profile/deviceprofile.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>
#include <span>

namespace mbscope {

// One value of a register map, as the exports write it: a device profile's table entries cut
// into their values (an f32 entry of 10 registers is 5 points), each with a name unique in the
// map ("voltage", "voltage_2"; "holding_121" when the entry has no name), its read function,
// format, scaling and meaning. Reserved entries are left out.
struct MapPoint {
    quint8 unitId = 1;
    SimTable table = SimTable::HoldingRegisters;
    quint16 address = 0;
    int registers = 1;        // registers of the value (bits: 1)
    RegisterFormat format;    // registers only
    QString name;             // [a-z0-9_], unique in the map
    QString label;            // the entry's name as written, with the value's index when it has several
    QString description;
    QString unit;
    double scale = 1;
    double offset = 0;
    ValueKind kind = ValueKind::Unspecified;
    bool writable = false;
    std::optional<double> min, max;
    int stringLength = 0;
    bool spacePadded = false;
    QMap<int, QString> bitNames;
    QMap<qint64, QString> enumNames;
    std::optional<quint64> notImplemented;
    bool notImplementedNaN = false;
    std::optional<quint16> scaleRegister;

    [[nodiscard]] bool isBit() const { return isBitTable(table); }
    [[nodiscard]] bool isString() const { return stringLength > 0; }
    // 1-4: the function code that reads the point's table.
    [[nodiscard]] quint8 readFunction() const;
    // "coils", "discrete", "input", "holding".
    [[nodiscard]] QString tableKey() const;
    // The number type as YAML configs name it: "int16", "uint32", "float32"... ("uint16" for
    // u16 and anything not numeric: callers handle strings and bits first).
    [[nodiscard]] QString numberType() const;
    // A YAML double-quoted scalar of s (Home Assistant's and modbus_exporter's files).
    [[nodiscard]] static QString yamlQuoted(const QString &s);

    // The engineering value of the point in registers (its own, wire order; bits: one 0/1):
    // raw * scale + offset; nullopt for the "not implemented" sentinel and for strings.
    [[nodiscard]] std::optional<double> decode(std::span<const quint16> registers) const;
    // A string's text without its padding.
    [[nodiscard]] QString decodeText(std::span<const quint16> registers) const;
    [[nodiscard]] bool isNotImplemented(std::span<const quint16> registers) const;

    // Every point of the profile (of one unit when unitId is given), in unit, table and address order.
    [[nodiscard]] static QList<MapPoint> fromProfile(const DeviceProfile &profile,
                                                     std::optional<quint8> unitId = std::nullopt);
    // "Phase L1 voltage" -> "phase_l1_voltage"; empty when nothing is left.
    [[nodiscard]] static QString slug(const QString &text);
};

} // namespace mbscope
