#pragma once

#include "watch/watchdefinition.h"
#include "watch/watchpointvalue.h"
#include "watch/watchruleevent.h"

#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>
#include <vector>

namespace mbscope {

// Logs the values of watches to CSV: a file per watch in one directory, named by the watch and
// the time the file was started ("gamma-20261126-061500.csv"), a header row with the values'
// names and units, then a row per poll (or, in OnChange mode, a row when a value or the poll's
// status changes): the time (ISO 8601, UTC, ms), the status, the values as shown, the error.
// A file is closed and a new one started when it passes rollBytes, or rollSeconds after it
// started. Rows are flushed to the OS at least once a second and on flush() / close().
//
// Rule events go to a second file per watch, opened at the watch's first event and rolled the
// same way ("gamma-events-20261126-061500.csv"): time, event (fired / cleared), severity, rule
// (its index in the watch), point, value, message, fired (the rule's firings so far). A row per
// event in either mode; the log's own rows (appendNote: rows dropped when it fell behind) there
// too. A folder removed while logging is made again at the next file.
//
// A row that cannot be written (disk full, the folder gone and not to be made again) is counted
// in lostRows(), as are the rows in the OS buffer when a flush fails: nothing is lost unsaid.
// Not thread-safe; core/fleet's WatchLogWriter runs one in a thread of its own.
class WatchCsvLog
{
public:
    // directory: settings.directory resolved against baseDirectory when relative.
    WatchCsvLog(const WatchLogSettings &settings, const QString &baseDirectory = {});
    ~WatchCsvLog();

    // Makes the directory; false with *error when it cannot.
    bool open(const QList<WatchDefinition> &watches, QString *error = nullptr);
    // One poll of watch index; status "ok", "timeout"...; values empty for a failed poll.
    // False with *error when the file cannot be written (the caller says it, and carries on).
    bool append(int watch, qint64 timeMs, const QString &status, const QList<WatchPointValue> &values,
                const QString &errorText = {}, QString *error = nullptr);
    // A rule event of watch index (event.watch); false with *error as append().
    bool appendEvent(const WatchRuleEvent &event, QString *error = nullptr);
    // A row of the log's own in the events file of watch index: event ("overflow", "dropped"),
    // severity warning, no rule or point, value rows; false with *error as append().
    bool appendNote(int watch, qint64 timeMs, const QString &event, quint64 rows, const QString &message, QString *error = nullptr);
    // Hands the buffered rows to the OS; false with *error when it refuses them (disk full).
    bool flush(QString *error = nullptr);
    void close();

    // Rows that could not be written since open().
    [[nodiscard]] quint64 lostRows() const { return m_lostRows; }

    [[nodiscard]] QString directory() const { return m_directory; }
    // The files written so far, oldest first (for the report and tests).
    [[nodiscard]] QStringList files() const { return m_files; }
    // The header row of a watch (names with units in brackets), without the line end.
    [[nodiscard]] static QString header(const WatchDefinition &watch);
    // The header's columns, quoted where they must be: time, status, a value each, error.
    [[nodiscard]] static QStringList columns(const WatchDefinition &watch);
    // The events file's header row, without the line end.
    [[nodiscard]] static QString eventHeader();
    // A field quoted as RFC 4180 wants when it holds a comma, a quote or a line end.
    [[nodiscard]] static QString csvField(const QString &text);
    // The watch's name made safe for a file name ("gamma counts/2" -> "gamma_counts_2").
    [[nodiscard]] static QString fileStem(const QString &name);

private:
    // One open CSV file and what rolling it needs to know.
    struct Output {
        std::unique_ptr<QFile> file;
        qint64 startedMs = 0;
        qint64 bytes = 0;
        quint64 unflushedRows = 0;
    };
    struct File {
        WatchDefinition watch;
        qsizetype valueColumns = 0;
        Output values;
        Output events;
        QStringList lastValues;
        QString lastStatus;
        bool hasRow = false;
    };

    bool startFile(Output &out, const QString &stem, const QString &header, qint64 timeMs, QString *error);
    bool writeRow(Output &out, const QString &stem, const QString &header, qint64 timeMs, const QByteArray &line, QString *error);
    bool flushOutput(Output &out, QString *error);
    bool maybeFlush(qint64 timeMs, QString *error);

    WatchLogSettings m_settings;
    QString m_directory;
    std::vector<File> m_logs;
    QStringList m_files;
    qint64 m_lastFlushMs = 0;
    quint64 m_lostRows = 0;
};

} // namespace mbscope
