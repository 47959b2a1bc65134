// Verdicts and exit statuses as users meet them (issue 19, items 4-9 and 11), through the mbscope
// executable against `mbscope simulate --profile rosrao-gamma` on loopback (RTU over TCP):
// a request mbscope judges malformed is never a broadcast; function code 0 is an error; an ASCII
// frame given as the hex of its characters is decoded; frames beyond the ADU maximum of their
// framing are said to be; a Modicon reference typed as an address gets a hint; output files are
// checked before the first request; --json failures are a JSON error object on standard output.

#include "clitest.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
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

    void largeInputSmallOutput();
    void everyExitStatus_data();
    void everyExitStatus();
    void manPageListsEveryExitStatus();

private:
    // The files everyExitStatus runs on, made once.
    bool prepareExitStatusFiles(QString *error);
    QString m_closed; // a target nothing listens on
    bool m_prepared = false;
    Background m_sim;
    Background m_tcpSim;
    QString m_target; // the simulator, RTU over TCP, with a short response timeout
    QTemporaryDir m_dir;
};

namespace {

bool writeText(const QString &path, const QString &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(text.toUtf8()) >= 0;
}

// The (command, status) pairs everyExitStatus runs: the man page's EXIT STATUS must list these
// and no others. "mbscope" stands for the executable without a command. Some are run by tests of
// their own (named beside them), where what they need is set up: a bus, a broker.
struct StatusCase {
    const char *command;
    int status;
    const char *elsewhere; // the test that runs it, when not everyExitStatus
};
const StatusCase kElsewhere[] = {
    {"monitor", 0, "tst_cli_monitor nothingHeardHasItsOwnStatus"},
    {"monitor", 1, "tst_cli_monitor nothingHeardHasItsOwnStatus"},
    {"monitor", 3, "tst_cli_monitor nothingHeardHasItsOwnStatus"},
    {"watch", 3, "tst_cli_watch unreachableBrokerHasItsOwnStatus"},
};

// One row of everyExitStatus: a command line (TARGET, CLOSED and DIR/ filled in when run), the
// status it ends with and a piece of what it says.
struct ExitRow {
    const char *command;
    int status;
    const char *what;
    QStringList arguments;
    const char *said;
};

QList<ExitRow> exitRows();

} // namespace

void TestCliVerdicts::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QString error;
    QVERIFY2(m_sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                          QStringLiteral("rtu-tcp://127.0.0.1:0")},
                         &error),
             qPrintable(error));
    m_target = m_sim.url() + QStringLiteral("?timeout=300");
    m_closed = QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(closedPort());
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
    // Issue 26 item 11: /proc passed the permission check; the file could not be made after the polls.
    QTest::newRow("poll --csv under /proc") << QStringList{QStringLiteral("poll"), QStringLiteral("--csv"), QStringLiteral("/proc/mbscope-x.csv")}
                                            << QStringLiteral("--csv: cannot write /proc/mbscope-x.csv: ");
    QTest::newRow("poll --record under /proc") << QStringList{QStringLiteral("poll"), QStringLiteral("--record"), QStringLiteral("/proc/mbscope-x.journal")}
                                               << QStringLiteral("--record: cannot write /proc/mbscope-x.journal: ");
    QTest::newRow("poll --histogram under /proc") << QStringList{QStringLiteral("poll"), QStringLiteral("--histogram"), QStringLiteral("/proc/mbscope-x.png")}
                                                  << QStringLiteral("--histogram: cannot write /proc/mbscope-x.png: ");
    // ... and an existing --csv was overwritten where an existing --record is refused.
    QTest::newRow("poll --csv exists") << QStringList{QStringLiteral("poll"), QStringLiteral("--csv"), m_dir.filePath(QStringLiteral("exists.csv"))}
                                       << QStringLiteral("--csv: %1 exists: an output file is never overwritten (give another name, or --force to replace it)")
                                              .arg(m_dir.filePath(QStringLiteral("exists.csv")));
    QTest::newRow("poll --record no folder") << QStringList{QStringLiteral("poll"), QStringLiteral("--record"), missing + QStringLiteral("/x.mbscope.journal")}
                                             << QStringLiteral("--record: cannot write %1/x.mbscope.journal: the folder does not exist").arg(missing);
}

void TestCliVerdicts::outputsCheckedBeforeTheFirstRequest()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QFile exists(m_dir.filePath(QStringLiteral("exists.csv")));
    QVERIFY(exists.open(QIODevice::WriteOnly));
    exists.close();
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

