#pragma once

#include "scan/scanoptions.h"

#include "discovery/timingscanner.h"

class QTextStream;

namespace mbscope::app {

// mbscope scan --timing UNIT: the timing scan run, its measurements and the settings they give
// (mbscope's watch link gapMs and timeoutMs, poll's --timeout, Telegraf's modbus input), or JSON.
// profilePath (--profile-out), when not empty: an existing profile the limits measured are merged into.
int runTimingScan(const TimingScanSettings &settings, bool json, const ScanRecord &record, const QString &profilePath,
                  QTextStream &out, QTextStream &err);

} // namespace mbscope::app
