#pragma once

#include <QtCore/qglobal.h>
#include <QtCore/QString>

namespace mbscope {

// How bad a field is. Wireshark's "expert info" is the model: severity is data on the
// field, and views only colour it.
enum class Severity : quint8 {
    Ok,      // nothing to say
    Info,    // worth knowing (broadcast, user-defined code), not a fault
    Warning, // legal but suspicious (reserved unit id, trailing bytes in a stream)
    Error,   // the frame breaks the spec (bad CRC, byte count against data, truncation)
};

[[nodiscard]] QString severityName(Severity severity);

} // namespace mbscope
