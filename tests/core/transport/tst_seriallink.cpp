#include "protocol/rtuframer.h"
#include "transport/linecontrol.h"
#include "transport/monotonicclock.h"
#include "transport/seriallink.h"

#include "linktesting.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <cerrno>
#include <functional>
#include <memory>
#include <unistd.h>

using namespace mbscope;
using linktesting::Recorder;

namespace {

constexpr int kWaitMs = 10000;

std::unique_ptr<Link> makeLink(const QString &text)
{
    const auto parsed = LinkUrl::parse(text);
    if (!parsed.url)
        qFatal("bad URL in test: %s", qPrintable(parsed.error));
    return std::unique_ptr<Link>(Link::create(*parsed.url));
}

// A pty has no modem lines: this one records the RTS switching the link asks for, with the
// monotonic time of each call, as a USB-RS485 adapter's RTS would see it.
struct RtsCall {
    qint64 ns;
    bool asserted;
};
class RecordingLines final : public LineControl
{
public:
    explicit RecordingLines(QList<RtsCall> *calls)
        : m_calls(calls)
    {
    }
    int setRts(bool asserted) override
    {
        m_calls->append(RtsCall{monotonicNowNs(), asserted});
        return 0;
    }
    int kernelRs485(KernelRs485 *) override { return ENOTTY; }
    int setKernelRs485(const KernelRs485 &) override { return ENOTTY; }

private:
    QList<RtsCall> *m_calls;
};

// Runs the event loop until pred holds, as an application's loop runs: QTRY_* waits with
// QTest::qWait, which sleeps up to 10 ms between turns and so makes every timer late.
bool spinUntil(const std::function<bool()> &pred, int timeoutMs = kWaitMs)
{
    QDeadlineTimer deadline(timeoutMs);
    QTimer wake; // wakes the wait now and then to look at the deadline
    wake.start(100);
    while (!pred()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return true;
}

} // namespace

// Serial links over a pseudo-terminal pair made by socat: what one end writes, the other reads.
// The baud rate of a pty is nominal (bytes pass at once), which is enough to check the settings,
// the computed drain times and the errors.
class TestSerialLink : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QProcess m_socat;
    QString m_a;
    QString m_b;

