#pragma once

#include "profile/linerule.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

#include <functional>

namespace mbscope {

class SimUnit;

// What a delimited protocol's device made of one frame (LineResponder::respond).
struct LineAnswer {
    bool matched = false;   // a rule's pattern matched the frame
    QString rule;           // its name
    int unitId = -1;        // the unit that answers; -1 when none
    bool unitMissing = false; // the unit the frame names is not here
    bool answers = false;   // bytes to send (else silence)
    QByteArray bytes;       // the answer from start byte to end byte (no checksum byte)
    QString note;           // why there is no answer, or what was written
};

// Serves a LineTable: matches a frame against the rules in order, picks the unit by the
// table's unit capture (or the first unit), applies the rule's writes to that unit as a
// client's writes (read-only addresses are refused and said so), and fills in the answer.
class LineResponder
{
public:
    using UnitOf = std::function<SimUnit *(int id)>; // nullptr when there is no such unit; -1: the first unit
    [[nodiscard]] static LineAnswer respond(const LineTable &table, QByteArrayView frame, const UnitOf &unitOf);
};

} // namespace mbscope