// Issue 26 item 10: decode of 1 MB of input wrote 11 MB: the frame's trailing bytes were shown
// whole in the VALUE column, and every row with a problem was padded to that width. The table
// cuts a long value as it cuts the BYTES column; --json keeps every byte.
void TestCliVerdicts::largeInputSmallOutput()
{
    const QString input = m_dir.filePath(QStringLiteral("large.hex"));
    QByteArray text;
    while (text.size() < 1024 * 1024)
        text += "01 03 00 79 00 16 15 DD ";
    QFile f(input);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
    f.close();
    QProcess decode;
    decode.setStandardInputFile(input);
    decode.start(mbscopePath(), {QStringLiteral("decode")});
    QVERIFY(decode.waitForFinished(120000));
    const QByteArray out = decode.readAllStandardOutput();
    QCOMPARE(decode.exitCode(), 1); // far beyond the largest frame
    QVERIFY2(out.contains("Frame too long"), out.left(4000).constData());
    QVERIFY2(out.size() < 16 * 1024, qPrintable(QStringLiteral("%1 bytes of output for %2 of input:\n%3")
                                                     .arg(out.size())
                                                     .arg(text.size())
                                                     .arg(QString::fromUtf8(out.left(3000)))));
    for (const QByteArray &line : out.split('\n'))
        QVERIFY2(line.size() < 400, line.left(400).constData());
}

bool TestCliVerdicts::prepareExitStatusFiles(QString *error)
{
    if (m_prepared)
        return true;
    const auto run = [&](const QStringList &arguments, int status) {
        const CliResult r = runMbscope(arguments);
        if (r.exitCode != status)
            *error = QString::fromUtf8(r.describe());
        return r.exitCode == status;
    };
    const QString sessions = QStringLiteral(R"({"format": "mbscope-session", "version": 2, "name": "NAME",
  "requests": [{"name": "settings", "function": 3, "unit": UNIT, "address": "0x0079", "quantity": 2}],
  "plan": [{"name": "read the settings", "send": "settings"}],
  "watches": [{"name": "settings", "target": "TARGET", "unit": UNIT, "address": "0x0079", "quantity": 2, "intervalMs": 50}]})");
    for (const auto &[name, unit] : {std::pair{QStringLiteral("good"), 1}, std::pair{QStringLiteral("silent"), 9}}) {
        QString text = sessions;
        text.replace(QLatin1String("NAME"), name).replace(QLatin1String("UNIT"), QString::number(unit)).replace(QLatin1String("TARGET"), m_target);
        if (!writeText(m_dir.filePath(name + QStringLiteral(".mbscope.json")), text)) {
            *error = QStringLiteral("cannot write the session");
            return false;
        }
    }
    // Journals: every read answered; one unanswered; unit 3's results register read before a
    // write changes it (replayed, the answer differs); a damaged copy of the first.
    const QString good = m_dir.filePath(QStringLiteral("good.mbscope.journal"));
    if (!run({QStringLiteral("read"), QStringLiteral("--target"), m_target, QStringLiteral("--address"), QStringLiteral("0x79"),
              QStringLiteral("--quantity"), QStringLiteral("2"), QStringLiteral("--record"), good},
             0)
        // unit 9 is silent, then unit 1 answers: the timeout is inside the journal, not cut by its end.
        || !run({QStringLiteral("poll"), QStringLiteral("--target"), m_target, QStringLiteral("--count"), QStringLiteral("1"),
                 QStringLiteral("--hex"), QStringLiteral("09 03 00 79 00 01 54 9B"), QStringLiteral("--hex"), QStringLiteral("01 03 00 79 00 01 55 D3"),
                 QStringLiteral("--record"), m_dir.filePath(QStringLiteral("silent.mbscope.journal"))},
                1)
        || !run({QStringLiteral("write"), QStringLiteral("--target"), m_target, QStringLiteral("--unit"), QStringLiteral("3"),
                 QStringLiteral("--address"), QStringLiteral("0x87"), QStringLiteral("--registers"), QStringLiteral("0"), QStringLiteral("--single")},
                0)
        || !run({QStringLiteral("read"), QStringLiteral("--target"), m_target, QStringLiteral("--unit"), QStringLiteral("3"),
                 QStringLiteral("--address"), QStringLiteral("0x87"), QStringLiteral("--record"), m_dir.filePath(QStringLiteral("before.mbscope.journal"))},
                0)
        || !run({QStringLiteral("write"), QStringLiteral("--target"), m_target, QStringLiteral("--unit"), QStringLiteral("3"),
                 QStringLiteral("--address"), QStringLiteral("0x87"), QStringLiteral("--registers"), QStringLiteral("7"), QStringLiteral("--single")},
                0))
        return false;
    QFile in(good);
    if (!in.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read ") + good;
        return false;
    }
    const QByteArray bytes = in.readAll();
    QFile damaged(m_dir.filePath(QStringLiteral("damaged.mbscope.journal")));
    if (!damaged.open(QIODevice::WriteOnly) || damaged.write(bytes.left(bytes.size() - 5) + QByteArray(40, '\xA5')) < 0) {
        *error = QStringLiteral("cannot write the damaged journal");
        return false;
    }
    m_prepared = true;
    return true;
}

