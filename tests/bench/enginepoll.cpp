#include "enginepoll.h"

#include "peer_datamap.h"

#include "engine/engineoptions.h"
#include "exchange/requestitem.h"
#include "traffic/trafficlog.h"
#include "traffic/trafficrecording.h"
#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "transport/linkurl.h"

#include <QtCore/QTemporaryDir>

#include <memory>

namespace mbscope::bench {

namespace {

std::optional<PollReport> runPoll(TransactionEngine &engine, const RequestItem &item, long long count)
{
    PollSettings settings;
    settings.items = {item};
    settings.count = quint64(count);
    settings.intervalNs = 0;
    engine.startPoll(settings);
    return engine.waitForFinished(600000);
}

} // namespace

PollFigures pollEngine(const EnginePollSettings &s)
{
    PollFigures f;
    f.client = s.pipelineDepth > 1 ? QStringLiteral("mbscope engine, pipeline %1").arg(s.pipelineDepth)
                                   : QStringLiteral("mbscope engine, sequential");
    const LinkUrl::Result parsed = LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(s.plan.port));
    if (!parsed.url) {
        f.errors = s.plan.count;
        f.note = parsed.error;
        return f;
    }
    const LinkUrl url = *parsed.url;
    QByteArray pdu = QByteArray::fromHex("0300000000");
    pdu[4] = char(s.plan.quantity);
    AduOptions adu;
    adu.framing = Framing::Tcp;
    adu.unitId = PEER_UNIT;
    adu.transactionId = 1;
    RequestItem item = RequestItem::forLink(AduBuilder::complete(pdu, adu), url, QStringLiteral("read"));
    item.timeoutMs = 1000;

    TransactionEngine engine;
    EngineOptions options;
    options.pipelineDepth = s.pipelineDepth;
    engine.setTarget(url, options);
    QTemporaryDir dir;
    std::unique_ptr<TrafficLog> memory;
    std::unique_ptr<TrafficRecording> recording;
    TrafficLog *log = nullptr;
    if (s.log == EnginePollSettings::Log::Memory) {
        memory = std::make_unique<TrafficLog>();
        log = memory.get();
    } else if (s.log == EnginePollSettings::Log::Journal) {
        recording = std::make_unique<TrafficRecording>();
        TrafficMetadata metadata = TrafficMetadata::forCommand(QStringLiteral("bench_poll"), {}, QStringLiteral("bench"));
        metadata.target = url.toString();
        metadata.requests = {TrafficMetadataRequest{item.name, {}, item.bytes}};
        QString error;
        if (!dir.isValid() || !recording->open(dir.filePath(QStringLiteral("traffic.mbscope.journal")), metadata, false, &error))
            f.note = QStringLiteral("no journal: ") + error;
        log = recording->log();
    }
    if (log)
        engine.setTrafficLog(log);
    if (s.plan.warmup > 0)
        (void)runPoll(engine, item, s.plan.warmup);
    // Bytes on disk per frame: what the measured poll added to the journal.
    const qint64 bytesBefore = recording ? recording->bytes() : 0;
    const quint64 framesBefore = recording ? recording->frames() + recording->log()->journal().framesPending() : 0;
    const std::optional<PollReport> report = runPoll(engine, item, s.plan.count);
    if (log)
        engine.setTrafficLog(nullptr);
    if (recording) {
        recording->close();
        if (f.note.isEmpty()) {
            const quint64 frames = recording->frames() - framesBefore;
            f.note = QStringLiteral("journaled (--record): %1 frames, %2 B/frame on disk")
                         .arg(frames)
                         .arg(frames > 0 ? double(recording->bytes() - bytesBefore) / double(frames) : 0.0, 0, 'f', 1);
        }
    } else if (memory) {
        f.note = QStringLiteral("logged in memory, no journal: %1 frames").arg(memory->appended());
    } else {
        f.note = QStringLiteral("traffic log off");
    }
    if (!report || report->runs.isEmpty()) {
        f.errors = s.plan.count;
        f.note = QStringLiteral("the poll did not finish");
        return f;
    }
    const PollRun &run = report->runs.first();
    const Statistics &stats = run.statistics.overall();
    f.transactions = qint64(stats.count());
    f.errors = qint64(stats.failed());
    f.seconds = double(run.elapsedNs) / 1e9;
    const auto sorted = stats.latency().sorted();
    f.latencyNs.assign(sorted.begin(), sorted.end());
    return f;
}

} // namespace mbscope::bench
