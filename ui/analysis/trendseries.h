#pragma once

#include "protocol/modiconreference.h"
#include "protocol/readanswer.h"
#include "protocol/registerformat.h"
#include "profile/deviceprofile.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// One register (or coil) followed over time by the RegisterTrendPanel: where it is, how its
// registers read (u16, i16, f32-cdab...), and the profile's meaning of the number:
//   value = raw * scale + offset, in unit
// A value wider than one register is taken from an answer that holds all its registers, wherever
// in the answer they are.
struct TrendSeries {
    int unitId = -1; // -1: the answer of any unit
    ModbusTable table = ModbusTable::HoldingRegisters;
    int address = 0; // PDU address of the first register
    RegisterFormat format;
    double scale = 1;
    double offset = 0;
    QString name;        // from the profile; empty for a register added by address
    QString unit;        // engineering unit text ("degC")
    QString profileName; // the profile the name comes from
    // A value of a watch of the workspace (not empty): plotted from the watch's samples, decoded
    // as the watch says (format, scale, unit); address is the value's first address in the watch,
    // name its point's name (empty for an address no point names). Table and format do not apply.
    QString watchName;

    [[nodiscard]] bool isWatchValue() const { return !watchName.isEmpty(); }

    // "temperature, 40209 (degC)"; "40209 (i16)" without a name.
    [[nodiscard]] QString label() const;
    // "temperature: 40209, i16, value = raw x 0.1 + 0 degC, profile conformance"
    [[nodiscard]] QString description() const;
    [[nodiscard]] bool sameRegister(const TrendSeries &other) const;
    // The scaled value this answer holds, if it holds all of the series' registers.
    [[nodiscard]] std::optional<double> valueIn(const ReadAnswer &answer) const;

    // As the trend panel keeps it between runs (one JSON object a series), and back; nullopt for
    // an object that does not name a register (a table, an address or a format out of range).
    [[nodiscard]] QJsonObject toJson() const;
    [[nodiscard]] static std::optional<TrendSeries> fromJson(const QJsonObject &object);

    // One series per value of each register or bit entry of the unit's profile, in table order.
    [[nodiscard]] static QList<TrendSeries> fromProfile(const UnitProfile &unit, const QString &profileName);
};

} // namespace mbscope
