#include "transport/linkurl.h"
#include "transport/rtsdirection.h"

#include <QtTest/QtTest>

#include <cerrno>
#include <memory>

using namespace mbscope;

namespace {

// A clock and a log the fakes share with the test: times in microseconds.
struct Bench {
    qint64 nowUs = 0;
    QStringList log;
    void note(const QString &what) { log.append(QString::number(nowUs) + QLatin1Char(' ') + what); }
};

// Records every line-control call at the bench's time; answers with the errno it is told.
class RecordingLines final : public LineControl
{
public:
    explicit RecordingLines(Bench *bench)
        : m_bench(bench)
    {
    }
    int rtsError = 0;
    int getError = 0;
    int setError = 0;
    bool driverChangesDelays = false; // a driver that takes the call but zeroes the delays
    KernelRs485 current{false, false, true, 0, 0}; // as a driver might hold it before

    int setRts(bool asserted) override
    {
        if (rtsError)
            return rtsError;
        m_bench->note(QStringLiteral("rts %1").arg(asserted ? 1 : 0));
        return 0;
    }
    int kernelRs485(KernelRs485 *settings) override
    {
        if (getError)
            return getError;
        *settings = current;
        return 0;
    }
    int setKernelRs485(const KernelRs485 &k) override
    {
        if (setError)
            return setError;
        m_bench->note(QStringLiteral("kernel %1 on-send %2 after-send %3 before %4ms after %5ms")
                          .arg(k.enabled ? QStringLiteral("on") : QStringLiteral("off"))
                          .arg(int(k.rtsOnSend))
                          .arg(int(k.rtsAfterSend))
                          .arg(k.delayBeforeMs)
                          .arg(k.delayAfterMs));
        current = k;
        if (driverChangesDelays)
            current.delayBeforeMs = current.delayAfterMs = 0;
        return 0;
    }

private:
    Bench *m_bench;
};

Rs485Settings settingsOf(const QString &options)
{
    const auto parsed = LinkUrl::parse(QStringLiteral("rtu:///dev/ttyTEST?") + options);
    if (!parsed.url)
        qFatal("bad URL in test: %s", qPrintable(parsed.error));
    return parsed.url->serial.rs485;
}

} // namespace