    void startSocat()
    {
        const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (socat.isEmpty())
            QSKIP("socat is not installed: no pty pair to test serial links on");
        static int pair = 0;
        ++pair;
        m_a = m_dir.filePath(QStringLiteral("a%1").arg(pair));
        m_b = m_dir.filePath(QStringLiteral("b%1").arg(pair));
        m_socat.start(socat, {QStringLiteral("-d"), QStringLiteral("-d"), QStringLiteral("pty,raw,echo=0,link=") + m_a,
                              QStringLiteral("pty,raw,echo=0,link=") + m_b});
        QVERIFY2(m_socat.waitForStarted(kWaitMs), qPrintable(m_socat.errorString()));
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(m_a) && QFileInfo::exists(m_b), kWaitMs);
    }
    void stopSocat()
    {
        if (m_socat.state() == QProcess::NotRunning)
            return;
        m_socat.terminate();
        if (!m_socat.waitForFinished(kWaitMs)) {
            m_socat.kill();
            m_socat.waitForFinished(kWaitMs);
        }
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void init() { startSocat(); }
    void cleanup() { stopSocat(); }

    void timing_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<qint64>("character");
        QTest::addColumn<qint64>("t15");
        QTest::addColumn<qint64>("t35");
        QTest::addColumn<qint64>("turnaround");
        // Serial Line V1.02, 2.5.1.1: t1.5 and t3.5 from 11-bit characters, fixed at 750 us and
        // 1750 us above 19200 baud. The line character counts the bits actually configured.
        QTest::newRow("9600 8E1") << QStringLiteral("rtu:///dev/x?baud=9600") << qint64(11) * 1000000000 / 9600
                                  << RtuFramer::t15Ns(9600) << RtuFramer::t35Ns(9600) << qint64(0);
        QTest::newRow("9600 8N1, turnaround 10ms") << QStringLiteral("rtu:///dev/x?baud=9600&parity=N&turnaround=10ms")
                                                   << qint64(10) * 1000000000 / 9600 << RtuFramer::t15Ns(9600)
                                                   << RtuFramer::t35Ns(9600) << qint64(10000000);
        QTest::newRow("19200 8N2") << QStringLiteral("rtu:///dev/x?baud=19200&parity=N&stop=2") << qint64(11) * 1000000000 / 19200
                                   << RtuFramer::t15Ns(19200) << RtuFramer::t35Ns(19200) << qint64(0);
        QTest::newRow("38400: fixed 750/1750 us") << QStringLiteral("rtu:///dev/x?baud=38400&turnaround_us=500")
                                                  << qint64(11) * 1000000000 / 38400 << qint64(750000) << qint64(1750000)
                                                  << qint64(500000);
        QTest::newRow("ascii 9600 7E1") << QStringLiteral("ascii:///dev/x?baud=9600") << qint64(10) * 1000000000 / 9600
                                        << RtuFramer::t15Ns(9600) << RtuFramer::t35Ns(9600) << qint64(0);
    }
    void timing()
    {
        QFETCH(QString, url);
        QFETCH(qint64, character);
        QFETCH(qint64, t15);
        QFETCH(qint64, t35);
        QFETCH(qint64, turnaround);
        auto link = makeLink(url);
        auto *serial = qobject_cast<SerialLink *>(link.get());
        QVERIFY(serial);
        QCOMPARE(SerialLink::lineCharacterNs(link->url().serial), character);
        QCOMPARE(link->t15Ns(), t15);
        QCOMPARE(link->t35Ns(), t35);
        QCOMPARE(link->turnaroundNs(), turnaround);
        QVERIFY(t35 > t15);
    }

    void bothWays()
    {
        auto a = makeLink(QStringLiteral("rtu://%1?baud=9600").arg(m_a));
        auto b = makeLink(QStringLiteral("rtu://%1?baud=9600").arg(m_b));
        Recorder ra(a.get());
        Recorder rb(b.get());
        a->open();
        b->open();
        QCOMPARE(ra.opened, 0); // signalled after open() returns
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened + rb.opened, 2, kWaitMs);
        QVERIFY2(ra.errors.isEmpty() && rb.errors.isEmpty(), qPrintable(ra.lastMessage() + rb.lastMessage()));

        const QByteArray request = QByteArray::fromHex("010300790016" "15DD");
        QVERIFY(a->write(request));
        QTRY_COMPARE_WITH_TIMEOUT(rb.received, request, kWaitMs);
        for (int i = 0; i < rb.chunks.size(); ++i)
            QCOMPARE(rb.firstNs.at(i), rb.lastNs.at(i));
        const QByteArray answer = QByteArray::fromHex("0103020001" "7984");
        QVERIFY(b->write(answer));
        QTRY_COMPARE_WITH_TIMEOUT(ra.received, answer, kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(ra.writtenNs.size(), 1, kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(rb.writtenNs.size(), 1, kWaitMs);
    }

    // bytesWritten carries the computed drain time: never before the bytes could have left at
    // the configured rate, never emitted before that time, and writes queue behind each other.
    void drainTime()
    {
        auto a = makeLink(QStringLiteral("rtu://%1?baud=9600").arg(m_a));
        auto b = makeLink(QStringLiteral("rtu://%1?baud=9600").arg(m_b));
        auto *serial = qobject_cast<SerialLink *>(a.get());
        Recorder ra(a.get());
        Recorder rb(b.get());
        QList<qint64> emittedAt;
        connect(a.get(), &Link::bytesWritten, this, [&emittedAt](qint64) { emittedAt.append(monotonicNowNs()); });
        a->open();
        b->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened + rb.opened, 2, kWaitMs);
        const qint64 character = SerialLink::lineCharacterNs(a->url().serial);

        const QByteArray first(200, 'x');
        const QByteArray second(10, 'y');
        const qint64 before = monotonicNowNs();
        QVERIFY(a->write(first));
        const qint64 free1 = serial->lineFreeNs();
        QVERIFY(free1 >= before + 200 * character);
        QVERIFY(a->write(second));
        const qint64 afterSecond = monotonicNowNs();
        const qint64 free2 = serial->lineFreeNs();
        if (afterSecond < free1)
            QCOMPARE(free2, free1 + 10 * character); // queued behind the first write
        else
            QVERIFY(free2 >= free1 + 10 * character);
        QCOMPARE(ra.writtenNs.size(), 0); // not yet: the line is still busy

        QTRY_COMPARE_WITH_TIMEOUT(ra.writtenNs.size(), 2, kWaitMs);
        QCOMPARE(ra.writtenNs.at(0), free1);
        QCOMPARE(ra.writtenNs.at(1), free2);
        QVERIFY(emittedAt.at(0) >= ra.writtenNs.at(0));
        QVERIFY(emittedAt.at(1) >= ra.writtenNs.at(1));
        QTRY_COMPARE_WITH_TIMEOUT(rb.received, first + second, kWaitMs);
    }

    void closeAndReopen()
    {
        auto a = makeLink(QStringLiteral("rtu://%1?baud=19200&parity=N&stop=2").arg(m_a));
        auto b = makeLink(QStringLiteral("rtu://%1?baud=19200&parity=N&stop=2").arg(m_b));
        Recorder ra(a.get());
        Recorder rb(b.get());
        a->open();
        b->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened + rb.opened, 2, kWaitMs);
        a->close();
        QCOMPARE(ra.closed, 1);
        QCOMPARE(a->state(), Link::State::Closed);
        QVERIFY(!a->write("x"));
        QCOMPARE(ra.errors.last().kind, LinkError::Kind::Closed);
        a->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened, 2, kWaitMs);
        QVERIFY(a->write("again"));
        QTRY_COMPARE_WITH_TIMEOUT(rb.received, QByteArray("again"), kWaitMs);
    }

    // The other end goes away (socat ends, as an unplugged adapter would): the link is lost, with
    // a message, and closed() follows.
    void deviceGoesAway()
    {
        auto a = makeLink(QStringLiteral("rtu://%1").arg(m_a));
        Recorder ra(a.get());
        a->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened, 1, kWaitMs);
        stopSocat();
        QTRY_COMPARE_WITH_TIMEOUT(ra.closed, 1, kWaitMs);
        QCOMPARE(a->state(), Link::State::Closed);
        QVERIFY(!ra.errors.isEmpty());
        QCOMPARE(ra.errors.last().kind, LinkError::Kind::Closed);
        QVERIFY2(ra.lastMessage().startsWith(a->url().toString() + QStringLiteral(": ") + m_a + QStringLiteral(" went away")),
                 qPrintable(ra.lastMessage()));
        qInfo().noquote() << ra.lastMessage();
        // Opening again now says the device is missing.
        a->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.errors.size(), 2, kWaitMs);
        QCOMPARE(ra.errors.last().kind, LinkError::Kind::NotFound);
    }

    void missingDevice()
    {
        auto link = makeLink(QStringLiteral("rtu:///dev/mbscope-no-such-tty"));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::NotFound);
        QCOMPARE(rec.lastMessage(),
                 QStringLiteral("rtu:///dev/mbscope-no-such-tty?baud=9600&parity=E&data=8&stop=1: no such device "
                                "/dev/mbscope-no-such-tty (%1): is the adapter plugged in? 'ls /dev/serial/by-id' lists the "
                                "serial devices present")
                     .arg(qt_error_string(ENOENT)));
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.opened, 0);
    }

    void notASerialPort()
    {
        const QString file = m_dir.filePath(QStringLiteral("plain-file"));
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.close();
        auto link = makeLink(QStringLiteral("rtu://") + file);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Config);
        QVERIFY2(rec.lastMessage().endsWith(file + QStringLiteral(" is not a serial port (not a terminal device)")),
                 qPrintable(rec.lastMessage()));
    }

    // Permission denied names the group that owns the device. As root the kernel grants every
    // access, so then the message is checked through the function that builds it, with EACCES.
    void permissionDenied()
    {
        const QString device = QFileInfo(m_a).canonicalFilePath(); // the /dev/pts/N behind the link
        QVERIFY(!device.isEmpty());
        const QString group = QFileInfo(device).group();
        QVERIFY(!group.isEmpty());
        QCOMPARE(SerialLink::owningGroup(device), group);
        const QString expected = QStringLiteral("permission denied opening %1 (%2): it belongs to group '%3'; join that "
                                                "group with 'sudo usermod -aG %3 $USER', then log out and in again")
                                     .arg(device, qt_error_string(EACCES), group);
        QCOMPARE(SerialLink::openFailureMessage(device, EACCES), expected);
        if (QFileInfo::exists(QStringLiteral("/dev/ttyS0")))
            QCOMPARE(SerialLink::owningGroup(QStringLiteral("/dev/ttyS0")), QFileInfo(QStringLiteral("/dev/ttyS0")).group());
        QCOMPARE(SerialLink::openFailureMessage(QStringLiteral("/dev/mbscope-none"), EACCES),
                 QStringLiteral("permission denied opening /dev/mbscope-none (%1): ask for read and write access to it")
                     .arg(qt_error_string(EACCES)));

        if (::geteuid() == 0) {
            qInfo("running as root: permission checks are bypassed, so only the message was checked");
            return;
        }
        QVERIFY(QFile::setPermissions(device, QFileDevice::Permissions()));
        auto link = makeLink(QStringLiteral("rtu://") + device);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Permission);
        QCOMPARE(rec.lastMessage(), link->url().toString() + QStringLiteral(": ") + expected);
    }

    // RS-485 direction control on a port without modem lines (a pty, as socat makes them; a driver
    // without TIOCSRS485 answers alike): the link does not open, and says why (issue 27).
    void rs485Refused_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<QString>("message");
        QTest::newRow("rts=up") << QStringLiteral("rts=up")
                                << QStringLiteral("cannot switch RTS on %1 for rts=up (%2): the port has no modem control lines "
                                                  "(a pseudo terminal has none); use a port whose RTS drives the transceiver, or "
                                                  "leave rts= out if the adapter switches direction by itself");
        QTest::newRow("rts=down, delays") << QStringLiteral("rts=down&rts_before=1ms&rts_after=1ms")
                                          << QStringLiteral("cannot switch RTS on %1 for rts=down (%2): the port has no modem "
                                                            "control lines (a pseudo terminal has none); use a port whose RTS "
                                                            "drives the transceiver, or leave rts= out if the adapter switches "
                                                            "direction by itself");
        QTest::newRow("rs485=kernel") << QStringLiteral("rs485=kernel")
                                      << QStringLiteral("%1 has no RS-485 mode for rs485=kernel (TIOCSRS485: %2): its driver "
                                                        "does not offer one; leave rs485=kernel out to have mbscope switch RTS "
                                                        "itself (rts=up)");
    }
    void rs485Refused()
    {
        QFETCH(QString, options);
        QFETCH(QString, message);
        auto link = makeLink(QStringLiteral("rtu://%1?").arg(m_a) + options);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Config);
        QCOMPARE(rec.lastMessage(), link->url().toString() + QStringLiteral(": ") + message.arg(m_a, qt_error_string(ENOTTY)));
        QCOMPARE(link->state(), Link::State::Closed);
        QCOMPARE(rec.opened, 0);
        // Without the option the same port opens.
        auto plain = makeLink(QStringLiteral("rtu://") + m_a);
        Recorder recPlain(plain.get());
        plain->open();
        QTRY_COMPARE_WITH_TIMEOUT(recPlain.opened, 1, kWaitMs);
    }

    // On an open link, RTS rests at open, rises before the bytes (rts_before ahead of them), and
    // goes back rts_after after the computed drain time of the last byte, never sooner; a second
    // write while RTS is up goes at once, and the last write's drain time counts.
    void rtsAroundWrites_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<bool>("sendLevel");
        QTest::addColumn<qint64>("beforeNs");
        QTest::addColumn<qint64>("afterNs");
        QTest::newRow("up") << QStringLiteral("rts=up") << true << qint64(0) << qint64(0);
        QTest::newRow("down, 3 ms before, 2 ms after") << QStringLiteral("rts=down&rts_before=3ms&rts_after=2ms") << false
                                                       << qint64(3000000) << qint64(2000000);
        QTest::newRow("up, 500 us after") << QStringLiteral("rts=up&rts_after=500us") << true << qint64(0) << qint64(500000);
    }
    void rtsAroundWrites()
    {
        QFETCH(QString, options);
        QFETCH(bool, sendLevel);
        QFETCH(qint64, beforeNs);
        QFETCH(qint64, afterNs);
        auto a = makeLink(QStringLiteral("rtu://%1?baud=9600&").arg(m_a) + options);
        auto b = makeLink(QStringLiteral("rtu://%1?baud=9600").arg(m_b));
        QList<RtsCall> calls;
        qobject_cast<SerialLink *>(a.get())->setLineControlFactory([&calls](int) { return std::make_unique<RecordingLines>(&calls); });
        Recorder ra(a.get());
        Recorder rb(b.get());
        a->open();
        b->open();
        QTRY_COMPARE_WITH_TIMEOUT(ra.opened + rb.opened, 2, kWaitMs);
        QCOMPARE(calls.size(), 1);
        QCOMPARE(calls.at(0).asserted, !sendLevel); // at rest: the transmitter off

        const qint64 before = monotonicNowNs();
        QVERIFY(a->write(QByteArray::fromHex("010300790016" "15DD")));
        QCOMPARE(calls.size(), 2);
        QCOMPARE(calls.at(1).asserted, sendLevel);
        QVERIFY(calls.at(1).ns >= before);
        QVERIFY(spinUntil([&] { return ra.writtenNs.size() == 1; }));
        // The bytes went rts_before after RTS rose: they cannot have left before that plus their line time.
        const qint64 character = SerialLink::lineCharacterNs(a->url().serial);
        QVERIFY(ra.writtenNs.at(0) >= calls.at(1).ns + beforeNs + 8 * character);
        QVERIFY(a->write(QByteArray::fromHex("01060001000319CB")));
        if (calls.size() == 2) { // RTS still up: no second rise, no rts_before
            QVERIFY(spinUntil([&] { return ra.writtenNs.size() == 2 && calls.size() == 3; }));
        } else { // the first write had drained and RTS had gone back already: up again for the second
            QCOMPARE(calls.size(), 4);
            QVERIFY(spinUntil([&] { return ra.writtenNs.size() == 2 && calls.size() == 5; }));
        }
        QCOMPARE(calls.last().asserted, !sendLevel);
        QVERIFY(calls.last().ns >= ra.writtenNs.last() + afterNs);
        // For the record (not asserted: timers): how late RTS went back after the time it was due.
        qInfo("RTS back %.3f ms after the last byte's computed line end + rts_after (timer grain: 1 ms)",
              double(calls.last().ns - ra.writtenNs.last() - afterNs) / 1e6);
        QTRY_COMPARE_WITH_TIMEOUT(rb.received.size(), 16, kWaitMs);
        // Closing leaves RTS at rest: nothing more to switch.
        a->close();
        QCOMPARE(calls.last().asserted, !sendLevel);
    }

    void otherMessages()
    {
        QCOMPARE(SerialLink::openFailureMessage(QStringLiteral("/dev/ttyUSB0"), EBUSY),
                 QStringLiteral("/dev/ttyUSB0 is in use by another program (%1)").arg(qt_error_string(EBUSY)));
        QCOMPARE(SerialLink::openFailureMessage(QStringLiteral("/dev/ttyUSB0"), EIO),
                 QStringLiteral("cannot open /dev/ttyUSB0 (%1)").arg(qt_error_string(EIO)));
    }
};

QTEST_GUILESS_MAIN(TestSerialLink)
#include "tst_seriallink.moc"
