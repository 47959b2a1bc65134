// `mbscope tap` as users run it (issue 27): masters send to the tap's listening URL, the tap
// forwards to a device (the built-in simulator, pymodbus) over another framing, and what the
// master gets is what the device said, function code and data unchanged; what the tap says when
// the device is silent or no route serves a unit; read-only mode; renumbered units; faults on
// the way; both legs in one journal; mbpoll as a real master.
#include "clitest.h"

#include "protocol/adubuilder.h"
#include "transport/linkurl.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

// What one request through `mbscope send --complete --json` got back.
struct Sent {
    CliResult run;
    QString status;
    QByteArray pdu; // of the answer, function code first
};

QByteArray bytesOfHex(const QString &hex)
{
    return QByteArray::fromHex(hex.toLatin1());
}

Sent sendPdu(const QString &url, int unit, const QString &pduHex, const QStringList &more = {})
{
    Sent s;
    s.run = runMbscope(QStringList{QStringLiteral("send"), QStringLiteral("--target"), url, QStringLiteral("--unit"), QString::number(unit),
                                   QStringLiteral("--complete"), QStringLiteral("--hex"), pduHex, QStringLiteral("--json")}
                       + more);
    const QJsonObject o = s.run.json();
    s.status = o.value(QStringLiteral("status")).toString();
    const QString hex = o.value(QStringLiteral("response")).toObject().value(QStringLiteral("hex")).toString();
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    if (parsed.url && !hex.isEmpty())
        s.pdu = AduBuilder::parse(bytesOfHex(hex), parsed.url->framing()).pdu;
    return s;
}

QString pduText(const QByteArray &pdu)
{
    return QString::fromLatin1(pdu.toHex(' ')).toUpper();
}

} // namespace

class TestCliTap : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void forwardsAcrossFramings_data();
    void forwardsAcrossFramings();
    void exceptionsPassUnchanged_data();
    void exceptionsPassUnchanged();
    void silentDevice_data();
    void silentDevice();
    void unroutedUnit();
    void renumbersUnits();
    void readOnlyRefusesWrites();
    void writesPassWhenNotReadOnly();
    void faultsOnTheWay();
    void retriesReadsNeverWrites();
    void retriesPerRoute_data();
    void retriesPerRoute();
    void recordsBothLegs();
    void mbpollThroughTheTap();
    void pymodbusBehindTheTap();
    void badOptions_data();
    void badOptions();

private:
    // Starts a tap; its listening URL through url().
    bool startTap(Background &tap, const QStringList &arguments, QString *error)
    {
        return tap.start(QStringList{QStringLiteral("tap")} + arguments, error);
    }

    Background m_rtuSim; // libmodbus-unit-test's unit 17 on rtu-tcp://
    Background m_tcpSim; // the same on tcp://
    QTemporaryDir m_dir;
};

void TestCliTap::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QString error;
    // Read Input Registers (04) gets no answer from it: a silent device.
    const QString silent = m_dir.filePath(QStringLiteral("silent04.json"));
    QFile faults(silent);
    QVERIFY(faults.open(QIODevice::WriteOnly));
    faults.write(R"({"seed": 1, "rules": [{"name": "silent 04", "kind": "drop", "functions": ["0x04"]}]})");
    faults.close();
    QVERIFY2(m_rtuSim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"),
                             QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet"),
                             QStringLiteral("--faults"), silent},
                            &error),
             qPrintable(error));
    QVERIFY2(m_tcpSim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"),
                             QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                            &error),
             qPrintable(error));
}

void TestCliTap::forwardsAcrossFramings_data()
{
    QTest::addColumn<QString>("listen");
    QTest::addColumn<bool>("rtuTarget");
    QTest::addColumn<QString>("pdu");
    // Read Holding Registers, Read Coils, Read Discrete Inputs, Report Server ID.
    for (const char *pdu : {"03 01 60 00 03", "01 01 30 00 25", "02 01 C4 00 16"}) {
        QTest::addRow("tcp master, rtu-tcp device, %s", pdu) << QStringLiteral("tcp://127.0.0.1:0") << true << QString::fromLatin1(pdu);
        QTest::addRow("rtu-tcp master, tcp device, %s", pdu) << QStringLiteral("rtu-tcp://127.0.0.1:0") << false << QString::fromLatin1(pdu);
    }
    QTest::newRow("udp master, rtu-tcp device") << QStringLiteral("udp://127.0.0.1:0") << true << QStringLiteral("03 01 60 00 0A");
    QTest::newRow("tcp master, tcp device (proxy)") << QStringLiteral("tcp://127.0.0.1:0") << false << QStringLiteral("03 01 60 00 0A");
    QTest::newRow("rtu-tcp both sides (pass-through)") << QStringLiteral("rtu-tcp://127.0.0.1:0") << true << QStringLiteral("03 01 60 00 0A");
    QTest::newRow("ascii-tcp master, rtu-tcp device") << QStringLiteral("ascii-tcp://127.0.0.1:0") << true << QStringLiteral("03 01 60 00 02");
}

