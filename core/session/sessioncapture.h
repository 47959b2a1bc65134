#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// Captured traffic: never inline in the document (a long poll's frames would make it huge and
// rewriting it on every batch would not survive a crash); the frames live in an append-only
// traffic journal (engine/trafficjournal.h) beside the document, which this names.
struct SessionCapture {
    QString journal; // a file name relative to the document's folder: "bench.mbscope.journal"
    QString notes;
    // Fields of the answers a replay expects to change (a counter, a clock): replay reports their
    // differences as ignored (FieldExpectation selectors: "modbus.register_value@0x007D").
    QStringList ignore;

    friend bool operator==(const SessionCapture &, const SessionCapture &) = default;
};

} // namespace mbscope
