#include "enginepoll.h"

#include "peer_datamap.h"

#include "engine/engineoptions.h"
#include "exchange/requestitem.h"
#include "traffic/trafficlog.h"
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
    std::unique_ptr<TrafficLog> log;
    if (s.logTraffic) {
        log = std::make_unique<TrafficLog>();
        QString error;
        if (!dir.isValid() || !log->openJournal(dir.filePath(QStringLiteral("traffic.journal")), {}, false, &error)) {
            f.note = QStringLiteral("no journal: ") + error;
        }
        engine.setTrafficLog(log.get());
    }
    if (s.plan.warmup > 0)
        (void)runPoll(engine, item, s.plan.warmup);
    const std::optional<PollReport> report = runPoll(engine, item, s.plan.count);
    if (log) {
        engine.setTrafficLog(nullptr);
        if (f.note.isEmpty())
            f.note = QStringLiteral("traffic log on: %1 frames, %2 journaled").arg(log->appended()).arg(
                log->journal().isOpen() ? QStringLiteral("all") : QStringLiteral("none"));
        log->closeJournal();
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
