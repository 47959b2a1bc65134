// Verdicts and exit statuses as users meet them (issue 19, items 4-9 and 11), through the mbscope
// executable against `mbscope simulate --profile rosrao-gamma` on loopback (RTU over TCP):
// a request mbscope judges malformed is never a broadcast; function code 0 is an error; an ASCII
// frame given as the hex of its characters is decoded; frames beyond the ADU maximum of their
// framing are said to be; a Modicon reference typed as an address gets a hint; output files are
// checked before the first request; --json failures are a JSON error object on standard output.

#include "clitest.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

// Write Multiple Registers (0x10) of n registers at 0: a PDU of 6 + 2n bytes (V1.1b3, 6.12).
QByteArray writeRegistersPdu(int n)
{
    QByteArray pdu = QByteArray::fromHex("100000");
    pdu.append(char(n >> 8)).append(char(n & 0xFF)).append(char(quint8(2 * n)));
    pdu.append(QByteArray(2 * n, '\x01'));
    return pdu;
}

// The hex of each character, as a serial analyser shows an ASCII frame: "3A 30 31 ... 0D 0A".
QString charactersAsHex(const QByteArray &frame)
{
    return HexText::format(frame);
}

} // namespace

class TestCliVerdicts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void malformedRequestIsNoBroadcast();
    void functionCodeZeroIsAnError_data();
    void functionCodeZeroIsAnError();
    void asciiFrameAsHexOfItsCharacters();
    void aduMaximum_data();
    void aduMaximum();
    void modiconReferenceHint_data();
    void modiconReferenceHint();
    void outputsCheckedBeforeTheFirstRequest_data();
    void outputsCheckedBeforeTheFirstRequest();
    void jsonErrorObject_data();
    void jsonErrorObject();
    void broadcastReadIsFlagged_data();
    void broadcastReadIsFlagged();
    void broadcastReadIsRefusedOrSaid();
    void broadcastWriteIsSentNotAnswered();
    void pollNumbersItsRequests();

private:
    // The simulator on Modbus/TCP, for the tests that need MBAP (started by the first).
    bool startTcpSimulator();

    Background m_sim;
    Background m_tcpSim;
    QString m_target; // the simulator, RTU over TCP, with a short response timeout
    QTemporaryDir m_dir;
};

void TestCliVerdicts::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QString error;
    QVERIFY2(m_sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                          QStringLiteral("rtu-tcp://127.0.0.1:0")},
                         &error),
             qPrintable(error));
    m_target = m_sim.url() + QStringLiteral("?timeout=300");
}

bool TestCliVerdicts::startTcpSimulator()
{
    QString error;
    if (m_tcpSim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0")},
                       &error))
        return true;
    qWarning("%s", qPrintable(error));
    return false;
}

void TestCliVerdicts::malformedRequestIsNoBroadcast()
{
    // MBAP bytes sent to an RTU link: read as RTU, unit 0 (the transaction id's high byte) and a
    // wrong CRC. mbscope says the request is malformed: no broadcast, exit 1.
    const CliResult r = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_target, QStringLiteral("--hex"),
                                    QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 01")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData());
    QVERIFY2(!r.outText().contains(QStringLiteral("RESULT broadcast")), r.describe().constData());
    QVERIFY2(!r.outText().contains(QStringLiteral("no answer expected")), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("RESULT the request itself is malformed, ")), r.describe().constData());
    const CliResult json = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_target, QStringLiteral("--hex"),
                                       QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 01"), QStringLiteral("--json")});
    QVERIFY2(json.exitCode == 1, json.describe().constData());
    QVERIFY(json.json().value(QStringLiteral("status")).toString() != QStringLiteral("broadcast"));
    QVERIFY2(json.json().value(QStringLiteral("request_problem")).toString().startsWith(QStringLiteral("the request itself is malformed, 3 error(s)")),
             json.describe().constData());

    // A well-formed broadcast (unit 0, CRC right) is still one: sent, no answer expected, exit 0.
    const CliResult broadcast = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_target, QStringLiteral("--hex"),
                                            QStringLiteral("00 06 00 7D 00 FA 98 40")});
    QVERIFY2(broadcast.finished && broadcast.exitCode == 0, broadcast.describe().constData());
    QVERIFY2(broadcast.outText().contains(QStringLiteral("RESULT broadcast: sent to every unit, no answer expected")), broadcast.describe().constData());
}

