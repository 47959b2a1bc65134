#include "sim/replayserve.h"

#include "common/cli.h"
#include "common/interruptwatcher.h"

#include "replay/replayscript.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QEventLoop>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

#include <chrono>

namespace mbscope::app {

int serveReplay(const ReplayScript &script, const QString &source, const ReplayServeOptions &options, QTextStream &out,
                QTextStream &err)
{
    Simulator sim;
    ReplayResponder responder(script, options.unrecorded, options.speed);
    responder.install(sim);
    QString error;
    SimEndpoint *endpoint = sim.listen(options.url, responder.endpointOptions(), &error);
    if (!endpoint) {
        err << "mbscope replay: --serve " << options.url << ": " << error << '\n';
        return ExitUsage;
    }
    const QString bound = endpoint->name();
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("replay"), options.arguments);
    metadata.role = TrafficMetadata::Role::Server;
    metadata.listen = {bound};
    metadata.settings.insert(QStringLiteral("source"), source);
    metadata.settings.insert(QStringLiteral("speed"), options.speed);
    if (!openRecording(recording, options.record, metadata, QStringLiteral("replay"), err))
        return ExitUsage;
    if (recording.isOpen())
        sim.setTrafficLog(recording.log());
    QStringList units;
    for (quint8 id : script.unitIds())
        units.append(QString::number(id));
    // Ctrl-C is caught before "listening" is said: a stop sent right after it ends the replay cleanly.
    QEventLoop loop;
    InterruptWatcher interrupt;
    bool interrupted = false;
    QObject::connect(&interrupt, &InterruptWatcher::interrupted, &loop, [&] {
        interrupted = true;
        loop.quit();
    });
    if (!options.json) {
        // Answers and silences apart: a request recorded without an answer is not an answer.
        out << "serving " << responder.recordedAnswers() << (responder.recordedAnswers() == 1 ? " recorded answer" : " recorded answers");
        if (responder.recordedSilences() > 0)
            out << " and " << responder.recordedSilences()
                << (responder.recordedSilences() == 1 ? " recorded silence" : " recorded silences");
        out << " of " << source << " (" << responder.distinctRequests()
            << " distinct requests, units " << units.join(QStringLiteral(", ")) << ")\n"
            << "latency       "
            << (options.speed > 0 ? QStringLiteral("as recorded%1").arg(options.speed == 1.0 ? QString() : QStringLiteral(" / %1").arg(options.speed))
                                  : QStringLiteral("none (--speed max)"))
            << "\nnot recorded  " << ReplayResponder::policyText(options.unrecorded) << '\n'
            << "listening " << bound << '\n';
        out.flush();
    } else {
        // Standard output stays one JSON document; a script still learns the port the OS chose.
        err << "listening " << bound << Qt::endl;
    }

    if (options.durationMs > 0)
        QTimer::singleShot(std::chrono::milliseconds(options.durationMs), &loop, &QEventLoop::quit);
    loop.exec();
    sim.closeAll();
    sim.setFaultHook({});
    sim.setTrafficLog(nullptr);
    finishRecording(recording, err);

    const ReplayResponder::Counters &c = responder.counters();
    if (options.json) {
        out << QJsonDocument(QJsonObject{{QStringLiteral("listening"), bound},
                                         {QStringLiteral("served"), double(c.served)},
                                         {QStringLiteral("silences"), double(c.silences)},
                                         {QStringLiteral("unrecorded"), double(c.unrecorded)},
                                         {QStringLiteral("interrupted"), interrupted}})
                   .toJson(QJsonDocument::Indented);
    } else {
        const auto counted = [](quint64 n, const char *one, const char *many) {
            return QStringLiteral("%1 %2").arg(n).arg(QLatin1String(n == 1 ? one : many));
        };
        out << (interrupted ? "interrupted: " : "stopped: ") << counted(c.served, "recorded answer", "recorded answers") << " served, "
            << counted(c.silences, "recorded silence", "recorded silences") << " kept, "
            << counted(c.unrecorded, "request", "requests") << " never recorded\n";
    }
    return ExitOk;
}

} // namespace mbscope::app
