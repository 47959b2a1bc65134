#pragma once

#include "fieldtree.h"
#include "framing.h"

#include <QtCore/QString>

namespace mbscope {

// The result of dissecting one frame: how it was read and the fields found.
struct Dissection {
    Framing framing = Framing::Auto;       // the framing used (detected when asked for Auto)
    Direction direction = Direction::Auto; // the direction used (detected when asked for Auto)
    QString framingReason;   // why this framing was chosen, when it was detected
    QString directionReason; // why this direction was chosen, when it was detected
    QString note;            // how to read the offsets when it is not obvious (ASCII frames)
    FieldTree fields;

    [[nodiscard]] bool isValid() const { return !fields.isEmpty() && fields.worstSeverity() < Severity::Error; }
    // One line: "RTU request, unit 1: Read Holding Registers, 22 registers from 121 (0x0079)".
    [[nodiscard]] QString summary() const;
};

} // namespace mbscope