void TestCliVerdicts::functionCodeZeroIsAnError_data()
{
    // MODBUS Application Protocol V1.1b3, 4.1: valid function codes are 1-255; 0 is none.
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("pdu 00") << QStringList{QStringLiteral("--framing"), QStringLiteral("pdu"), QStringLiteral("00 00 01")}
                            << QStringLiteral("function code 0 is not valid: valid codes are 1-255 (MODBUS Application Protocol V1.1b3, 4.1)");
    QTest::newRow("rtu 01 00") << QStringList{HexText::format(AduBuilder::rtu(QByteArray::fromHex("000001"), 1))}
                               << QStringLiteral("function code 0 is not valid");
    QTest::newRow("tcp exception 80") << QStringList{QStringLiteral("--framing"), QStringLiteral("tcp"), QStringLiteral("--direction"),
                                                     QStringLiteral("response"), HexText::format(AduBuilder::mbap(QByteArray::fromHex("8001"), 1, 1))}
                                      << QStringLiteral("exception for function 0x00, which is not a valid function code");
}

void TestCliVerdicts::functionCodeZeroIsAnError()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliResult r = runMbscope(QStringList{QStringLiteral("decode")} + arguments);
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData());
    QVERIFY2(r.outText().contains(message), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("Invalid function code")), r.describe().constData());
}

void TestCliVerdicts::asciiFrameAsHexOfItsCharacters()
{
    const QByteArray frame = AduBuilder::ascii(QByteArray::fromHex("0300790016"), 1); // ":0103007900166D\r\n"
    const QString hex = charactersAsHex(frame);
    QVERIFY(hex.startsWith(QStringLiteral("3A 30 31 30 33")));
    for (const QStringList &framing : {QStringList{QStringLiteral("--framing"), QStringLiteral("ascii")}, QStringList{}}) {
        const CliResult r = runMbscope(QStringList{QStringLiteral("decode")} + framing + QStringList{hex});
        QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
        QVERIFY2(r.outText().contains(QStringLiteral("Read Holding Registers")), r.describe().constData());
        QVERIFY2(r.outText().contains(QStringLiteral("(valid)")), r.describe().constData()); // the LRC
    }
    // The same as the request a response is checked against.
    const QByteArray answer = AduBuilder::ascii(QByteArray::fromHex("0302041A"), 1);
    const CliResult withRequest = runMbscope({QStringLiteral("decode"), QStringLiteral("--framing"), QStringLiteral("ascii"), QStringLiteral("--request"),
                                              charactersAsHex(AduBuilder::ascii(QByteArray::fromHex("0300790001"), 1)), charactersAsHex(answer)});
    QVERIFY2(withRequest.finished && withRequest.exitCode == 0, withRequest.describe().constData());
    QVERIFY2(withRequest.outText().contains(QStringLiteral("1050")), withRequest.describe().constData());
}

void TestCliVerdicts::aduMaximum_data()
{
    // Serial Line V1.02, 2.5.1.1: an RTU ADU is at most 256 bytes; MBAP (Messaging on TCP/IP
    // V1.0b, 4.1) at most 260; an ASCII frame (Serial Line V1.02, 2.5.2.1) at most 513 characters.
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("length");
    QTest::addColumn<bool>("tooLong");
    QTest::addColumn<QString>("message");
    const QByteArray largest = writeRegistersPdu(123); // 252 bytes: the largest write (V1.1b3, 6.12)
    const QByteArray large = writeRegistersPdu(196);   // 398 bytes
    const auto row = [](const char *name, const QString &framing, const QByteArray &frame, bool tooLong, const QString &message) {
        const QString given = framing == QLatin1String("ascii") ? QString::fromLatin1(frame.trimmed()) : HexText::format(frame);
        QTest::newRow(name) << QStringList{QStringLiteral("--framing"), framing, QStringLiteral("--direction"), QStringLiteral("request"), given}
                            << int(frame.size()) << tooLong << message;
    };
    row("rtu 255", QStringLiteral("rtu"), AduBuilder::rtu(largest, 1), false, QString());
    row("rtu 401", QStringLiteral("rtu"), AduBuilder::rtu(large, 1), true,
        QStringLiteral("the frame is 401 bytes; an RTU ADU is at most 256 bytes (MODBUS over Serial Line V1.02, 2.5.1.1): 145 bytes too many"));
    row("mbap 259", QStringLiteral("tcp"), AduBuilder::mbap(largest, 1, 1), false, QString());
    row("mbap 405", QStringLiteral("tcp"), AduBuilder::mbap(large, 1, 1), true,
        QStringLiteral("the frame is 405 bytes; an MBAP ADU is at most 260 bytes (MODBUS Messaging on TCP/IP V1.0b, 4.1): 145 bytes too many"));
    row("ascii 511", QStringLiteral("ascii"), AduBuilder::ascii(largest, 1), false, QString());
    row("ascii 803", QStringLiteral("ascii"), AduBuilder::ascii(large, 1), true,
        QStringLiteral("the frame is 803 characters; an ASCII frame is at most 513 characters (MODBUS over Serial Line V1.02, 2.5.2.1): 290 characters too many"));
}

