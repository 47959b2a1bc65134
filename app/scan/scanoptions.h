#pragma once

#include "common/printoptions.h"
#include "common/recordoptions.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

#include <functional>

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

// Writes bytes to path and says so on err ("mbscope scan: <what> written to <path>"), or why not
// (the file as it was kept whole when the write fails).
bool writeScanFile(const QString &path, const QByteArray &bytes, const char *what, QTextStream &err);

// --profile-out FILE of the scans that merge into an existing profile (--timing's limits, the
// unit scan's units): its text read into *json when it loads as the simulator loads a profile;
// false with a message naming the file and every problem otherwise. what ends the message when
// the file cannot be read ("the units found are").
bool readProfileToMerge(const QString &path, const char *what, QByteArray *json, QTextStream &err);
// Reads the profile at path again, merges with merge (a ProfileDraft merge) and writes the result
// when it loads too, saying first what merge said, then "<written> written to <path>"; false with
// a message otherwise, the file left as it was.
using ProfileMergeFunction = std::function<QByteArray(const QByteArray &profile, QString *said, QString *problem)>;
bool mergeIntoProfileFile(const QString &path, const ProfileMergeFunction &merge, const char *written, QTextStream &err);

// --record FILE of a scan (and its live frame log): opened by the scan once its settings are known good (a usage error
// leaves no journal), every connection the scan opens on it, closed when the scan is done.
struct ScanRecord {
    RecordSettings settings;
    TrafficMetadata metadata;
    PrintSettings print; // --print frames, --frame-log FILE: the live frame log
};

} // namespace mbscope::app
