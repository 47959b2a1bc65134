#pragma once

#include "framing.h"

#include <QtCore/QByteArrayView>

namespace mbscope::pdusize {

// What the bytes seen so far predict about a PDU's total size (function code included).
// Used by the RTU framer to find frame ends without timing, and by the dissector to say how
// many bytes a truncated frame is missing.
enum class Status : quint8 {
    Complete, // size is the whole PDU's size
    NeedMore, // size is how many PDU bytes must be seen before the size can be known
    Unknown,  // no length rule for this code (user-defined, reserved, unassigned): use silence
};

struct Expected {
    Status status = Status::Unknown;
    int size = 0;
};

// pdu starts at the function code and may hold fewer bytes than the PDU needs.
// Direction::Auto: exception codes count as responses; otherwise the answer is given only where
// the request and response rules agree, else Unknown (see pdusize.cpp).
[[nodiscard]] Expected expectedPduSize(QByteArrayView pdu, Direction direction);

} // namespace mbscope::pdusize
