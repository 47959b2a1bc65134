#pragma once

#include "exportblock.h"
#include "mappoint.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// One point as read through the map before an export (mbscope export-map --verify).
struct MapVerdict {
    qsizetype point = 0;  // index into the points
    QString value;        // the engineering value as text, a string's text, "not implemented"
    QString problem;      // empty when the value is usable: "NaN is not finite", "250.3 is above max 240"
    [[nodiscard]] bool ok() const { return problem.isEmpty(); }
};

// What one block's read gave: its registers (bits as 0/1), or what went wrong.
struct ExportBlockReading {
    QList<quint16> words;
    QString error;        // "exception 02 (illegal data address)", "timeout after 1000 ms"
};

// Judges every point of a map from one read of each block: a value must be finite and inside
// the entry's declared min and max; a "not implemented" sentinel is reported as such, not as a
// failure; a block whose read failed fails each of its points with the read's error.
class MapVerifier
{
public:
    [[nodiscard]] static QList<MapVerdict> judge(const QList<MapPoint> &points, const QList<ExportBlock> &blocks,
                                                 const QList<ExportBlockReading> &readings);
};

} // namespace mbscope
