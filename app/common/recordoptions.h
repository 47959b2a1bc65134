#pragma once

#include "traffic/trafficmetadata.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>
#include <QtCore/QStringList>

class QCommandLineParser;
class QTextStream;

namespace mbscope {
class TrafficRecording;
}

namespace mbscope::app {

struct RequestPlan;
struct TargetSettings;

// What --record and --force said.
struct RecordSettings {
    QString path;           // empty: not recording
    bool overwrite = false; // --force

    [[nodiscard]] bool isSet() const { return !path.isEmpty(); }
};

// The options every command that talks to a device or serves one shares:
//   --record FILE  journal every frame to FILE (a traffic journal with the command's metadata)
//   --force        let --record (and the command's other output files) replace an existing file
class RecordOptions
{
public:
    RecordOptions();

    void addTo(QCommandLineParser &parser) const;
    // Checks what can be checked before the command runs (OutputPath's policy: the file exists
    // without --force, the folder is missing, the file cannot be created); on error writes
    // "mbscope COMMAND: ..." to err and returns false. otherOutputs: the command writes other files
    // that --force applies to (poll's --csv), so --force without --record is no mistake.
    [[nodiscard]] bool read(const QCommandLineParser &parser, const QString &command, RecordSettings &out, QTextStream &err,
                            bool otherOutputs = false) const;

private:
    QCommandLineOption m_record;
    QCommandLineOption m_force;
};

// The metadata of a client command: this command line (arguments as the subcommand got them,
// its name first), the target, the requests.
[[nodiscard]] TrafficMetadata clientMetadata(const QString &command, const QStringList &arguments, const TargetSettings &target,
                                             const RequestPlan &plan);
// The same for a command that is not about one target (simulate): the command line alone.
[[nodiscard]] TrafficMetadata commandMetadata(const QString &command, const QStringList &arguments);

// Opens the recording when settings ask for one; false (with "mbscope COMMAND: --record: ..." on
// err) when the journal cannot be created.
[[nodiscard]] bool openRecording(TrafficRecording &recording, const RecordSettings &settings, const TrafficMetadata &metadata,
                                 const QString &command, QTextStream &err);
// Closes it and prints its one line on err: "recorded N frames (M transactions) to FILE"; a
// journal that holds no frame is removed instead ("recorded no frame: removed FILE ..."), so that
// a command whose link never came up leaves nothing that refuses its rerun.
void finishRecording(TrafficRecording &recording, QTextStream &err);

} // namespace mbscope::app
