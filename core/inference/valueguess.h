#pragma once

#include "profile/valuekind.h"
#include "protocol/registerformat.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// What inference proposes for one group of registers (or one bit): its type and order, scale,
// unit and kind, each a guess with a confidence (0-1) and the evidence in words.
struct ValueGuess {
    quint8 function = 3;
    quint16 address = 0;
    int registers = 1;       // addresses covered: the format's registers, a string's length, 1 for a bit
    RegisterFormat format;   // registers; Ascii for a string of `registers` registers
    bool text = false;       // an ASCII string (format ascii)
    bool bit = false;        // a coil or discrete input
    // What the value did over the samples: Constant (the same raw words in every sample),
    // Counter (only grows; one wrap allowed), Measurement (up and down) or Status (a few values,
    // each change a bit or two flipping): the profile format's kinds (core/profile/valuekind.h).
    ValueKind kind = ValueKind::Constant;
    double scale = 1;        // a power of ten
    QString unit;            // "V", "Hz", "degC"; empty when nothing suggests one
    QString quantity;        // "voltage", "frequency", "power factor", "temperature"; may be empty
    int scaleRegister = -1;  // the address of a scale-factor register (SunSpec style) the scale came from
    double confidence = 0.5; // of the type and order
    QString evidence;        // why this type and order
    QString scaleEvidence;   // why this scale and unit (empty: scale 1 for want of a reason)
    double scaleConfidence = 0.3; // of the scale and unit (0.3: scale 1 for want of a reason)
    double minimum = 0;      // engineering values (raw x scale) over the samples
    double maximum = 0;
    double last = 0;
    QString lastText;        // the last value as text (strings: the characters)
    QList<quint16> lastWords; // the last sample's words, wire order
    QString name;            // given by a person (the window's Infer); empty: named after its quantity
    bool confirmed = false;  // a person confirmed or corrected it: the draft no longer calls it a guess
    double typicalStep = 0;  // the median size of a change between samples (engineering units)

    [[nodiscard]] QString typeName() const; // "f32-cdab", "ascii[16]", "bit"
};

} // namespace mbscope
