// RS-485 direction control from the command line (issue 27): the URL options reach every
// command's serial link and the simulator's serial endpoints. A socat pty has no modem lines and
// no driver RS-485 mode, so a command asked to switch RTS on one must fail at open, exit 2, and
// say which device, which option and what the operating system answered; a bad option value is a
// usage error that names it.

#include "clitest.h"

#include <QtCore/QFileInfo>
#include <QtCore/QJsonObject>
#include <QtTest/QtTest>

#include <cerrno>

using namespace mbscope::testcli;
using namespace mbscope;

namespace {

QString noModemLines(const QString &device, const QString &option)
{
    return QStringLiteral("cannot switch RTS on %1 for %2 (%3): the port has no modem control lines (a pseudo terminal has "
                          "none); use a port whose RTS drives the transceiver, or leave rts= out if the adapter switches "
                          "direction by itself")
        .arg(device, option, qt_error_string(ENOTTY));
}

QString noKernelMode(const QString &device)
{
    return QStringLiteral("%1 has no RS-485 mode for rs485=kernel (TIOCSRS485: %2): its driver does not offer one; leave "
                          "rs485=kernel out to have mbscope switch RTS itself (rts=up)")
        .arg(device, qt_error_string(ENOTTY));
}

} // namespace

class TestCliRs485 : public QObject
{
    Q_OBJECT
private:
    testpeers::PtyPair m_pty;
    QString m_device; // /dev/pts/N behind our end

private slots:
    void initTestCase()
    {
        QString why;
        if (!testpeers::socatAvailable(&why))
            QSKIP(qPrintable(why));
        QVERIFY2(m_pty.start(), qPrintable(m_pty.error()));
        m_device = QFileInfo(m_pty.ourEnd()).canonicalFilePath();
        QVERIFY2(m_device.startsWith(QLatin1String("/dev/")), qPrintable(m_device));
    }

    // The commands that talk to a target fail at open, with the link's message.
    void refusedAtOpen_data()
    {
        QTest::addColumn<QStringList>("arguments"); // %1: the target URL
        QTest::addColumn<QString>("options");
        QTest::addColumn<bool>("kernel");
        const QStringList read{QStringLiteral("read"), QStringLiteral("--target"), QStringLiteral("%1"),
                               QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--quantity"),
                               QStringLiteral("2"), QStringLiteral("--timeout"), QStringLiteral("200ms")};
        const QStringList send{QStringLiteral("send"), QStringLiteral("--target"), QStringLiteral("%1"), QStringLiteral("--hex"),
                               QStringLiteral("01 03 00 00 00 01 84 0A"), QStringLiteral("--timeout"), QStringLiteral("200ms")};
        const QStringList poll{QStringLiteral("poll"), QStringLiteral("--target"), QStringLiteral("%1"), QStringLiteral("--hex"),
                               QStringLiteral("01 03 00 00 00 01 84 0A"), QStringLiteral("--count"), QStringLiteral("2"),
                               QStringLiteral("--interval"), QStringLiteral("10ms")};
        QTest::newRow("read rts=up") << read << QStringLiteral("rts=up") << false;
        QTest::newRow("read rts=down with delays") << read << QStringLiteral("rts=down&rts_before=1ms&rts_after=500us") << false;
        QTest::newRow("read rs485=kernel") << read << QStringLiteral("rs485=kernel") << true;
        QTest::newRow("send rts=up") << send << QStringLiteral("rts=up") << false;
        QTest::newRow("poll rs485=kernel") << poll << QStringLiteral("rs485=kernel&rts_after=2ms") << true;
    }
    void refusedAtOpen()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, options);
        QFETCH(bool, kernel);
        const QString target = QStringLiteral("rtu://%1?baud=9600&parity=N&").arg(m_device) + options;
        arguments.replaceInStrings(QStringLiteral("%1"), target);
        const CliResult r = runMbscope(arguments, 60000);
        QVERIFY2(r.finished, r.describe());
        QVERIFY2(r.exitCode == 2, r.describe());
        const QString rts = options.section(QLatin1Char('&'), 0, 0);
        const QString expected = kernel ? noKernelMode(m_device) : noModemLines(m_device, rts);
        QVERIFY2(r.errText().contains(expected), r.describe());

        // With --json: one document that carries the same message, as the transaction's problem
        // (send, read: the request could not go) or as the command's error (poll).
        arguments.append(QStringLiteral("--json"));
        const CliResult j = runMbscope(arguments, 60000);
        QVERIFY2(j.exitCode == 2, j.describe());
        const QJsonObject document = j.json();
        const QString said = document.contains(QStringLiteral("error"))
            ? document.value(QStringLiteral("error")).toObject().value(QStringLiteral("message")).toString()
            : document.value(QStringLiteral("problem")).toString();
        QVERIFY2(said.contains(expected), j.describe());
    }

    // A simulated slave on RS-485 drives its transmitter too: on a pty it cannot, and says so.
    void simulatorRefused_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<bool>("kernel");
        QTest::newRow("rts=up") << QStringLiteral("rts=up") << false;
        QTest::newRow("rs485=kernel") << QStringLiteral("rs485=kernel") << true;
    }
    void simulatorRefused()
    {
        QFETCH(QString, options);
        QFETCH(bool, kernel);
        const QString listen = QStringLiteral("rtu://%1?baud=9600&parity=N&").arg(m_device) + options;
        const CliResult r = runMbscope({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"),
                                        QStringLiteral("--listen"), listen, QStringLiteral("--duration"), QStringLiteral("5s")},
                                       60000);
        QVERIFY2(r.finished, r.describe());
        QVERIFY2(r.exitCode == 2, r.describe());
        const QString expected = kernel ? noKernelMode(m_device) : noModemLines(m_device, options);
        QVERIFY2(r.errText().contains(expected), r.describe());
    }

    // Bad values are usage errors that name the option and what was expected.
    void badOptions_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<QString>("message");
        QTest::newRow("rts level") << QStringLiteral("rts=sideways")
                                   << QStringLiteral("rts 'sideways' is not up or down (the RTS level while sending)");
        QTest::newRow("delay alone") << QStringLiteral("rts_after=1ms")
                                     << QStringLiteral("'rts_after' needs rts=up, rts=down or rs485=kernel");
        QTest::newRow("kernel microseconds") << QStringLiteral("rs485=kernel&rts_before=250us")
                                             << QStringLiteral("rts_before 250us is not a whole number of milliseconds: "
                                                               "rs485=kernel hands the driver milliseconds");
    }
    void badOptions()
    {
        QFETCH(QString, options);
        QFETCH(QString, message);
        const QString target = QStringLiteral("rtu://%1?").arg(m_device) + options;
        const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--address"),
                                        QStringLiteral("0")});
        QVERIFY2(r.exitCode == 2, r.describe());
        QVERIFY2(r.errText().contains(target + QStringLiteral(": ") + message), r.describe());
    }
};

QTEST_GUILESS_MAIN(TestCliRs485)
#include "tst_cli_rs485.moc"