void TestCliTap::forwardsAcrossFramings()
{
    QFETCH(QString, listen);
    QFETCH(bool, rtuTarget);
    QFETCH(QString, pdu);
    const QString device = rtuTarget ? m_rtuSim.url() : m_tcpSim.url();
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), listen, QStringLiteral("--target"), device}, &error), qPrintable(error));
    const Sent direct = sendPdu(device, 17, pdu);
    const Sent tapped = sendPdu(tap.url(), 17, pdu);
    QCOMPARE(direct.status, QStringLiteral("ok"));
    QVERIFY2(tapped.status == QLatin1String("ok"), tapped.run.describe());
    QCOMPARE(pduText(tapped.pdu), pduText(direct.pdu));
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("answered (device ")), qPrintable(lines));
    QVERIFY2(lines.contains(QLatin1String("tap: 1 request, 1 forwarded: 1 answered")), qPrintable(lines));
}

void TestCliTap::exceptionsPassUnchanged_data()
{
    QTest::addColumn<QString>("pdu");
    QTest::addColumn<QString>("answer");
    // The device's own exception reaches the master as the device gave it (a gateway that waits
    // for a normal-length answer, or turns 01 into 04, is what this catches).
    QTest::newRow("02 illegal address") << QStringLiteral("03 00 00 00 01") << QStringLiteral("83 02");
    QTest::newRow("02 block past the end") << QStringLiteral("03 01 7E 00 04") << QStringLiteral("83 02");
    QTest::newRow("03 quantity 0") << QStringLiteral("03 01 60 00 00") << QStringLiteral("83 03");
    QTest::newRow("01 unknown function") << QStringLiteral("41 00 00") << QStringLiteral("C1 01");
}

void TestCliTap::exceptionsPassUnchanged()
{
    QFETCH(QString, pdu);
    QFETCH(QString, answer);
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), m_rtuSim.url()}, &error),
             qPrintable(error));
    const Sent direct = sendPdu(m_rtuSim.url(), 17, pdu);
    QCOMPARE(pduText(direct.pdu), answer);
    const Sent tapped = sendPdu(tap.url(), 17, pdu);
    QVERIFY2(tapped.status == QLatin1String("exception"), tapped.run.describe());
    QCOMPARE(pduText(tapped.pdu), answer);
    // At once, not after the response timeout: the exception is complete with its 5 bytes.
    const double latencyUs = tapped.run.json().value(QStringLiteral("latency_us")).toDouble();
    QVERIFY2(latencyUs > 0 && latencyUs < 500000, tapped.run.describe());
}

void TestCliTap::silentDevice_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<bool>("absentTarget");
    QTest::addColumn<QString>("status");
    QTest::addColumn<QString>("answer");
    QTest::newRow("device silent: 0B") << QStringList{} << false << QStringLiteral("exception") << QStringLiteral("84 0B");
    QTest::newRow("target down: 0B") << QStringList{} << true << QStringLiteral("exception") << QStringLiteral("84 0B");
    QTest::newRow("silence asked") << QStringList{QStringLiteral("--no-answer"), QStringLiteral("silence")} << false
                                   << QStringLiteral("timeout") << QString();
}

void TestCliTap::silentDevice()
{
    QFETCH(QStringList, options);
    QFETCH(bool, absentTarget);
    QFETCH(QString, status);
    QFETCH(QString, answer);
    const QString target = absentTarget ? QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort()) : m_rtuSim.url();
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), target,
                                       QStringLiteral("--timeout"), QStringLiteral("200ms")}
                               + options,
                      &error),
             qPrintable(error));
    // The device drops every Read Input Registers (its fault rule).
    const Sent tapped = sendPdu(tap.url(), 17, QStringLiteral("04 01 08 00 01"));
    QVERIFY2(tapped.status == status, tapped.run.describe());
    QCOMPARE(pduText(tapped.pdu), answer);
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(absentTarget ? QLatin1String("1 link error,") : QLatin1String("1 without answer")), qPrintable(lines));
}

