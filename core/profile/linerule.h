#pragma once

#include "script/scriptsettings.h"
#include "simtable.h"

#include <QtCore/QList>
#include <QtCore/QRegularExpression>
#include <QtCore/QString>

namespace mbscope {

// A device that does not speak Modbus, served over framing=delimited (docs/profiles.md,
// "Delimited protocols"): each frame received (from its start byte to its end byte, both
// included, without a checksum byte) is matched against the rules' request patterns in order;
// the first that matches answers with its template and applies its writes.
//
// Templates are text (Latin-1 bytes) with fields in braces: {name} a named capture of the
// pattern; {holding:0-7}, {coils:3}, {input:...}, {discrete:...} values of the answering unit's
// tables, decimal, separated by spaces; {{ and }} literal braces.
struct LineWrite {
    SimTable table = SimTable::Coils; // coils or holding
    QString address;                  // a template giving a decimal address
    QString value;                    // a template giving a decimal value (bits: 0 or non-zero)

    friend bool operator==(const LineWrite &, const LineWrite &) = default;
};

struct LineRule {
    QString name;                // for the logs; default "rule N"
    QString pattern;             // as written
    QRegularExpression request;  // anchored: the whole frame must match
    QString answer;              // the answer template; empty with silent
    bool silent = false;         // "answer": null: the device takes the request and says nothing
    QList<LineWrite> writes;

    friend bool operator==(const LineRule &, const LineRule &) = default;
};

struct LineTable {
    // The capture naming the unit that answers (its text read as a decimal id); a rule without
    // it is answered by the profile's first unit.
    QString unitCapture = QStringLiteral("unit");
    QList<LineRule> rules;
    ScriptSettings script; // "script": onFrame(frame) speaks before the rules (docs/profiles.md)

    [[nodiscard]] bool isEmpty() const { return rules.isEmpty(); }

    friend bool operator==(const LineTable &, const LineTable &) = default;
};

} // namespace mbscope