void TestCliVerdicts::aduMaximum()
{
    QFETCH(QStringList, arguments);
    QFETCH(bool, tooLong);
    QFETCH(QString, message);
    const CliResult r = runMbscope(QStringList{QStringLiteral("decode")} + arguments);
    QVERIFY2(r.finished, r.describe().constData());
    if (!tooLong) {
        QVERIFY2(r.exitCode == 0, r.describe().constData());
        QVERIFY2(!r.outText().contains(QStringLiteral("Frame too long")), r.describe().constData());
        return;
    }
    QVERIFY2(r.exitCode == 1, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("Frame too long")), r.describe().constData());
    QVERIFY2(r.outText().contains(message), r.describe().constData());
}

void TestCliVerdicts::modiconReferenceHint_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("hint");
    QTest::addColumn<bool>("onStdout");
    // Answered with exception 02 by the device (it has no register 40122).
    QTest::newRow("read 40122") << QStringList{QStringLiteral("read"), QStringLiteral("--address"), QStringLiteral("40122")} << 1
                                << QStringLiteral("HINT 40122 looks like a Modicon reference; its PDU address is 121 (0x0079): give --address 121")
                                << true;
    QTest::newRow("write 40126") << QStringList{QStringLiteral("write"), QStringLiteral("--address"), QStringLiteral("40126"),
                                                QStringLiteral("--registers"), QStringLiteral("250")}
                                 << 1 << QStringLiteral("HINT 40126 looks like a Modicon reference; its PDU address is 125 (0x007D): give --address 125")
                                 << true;
    // Refused by mbscope (beyond 65535): the six-digit form.
    QTest::newRow("read 400122") << QStringList{QStringLiteral("read"), QStringLiteral("--address"), QStringLiteral("400122")} << 2
                                 << QStringLiteral("400122 looks like a Modicon reference; its PDU address is 121 (0x0079): give --address 121")
                                 << false;
    // An ordinary exception 02 says nothing of references.
    QTest::newRow("read 512") << QStringList{QStringLiteral("read"), QStringLiteral("--address"), QStringLiteral("512")} << 1 << QString() << true;
}

void TestCliVerdicts::modiconReferenceHint()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, hint);
    QFETCH(bool, onStdout);
    const CliResult r = runMbscope(arguments + QStringList{QStringLiteral("--target"), m_target});
    QVERIFY2(r.finished && r.exitCode == exitCode, r.describe().constData());
    if (hint.isEmpty()) {
        QVERIFY2(!r.outText().contains(QStringLiteral("Modicon reference;")), r.describe().constData());
        return;
    }
    QVERIFY2((onStdout ? r.outText() : r.errText()).contains(hint), r.describe().constData());
    if (onStdout) {
        const CliResult json = runMbscope(arguments + QStringList{QStringLiteral("--target"), m_target, QStringLiteral("--json")});
        const QJsonObject o = json.json();
        const QString given = o.contains(QStringLiteral("hint"))
                                  ? o.value(QStringLiteral("hint")).toString()
                                  : o.value(QStringLiteral("transactions")).toArray().at(0).toObject().value(QStringLiteral("hint")).toString();
        QCOMPARE(QStringLiteral("HINT ") + given, hint);
    }
}