void TestCliTap::unroutedUnit()
{
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                            QStringLiteral("17=") + m_rtuSim.url()},
                      &error),
             qPrintable(error));
    const Sent other = sendPdu(tap.url(), 5, QStringLiteral("03 01 60 00 01"));
    QVERIFY2(other.status == QLatin1String("exception"), other.run.describe());
    QCOMPARE(pduText(other.pdu), QStringLiteral("83 0A"));
    const Sent routed = sendPdu(tap.url(), 17, QStringLiteral("03 01 60 00 01"));
    QVERIFY2(routed.status == QLatin1String("ok"), routed.run.describe());
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("route unit 17 -> ")), qPrintable(lines));
    QVERIFY2(lines.contains(QLatin1String("1 without route")), qPrintable(lines));
}

void TestCliTap::renumbersUnits()
{
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                            QStringLiteral("1:17=") + m_rtuSim.url()},
                      &error),
             qPrintable(error));
    const Sent direct = sendPdu(m_rtuSim.url(), 17, QStringLiteral("03 01 60 00 03"));
    const Sent tapped = sendPdu(tap.url(), 1, QStringLiteral("03 01 60 00 03"));
    QVERIFY2(tapped.status == QLatin1String("ok"), tapped.run.describe());
    QCOMPARE(pduText(tapped.pdu), pduText(direct.pdu));
    // The master's answer carries the unit it asked (1), not the device's 17.
    const QString hex = tapped.run.json().value(QStringLiteral("response")).toObject().value(QStringLiteral("hex")).toString();
    QCOMPARE(bytesOfHex(hex).at(6), char(1));
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("route unit 1 as 17 -> ")), qPrintable(lines));
}

void TestCliTap::readOnlyRefusesWrites()
{
    // A simulator of its own: the write must not reach it.
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"), QStringLiteral("--listen"),
                        QStringLiteral("rtu-tcp://127.0.0.1:0")},
                       &error),
             qPrintable(error));
    Background tap;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), sim.url(),
                            QStringLiteral("--read-only")},
                      &error),
             qPrintable(error));
    const Sent before = sendPdu(sim.url(), 17, QStringLiteral("03 01 60 00 01"));
    const Sent write = sendPdu(tap.url(), 17, QStringLiteral("06 01 60 12 34"));
    QVERIFY2(write.status == QLatin1String("exception"), write.run.describe());
    QCOMPARE(pduText(write.pdu), QStringLiteral("86 01"));
    const Sent restart = sendPdu(tap.url(), 17, QStringLiteral("08 00 01 00 00"));
    QCOMPARE(pduText(restart.pdu), QStringLiteral("88 01"));
    const Sent read = sendPdu(tap.url(), 17, QStringLiteral("03 01 60 00 01"));
    QVERIFY2(read.status == QLatin1String("ok"), read.run.describe());
    QCOMPARE(pduText(read.pdu), pduText(before.pdu));
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("2 writes refused")), qPrintable(lines));
    QVERIFY2(lines.contains(QLatin1String("exception 01 Illegal Function (read-only: Write Single Register (0x06) address 0x0160 quantity 1 not forwarded)")), qPrintable(lines));
    // The device saw the read only: no write, no restart.
    const QString device = QString::fromUtf8(sim.stop());
    QVERIFY2(!device.contains(QLatin1String("06 Write Single Register")) && !device.contains(QLatin1String("08 Diagnostics")),
             qPrintable(device));
}

void TestCliTap::writesPassWhenNotReadOnly()
{
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"), QStringLiteral("--listen"),
                        QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    Background tap;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), sim.url()}, &error),
             qPrintable(error));
    const Sent write = sendPdu(tap.url(), 17, QStringLiteral("06 01 60 12 34"));
    QVERIFY2(write.status == QLatin1String("ok"), write.run.describe());
    QCOMPARE(pduText(write.pdu), QStringLiteral("06 01 60 12 34"));
    const Sent read = sendPdu(sim.url(), 17, QStringLiteral("03 01 60 00 01"));
    QCOMPARE(pduText(read.pdu), QStringLiteral("03 02 12 34"));
}