// Issue 26 item 10: every exit status of every command, as the man page's EXIT STATUS lists them,
// run as a script would meet it (the statuses run elsewhere are in kElsewhere).
namespace {

QList<ExitRow> exitRows()
{
    QList<ExitRow> rows;
    const auto row = [&rows](const char *command, int status, const char *what, QStringList arguments, const char *said = "") {
        rows.append(ExitRow{command, status, what, std::move(arguments), said});
    };
    const QString hex = QStringLiteral("--hex");
    const QString T = QStringLiteral("TARGET");
    const QString C = QStringLiteral("CLOSED");
    const QString D = QStringLiteral("DIR/");
    const QStringList settings{QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("2")};
    const QStringList silent{QStringLiteral("--unit"), QStringLiteral("9")};
    row("decode", 0, "a valid frame", {QStringLiteral("decode"), QStringLiteral("01 03 00 79 00 16 15 DD")});
    row("decode", 1, "a wrong CRC", {QStringLiteral("decode"), QStringLiteral("01 03 00 79 00 16 15 DE")}, "CRC");
    row("decode", 2, "not hex", {QStringLiteral("decode"), QStringLiteral("01 0G")}, "mbscope decode: frame: ");
    row("send", 0, "answered", {QStringLiteral("send"), QStringLiteral("--target"), T, QStringLiteral("--complete"), QStringLiteral("--unit"), QStringLiteral("1"), hex, QStringLiteral("03 00 79 00 01")});
    row("send", 1, "no answer", {QStringLiteral("send"), QStringLiteral("--target"), T, QStringLiteral("--complete"), QStringLiteral("--unit"), QStringLiteral("9"), hex, QStringLiteral("03 00 79 00 01")}, "timeout");
    row("send", 2, "refused", {QStringLiteral("send"), QStringLiteral("--target"), C, hex, QStringLiteral("01 03 00 79 00 16 15 DD")}, "connection refused");
    row("read", 0, "answered", QStringList{QStringLiteral("read"), QStringLiteral("--target"), T} + settings);
    row("read", 1, "no answer", QStringList{QStringLiteral("read"), QStringLiteral("--target"), T} + silent, "timeout");
    row("read", 2, "f32 of one register", {QStringLiteral("read"), QStringLiteral("--target"), T, QStringLiteral("--format"), QStringLiteral("f32")},
        "--format f32-abcd needs 2 registers for one value, but --quantity 1 reads only 1");
    row("read", 2, "refused", QStringList{QStringLiteral("read"), QStringLiteral("--target"), C}, "connection refused");
    const QStringList write{QStringLiteral("write"), QStringLiteral("--target"), T, QStringLiteral("--address"), QStringLiteral("0x87"),
                            QStringLiteral("--registers"), QStringLiteral("7"), QStringLiteral("--single")};
    row("write", 0, "written, the echo matched", write + QStringList{QStringLiteral("--unit"), QStringLiteral("3")});
    row("write", 1, "no answer", write + silent, "timeout");
    row("write", 2, "nothing to write", {QStringLiteral("write"), QStringLiteral("--target"), T}, "nothing to write");
    const QStringList poll = QStringList{QStringLiteral("poll"), QStringLiteral("--target"), T, QStringLiteral("--count"), QStringLiteral("2"),
                                         QStringLiteral("--interval"), QStringLiteral("0")} + settings;
    row("poll", 0, "every answer", poll);
    row("poll", 1, "no answer", poll + silent);
    row("poll", 2, "--csv under /proc", poll + QStringList{QStringLiteral("--csv"), QStringLiteral("/proc/mbscope.csv")}, "--csv: cannot write /proc/mbscope.csv");
    const QStringList sweep = QStringList{QStringLiteral("sweep"), QStringLiteral("--target"), T, QStringLiteral("--count"), QStringLiteral("2"),
                                          QStringLiteral("--intervals"), QStringLiteral("0,5ms")} + settings;
    row("sweep", 0, "every answer", sweep);
    row("sweep", 1, "no answer", sweep + silent);
    row("sweep", 2, "refused", QStringList{QStringLiteral("sweep"), QStringLiteral("--target"), C, QStringLiteral("--count"), QStringLiteral("2"),
                                            QStringLiteral("--intervals"), QStringLiteral("0,5ms")} + settings, "connection refused");
    row("monitor", 2, "not a bus", {QStringLiteral("monitor"), QStringLiteral("tcp://127.0.0.1:502")}, "not a bus another master drives");
    row("watch", 0, "every poll answered", {QStringLiteral("watch"), D + QStringLiteral("good.mbscope.json"), QStringLiteral("--count"), QStringLiteral("2")});
    row("watch", 1, "no answer", {QStringLiteral("watch"), D + QStringLiteral("silent.mbscope.json"), QStringLiteral("--count"), QStringLiteral("1")});
    row("watch", 2, "no session", {QStringLiteral("watch"), D + QStringLiteral("none.mbscope.json")}, "mbscope watch: the session cannot be used");
    row("scan", 0, "unit 1 found", {QStringLiteral("scan"), QStringLiteral("--target"), T, QStringLiteral("--units"), QStringLiteral("1-2")}, "found 1 device(s)");
    row("scan", 1, "nothing found", {QStringLiteral("scan"), QStringLiteral("--target"), T, QStringLiteral("--units"), QStringLiteral("9-10")}, "found 0 device(s)");
    row("scan", 2, "refused", {QStringLiteral("scan"), QStringLiteral("--target"), C, QStringLiteral("--units"), QStringLiteral("1-2")}, "refused");
    row("conform", 0, "every mandatory check passed", {QStringLiteral("conform"), QStringLiteral("--target"), T, QStringLiteral("--only"), QStringLiteral("read.03.quantity")},
        "every mandatory check passed");
    row("conform", 1, "a mandatory check failed", {QStringLiteral("conform"), QStringLiteral("--target"), T, QStringLiteral("--only"), QStringLiteral("read.03.missing-address"),
                                                   QStringLiteral("--missing"), QStringLiteral("holding:0x79")},
        "1 mandatory check(s) failed");
    row("conform", 2, "refused", {QStringLiteral("conform"), QStringLiteral("--target"), C}, "refused");
    row("run", 0, "every step passed", {QStringLiteral("run"), D + QStringLiteral("good.mbscope.json"), QStringLiteral("--target"), T});
    row("run", 1, "a step failed", {QStringLiteral("run"), D + QStringLiteral("silent.mbscope.json"), QStringLiteral("--target"), T});
    row("run", 2, "refused", {QStringLiteral("run"), D + QStringLiteral("good.mbscope.json"), QStringLiteral("--target"), C}, "connection refused");
    row("simulate", 0, "stopped by --duration", {QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                                                 QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--duration"), QStringLiteral("200ms")});
    row("simulate", 2, "unknown profile", {QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("no-such-profile")}, "no-such-profile");
    row("analyze", 0, "every answer", {QStringLiteral("analyze"), D + QStringLiteral("good.mbscope.journal")});
    row("analyze", 1, "a timeout", {QStringLiteral("analyze"), D + QStringLiteral("silent.mbscope.journal")});
    row("analyze", 1, "damaged", {QStringLiteral("analyze"), D + QStringLiteral("damaged.mbscope.journal")});
    row("analyze", 2, "no such file", {QStringLiteral("analyze"), D + QStringLiteral("none.pcap")}, "no such file");
    row("export", 0, "written", {QStringLiteral("export"), D + QStringLiteral("good.mbscope.journal"), QStringLiteral("--csv"), QStringLiteral("-")});
    row("export", 1, "from a damaged source", {QStringLiteral("export"), D + QStringLiteral("damaged.mbscope.journal"), QStringLiteral("--csv"), QStringLiteral("-")});
    row("export", 2, "an output that exists", {QStringLiteral("export"), D + QStringLiteral("good.mbscope.journal"), QStringLiteral("--csv"), D + QStringLiteral("good.mbscope.json")},
        "exists: an output file is never overwritten");
    row("replay", 0, "every answer matched", {QStringLiteral("replay"), D + QStringLiteral("good.mbscope.journal"), QStringLiteral("--target"), T});
    row("replay", 1, "an answer differed", {QStringLiteral("replay"), D + QStringLiteral("before.mbscope.journal"), QStringLiteral("--target"), T});
    row("replay", 2, "no such file", {QStringLiteral("replay"), D + QStringLiteral("none.mbscope.journal"), QStringLiteral("--target"), T});
    row("completion", 0, "a bash script", {QStringLiteral("completion"), QStringLiteral("bash")}, "complete -F _mbscope mbscope");
    row("completion", 2, "a shell it does not write for", {QStringLiteral("completion"), QStringLiteral("fish")}, "bash or zsh");
    row("mbscope", 0, "--version", {QStringLiteral("--version")}, "mbscope ");
    row("mbscope", 0, "--help-all", {QStringLiteral("--help-all")}, "== mbscope replay ==");
    row("mbscope", 2, "an unknown command", {QStringLiteral("frobnicate")}, "mbscope: unknown subcommand 'frobnicate'");
    return rows;
}

} // namespace

void TestCliVerdicts::everyExitStatus_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("said"); // on standard output or error
    for (const ExitRow &r : exitRows())
        QTest::addRow("%s %d: %s", r.command, r.status, r.what) << r.arguments << r.status << QString::fromUtf8(r.said);
}

void TestCliVerdicts::everyExitStatus()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, status);
    QFETCH(QString, said);
    QString error;
    QVERIFY2(prepareExitStatusFiles(&error), qPrintable(error));
    for (QString &a : arguments) {
        if (a == QLatin1String("TARGET"))
            a = m_target;
        else if (a == QLatin1String("CLOSED"))
            a = m_closed;
        else if (a.startsWith(QLatin1String("DIR/")))
            a = m_dir.filePath(a.mid(4));
    }
    const CliResult r = runMbscope(arguments, 60000);
    QVERIFY2(r.finished && r.exitCode == status, r.describe().constData());
    QVERIFY2((r.outText() + r.errText()).contains(said), r.describe().constData());
}

