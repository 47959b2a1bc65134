#pragma once

#include "protocol/registerformat.h"

#include <QtCore/QString>

#include <optional>

namespace mbscope::app {

// mbpoll's -t: a table by the first digit of its Modicon references, with an optional display
// suffix: 0 coils, 1 discrete inputs, 3 input registers, 4 holding registers; "4:hex" (16-bit
// hex), "4:int" (32-bit signed), "4:float" (32-bit float), and here any --format name as well
// ("4:u32", "3:f32-badc"). mbpoll reads :int and :float low word first unless -B (big endian
// word order) is given, and so does this: "4:float" is f32-cdab, with -B f32.
struct TableType {
    quint8 functionCode = 0;              // 01, 02, 04 or 03
    std::optional<RegisterFormat> format; // the suffix's; none without one
    QString error;                        // names the option ("-t/--table '2' is not a table: ...")
    bool ok = false;

    // Registers one counted value takes: mbpoll's -c counts values, two registers each for :int
    // and :float.
    [[nodiscard]] int registersPerValue() const { return format ? format->registerCount() : 1; }

    [[nodiscard]] static TableType parse(const QString &text, bool bigEndianWords);
};

} // namespace mbscope::app