void TestCliTap::faultsOnTheWay()
{
    const QString faults = m_dir.filePath(QStringLiteral("faults.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 1, "rules": [{"name": "busy", "kind": "exception", "code": 6, "functions": ["0x03"]}]})");
    file.close();
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), m_rtuSim.url(),
                            QStringLiteral("--faults"), faults},
                      &error),
             qPrintable(error));
    const Sent read = sendPdu(tap.url(), 17, QStringLiteral("03 01 60 00 01"));
    QVERIFY2(read.status == QLatin1String("exception"), read.run.describe());
    QCOMPARE(pduText(read.pdu), QStringLiteral("83 06"));
    const Sent coils = sendPdu(tap.url(), 17, QStringLiteral("01 01 30 00 08"));
    QVERIFY2(coils.status == QLatin1String("ok"), coils.run.describe());
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("changed by fault (busy)")), qPrintable(lines));
}

void TestCliTap::retriesReadsNeverWrites()
{
    // A device that drops every 04 and 06: the tap tries a read three times (--retries 2) but
    // sends the master's write once, since the device may have acted on it.
    const QString faults = m_dir.filePath(QStringLiteral("drops.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 1, "rules": [{"kind": "drop", "functions": ["0x04", "0x06"]}]})");
    file.close();
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"), QStringLiteral("--listen"),
                        QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults},
                       &error),
             qPrintable(error));
    Background tap;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), sim.url(),
                            QStringLiteral("--timeout"), QStringLiteral("100ms"), QStringLiteral("--retries"), QStringLiteral("2")},
                      &error),
             qPrintable(error));
    QCOMPARE(sendPdu(tap.url(), 17, QStringLiteral("04 01 08 00 01"), {QStringLiteral("--timeout"), QStringLiteral("2s")}).status,
             QStringLiteral("exception"));
    QCOMPARE(sendPdu(tap.url(), 17, QStringLiteral("06 01 60 00 07"), {QStringLiteral("--timeout"), QStringLiteral("2s")}).status,
             QStringLiteral("exception"));
    tap.stop();
    const QString device = QString::fromUtf8(sim.stop());
    QVERIFY2(device.count(QLatin1String("04 Read Input Registers")) == 3, qPrintable(device));
    QVERIFY2(device.count(QLatin1String("06 Write Single Register")) == 1, qPrintable(device));
}

// A route's URL gives its own retries: the master's unit 5 reaches the device's 17 with none
// (an absent unit must not hold the line), unit 17 straight through with the tap's 2.
void TestCliTap::retriesPerRoute_data()
{
    QTest::addColumn<int>("unit");
    QTest::addColumn<int>("sent");
    QTest::newRow("routed with retries=0") << 5 << 1;
    QTest::newRow("through --target, --retries 2") << 17 << 3;
}

void TestCliTap::retriesPerRoute()
{
    QFETCH(int, unit);
    QFETCH(int, sent);
    const QString faults = m_dir.filePath(QStringLiteral("drops04.json"));
    QVERIFY(writeFile(faults, R"({"seed": 1, "rules": [{"kind": "drop", "functions": ["0x04"]}]})"));
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("libmodbus-unit-test"), QStringLiteral("--listen"),
                        QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults},
                       &error),
             qPrintable(error));
    Background tap;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                            QStringLiteral("5:17=%1?retries=0").arg(sim.url()), QStringLiteral("--target"), sim.url(),
                            QStringLiteral("--timeout"), QStringLiteral("100ms"), QStringLiteral("--retries"), QStringLiteral("2")},
                      &error),
             qPrintable(error));
    QCOMPARE(sendPdu(tap.url(), quint8(unit), QStringLiteral("04 01 08 00 01"), {QStringLiteral("--timeout"), QStringLiteral("2s")}).status,
             QStringLiteral("exception"));
    const QString lines = QString::fromUtf8(tap.stop());
    QVERIFY2(lines.contains(QLatin1String("(retries 0)")), qPrintable(lines));
    const QString device = QString::fromUtf8(sim.stop());
    QVERIFY2(device.count(QLatin1String("04 Read Input Registers")) == sent, qPrintable(device));
}

