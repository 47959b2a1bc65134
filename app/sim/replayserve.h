#pragma once

#include "common/recordoptions.h"

#include "replay/replayresponder.h"

#include <QtCore/QString>

class QTextStream;

namespace mbscope {
class ReplayScript;
}

namespace mbscope::app {

// mbscope replay SOURCE --serve URL: the simulator on URL answering with the script's recorded
// answers until Ctrl-C (or durationMs, when more than 0). Returns the exit status.
struct ReplayServeOptions {
    QString url;
    ReplayResponder::Unrecorded unrecorded = ReplayResponder::Unrecorded::Exception0B;
    double speed = 1.0; // recorded latency divided by it; 0: at once
    qint64 durationMs = 0;
    bool json = false;
    RecordSettings record;  // --record: what was served
    QStringList arguments;  // the command line, for the recording's metadata
};
int serveReplay(const ReplayScript &script, const QString &source, const ReplayServeOptions &options, QTextStream &out,
                QTextStream &err);

} // namespace mbscope::app
