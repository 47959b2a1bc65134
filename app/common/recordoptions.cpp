#include "common/recordoptions.h"

#include "common/outputpath.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"

#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QTextStream>

namespace mbscope::app {

RecordOptions::RecordOptions()
    : m_record(QStringLiteral("record"),
               QStringLiteral("Journal every frame sent and received to FILE, a crash-safe traffic journal that starts with "
                              "this command, its target and requests (analyze, export and replay read it); removed at the end when "
                              "no frame crossed the link."),
               QStringLiteral("FILE"))
    , m_force(OutputPath::forceOption())
{
}

void RecordOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_record, m_force});
}

bool RecordOptions::read(const QCommandLineParser &parser, const QString &command, RecordSettings &out, QTextStream &err,
                         bool otherOutputs) const
{
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);
    out.overwrite = parser.isSet(m_force);
    if (!parser.isSet(m_record)) {
        if (out.overwrite && !otherOutputs) {
            err << prefix << "--force replaces output files that exist, but no output file is given (--record FILE...)\n";
            return false;
        }
        return true;
    }
    const QString path = parser.value(m_record);
    // Said now, not after a 60 s poll.
    const QString problem = OutputPath::problem(QStringLiteral("--record"), path, QStringLiteral("--record poll.mbscope.journal"),
                                                out.overwrite, QStringLiteral("a journal"));
    if (!problem.isEmpty()) {
        err << prefix << problem << '\n';
        return false;
    }
    out.path = path;
    return true;
}

TrafficMetadata commandMetadata(const QString &command, const QStringList &arguments)
{
    // The subcommand's arguments start with its name (QCommandLineParser's program name).
    return TrafficMetadata::forCommand(command, arguments.mid(1), QStringLiteral(MBSCOPE_VERSION));
}

TrafficMetadata clientMetadata(const QString &command, const QStringList &arguments, const TargetSettings &target,
                               const RequestPlan &plan)
{
    TrafficMetadata m = commandMetadata(command, arguments);
    m.role = TrafficMetadata::Role::Client;
    m.target = target.url.toString();
    for (const PlannedRequest &r : plan.requests)
        m.requests.append(TrafficMetadataRequest{r.item.name, r.description, r.item.bytes});
    m.settings.insert(QStringLiteral("timeout_ms"), target.timeoutMs);
    m.settings.insert(QStringLiteral("retries"), target.retries);
    return m;
}

bool openRecording(TrafficRecording &recording, const RecordSettings &settings, const TrafficMetadata &metadata,
                   const QString &command, QTextStream &err)
{
    if (!settings.isSet())
        return true;
    QString error;
    if (!recording.open(settings.path, metadata, settings.overwrite, &error)) {
        err << "mbscope " << command << ": --record: " << error << '\n';
        return false;
    }
    return true;
}

void finishRecording(TrafficRecording &recording, QTextStream &err)
{
    if (!recording.isOpen())
        return;
    recording.close();
    // A journal with no frame (the link never came up, or carried nothing) is no evidence of
    // anything, and left behind it would refuse the next --record of the same name.
    if (recording.frames() == 0 && recording.error().isEmpty() && QFile::remove(recording.path())) {
        err << "recorded no frame: removed " << recording.path() << " (nothing crossed the link)\n";
        err.flush();
        return;
    }
    err << recording.summary() << '\n';
    err.flush();
}

} // namespace mbscope::app
