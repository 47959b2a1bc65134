#pragma once

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// What a value of a register map is, as a device's documentation says it (a profile entry's
// "kind"): a measurement moves on its own, a counter only grows (and wraps), a setting is
// written by someone, status bits change alone, an enumeration is a number with named meanings,
// a constant never changes (serial number, firmware), reserved registers exist but mean nothing.
// Exports and inference use it; the simulator does not (generators say how values move).
enum class ValueKind : quint8 {
    Unspecified,
    Measurement,
    Counter,
    Setting,
    Status,
    Enumeration,
    Constant,
    Reserved,
};

// "measurement", "counter", ... (empty for Unspecified), and back; nullopt for anything else.
[[nodiscard]] QString valueKindName(ValueKind kind);
[[nodiscard]] std::optional<ValueKind> valueKindFromName(QStringView name);
// "measurement, counter, setting, status, enumeration, constant or reserved" (for messages).
[[nodiscard]] QString valueKindNames();

} // namespace mbscope