// The man page's EXIT STATUS lists, command by command, exactly the statuses that are tested
// (everyExitStatus's rows and kElsewhere): a status added to the code or the page without the
// other fails here.
void TestCliVerdicts::manPageListsEveryExitStatus()
{
    QFile page(QStringLiteral(MBSCOPE_SOURCE_DIR "/docs/mbscope.1"));
    QVERIFY(page.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(page.readAll()).split(QLatin1Char('\n'));
    static const QRegularExpression commandWord(
        QStringLiteral(R"(\b(decode|send|read|write|poll|sweep|monitor|watch|scan|run|simulate|analyze|export|replay|completion)\b)"));
    static const QRegularExpression statusAt(QStringLiteral(R"(^([0-9]) )"));
    QSet<QString> documented;
    bool inSection = false;
    bool perCommand = false;
    QStringList commands;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString &line = lines.at(i);
        if (line.startsWith(QLatin1String(".SH ")))
            inSection = line == QLatin1String(".SH EXIT STATUS");
        if (!inSection)
            continue;
        if (line.startsWith(QLatin1String("Each command's statuses")))
            perCommand = true;
        if (!perCommand)
            continue;
        if (line == QLatin1String(".TP") && i + 1 < lines.size()) {
            commands.clear();
            auto words = commandWord.globalMatch(lines.at(i + 1));
            while (words.hasNext())
                commands.append(words.next().captured(1));
            if (commands.isEmpty())
                commands.append(QStringLiteral("mbscope"));
            ++i;
            continue;
        }
        const QRegularExpressionMatch m = statusAt.match(line);
        if (m.hasMatch()) {
            for (const QString &c : std::as_const(commands))
                documented.insert(c + QLatin1Char(' ') + m.captured(1));
        }
    }
    QSet<QString> tested;
    for (const StatusCase &c : kElsewhere)
        tested.insert(QStringLiteral("%1 %2").arg(QLatin1String(c.command)).arg(c.status));
    for (const ExitRow &r : exitRows())
        tested.insert(QStringLiteral("%1 %2").arg(QLatin1String(r.command)).arg(r.status));
    QVERIFY2(!documented.isEmpty(), "no EXIT STATUS list found in docs/mbscope.1");
    const QSet<QString> untested = documented - tested;
    const QSet<QString> undocumented = tested - documented;
    QVERIFY2(untested.isEmpty(), qPrintable(QStringLiteral("documented, never run: ") + QStringList(untested.values()).join(QStringLiteral(", "))));
    QVERIFY2(undocumented.isEmpty(), qPrintable(QStringLiteral("run, not documented: ") + QStringList(undocumented.values()).join(QStringLiteral(", "))));
}

QTEST_GUILESS_MAIN(TestCliVerdicts)
#include "tst_cli_verdicts.moc"
