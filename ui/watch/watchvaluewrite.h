#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

struct WatchWriteWords {
    QList<quint16> words; // the point's registers in wire order (a coil: one word, 0 or 1)
    QString error;        // empty when words can be written
};

// The words a value typed into a watch's table writes: read as the register table reads an edit
// (RegisterValue::fromText in the point's format, or ScaledValue::encode when the point is scaled,
// its unit optional; a coil as 1/0, on/off, true/false). Only points marked writable of a coil
// or holding-register watch are written; anything else is refused saying what and where.
class WatchValueWrite
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::WatchValueWrite)

public:
    // point: index in watch.points.
    [[nodiscard]] static WatchWriteWords words(const WatchDefinition &watch, int point, const QString &text);
    [[nodiscard]] static bool isWritable(const WatchDefinition &watch, int point);
};

} // namespace mbscope
