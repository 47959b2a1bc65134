#pragma once

#include "discovery/registermap.h"
#include "job/jobend.h"
#include "job/jobprogress.h"
#include "discovery/unitprobe.h"
#include "discovery/unitscansettings.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope::app {

// What mbscope scan prints: the table of a unit scan and of a register map, and their JSON.
class ScanReport
{
public:
    [[nodiscard]] static QString unitsText(const UnitScanSettings &settings, const QList<UnitProbe> &probes,
                                           const JobProgress &progress, JobEnd end, bool all);
    [[nodiscard]] static QJsonObject unitsJson(const UnitScanSettings &settings, const QList<UnitProbe> &probes,
                                               const JobProgress &progress, JobEnd end);
    [[nodiscard]] static QString mapText(const RegisterMap &map, JobEnd end, qint64 elapsedMs);
    [[nodiscard]] static QJsonObject mapJson(const RegisterMap &map, JobEnd end, qint64 elapsedMs);
    // "1m 05s", "12.3 s", "850 ms"
    // The devices a unit scan found: ids 1-247 that answered (an MBAP server answering 0 or 255
    // for itself is no device of its own).
    [[nodiscard]] static int devicesFound(const QList<UnitProbe> &probes);
    [[nodiscard]] static QString durationText(qint64 ms);
    // The live line: "ids 37/247  found 2  12 s, about 48 s left  (Ctrl-C stops)"; detail (what is
    // being done: "gap 50 ms") follows the counts.
    [[nodiscard]] static QString progressText(const QString &what, const JobProgress &progress, const QString &detail = {});
};

} // namespace mbscope::app
