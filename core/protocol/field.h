#pragma once

#include "severity.h"

#include <QtCore/QString>

namespace mbscope {

// How a field's value is shown. Text is made lazily (FieldTree::display), so dissecting a
// frame allocates nothing per field on the hot path.
enum class ValueFormat : quint8 {
    None,       // a group node, or a field without a numeric value: only the meaning is shown
    Decimal,    // 1050
    Hex,        // 0x03, 0x0079: as many digits as the field's length in bytes (at most 8 bytes)
    DecimalHex, // 121 (0x0079)
    Bytes,      // the raw bytes as hex: 01 02 03
    Ascii,      // the raw bytes as quoted text, non-printable bytes escaped
    Bit,        // 0 or 1: a coil or discrete input; meaning says ON or OFF
    Reference5, // a Modicon reference in five digits, zero-padded: 00122, 40122
    Reference6, // a Modicon reference in six digits, zero-padded: 000122, 400122
};

// One node of a dissection. Keys, names and meanings are static strings (string literals or
// tables) so that building a tree allocates only when something is wrong (message).
struct Field {
    const char *key = "";           // stable filter-style key: "modbus.function_code"
    const char *name = "";          // human name: "Function code"; with address: "Register 121"
    const char *meaning = nullptr;  // static meaning of the value: "Read Holding Registers"
    QString message;                // what is wrong and what was expected; empty when fine
    quint64 value = 0;              // the numeric value (register, code, CRC, count)
    qint32 offset = 0;              // byte offset in the whole frame
    qint32 length = 0;              // bytes covered (0 for a field about missing bytes)
    qint32 parent = -1;             // index of the parent field, -1 at the top
    qint32 address = -1;            // register/coil/object address for per-item fields, else -1
    ValueFormat format = ValueFormat::None;
    Severity severity = Severity::Ok;
};

} // namespace mbscope