void TestCliVerdicts::outputsCheckedBeforeTheFirstRequest_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString missing = m_dir.filePath(QStringLiteral("missing"));
    QTest::newRow("poll --histogram jpg") << QStringList{QStringLiteral("poll"), QStringLiteral("--histogram"), m_dir.filePath(QStringLiteral("x.jpg"))}
                                          << QStringLiteral("--histogram: '%1': the plot's format comes from the file name").arg(m_dir.filePath(QStringLiteral("x.jpg")));
    QTest::newRow("sweep --histogram jpg") << QStringList{QStringLiteral("sweep"), QStringLiteral("--intervals"), QStringLiteral("0,10ms"),
                                                          QStringLiteral("--histogram"), m_dir.filePath(QStringLiteral("x.jpg"))}
                                           << QStringLiteral("the plot's format comes from the file name");
    QTest::newRow("poll --histogram no folder") << QStringList{QStringLiteral("poll"), QStringLiteral("--histogram"), missing + QStringLiteral("/x.png")}
                                                << QStringLiteral("--histogram: cannot write %1/x.png: the folder does not exist").arg(missing);
    QTest::newRow("poll --csv no folder") << QStringList{QStringLiteral("poll"), QStringLiteral("--csv"), missing + QStringLiteral("/x.csv")}
                                          << QStringLiteral("--csv: cannot write %1/x.csv: the folder does not exist").arg(missing);
    QTest::newRow("poll --record no folder") << QStringList{QStringLiteral("poll"), QStringLiteral("--record"), missing + QStringLiteral("/x.mbscope.journal")}
                                             << QStringLiteral("--record: cannot write %1/x.mbscope.journal: the folder does not exist").arg(missing);
}

void TestCliVerdicts::outputsCheckedBeforeTheFirstRequest()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    // Two seconds of polling that would be lost: refused at once, nothing polled.
    const CliResult r = runMbscope(arguments + QStringList{QStringLiteral("--target"), m_target, QStringLiteral("--count"), QStringLiteral("20"),
                                                           QStringLiteral("--address"), QStringLiteral("0x79")});
    QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(message), r.describe().constData());
    QVERIFY2(r.out.isEmpty(), r.describe().constData()); // no statistics: not one request went out
}

void TestCliVerdicts::jsonErrorObject_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("command");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::newRow("poll bad count") << QStringList{QStringLiteral("poll"), QStringLiteral("--json"), QStringLiteral("--target"), m_target,
                                                   QStringLiteral("--count"), QStringLiteral("x")}
                                    << QStringLiteral("poll") << 2 << QStringLiteral("--count");
    QTest::newRow("decode bad hex") << QStringList{QStringLiteral("decode"), QStringLiteral("--json"), QStringLiteral("01 0G")}
                                    << QStringLiteral("decode") << 2 << QStringLiteral("mbscope decode: frame: ");
    QTest::newRow("read unknown option") << QStringList{QStringLiteral("read"), QStringLiteral("--json"), QStringLiteral("--adress"), QStringLiteral("1")}
                                         << QStringLiteral("read") << 2 << QStringLiteral("adress");
    QTest::newRow("simulate rejects --json") << QStringList{QStringLiteral("simulate"), QStringLiteral("--json")}
                                             << QStringLiteral("simulate") << 2 << QStringLiteral("Unknown option 'json'");
    QTest::newRow("export rejects --json") << QStringList{QStringLiteral("export"), QStringLiteral("x.pcapng"), QStringLiteral("--json")}
                                           << QStringLiteral("export") << 2 << QStringLiteral("Unknown option 'json'");
}

void TestCliVerdicts::jsonErrorObject()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, command);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.finished && r.exitCode == exitCode, r.describe().constData());
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(r.out, &parseError);
    QVERIFY2(parseError.error == QJsonParseError::NoError && document.isObject(), r.describe().constData());
    const QJsonObject error = document.object().value(QStringLiteral("error")).toObject();
    QCOMPARE(error.value(QStringLiteral("command")).toString(), command);
    QCOMPARE(error.value(QStringLiteral("exit_status")).toInt(), exitCode);
    QVERIFY2(error.value(QStringLiteral("message")).toString().contains(message), r.describe().constData());
    // Standard error says it as before, in plain text.
    QVERIFY2(r.errText().contains(message), r.describe().constData());
}

