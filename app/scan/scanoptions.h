#pragma once

#include "common/printoptions.h"
#include "common/recordoptions.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

class QCommandLineParser;
class QTextStream;

namespace mbscope::app {

// Small readers of mbscope scan's (and infer's) options; each writes "mbscope scan: ..." and returns false on
// bad input, naming the option and what was expected.
struct ScanOptionReader {
    const QCommandLineParser &parser;
    QTextStream &err;
    QString command = QStringLiteral("scan"); // the subcommand the messages name

    // "FIRST-LAST" or one number, within [low, high].
    bool range(const QCommandLineOption &option, int low, int high, int *first, int *last) const;
    // A duration in whole milliseconds within [lowMs, highMs].
    bool durationMs(const QCommandLineOption &option, qint64 lowMs, qint64 highMs, qint64 *ms) const;
    bool integer(const QCommandLineOption &option, qint64 low, qint64 high, qint64 *value) const;
    // A comma-separated list of whole numbers within [low, high].
    bool integers(const QCommandLineOption &option, qint64 low, qint64 high, QList<qint64> *values) const;
};

// Writes bytes to path and says so on err ("mbscope scan: <what> written to <path>"), or why not.
bool writeScanFile(const QString &path, const QByteArray &bytes, const char *what, QTextStream &err);

// --record FILE of a scan (and its live frame log): opened by the scan once its settings are known good (a usage error
// leaves no journal), every connection the scan opens on it, closed when the scan is done.
struct ScanRecord {
    RecordSettings settings;
    TrafficMetadata metadata;
    PrintSettings print; // --print frames, --frame-log FILE: the live frame log
};

} // namespace mbscope::app
