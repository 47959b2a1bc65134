// WatchRunner against the simulator (SimulatorHost, in this process): values decoded, watches on one link taking
// turns, a dead link not stalling another, a timeout costing one turn, a reconnect counted with
// backoff, a rule firing, and a write to a writable point read back; the CSV log written off the
// caller's thread, every sample and rule event in it by the time stopped() comes.
#include "fleet/watchrunner.h"
#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpServer>
#include <QtTest/QtTest>

#include <memory>

using namespace mbscope;

namespace {

std::unique_ptr<SimulatorHost> startSim(const QString &profile, const QString &listen, LinkUrl *bound)
{
    auto host = std::make_unique<SimulatorHost>();
    // The shipped profiles, from the source tree (this test links no resources).
    const ProfileLoadResult loaded
        = ProfileLoader::loadFile(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/%1.json").arg(profile));
    if (!loaded.ok)
        return nullptr;
    QString error;
    if (!host->load(loaded.profile, &error))
        return nullptr;
    const std::optional<LinkUrl> url = host->listen(listen, &error);
    if (!url)
        return nullptr;
    *bound = *url;
    host->start();
    return host;
}

int freePort()
{
    QTcpServer server;
    server.listen(QHostAddress::LocalHost, 0);
    return server.serverPort();
}

WatchDefinition watch(const QString &name, const QString &target, quint8 function, quint16 address, quint16 quantity,
                      qint64 intervalMs)
{
    WatchDefinition w;
    w.name = name;
    w.target = target;
    w.function = function;
    w.address = address;
    w.quantity = quantity;
    w.intervalMs = intervalMs;
    return w;
}

// Runs the event loop until pred() holds or waitMs passes.
template<typename Pred>
bool waitFor(Pred pred, int waitMs = 10000)
{
    QElapsedTimer timer;
    timer.start();
    while (!pred() && timer.elapsed() < waitMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return pred();
}

} // namespace

class tst_WatchRunner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void valuesFromTwoLinks();
    void deadLinkDoesNotStallOthers();
    void reconnectCountedWithBackoff();
    void ruleFiresAndWriteReadsBack();
    void logWrittenInItsThreadBeforeStopped();
};

void tst_WatchRunner::valuesFromTwoLinks()
{
    LinkUrl gammaUrl, plcUrl;
    auto gamma = startSim(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"), &gammaUrl);
    auto plc = startSim(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &plcUrl);
    QVERIFY(gamma && plc);

    SessionWatches watches;
    WatchDefinition settings = watch(QStringLiteral("settings"), gammaUrl.toString(), 3, 0x79, 13, 50);
    WatchPoint hv;
    hv.address = 0x79;
    hv.name = QStringLiteral("high voltage");
    hv.unit = QStringLiteral("V");
    settings.points.append(hv);
    WatchPoint time;
    time.address = 0x7F;
    time.name = QStringLiteral("measuring time");
    time.scale = 0.001;
    time.unit = QStringLiteral("s");
    settings.points.append(time);
    watches.watches.append(settings);
    watches.watches.append(watch(QStringLiteral("counts"), gammaUrl.toString(), 3, 0x86, 1, 50));
    watches.watches.append(watch(QStringLiteral("memory bits"), plcUrl.toString(), 1, 0, 16, 50));

    WatchRunner runner(watches);
    QList<WatchSample> samples;
    connect(&runner, &WatchRunner::sampled, this, [&](const QList<WatchSample> &batch, const QList<WatchCounters> &) {
        samples.append(batch);
    });
    runner.start();
    QVERIFY(waitFor([&] { return runner.counters(0).ok >= 3 && runner.counters(1).ok >= 3 && runner.counters(2).ok >= 3; }));
    runner.stop();
    QSignalSpy stopped(&runner, &WatchRunner::stopped);
    QVERIFY(stopped.wait(5000));

    bool sawSettings = false;
    for (const WatchSample &s : std::as_const(samples)) {
        QVERIFY2(s.isOk(), qPrintable(s.error));
        if (s.watch == 0) {
            sawSettings = true;
            QCOMPARE(s.words.size(), 13);
            QCOMPARE(s.values.first().name, QStringLiteral("high voltage"));
            QCOMPARE(s.values.first().value, 1050.0);
            QCOMPARE(s.values.at(6).name, QStringLiteral("measuring time"));
            QCOMPARE(s.values.at(6).text, QStringLiteral("1"));
        } else if (s.watch == 2) {
            QCOMPARE(s.bits.size(), 16);
        }
        QVERIFY(s.latencyNs > 0);
    }
    QVERIFY(sawSettings);
    const WatchCounters c = runner.counters(0);
    QCOMPARE(c.polls, c.ok);
    QCOMPARE(c.latencyCount, c.ok);
    QVERIFY(c.minLatencyNs > 0 && c.maxLatencyNs >= c.minLatencyNs);
}

void tst_WatchRunner::deadLinkDoesNotStallOthers()
{
    LinkUrl plcUrl;
    auto plc = startSim(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &plcUrl);
    QVERIFY(plc);
    const QString dead = QStringLiteral("tcp://127.0.0.1:%1").arg(freePort()); // nobody listens

    SessionWatches watches;
    watches.watches.append(watch(QStringLiteral("dead"), dead, 3, 0, 4, 20));
    watches.watches.append(watch(QStringLiteral("alive"), plcUrl.toString(), 3, 0, 4, 20));
    WatchLinkSettings fast;
    fast.target = dead;
    fast.reconnectMinMs = 20;
    fast.reconnectMaxMs = 80;
    watches.links.append(fast);

    WatchRunner runner(watches);
    QList<WatchLinkState> states;
    connect(&runner, &WatchRunner::linkStateChanged, this, [&](const WatchLinkState &s) { states.append(s); });
    runner.start();
    QVERIFY(waitFor([&] { return runner.counters(1).ok >= 20 && runner.counters(0).linkErrors >= 1; }));
    QCOMPARE(runner.counters(1).polls, runner.counters(1).ok);
    // The dead link backs off, doubling up to its maximum.
    QVERIFY(waitFor([&] {
        for (const WatchLinkState &s : std::as_const(states)) {
            if (s.target == dead && s.state == WatchLinkState::State::Backoff && s.retryInMs == 80)
                return true;
        }
        return false;
    }));
    QList<int> waits;
    for (const WatchLinkState &s : std::as_const(states)) {
        if (s.target == dead && s.state == WatchLinkState::State::Backoff)
            waits.append(s.retryInMs);
    }
    QCOMPARE(waits.mid(0, 3), (QList<int>{20, 40, 80}));
}

void tst_WatchRunner::reconnectCountedWithBackoff()
{
    const int port = freePort();
    const QString url = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
    LinkUrl bound;
    auto plc = startSim(QStringLiteral("m221-plc"), url, &bound);
    QVERIFY(plc);

    SessionWatches watches;
    watches.watches.append(watch(QStringLiteral("words"), url, 3, 0, 2, 10));
    WatchLinkSettings link;
    link.target = url;
    link.reconnectMinMs = 30;
    link.reconnectMaxMs = 200;
    watches.links.append(link);
    WatchRunner runner(watches);
    WatchLinkState last;
    connect(&runner, &WatchRunner::linkStateChanged, this, [&](const WatchLinkState &s) { last = s; });
    runner.start();
    QVERIFY(waitFor([&] { return runner.counters(0).ok >= 5; }));
    QCOMPARE(runner.counters(0).reconnects, 0u);
    QCOMPARE(last.state, WatchLinkState::State::Up);

    plc->stop();
    plc.reset();
    // The poll that finds the link gone, then attempts to open it again that fail.
    QVERIFY(waitFor([&] { return runner.counters(0).linkErrors >= 1 && last.failures >= 3; }));
    const quint64 okBefore = runner.counters(0).ok;
    plc = startSim(QStringLiteral("m221-plc"), url, &bound);
    QVERIFY(plc);
    QVERIFY(waitFor([&] { return runner.counters(0).ok >= okBefore + 5; }));
    QCOMPARE(runner.counters(0).reconnects, 1u);
    QCOMPARE(last.reconnects, 1u);
    QCOMPARE(last.state, WatchLinkState::State::Up);
}

void tst_WatchRunner::ruleFiresAndWriteReadsBack()
{
    LinkUrl plcUrl;
    auto plc = startSim(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &plcUrl);
    QVERIFY(plc);
    SessionWatches watches;
    WatchDefinition w = watch(QStringLiteral("setpoint"), plcUrl.toString(), 3, 10, 2, 10);
    WatchPoint p;
    p.address = 10;
    p.name = QStringLiteral("setpoint");
    p.writable = true;
    p.unit = QStringLiteral("hPa");
    w.points.append(p);
    WatchRule rule;
    rule.point = QStringLiteral("setpoint");
    rule.condition = WatchRule::Condition::Above;
    rule.high = 1100;
    rule.forPolls = 3;
    rule.severity = WatchSeverity::Alarm;
    w.rules.append(rule);
    watches.watches.append(w);

    WatchRunner runner(watches);
    QList<WatchRuleEvent> events;
    connect(&runner, &WatchRunner::ruleChanged, this, [&](const WatchRuleEvent &e) { events.append(e); });
    QSignalSpy written(&runner, &WatchRunner::writeFinished);
    runner.start();
    QVERIFY(waitFor([&] { return runner.counters(0).ok >= 3; }));
    QVERIFY(events.isEmpty());

    // A point not marked writable is refused with a reason.
    runner.write(0, 11, {1});
    QVERIFY(written.wait(5000));
    QCOMPARE(written.last().at(3).toBool(), false);
    QVERIFY(written.last().at(4).toString().contains(QLatin1String("writable")));

    runner.write(0, 10, {1200});
    QVERIFY(written.wait(5000));
    QCOMPARE(written.last().at(3).toBool(), true);
    QVERIFY(waitFor([&] { return !events.isEmpty(); }));
    QCOMPARE(events.first().fired, true);
    QCOMPARE(events.first().severity, WatchSeverity::Alarm);
    QCOMPARE(events.first().value, 1200.0);
    QCOMPARE(events.first().message, QStringLiteral("setpoint above 1100 hPa for 3 polls"));

    runner.write(0, 10, {1000});
    QVERIFY(waitFor([&] { return events.size() >= 2; }));
    QCOMPARE(events.at(1).fired, false);
    QCOMPARE(runner.counters(0).ruleFirings, 1u);
}

// setLog: the files open in the log's thread (logOpened), take every sample the caller received
// and every rule event, and are closed (logClosed, no row lost) before stopped(); the same
// settings again change nothing, and the watches changed while running open new files.
void tst_WatchRunner::logWrittenInItsThreadBeforeStopped()
{
    LinkUrl plcUrl;
    auto plc = startSim(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"), &plcUrl);
    QVERIFY(plc);
    SessionWatches watches;
    WatchDefinition words = watch(QStringLiteral("words"), plcUrl.toString(), 3, 0, 4, 20);
    WatchRule rule;
    rule.point = QStringLiteral("0");
    rule.condition = WatchRule::Condition::Below;
    rule.low = 100000; // always holds: fires at the first poll
    words.rules.append(rule);
    watches.watches.append(words);
    watches.watches.append(watch(QStringLiteral("bits"), plcUrl.toString(), 1, 0, 16, 20));

    QTemporaryDir dir;
    WatchLogSettings log;
    log.enabled = true;
    log.directory = dir.filePath(QStringLiteral("logs"));
    WatchRunner runner(watches);
    QList<WatchSample> samples;
    int events = 0;
    QStringList order;
    QStringList files;
    quint64 lost = 99;
    connect(&runner, &WatchRunner::sampled, this, [&](const QList<WatchSample> &batch, const QList<WatchCounters> &) { samples.append(batch); });
    connect(&runner, &WatchRunner::ruleChanged, this, [&](const WatchRuleEvent &) { ++events; });
    connect(&runner, &WatchRunner::logOpened, this, [&](const QString &) { order.append(QStringLiteral("opened")); });
    connect(&runner, &WatchRunner::logClosed, this, [&](const QString &, const QStringList &f, quint64 l) {
        order.append(QStringLiteral("closed"));
        files += f;
        lost = l;
    });
    connect(&runner, &WatchRunner::stopped, this, [&] { order.append(QStringLiteral("stopped")); });
    runner.setLog(log);
    runner.start();
    runner.setLog(log); // the same again: the files stay
    QVERIFY(waitFor([&] { return runner.counters(0).ok >= 5 && runner.counters(1).ok >= 5 && events >= 1; }));
    runner.stop();
    QVERIFY(waitFor([&] { return order.contains(QStringLiteral("stopped")); }));
    QCOMPARE(order, (QStringList{QStringLiteral("opened"), QStringLiteral("closed"), QStringLiteral("stopped")}));
    QCOMPARE(lost, 0u);
    QCOMPARE(files.size(), 3); // words, its events, bits
    qsizetype rows = 0;
    qsizetype eventRows = 0;
    for (const QString &path : std::as_const(files)) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const qsizetype n = f.readAll().count('\n') - 1;
        (path.contains(QLatin1String("-events-")) ? eventRows : rows) += n;
    }
    QCOMPARE(rows, samples.size());
    QCOMPARE(eventRows, qsizetype(events));

    // The watches changed while running: the files close and new ones open.
    order.clear();
    files.clear();
    runner.start();
    QVERIFY(waitFor([&] { return order.contains(QStringLiteral("opened")); }));
    watches.watches.removeLast();
    runner.setWatches(watches);
    QVERIFY(waitFor([&] { return order.size() >= 3; }));
    QCOMPARE(order.mid(0, 3), (QStringList{QStringLiteral("opened"), QStringLiteral("closed"), QStringLiteral("opened")}));
    runner.setLog(std::nullopt); // logging off while running
    QVERIFY(waitFor([&] { return order.size() >= 4; }));
    QCOMPARE(order.at(3), QStringLiteral("closed"));
    runner.stop();
    QVERIFY(waitFor([&] { return order.contains(QStringLiteral("stopped")); }));
    QCOMPARE(order.size(), 5);
}

QTEST_GUILESS_MAIN(tst_WatchRunner)
#include "tst_watchrunner.moc"