// Issue 26, item 3: a read to unit 0 on a serial framing is a broadcast no unit answers, so its
// data can never come back (MODBUS over Serial Line V1.02, 2.1: broadcasts are writes only).
// decode says so in its verdict (exit 1); a write to unit 0 stays a valid broadcast, and unit 0
// on Modbus/TCP is no broadcast (Messaging on TCP/IP V1.0b, 4.4.1.1).
void TestCliVerdicts::broadcastReadIsFlagged_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<bool>("flagged");
    QTest::newRow("rtu read") << QStringList{HexText::format(AduBuilder::rtu(QByteArray::fromHex("0300790001"), 0))} << 1 << true;
    QTest::newRow("rtu read coils") << QStringList{HexText::format(AduBuilder::rtu(QByteArray::fromHex("0100000008"), 0))} << 1 << true;
    QTest::newRow("ascii read") << QStringList{QStringLiteral("--framing"), QStringLiteral("ascii"),
                                               QString::fromLatin1(AduBuilder::ascii(QByteArray::fromHex("0400000002"), 0)).trimmed()}
                                << 1 << true;
    QTest::newRow("rtu write single") << QStringList{HexText::format(AduBuilder::rtu(QByteArray::fromHex("06007D00FA"), 0))} << 0 << false;
    QTest::newRow("rtu write multiple") << QStringList{HexText::format(AduBuilder::rtu(QByteArray::fromHex("1000000001020007"), 0))} << 0 << false;
    QTest::newRow("tcp read unit 0") << QStringList{QStringLiteral("--framing"), QStringLiteral("tcp"),
                                                    HexText::format(AduBuilder::mbap(QByteArray::fromHex("0300790001"), 0, 1))}
                                     << 0 << false;
}

void TestCliVerdicts::broadcastReadIsFlagged()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(bool, flagged);
    const CliResult r = runMbscope(QStringList{QStringLiteral("decode")} + arguments);
    QVERIFY2(r.finished && r.exitCode == exitCode, r.describe().constData());
    const QString why = QStringLiteral("broadcasts are for writes only (MODBUS over Serial Line V1.02, 2.1)");
    QCOMPARE(r.outText().contains(why), flagged);
    QCOMPARE(r.outText().contains(QStringLiteral("valid frame")), !flagged);
    const CliResult json = runMbscope(QStringList{QStringLiteral("decode"), QStringLiteral("--json")} + arguments);
    QVERIFY2(json.finished && json.exitCode == exitCode, json.describe().constData());
    QCOMPARE(json.outText().contains(why), flagged);
}

// send sends what was typed and says the read cannot be answered (exit 1, not a success);
// read refuses --unit 0 on a serial framing before anything is sent.
void TestCliVerdicts::broadcastReadIsRefusedOrSaid()
{
    const QString hex = HexText::format(AduBuilder::rtu(QByteArray::fromHex("0300790001"), 0));
    const CliResult sent = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_target, QStringLiteral("--hex"), hex});
    QVERIFY2(sent.finished && sent.exitCode == 1, sent.describe().constData());
    QVERIFY2(sent.outText().contains(QStringLiteral("REQUEST to ")), sent.describe().constData());
    QVERIFY2(sent.outText().contains(QStringLiteral("RESULT the read cannot be answered: ")), sent.describe().constData());
    QVERIFY2(!sent.outText().contains(QStringLiteral("malformed")), sent.describe().constData());
    const CliResult json = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), m_target, QStringLiteral("--hex"), hex,
                                       QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 1, json.describe().constData());
    QVERIFY2(json.json().value(QStringLiteral("request_problem")).toString().startsWith(QStringLiteral("the read cannot be answered: ")),
             json.describe().constData());

    const CliResult polled = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), m_target, QStringLiteral("--count"), QStringLiteral("2"),
                                         QStringLiteral("--hex"), hex});
    QVERIFY2(polled.finished && polled.exitCode == 1, polled.describe().constData());
    QVERIFY2(polled.errText().contains(QStringLiteral(": the read cannot be answered: ")), polled.describe().constData());

    const QStringList unitZero{QStringLiteral("--target"), m_target, QStringLiteral("--unit"), QStringLiteral("0"), QStringLiteral("--address"),
                               QStringLiteral("0x79")};
    for (const QStringList &arguments : {QStringList{QStringLiteral("read")} + unitZero,
                                         QStringList{QStringLiteral("poll"), QStringLiteral("--count"), QStringLiteral("1")} + unitZero}) {
        const CliResult r = runMbscope(arguments);
        QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
        QVERIFY2(r.errText().contains(QStringLiteral("--unit 0 is the broadcast address on RTU framing")), r.describe().constData());
        QVERIFY2(r.errText().contains(QStringLiteral("give the unit's own address, 1-247")), r.describe().constData());
    }

    // Modbus/TCP: unit 0 addresses the server itself, which answers.
    QVERIFY2(!m_tcpSim.url().isEmpty() || startTcpSimulator(), "mbscope simulate on tcp:// did not start");
    const CliResult overTcp = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), m_tcpSim.url(), QStringLiteral("--unit"), QStringLiteral("0"),
                                          QStringLiteral("--address"), QStringLiteral("0x79")});
    QVERIFY2(overTcp.finished && overTcp.exitCode == 0, overTcp.describe().constData());
    QVERIFY2(overTcp.outText().contains(QStringLiteral("RESULT ok")), overTcp.describe().constData());
}