// RS-485 direction control (issue 27): when RTS switches around a send, against the line-free
// time the link computes, with libmodbus's order (RTS, rts_before, bytes, line time, rts_after,
// RTS back) but timers instead of sleeps. The test drives a clock of its own and calls service()
// where the timer would: no wall-clock time is read.
class TestRtsDirection : public QObject
{
    Q_OBJECT
private slots:
    // Steps: "T send N" (N bytes at T us), "T drained F" (the link says the line is free at F us),
    // "T service" (the timer fires at T), "T deadline" (logs when service() is due next),
    // "T stop". The log: what the line control and the writer saw, at what time.
    void schedule_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<QStringList>("steps");
        QTest::addColumn<QStringList>("expected");
        using Lines = std::initializer_list<const char *>;
        auto row = [](const char *name, const char *options, Lines steps, Lines expected) {
            auto list = [](Lines lines) {
                QStringList out;
                for (const char *line : lines)
                    out.append(QString::fromLatin1(line));
                return out;
            };
            QTest::newRow(name) << QString::fromLatin1(options) << list(steps) << list(expected);
        };
        // 8 bytes at 9600 8E1 take 9166 us: the link says so through drained().
        row("up: raised for the send, back when the last byte left", "rts=up",
            {"100 send 8", "100 drained 9266", "100 deadline", "9265 service", "9266 service", "9266 deadline"},
            {"0 rts 0", "100 rts 1", "100 write 8", "100 deadline 9266", "9266 rts 0", "9266 deadline 0"});
        row("down: the other way round", "rts=down", {"100 send 8", "100 drained 9266", "9266 service"},
            {"0 rts 1", "100 rts 0", "100 write 8", "9266 rts 1"});
        row("rts_before holds the bytes back, rts_after keeps RTS up", "rts=up&rts_before=1ms&rts_after=500us",
            {"0 send 8", "0 deadline", "999 service", "1000 service", "1000 drained 10166", "10165 deadline", "10665 service",
             "10666 service"},
            {"0 rts 0", "0 rts 1", "0 deadline 1000", "1000 write 8", "10165 deadline 10666", "10666 rts 0"});
        row("a send during rts_after goes at once and keeps RTS up", "rts=up&rts_before=1ms&rts_after=2ms",
            {"0 send 8", "1000 service", "1000 drained 10166", "11000 send 8", "11000 drained 20166", "12166 service",
             "22165 service", "22166 service"},
            {"0 rts 0", "0 rts 1", "1000 write 8", "11000 write 8", "22166 rts 0"});
        row("a send after RTS went back waits rts_before again", "rts=down&rts_before=1ms",
            {"0 send 8", "1000 service", "1000 drained 10166", "10166 service", "20000 send 5", "21000 service",
             "21000 drained 26729", "26729 service"},
            {"0 rts 1", "0 rts 0", "1000 write 8", "10166 rts 1", "20000 rts 0", "21000 write 5", "26729 rts 1"});
        row("sends made while held go behind, in order", "rts=up&rts_before=2ms",
            {"0 send 8", "500 send 4", "500 drained 0", "2000 service", "2000 drained 15000", "15000 service"},
            {"0 rts 0", "0 rts 1", "2000 write 8", "2000 write 4", "15000 rts 0"});
        row("a send cancels the planned return; its own drain time sets the next", "rts=up",
            {"0 send 8", "5000 drained 9166", "6000 send 4", "7000 service", "9166 service", "9166 drained 12800",
             "12800 service"},
            {"0 rts 0", "0 rts 1", "0 write 8", "6000 write 4", "12800 rts 0"});
        row("a failed write puts RTS back rts_after later", "rts=up&rts_after=1ms",
            {"0 send 0", "0 deadline", "1000 service"}, {"0 rts 0", "0 rts 1", "0 write failed", "0 deadline 1000", "1000 rts 0"});
        row("stop puts RTS back and drops what was held", "rts=up&rts_before=5ms",
            {"0 send 8", "100 stop", "5000 service", "5000 deadline"}, {"0 rts 0", "0 rts 1", "100 rts 0", "5000 deadline 0"});
        row("stop after RTS went back touches nothing", "rts=up",
            {"0 send 8", "0 drained 9166", "9166 service", "9200 stop"}, {"0 rts 0", "0 rts 1", "0 write 8", "9166 rts 0"});
        // The driver's RS-485 mode: level and delays handed to it at start, sends go straight through.
        row("kernel: the driver switches, up", "rs485=kernel&rts_before=2&rts_after=3",
            {"100 send 8", "100 drained 9266", "100 deadline", "9266 service", "9300 stop"},
            {"0 kernel on on-send 1 after-send 0 before 2ms after 3ms", "100 write 8", "100 deadline 0",
             "9300 kernel off on-send 0 after-send 1 before 0ms after 0ms"});
        row("kernel: down", "rs485=kernel&rts=down", {"100 send 8"},
            {"0 kernel on on-send 0 after-send 1 before 0ms after 0ms", "100 write 8"});
    }
    void schedule()
    {
        QFETCH(QString, options);
        QFETCH(QStringList, steps);
        QFETCH(QStringList, expected);
        Bench bench;
        RtsDirection rts(settingsOf(options), QStringLiteral("/dev/ttyTEST"), [&bench](const QByteArray &bytes) {
            bench.note(bytes.isEmpty() ? QStringLiteral("write failed") : QStringLiteral("write %1").arg(bytes.size()));
            return !bytes.isEmpty();
        });
        rts.setClock([&bench] { return bench.nowUs * 1000; });
        QCOMPARE(rts.start(std::make_unique<RecordingLines>(&bench)), QString());
        for (const QString &step : std::as_const(steps)) {
            const QStringList parts = step.split(QLatin1Char(' '));
            bench.nowUs = parts.at(0).toLongLong();
            const QString what = parts.at(1);
            if (what == u"send") {
                rts.send(QByteArray(parts.at(2).toInt(), 'x'));
            } else if (what == u"drained") {
                rts.drained(parts.at(2).toLongLong() * 1000);
            } else if (what == u"service") {
                rts.service();
            } else if (what == u"deadline") {
                bench.note(QStringLiteral("deadline %1").arg(rts.deadlineNs() / 1000));
            } else if (what == u"stop") {
                rts.stop();
            } else {
                QFAIL(qPrintable(QStringLiteral("unknown step ") + step));
            }
        }
        QCOMPARE(bench.log, expected);
    }

    // A port that cannot do it says so at start, naming the device, the option and the OS's answer.
    void startErrors_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<int>("rtsError");
        QTest::addColumn<int>("setError");
        QTest::addColumn<bool>("driverChangesDelays");
        QTest::addColumn<QString>("message");
        QTest::newRow("pty: no modem lines") << QStringLiteral("rts=up") << ENOTTY << 0 << false
                                             << QStringLiteral("cannot switch RTS on /dev/ttyTEST for rts=up (%1): the port has no "
                                                               "modem control lines (a pseudo terminal has none); use a port whose "
                                                               "RTS drives the transceiver, or leave rts= out if the adapter "
                                                               "switches direction by itself")
                                                    .arg(qt_error_string(ENOTTY));
        QTest::newRow("unplugged") << QStringLiteral("rts=down") << EIO << 0 << false
                                   << QStringLiteral("cannot switch RTS on /dev/ttyTEST for rts=down (%1)").arg(qt_error_string(EIO));
        QTest::newRow("driver without RS-485 mode")
            << QStringLiteral("rs485=kernel") << 0 << ENOTTY << false
            << QStringLiteral("/dev/ttyTEST has no RS-485 mode for rs485=kernel (TIOCSRS485: %1): its driver does not offer "
                              "one; leave rs485=kernel out to have mbscope switch RTS itself (rts=up)")
                   .arg(qt_error_string(ENOTTY));
        QTest::newRow("driver refusing otherwise") << QStringLiteral("rs485=kernel&rts=down") << 0 << EIO << false
                                                   << QStringLiteral("cannot switch /dev/ttyTEST to its driver's RS-485 mode for "
                                                                     "rs485=kernel (TIOCSRS485: %1)")
                                                          .arg(qt_error_string(EIO));
        QTest::newRow("driver dropping the delays")
            << QStringLiteral("rs485=kernel&rts_after=2ms") << 0 << 0 << true
            << QStringLiteral("the driver of /dev/ttyTEST does not keep the RS-485 settings of rs485=kernel: asked for RTS up "
                              "while sending and down after, 0 ms before, 2 ms after, it set RTS up while sending and down "
                              "after, 0 ms before, 0 ms after");
    }
    void startErrors()
    {
        QFETCH(QString, options);
        QFETCH(int, rtsError);
        QFETCH(int, setError);
        QFETCH(bool, driverChangesDelays);
        QFETCH(QString, message);
        Bench bench;
        RtsDirection rts(settingsOf(options), QStringLiteral("/dev/ttyTEST"), [](const QByteArray &) { return true; });
        rts.setClock([&bench] { return bench.nowUs * 1000; });
        auto lines = std::make_unique<RecordingLines>(&bench);
        lines->rtsError = rtsError;
        lines->setError = setError;
        lines->driverChangesDelays = driverChangesDelays;
        QCOMPARE(rts.start(std::move(lines)), message);
        QVERIFY(!rts.isStarted());
        if (driverChangesDelays) // what the driver had is put back
            QCOMPARE(bench.log.last(), QStringLiteral("0 kernel off on-send 0 after-send 1 before 0ms after 0ms"));
    }

    // RTS that cannot be switched during a send (the adapter went away) is an error, and the bytes
    // are not sent with the transmitter off.
    void failsDuringSend()
    {
        Bench bench;
        int writes = 0;
        RtsDirection rts(settingsOf(QStringLiteral("rts=up")), QStringLiteral("/dev/ttyTEST"), [&writes](const QByteArray &) {
            ++writes;
            return true;
        });
        rts.setClock([&bench] { return bench.nowUs * 1000; });
        auto owned = std::make_unique<RecordingLines>(&bench);
        RecordingLines *lines = owned.get();
        QCOMPARE(rts.start(std::move(owned)), QString());
        QStringList failures;
        connect(&rts, &RtsDirection::failed, this, [&failures](const QString &what) { failures.append(what); });
        lines->rtsError = EIO;
        QVERIFY(!rts.send(QByteArray(8, 'x')));
        QCOMPARE(writes, 0);
        QCOMPARE(failures, QStringList{QStringLiteral("cannot switch RTS on /dev/ttyTEST before a send (%1)").arg(qt_error_string(EIO))});
    }
};

QTEST_GUILESS_MAIN(TestRtsDirection)
#include "tst_rtsdirection.moc"