void TestCliTap::recordsBothLegs()
{
    const QString journal = m_dir.filePath(QStringLiteral("tap.mbj"));
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), m_rtuSim.url(),
                            QStringLiteral("--record"), journal, QStringLiteral("--force")},
                      &error),
             qPrintable(error));
    for (int i = 0; i < 5; ++i)
        QCOMPARE(sendPdu(tap.url(), 17, QStringLiteral("03 01 60 00 02")).status, QStringLiteral("ok"));
    QCOMPARE(sendPdu(tap.url(), 17, QStringLiteral("03 00 00 00 01")).status, QStringLiteral("exception"));
    const QString tapUrl = tap.url();
    tap.stop();
    const CliResult analyzed = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    // 1: the exception (asked for on purpose) is a failed transaction, on each leg.
    QVERIFY2(analyzed.exitCode == 1, analyzed.describe());
    const QJsonObject o = analyzed.json();
    // Both legs, each paired on its own: the masters' (one conversation per connection of
    // `mbscope send`, to the tap's port) and the device's (one connection, to the simulator).
    const QString tapServer = QStringLiteral("127.0.0.1:%1").arg(LinkUrl::parse(tapUrl).url->port);
    const QString deviceServer = QStringLiteral("127.0.0.1:%1").arg(LinkUrl::parse(m_rtuSim.url()).url->port);
    int masterSide = 0;
    int deviceSide = 0;
    int deviceConversations = 0;
    for (const QJsonValue &v : o.value(QStringLiteral("conversations")).toArray()) {
        const QJsonObject c = v.toObject();
        const int transactions = c.value(QStringLiteral("transactions")).toInt();
        QCOMPARE(c.value(QStringLiteral("unmatched_responses")).toInt(), 0);
        if (c.value(QStringLiteral("server")).toString() == tapServer) {
            masterSide += transactions;
            QCOMPARE(c.value(QStringLiteral("framing")).toString(), QStringLiteral("tcp"));
        } else if (c.value(QStringLiteral("server")).toString() == deviceServer) {
            deviceSide += transactions;
            ++deviceConversations;
            QCOMPARE(c.value(QStringLiteral("framing")).toString(), QStringLiteral("rtu"));
        }
    }
    QVERIFY2(masterSide == 6 && deviceSide == 6 && deviceConversations == 1, analyzed.out);
    QVERIFY2(o.value(QStringLiteral("ok")).toInt() == 10, analyzed.out);
    QVERIFY2(o.value(QStringLiteral("exceptions")).toInt() == 2, analyzed.out);
    QVERIFY2(o.value(QStringLiteral("timeouts")).toInt() == 0, analyzed.out);
    // A table per leg: the masters' requests the tap answered, and those it sent the device. A
    // master's latency holds the device's (arrival to answer written encloses write to answer
    // read), so the answered leg's is never the shorter.
    const QJsonArray legs = o.value(QStringLiteral("legs")).toArray();
    QVERIFY2(legs.size() == 2, analyzed.out);
    const QJsonObject answered = legs.at(0).toObject();
    const QJsonObject sent = legs.at(1).toObject();
    QCOMPARE(answered.value(QStringLiteral("leg")).toString(), QStringLiteral("answered"));
    QCOMPARE(sent.value(QStringLiteral("leg")).toString(), QStringLiteral("sent"));
    QCOMPARE(answered.value(QStringLiteral("count")).toInt(), 6);
    QCOMPARE(sent.value(QStringLiteral("count")).toInt(), 6);
    const double answeredMin = answered.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("min")).toDouble();
    const double sentMin = sent.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("min")).toDouble();
    QVERIFY2(answeredMin >= sentMin && sentMin > 0, analyzed.out);
    const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
    QVERIFY2(text.outText().contains(QLatin1String("answered (masters)")) && text.outText().contains(QLatin1String("sent (devices)")),
             text.describe());
}

void TestCliTap::mbpollThroughTheTap()
{
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        QSKIP("mbpoll is not installed (scripts/install-deps.sh --tests installs it)");
    Background tap;
    QString error;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), m_rtuSim.url()}, &error),
             qPrintable(error));
    const quint16 port = LinkUrl::parse(tap.url()).url->port;
    const Sent direct = sendPdu(m_rtuSim.url(), 17, QStringLiteral("03 01 60 00 03"));
    QProcess p;
    // mbpoll counts references from 1: 353 is PDU address 0x160.
    p.start(mbpoll, {QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-a"), QStringLiteral("17"), QStringLiteral("-r"),
                     QStringLiteral("353"), QStringLiteral("-c"), QStringLiteral("3"), QStringLiteral("-t"), QStringLiteral("4:hex"),
                     QStringLiteral("-1"), QStringLiteral("-p"), QString::number(port), QStringLiteral("127.0.0.1")});
    QVERIFY(p.waitForFinished(30000));
    const QString text = QString::fromUtf8(p.readAllStandardOutput());
    QVERIFY2(p.exitCode() == 0, qPrintable(text + QString::fromUtf8(p.readAllStandardError())));
    // "[353]: 	0x022B": each register as the device holds it.
    for (int i = 0; i < 3; ++i) {
        const QString value = QStringLiteral("0x") + QString::fromLatin1(direct.pdu.mid(2 + 2 * i, 2).toHex()).toUpper();
        QVERIFY2(text.contains(QStringLiteral("[%1]:").arg(353 + i)) && text.contains(value), qPrintable(text + value));
    }
}

