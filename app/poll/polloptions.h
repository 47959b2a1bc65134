#pragma once

#include "common/printoptions.h"
#include "common/recordoptions.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"

#include "engine/engineoptions.h"
#include "engine/pollsettings.h"

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

class QCommandLineParser;
class QTextStream;

namespace mbscope::app {

// Everything poll and sweep read from their options.
struct PollConfig {
    TargetSettings target;
    RequestPlan plan;
    SweepSettings settings;   // poll: one interval in settings.poll.intervalNs and intervalsNs
    EngineOptions engine;
    bool stats = false;       // --stats: the detailed statistics
    bool json = false;
    QString histogramPath;    // --histogram FILE.png; empty: none
    RecordSettings record;    // --record FILE [--force]
    bool printValues = false; // poll --print values
    PrintSettings print;      // --print values|frames, --frame-log FILE
    QString csvPath;          // poll --csv FILE; empty: none
    QString profile;          // --profile: the device profile whose limits the poll honours; empty: none
    QStringList pace;         // what of the device's pace the engine keeps, each with where it came from
};

// The options poll and sweep share, and the one each has alone:
//   poll:   -l, --interval DURATION (default 1s; 0: back to back), -1, --once (--count 1),
//           --print values|frames, --csv FILE
//   sweep:  --intervals D1,D2,... (required)
//   both:   --count N (cycles per interval) | --duration DURATION, --pipeline N, --stats,
//           --histogram FILE.png, --json, --record FILE [--force], --gap DURATION, --warm-up DURATION,
//           --profile P (its limits: minGapMs and warmUpMs unless --gap and --warm-up say otherwise,
//           and reads cut to its maxQuantity: DevicePace), the target options and the request options
//           (--hex ... | --function/--address/--quantity | --coils/--registers).
class PollOptions
{
public:
    explicit PollOptions(bool sweep);

    void addTo(QCommandLineParser &parser) const;
    [[nodiscard]] bool read(const QCommandLineParser &parser, PollConfig &out, QTextStream &err) const;

private:
    bool m_sweep;
    QString m_command;
    TargetOptions m_target;
    RequestOptions m_requests;
    QCommandLineOption m_interval;
    QCommandLineOption m_intervals;
    QCommandLineOption m_count;
    QCommandLineOption m_duration;
    QCommandLineOption m_once;
    QCommandLineOption m_pipeline;
    QCommandLineOption m_stats;
    QCommandLineOption m_histogram;
    QCommandLineOption m_json;
    PrintOptions m_print;
    QCommandLineOption m_csv;
    QCommandLineOption m_gap;
    QCommandLineOption m_warmUp;
    QCommandLineOption m_profile;
    RecordOptions m_record;
};

} // namespace mbscope::app