// A write to unit 0 on a serial framing: sent, no answer expected, exit 0; the engine waits the
// turnaround delay, not the response timeout (here 10 minutes: the harness kills a run after 2).
void TestCliVerdicts::broadcastWriteIsSentNotAnswered()
{
    const QString slow = m_sim.url() + QStringLiteral("?timeout=600000");
    const QStringList write{QStringLiteral("write"), QStringLiteral("--target"), slow, QStringLiteral("--unit"), QStringLiteral("0"),
                            QStringLiteral("--address"), QStringLiteral("0x7D"), QStringLiteral("--registers"), QStringLiteral("250")};
    const CliResult r = runMbscope(write);
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("RESULT broadcast: sent to every unit, no answer expected")), r.describe().constData());
    QVERIFY2(!r.outText().contains(QStringLiteral("RESPONSE")), r.describe().constData());
    QVERIFY2(!r.outText().contains(QStringLiteral("VALUES written")), r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("VALUES broadcast, no answer expected: ")), r.describe().constData());
    const CliResult json = runMbscope(write + QStringList{QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 0, json.describe().constData());
    const QJsonObject t = json.json().value(QStringLiteral("transactions")).toArray().first().toObject();
    QCOMPARE(t.value(QStringLiteral("status")).toString(), QStringLiteral("broadcast"));
    QVERIFY(t.value(QStringLiteral("response")).isNull());
    QVERIFY(t.value(QStringLiteral("request_problem")).isNull());
}

// Issue 26, item 2: a poll sends its items again and again on one Modbus/TCP connection; each
// request gets the connection's next transaction id (they were the typed 7, 7, 7, 7), as the
// journal of what went on the wire shows.
void TestCliVerdicts::pollNumbersItsRequests()
{
    QVERIFY2(!m_tcpSim.url().isEmpty() || startTcpSimulator(), "mbscope simulate on tcp:// did not start");
    const QString journal = m_dir.filePath(QStringLiteral("numbered.mbscope.journal"));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), m_tcpSim.url(), QStringLiteral("--count"), QStringLiteral("2"),
                                       QStringLiteral("--interval"), QStringLiteral("0"), QStringLiteral("--hex"),
                                       QStringLiteral("00 07 00 00 00 06 01 03 00 79 00 01"), QStringLiteral("--hex"),
                                       QStringLiteral("00 07 00 00 00 06 01 03 00 7A 00 01"), QStringLiteral("--record"), journal});
    QVERIFY2(poll.finished && poll.exitCode == 0, poll.describe().constData());
    const CliResult rows = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--jsonl"), QStringLiteral("-")});
    QVERIFY2(rows.finished && rows.exitCode == 0, rows.describe().constData());
    QList<int> ids;
    for (const QByteArray &line : rows.out.split('\n')) {
        const QJsonObject row = QJsonDocument::fromJson(line).object();
        if (row.contains(QStringLiteral("request_hex")))
            ids.append(QByteArray::fromHex(row.value(QStringLiteral("request_hex")).toString().toLatin1()).left(2).toHex().toInt(nullptr, 16));
    }
    QCOMPARE(ids.size(), 4);
    for (qsizetype i = 1; i < ids.size(); ++i)
        QVERIFY2(ids.at(i) > ids.at(i - 1), rows.out.constData());
}

QTEST_GUILESS_MAIN(TestCliVerdicts)
#include "tst_cli_verdicts.moc"
