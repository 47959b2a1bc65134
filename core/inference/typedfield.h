#pragma once

#include "protocol/registerformat.h"

#include <QtCore/QString>

namespace mbscope {

// A group of registers of a block read as one value: where it starts (an index into the block),
// how many registers it takes, its format, how sure the type and order are and why.
struct TypedField {
    int offset = 0;
    int registers = 1;
    RegisterFormat format;
    bool text = false;        // an ASCII string of `registers` registers
    double confidence = 0.5;
    QString evidence;
};

} // namespace mbscope
