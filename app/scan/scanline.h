#pragma once

#include "scan/scanoptions.h"

#include "discovery/linescanner.h"

class QTextStream;

namespace mbscope::app {

// mbscope scan --line: the serial settings scan run, printed as a table of what was tried (runs of
// the same result grouped) and what worked, or as JSON.
int runLineScan(const LineScanSettings &settings, bool json, const ScanRecord &record, QTextStream &out, QTextStream &err);

} // namespace mbscope::app