void TestCliTap::pymodbusBehindTheTap()
{
    PymodbusTarget device;
    QString error;
    if (!device.start(QStringLiteral("rtu-tcp"), &error))
        QSKIP(qPrintable(error));
    Background tap;
    QVERIFY2(startTap(tap, {QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"), device.url()}, &error),
             qPrintable(error));
    const Sent tapped = sendPdu(tap.url(), 1, QStringLiteral("03 00 00 00 04"));
    QVERIFY2(tapped.status == QLatin1String("ok"), tapped.run.describe());
    QCOMPARE(tapped.pdu.size(), 10);
    for (int i = 0; i < 4; ++i)
        QCOMPARE(quint16(quint8(tapped.pdu.at(2 + 2 * i)) << 8 | quint8(tapped.pdu.at(3 + 2 * i))), holdingRegister(i));
}

void TestCliTap::badOptions_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no listen") << QStringList{QStringLiteral("--target"), QStringLiteral("tcp://127.0.0.1:502")}
                               << QStringLiteral("--listen URL is required");
    QTest::newRow("no target") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}
                               << QStringLiteral("--target URL or --route UNITS=URL is required");
    QTest::newRow("route without url") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                                                      QStringLiteral("1-4")}
                                       << QStringLiteral("--route '1-4': expected UNITS[:DEVICE_UNIT]=URL");
    QTest::newRow("unit above 255") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                                                   QStringLiteral("1-300=tcp://127.0.0.1:502")}
                                    << QStringLiteral("unit 300 is outside 0-255");
    QTest::newRow("backwards range") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                                                    QStringLiteral("9-3=tcp://127.0.0.1:502")}
                                     << QStringLiteral("the range 9-3 runs backwards");
    QTest::newRow("renumbered past 255") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                                                        QStringLiteral("1-10:250=tcp://127.0.0.1:502")}
                                         << QStringLiteral("run past 255");
    QTest::newRow("bad route retries") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--route"),
                                                      QStringLiteral("1=tcp://127.0.0.1:502?timeout=1s&retries=many")}
                                       << QStringLiteral("retries 'many' is not a count from 0 to 100");
    QTest::newRow("target retries above 100") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                                             QStringLiteral("tcp://127.0.0.1:502?retries=101")}
                                              << QStringLiteral("--target 'tcp://127.0.0.1:502?retries=101': retries '101' is not a count from 0 to 100");
    QTest::newRow("bad target url") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                                   QStringLiteral("tcp://127.0.0.1:99999")}
                                    << QStringLiteral("--target ");
    QTest::newRow("bad no-answer") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                                  QStringLiteral("tcp://127.0.0.1:502"), QStringLiteral("--no-answer"), QStringLiteral("never")}
                                   << QStringLiteral("--no-answer 'never': expected auto, exception or silence");
    QTest::newRow("refuse without read-only") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                                             QStringLiteral("tcp://127.0.0.1:502"), QStringLiteral("--refuse"), QStringLiteral("silence")}
                                              << QStringLiteral("without --read-only every write is forwarded");
    QTest::newRow("bad timeout") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                                QStringLiteral("tcp://127.0.0.1:502"), QStringLiteral("--timeout"), QStringLiteral("soon")}
                                 << QStringLiteral("--timeout: ");
    QTest::newRow("pipeline 0") << QStringList{QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                                               QStringLiteral("tcp://127.0.0.1:502"), QStringLiteral("--pipeline"), QStringLiteral("0")}
                                << QStringLiteral("--pipeline '0': expected a number from 1 to 64");
}

void TestCliTap::badOptions()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliResult r = runMbscope(QStringList{QStringLiteral("tap")} + arguments, 30000);
    QVERIFY2(r.finished && r.exitCode == 2, r.describe());
    QVERIFY2(r.errText().contains(message), r.describe());
}

QTEST_GUILESS_MAIN(TestCliTap)
#include "tst_cli_tap.moc"
