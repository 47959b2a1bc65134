// mbscope analyze and mbscope export as users run them, on captures and journals the test
// writes with the core (so every expected figure is known): text and JSON, damaged files with
// their messages and exit statuses, CSV / JSON lines / pcapng exports read back, plots in PNG,
// SVG and PDF, and usage errors; a long capture with one packet removed by editcap (Wireshark's),
// and captures whose Modbus is on another port than the one asked.
#include "clitest.h"

#include "capture/capturefilewriter.h"
#include "capture/exchangepcapexporter.h"
#include "capture/packetsynthesizer.h"
#include "traffic/journalendpoints.h"
#include "traffic/trafficjournal.h"
#include "protocol/adubuilder.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <functional>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

constexpr qint64 kStart = 1'700'000'000'000'000'000LL;
constexpr qint64 kMs = 1'000'000;

QByteArray mbap(quint16 tid, const char *pduHex)
{
    return AduBuilder::mbap(QByteArray::fromHex(pduHex), 1, tid);
}

CaptureExchange exchange(Framing framing, const QByteArray &request, qint64 sentNs, const QByteArray &response, qint64 doneNs)
{
    CaptureExchange e;
    e.framing = framing;
    e.transaction.request = request;
    e.transaction.response = response;
    e.transaction.sentNs = sentNs;
    e.transaction.doneNs = e.transaction.firstByteNs = doneNs;
    return e;
}

// Three reads answered in 2, 3 and 4 ms (and, with failures, an exception and a timeout).
bool writeCapture(const QString &path, bool failures, Framing framing = Framing::Tcp, quint16 serverPort = 0)
{
    CaptureFileWriter writer;
    QString error;
    if (!writer.open(path, CaptureFileWriter::formatFor(path), &error))
        return false;
    ExchangePcapExporter exporter(writer);
    CaptureConversation c;
    c.framing = framing;
    c.client.bytes = {192, 168, 1, 5};
    c.server.bytes = {192, 168, 1, 10};
    c.clientPort = 40000;
    c.serverPort = serverPort != 0 ? serverPort : framing == Framing::Rtu ? 4001 : 502;
    exporter.addConversation(c);
    for (int i = 0; i < 3; ++i) {
        const qint64 t = kStart + i * 100 * kMs;
        if (framing == Framing::Rtu)
            exporter.add(exchange(framing, AduBuilder::rtu(QByteArray::fromHex("0300640002"), 1), t,
                                  AduBuilder::rtu(QByteArray::fromHex("0304000a01f4"), 1), t + (2 + i) * kMs));
        else
            exporter.add(exchange(framing, mbap(quint16(i), "0300640002"), t, mbap(quint16(i), "0304000a01f4"), t + (2 + i) * kMs));
    }
    if (failures) {
        exporter.add(exchange(framing, mbap(10, "0327100001"), kStart + 400 * kMs, mbap(10, "8302"), kStart + 401 * kMs));
        exporter.add(exchange(framing, mbap(11, "0300000001"), kStart + 500 * kMs, {}, 0));
    }
    exporter.finish();
    if (failures) {
        // The capture goes on past the last request's timeout (1 s): it shows that no answer came
        // in time, a timeout (a capture that ended sooner would leave it unanswered at its end).
        PacketSynthesizer::Endpoints other;
        other.client.bytes = {192, 168, 1, 5};
        other.server.bytes = {192, 168, 1, 20};
        other.clientPort = 5353;
        other.serverPort = 5353;
        writer.write(kStart + 1600 * kMs, PacketSynthesizer::udp(other, true, QByteArrayView("not modbus")));
    }
    return writer.close(&error);
}

// A pcap or pcapng (by path's ending) of one Modbus/TCP conversation, 192.168.1.5:40000 to
// 192.168.1.10:502, its exchanges added by fill; false when the file cannot be written.
bool writeTcpCapture(const QString &path, const std::function<void(CaptureFileWriter &, ExchangePcapExporter &)> &fill)
{
    CaptureFileWriter writer;
    QString error;
    if (!writer.open(path, CaptureFileWriter::formatFor(path), &error))
        return false;
    ExchangePcapExporter exporter(writer);
    CaptureConversation c;
    c.client.bytes = {192, 168, 1, 5};
    c.server.bytes = {192, 168, 1, 10};
    c.clientPort = 40000;
    c.serverPort = 502;
    exporter.addConversation(c);
    fill(writer, exporter);
    return writer.close(&error);
}

// count reads of 2 registers, one every 100 ms, each answered in 3 ms: after the handshake (packets
// 1..3), transaction i's request is packet 4 + 2i and its answer 5 + 2i.
bool writeLongCapture(const QString &path, int count)
{
    return writeTcpCapture(path, [count](CaptureFileWriter &, ExchangePcapExporter &exporter) {
        for (int i = 0; i < count; ++i) {
            const qint64 t = kStart + i * 100 * kMs;
            exporter.add(exchange(Framing::Tcp, mbap(quint16(i), "0300640002"), t, mbap(quint16(i), "0304000a01f4"), t + 3 * kMs));
        }
        exporter.finish();
    });
}

// Per unit and per function (issue 30): unit 1 reads holding registers (0x03) answered in 2, 4
// and 9 ms; unit 7 writes registers (0x10) answered in 5 and 7 ms, then once with exception 02 in
// 1 ms, and reads (0x03) once left without an answer (a timeout: no latency).
bool writeUnitsCapture(const QString &path)
{
    return writeTcpCapture(path, [](CaptureFileWriter &writer, ExchangePcapExporter &exporter) {
        const auto add = [&](quint16 tid, quint8 unit, const char *request, const char *response, int ms) {
            const qint64 t = kStart + tid * 100 * kMs;
            exporter.add(exchange(Framing::Tcp, AduBuilder::mbap(QByteArray::fromHex(request), unit, tid), t,
                                  response ? AduBuilder::mbap(QByteArray::fromHex(response), unit, tid) : QByteArray(),
                                  response ? t + ms * kMs : 0));
        };
        add(0, 1, "0300640002", "0304000a01f4", 2);
        add(1, 7, "100000000102002a", "1000000001", 5);
        add(2, 1, "0300640002", "0304000a01f4", 4);
        add(3, 7, "100000000102002a", "1000000001", 7);
        add(4, 1, "0300640002", "0304000a01f4", 9);
        add(5, 7, "102710000102002a", "9002", 1);
        add(6, 7, "0300000001", nullptr, 0);
        exporter.finish();
        // Past the last request's timeout (1 s), so it is a timeout and not unanswered at the end.
        PacketSynthesizer::Endpoints other;
        other.client.bytes = {192, 168, 1, 5};
        other.server.bytes = {192, 168, 1, 20};
        other.clientPort = 5353;
        other.serverPort = 5353;
        writer.write(kStart + 2000 * kMs, PacketSynthesizer::udp(other, true, QByteArrayView("not modbus")));
    });
}

// UDP datagrams on port 5353 that look like nothing Modbus.
bool writeOtherTraffic(const QString &path)
{
    CaptureFileWriter writer;
    QString error;
    if (!writer.open(path, CaptureFileWriter::formatFor(path), &error))
        return false;
    PacketSynthesizer::Endpoints e;
    e.client.bytes = {192, 168, 1, 5};
    e.server.bytes = {192, 168, 1, 10};
    e.clientPort = 5353;
    e.serverPort = 5353;
    for (int i = 0; i < 4; ++i)
        writer.write(kStart + i * kMs, PacketSynthesizer::udp(e, i % 2 == 0, QByteArrayView("hello, this is not modbus")));
    return writer.close(&error);
}

QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestCliCapture : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void analyzeText();
    void analyzeJson();
    void analyzePerUnitAndFunction();
    void damaged_data();
    void damaged();
    void exportTables();
    void exportPcapAnalysedAgain();
    void exportRtuNotesTheDecodeOption();
    void exportJournal();
    void plots_data();
    void plots();
    void usageErrors_data();
    void usageErrors();
    void lostPacket_data();
    void lostPacket();
    void otherPort_data();
    void otherPort();
    void simulatedCrcErrors();
    void simulatedPieces_data();
    void simulatedPieces();
    void captureCutMidExchange();
    void journalWithoutEndpoints();
    void serialJournalExported();
    void recordedEndpoints();
    void outputsUnderOnePolicy();

private:
    QTemporaryDir m_dir;
    QString m_good;
    QString m_failing;
};

void TestCliCapture::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_good = m_dir.filePath(QStringLiteral("good.pcapng"));
    m_failing = m_dir.filePath(QStringLiteral("failing.pcapng"));
    QVERIFY(writeCapture(m_good, false));
    QVERIFY(writeCapture(m_failing, true));
    QCOMPARE(readFile(m_good).size(), 952);
}

void TestCliCapture::analyzeText()
{
    const CliResult r = runMbscope({QStringLiteral("analyze"), m_good});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QString text = r.outText();
    QVERIFY2(text.contains(QStringLiteral("(pcapng, 9 packets, 6 Modbus frames")), r.describe().constData());
    QVERIFY2(text.contains(QStringLiteral("tcp 192.168.1.5:40000 -> 192.168.1.10:502 (Modbus TCP): 3 transactions, 3 ok, 0 failed")),
             r.describe().constData());
    QVERIFY2(text.contains(QStringLiteral("0x03 Read Holding Registers")), r.describe().constData());

    const CliResult failing = runMbscope({QStringLiteral("analyze"), m_failing});
    QVERIFY2(failing.finished && failing.exitCode == 1, failing.describe().constData());
    QVERIFY2(failing.outText().contains(QStringLiteral("5 transactions, 3 ok, 2 failed")), failing.describe().constData());
}

void TestCliCapture::analyzeJson()
{
    const CliResult r = runMbscope({QStringLiteral("analyze"), m_failing, QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 5);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("exceptions")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 1);
    // Latencies 2, 3, 4 ms and the exception's 1 ms: answered means Ok and Exception.
    const QJsonObject latency = o.value(QStringLiteral("latency_us")).toObject();
    QCOMPARE(latency.value(QStringLiteral("count")).toInt(), 4);
    QCOMPARE(latency.value(QStringLiteral("min")).toDouble(), 1000.0);
    QCOMPARE(latency.value(QStringLiteral("max")).toDouble(), 4000.0);
    QVERIFY(o.value(QStringLiteral("histogram")).isObject());
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("format")).toString(), QStringLiteral("pcapng"));
    QCOMPARE(source.value(QStringLiteral("complete")).toBool(), true);
    QCOMPARE(source.value(QStringLiteral("requests")).toInt(), 5);
    const QJsonArray conversations = o.value(QStringLiteral("conversations")).toArray();
    QCOMPARE(conversations.size(), 1);
    QCOMPARE(conversations.at(0).toObject().value(QStringLiteral("server")).toString(), QStringLiteral("192.168.1.10:502"));
    const QJsonArray functions = o.value(QStringLiteral("functions")).toArray();
    QCOMPARE(functions.size(), 1);
    QCOMPARE(functions.at(0).toObject().value(QStringLiteral("function")).toString(), QStringLiteral("0x03"));
}

// The tables a lab publishes (issue 30): min, mean, median, p95, p99 and max latency per function
// code and per unit id, "-" where nothing was answered, and the same in --json ("functions",
// "units").
void TestCliCapture::analyzePerUnitAndFunction()
{
    const QString path = m_dir.filePath(QStringLiteral("units.pcapng"));
    QVERIFY(writeUnitsCapture(path));

    const CliResult r = runMbscope({QStringLiteral("analyze"), path});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData()); // an exception and a timeout
    const QStringList lines = r.outText().split(QLatin1Char('\n'));
    const auto cellsOf = [&](const QString &first) {
        for (const QString &line : lines) {
            if (line.startsWith(first + QLatin1Char(' ')))
                return line.simplified().split(QLatin1Char(' '));
        }
        return QStringList();
    };
    const QStringList latencyColumns{QStringLiteral("MIN"), QStringLiteral("MEAN"), QStringLiteral("MEDIAN"),
                                     QStringLiteral("P95"), QStringLiteral("P99"), QStringLiteral("MAX")};
    const QStringList counts{QStringLiteral("COUNT"), QStringLiteral("OK"), QStringLiteral("EXCEPTIONS"),
                             QStringLiteral("TIMEOUTS"), QStringLiteral("OTHER")};
    QCOMPARE(cellsOf(QStringLiteral("FUNCTION")), QStringList{QStringLiteral("FUNCTION")} + counts + latencyColumns);
    QCOMPARE(cellsOf(QStringLiteral("UNIT")), QStringList{QStringLiteral("UNIT")} + counts + latencyColumns);
    // The median is 4 ms: the tables are in ms, as the latency line below them.
    QCOMPARE(r.outText().count(QStringLiteral("LATENCY ms")), 2);
    QVERIFY2(r.outText().contains(QStringLiteral("latency ms    min 1.000")), r.describe().constData());
    for (const QString &line : lines)
        QVERIFY2(line.size() <= 120, qPrintable(line));

    // 0x03: unit 1's three reads (2, 4, 9 ms) and unit 7's timeout.
    QCOMPARE(cellsOf(QStringLiteral("0x03")),
             (QStringList{QStringLiteral("0x03"), QStringLiteral("Read"), QStringLiteral("Holding"), QStringLiteral("Registers"),
                          QStringLiteral("4"), QStringLiteral("3"), QStringLiteral("0"), QStringLiteral("1"), QStringLiteral("0"),
                          QStringLiteral("2.000"), QStringLiteral("5.000"), QStringLiteral("4.000"), QStringLiteral("9.000"),
                          QStringLiteral("9.000"), QStringLiteral("9.000")}));
    // Unit 7: the writes (5, 7 ms), the exception (1 ms; answered, so it has a latency), the timeout.
    const QStringList unit7 = cellsOf(QStringLiteral("7"));
    QCOMPARE(unit7.mid(0, 6), (QStringList{QStringLiteral("7"), QStringLiteral("4"), QStringLiteral("2"), QStringLiteral("1"),
                                           QStringLiteral("1"), QStringLiteral("0")}));
    const double min = unit7.at(6).toDouble();
    const double mean = unit7.at(7).toDouble();
    const double max = unit7.at(11).toDouble();
    QCOMPARE(min, 1.0);
    QCOMPARE(max, 7.0);
    QVERIFY(min <= mean && mean <= max);
    QCOMPARE(unit7.at(8), QStringLiteral("5.000"));
    const QStringList unit1 = cellsOf(QStringLiteral("1"));
    QCOMPARE(unit1.size(), 12);
    QCOMPARE(unit1.at(1).toInt() + unit7.at(1).toInt(), 7); // every transaction, under one unit each

    const CliResult j = runMbscope({QStringLiteral("analyze"), path, QStringLiteral("--json")});
    QVERIFY2(j.finished && j.exitCode == 1, j.describe().constData());
    const QJsonObject o = j.json();
    const QJsonArray units = o.value(QStringLiteral("units")).toArray();
    QCOMPARE(units.size(), 2);
    int total = 0;
    for (const QJsonValue &v : units) {
        const QJsonObject u = v.toObject();
        total += u.value(QStringLiteral("count")).toInt();
        const QJsonObject l = u.value(QStringLiteral("latency_us")).toObject();
        QVERIFY(l.value(QStringLiteral("min")).toDouble() <= l.value(QStringLiteral("mean")).toDouble());
        QVERIFY(l.value(QStringLiteral("mean")).toDouble() <= l.value(QStringLiteral("max")).toDouble());
        QVERIFY(l.value(QStringLiteral("p95")).isDouble());
    }
    QCOMPARE(total, o.value(QStringLiteral("count")).toInt());
    const QJsonObject u1 = units.at(0).toObject();
    QCOMPARE(u1.value(QStringLiteral("unit")).toInt(), 1);
    QCOMPARE(u1.value(QStringLiteral("count")).toInt(), 3);
    QCOMPARE(u1.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("max")).toDouble(), 9000.0);
    const QJsonObject u7 = units.at(1).toObject();
    QCOMPARE(u7.value(QStringLiteral("unit")).toInt(), 7);
    QCOMPARE(u7.value(QStringLiteral("timeouts")).toInt(), 1);
    QCOMPARE(u7.value(QStringLiteral("exceptions")).toInt(), 1);
    QCOMPARE(u7.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("count")).toInt(), 3);
    const QJsonArray functions = o.value(QStringLiteral("functions")).toArray();
    QCOMPARE(functions.size(), 2);
    QCOMPARE(functions.at(1).toObject().value(QStringLiteral("function")).toString(), QStringLiteral("0x10"));
    const double writeMeanUs = functions.at(1).toObject().value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("mean")).toDouble();
    QVERIFY2(qAbs(writeMeanUs - 13000.0 / 3.0) < 1e-6, qPrintable(QString::number(writeMeanUs)));
}

void TestCliCapture::damaged_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::addColumn<QString>("analysed"); // what stdout must still say, empty when nothing

    // The pcapng: a 44-byte section header and a 44-byte interface block, the handshake (3
    // blocks of 88), then each request and each answer in a block of 100: the second request,
    // at byte 552, is cut after 30 bytes (initTestCase checks the file's size).
    const QByteArray good = readFile(m_good);
    QTest::newRow("cut in a packet") << QStringLiteral("cut.pcapng") << good.left(552 + 30) << 1
                                     << QStringLiteral("at byte 552: the block of type 0x00000006 is cut short: it says 100 bytes, the file has 30")
                                     << QStringLiteral("1 transactions, 1 ok");
    QTest::newRow("not a capture") << QStringLiteral("notes.txt") << QByteArray("hello, this is text\n") << 2
                                   << QStringLiteral("not a capture file: it starts with 68 65 6C 6C") << QString();
    QTest::newRow("empty") << QStringLiteral("empty.pcap") << QByteArray() << 2 << QStringLiteral("the file is empty: not a capture")
                           << QString();
}

void TestCliCapture::damaged()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QFETCH(QString, analysed);
    const QString path = m_dir.filePath(name);
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
    f.close();
    const CliResult r = runMbscope({QStringLiteral("analyze"), path});
    QVERIFY2(r.finished && r.exitCode == exitCode, r.describe().constData());
    QVERIFY2(r.errText().contains(message), r.describe().constData());
    if (!analysed.isEmpty())
        QVERIFY2(r.outText().contains(analysed), r.describe().constData());
}

void TestCliCapture::exportTables()
{
    const QString csv = m_dir.filePath(QStringLiteral("out.csv"));
    const QString jsonl = m_dir.filePath(QStringLiteral("out.jsonl"));
    const CliResult r = runMbscope({QStringLiteral("export"), m_failing, QStringLiteral("--csv"), csv, QStringLiteral("--jsonl"), jsonl});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral(": 5 row(s)")), r.describe().constData());
    const QList<QByteArray> rows = readFile(csv).trimmed().split('\n');
    QCOMPARE(rows.size(), 6);
    QVERIFY(rows.at(0).startsWith("index,kind,request_time,response_time,latency_us,client,server,framing,unit,function"));
    QVERIFY2(rows.at(1).contains(",2000.000,192.168.1.5:40000,192.168.1.10:502,tcp,1,0x03,Read Holding Registers,100,2,10 500,ok,"),
             rows.at(1).constData());
    QVERIFY2(rows.at(1).contains("2023-11-14T22:13:20.000000000Z"), rows.at(1).constData());
    QVERIFY2(rows.at(4).contains(",exception,0x02,"), rows.at(4).constData());
    QVERIFY2(rows.at(5).contains(",timeout,,"), rows.at(5).constData());

    const QList<QByteArray> lines = readFile(jsonl).trimmed().split('\n');
    QCOMPARE(lines.size(), 5);
    const QJsonObject first = QJsonDocument::fromJson(lines.at(0)).object();
    QCOMPARE(first.value(QStringLiteral("latency_us")).toDouble(), 2000.0);
    QCOMPARE(first.value(QStringLiteral("address")).toInt(), 100);
    QCOMPARE(first.value(QStringLiteral("values")).toString(), QStringLiteral("10 500"));
    QCOMPARE(first.value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
    QCOMPARE(first.value(QStringLiteral("request_time_ns")).toString(), QString::number(kStart));
    const QJsonObject last = QJsonDocument::fromJson(lines.at(4)).object();
    QVERIFY(last.value(QStringLiteral("latency_us")).isNull());
    QCOMPARE(last.value(QStringLiteral("status")).toString(), QStringLiteral("timeout"));

    // CSV to standard output, the note to standard error.
    const CliResult toStdout = runMbscope({QStringLiteral("export"), m_good, QStringLiteral("--csv"), QStringLiteral("-")});
    QVERIFY2(toStdout.finished && toStdout.exitCode == 0, toStdout.describe().constData());
    QCOMPARE(toStdout.out.trimmed().split('\n').size(), 4);
}

void TestCliCapture::exportPcapAnalysedAgain()
{
    const QString pcap = m_dir.filePath(QStringLiteral("again.pcap"));
    const CliResult r = runMbscope({QStringLiteral("export"), m_failing, QStringLiteral("--pcap"), pcap});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("packet(s), pcap")), r.describe().constData());
    QVERIFY(readFile(pcap).startsWith(QByteArray::fromHex("4d3cb2a1"))); // nanosecond pcap, little-endian
    const CliResult again = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--json")});
    QVERIFY2(again.finished, again.describe().constData());
    // The export holds the exchanges only, not the packet that showed the last request's
    // timeout run out: that request ends the exported capture, unanswered at its end.
    QCOMPARE(again.json().value(QStringLiteral("count")).toInt(), 4);
    QCOMPARE(again.json().value(QStringLiteral("timeouts")).toInt(), 0);
    QCOMPARE(again.json().value(QStringLiteral("source")).toObject().value(QStringLiteral("unanswered_at_end")).toInt(), 1);
    QCOMPARE(again.json().value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("max")).toDouble(), 4000.0);
}

void TestCliCapture::exportRtuNotesTheDecodeOption()
{
    const QString rtu = m_dir.filePath(QStringLiteral("rtu.pcapng"));
    QVERIFY(writeCapture(rtu, false, Framing::Rtu));
    const CliResult analysed = runMbscope({QStringLiteral("analyze"), rtu, QStringLiteral("--rtu-port"), QStringLiteral("4001"), QStringLiteral("--json")});
    QVERIFY2(analysed.finished && analysed.exitCode == 0, analysed.describe().constData());
    QCOMPARE(analysed.json().value(QStringLiteral("ok")).toInt(), 3);
    const QString out = m_dir.filePath(QStringLiteral("rtu-out.pcapng"));
    const CliResult r = runMbscope({QStringLiteral("export"), rtu, QStringLiteral("--rtu-port"), QStringLiteral("4001"), QStringLiteral("--pcap"), out});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QVERIFY2(r.outText().contains(QStringLiteral("port 4001 (RTU over TCP): -o mbrtu.tcp.port:4001")), r.describe().constData());
    // Without --rtu-port nothing is on the Modbus ports: the RTU over TCP found on 4001 is analysed,
    // and stderr says so and names the option.
    const CliResult found = runMbscope({QStringLiteral("analyze"), rtu});
    QVERIFY2(found.finished && found.exitCode == 0, found.describe().constData());
    QVERIFY2(found.outText().contains(QStringLiteral("3 transactions, 3 ok")), found.describe().constData());
    QVERIFY2(found.errText().contains(QStringLiteral("found RTU over TCP on port 4001 and analysed that (--rtu-port 4001 "
                                                                  "to say so)")),
             found.describe().constData());
}

void TestCliCapture::exportJournal()
{
    const QString journal = m_dir.filePath(QStringLiteral("poll.mbscope.journal"));
    {
        TrafficJournalWriter writer;
        QString error;
        QVERIFY2(writer.open(journal, {}, true, &error), qPrintable(error));
        writer.addLink(0, u"tcp://192.168.1.20:502");
        // The connection's ends as the engine notes them when its link opens (issue 26 item 9).
        writer.addNote(0, 0, 999 * kMs, JournalEndpoints{QStringLiteral("192.168.1.5:40312"), QStringLiteral("192.168.1.20:502")}.toJson());
        quint64 sequence = 0;
        const auto add = [&](qint64 t, quint64 id, TrafficDirection d, TrafficVerdict v, const QByteArray &bytes) {
            writer.addFrame(TrafficEntry{sequence++, t, id, 0, d, v, bytes});
        };
        add(1000 * kMs, 1, TrafficDirection::Out, TrafficVerdict::Sent, mbap(1, "0300640002"));
        add(1003 * kMs, 1, TrafficDirection::In, TrafficVerdict::Ok, mbap(1, "0304000a01f4"));
        add(1100 * kMs, 2, TrafficDirection::Out, TrafficVerdict::Sent, mbap(2, "0300640002"));
        add(2100 * kMs, 2, TrafficDirection::In, TrafficVerdict::Timeout, {});
        writer.close();
    }
    const QString csv = m_dir.filePath(QStringLiteral("journal.csv"));
    const CliResult r = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--csv"), csv});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QList<QByteArray> rows = readFile(csv).trimmed().split('\n');
    QCOMPARE(rows.size(), 3);
    QVERIFY2(rows.at(1).contains(",3000.000,192.168.1.5:40312,192.168.1.20:502,tcp,1,0x03,Read Holding Registers,100,2,10 500,ok,"),
             rows.at(1).constData());
    QVERIFY2(rows.at(2).contains(",timeout,"), rows.at(2).constData());
    const CliResult analysed = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QCOMPARE(analysed.json().value(QStringLiteral("source")).toObject().value(QStringLiteral("format")).toString(), QStringLiteral("journal"));
    QCOMPARE(analysed.json().value(QStringLiteral("timeouts")).toInt(), 1);
    const QJsonObject conversation = analysed.json().value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QCOMPARE(conversation.value(QStringLiteral("client")).toString(), QStringLiteral("192.168.1.5:40312"));
    QCOMPARE(conversation.value(QStringLiteral("server")).toString(), QStringLiteral("192.168.1.20:502"));
    // The capture has the connection's own addresses and ports, not stand-ins.
    const QString pcap = m_dir.filePath(QStringLiteral("journal.pcapng"));
    const CliResult exported = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--pcap"), pcap});
    QVERIFY2(exported.finished && exported.exitCode == 0, exported.describe().constData());
    QVERIFY2(!exported.outText().contains(QStringLiteral("stands for it")), exported.describe().constData());
    const CliResult again = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--json")});
    const QJsonObject captured = again.json().value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QCOMPARE(captured.value(QStringLiteral("client")).toString(), QStringLiteral("192.168.1.5:40312"));
    QCOMPARE(captured.value(QStringLiteral("server")).toString(), QStringLiteral("192.168.1.20:502"));

    // A session document stands for the journal its "capture" names (beside it).
    const QString session = m_dir.filePath(QStringLiteral("poll.mbscope.json"));
    QFile doc(session);
    QVERIFY(doc.open(QIODevice::WriteOnly | QIODevice::Truncate));
    doc.write(R"({"format": "mbscope-session", "version": 1, "capture": {"journal": "poll.mbscope.journal"}})");
    doc.close();
    const CliResult viaSession = runMbscope({QStringLiteral("analyze"), session, QStringLiteral("--json")});
    QVERIFY2(viaSession.finished && viaSession.exitCode == 1, viaSession.describe().constData());
    QCOMPARE(viaSession.json().value(QStringLiteral("ok")).toInt(), 1);
    QCOMPARE(viaSession.json().value(QStringLiteral("timeouts")).toInt(), 1);
    const QString bare = m_dir.filePath(QStringLiteral("bare.mbscope.json"));
    QFile bareDoc(bare);
    QVERIFY(bareDoc.open(QIODevice::WriteOnly | QIODevice::Truncate));
    bareDoc.write(R"({"format": "mbscope-session", "version": 1})");
    bareDoc.close();
    const CliResult noCapture = runMbscope({QStringLiteral("export"), bare, QStringLiteral("--csv"), QStringLiteral("-")});
    QVERIFY2(noCapture.finished && noCapture.exitCode == 2, noCapture.describe().constData());
    QVERIFY2(noCapture.errText().contains(QStringLiteral("the session holds no captured traffic")), noCapture.describe().constData());
}

void TestCliCapture::plots_data()
{
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QByteArray>("magic");
    QTest::newRow("histogram png") << QStringLiteral("--histogram") << QStringLiteral("h.png") << QByteArray("\x89PNG");
    QTest::newRow("histogram pdf") << QStringLiteral("--histogram") << QStringLiteral("h.pdf") << QByteArray("%PDF");
    QTest::newRow("histogram svg") << QStringLiteral("--histogram") << QStringLiteral("h.svg") << QByteArray("<?xml");
    QTest::newRow("time series png") << QStringLiteral("--timeseries") << QStringLiteral("t.png") << QByteArray("\x89PNG");
    QTest::newRow("time series svg") << QStringLiteral("--timeseries") << QStringLiteral("t.svg") << QByteArray("<?xml");
}

void TestCliCapture::plots()
{
#ifndef MBSCOPE_HAVE_UI
    QSKIP("built without the GUI: no QCustomPlot, no plots");
#endif
    QFETCH(QString, option);
    QFETCH(QString, file);
    QFETCH(QByteArray, magic);
    const QString path = m_dir.filePath(file);
    QFile::remove(path);
    const CliResult r = runMbscope({QStringLiteral("export"), m_failing, option, path});
    if (r.exitCode == 2 && r.errText().contains(QStringLiteral("without Qt SVG")))
        QSKIP("this mbscope was built without Qt SVG (qt6-svg-dev)");
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QByteArray bytes = readFile(path);
    QVERIFY2(bytes.startsWith(magic), bytes.left(16).toHex(' ').constData());
    QVERIFY(bytes.size() > 1000);

    // analyze draws the same plot and says where, as poll does (tryout 8, item 9: it said nothing).
    QFile::remove(path);
    const CliResult a = runMbscope({QStringLiteral("analyze"), m_failing, option, path});
    QVERIFY2(a.finished && a.exitCode == 1, a.describe().constData()); // the capture holds failures
    QVERIFY2(a.outText().contains(QStringLiteral("\nplot          ") + path + QLatin1Char('\n')), a.describe().constData());
    QVERIFY2(readFile(path).startsWith(magic), a.describe().constData());
}

void TestCliCapture::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("export with nothing to write") << QStringList{QStringLiteral("export"), QStringLiteral("GOOD")}
                                                  << QStringLiteral("nothing to write: give --csv, --jsonl, --pcap");
    QTest::newRow("plot format") << QStringList{QStringLiteral("analyze"), QStringLiteral("GOOD"), QStringLiteral("--histogram"), QStringLiteral("x.gif")}
                                 << QStringLiteral("'x.gif': the plot's format comes from the file name, which must end in .png, .svg or .pdf");
    QTest::newRow("port") << QStringList{QStringLiteral("analyze"), QStringLiteral("GOOD"), QStringLiteral("--port"), QStringLiteral("50O2")}
                          << QStringLiteral("--port '50O2' is not a port: expected a number from 1 to 65535");
    QTest::newRow("timeout") << QStringList{QStringLiteral("analyze"), QStringLiteral("GOOD"), QStringLiteral("--timeout"), QStringLiteral("soon")}
                             << QStringLiteral("--timeout: ");
    QTest::newRow("no such file") << QStringList{QStringLiteral("analyze"), QStringLiteral("/nonexistent/x.pcap")}
                                  << QStringLiteral("/nonexistent/x.pcap: no such file");
    QTest::newRow("no capture") << QStringList{QStringLiteral("analyze")} << QStringLiteral("no capture given");
    QTest::newRow("overwrite the source") << QStringList{QStringLiteral("export"), QStringLiteral("GOOD"), QStringLiteral("--pcap"), QStringLiteral("GOOD")}
                                          << QStringLiteral("--pcap would overwrite the source");
}

void TestCliCapture::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    arguments.replaceInStrings(QStringLiteral("GOOD"), m_good);
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(message), r.describe().constData());
}

// A 1000-transaction capture with one packet taken out by editcap, as a user would: only the
// transaction whose packet was lost fails; the gap is reported with its bytes and direction.
void TestCliCapture::lostPacket_data()
{
    QTest::addColumn<int>("packet");
    QTest::addColumn<int>("timeouts");
    QTest::addColumn<int>("unmatched");
    QTest::addColumn<int>("lostBytes");
    QTest::addColumn<QString>("direction");

    QTest::newRow("packet 42 (a request) lost") << 42 << 0 << 1 << 12 << QStringLiteral("request");
    QTest::newRow("packet 41 (an answer) lost") << 41 << 1 << 0 << 13 << QStringLiteral("response");
}

void TestCliCapture::lostPacket()
{
    QFETCH(int, packet);
    QFETCH(int, timeouts);
    QFETCH(int, unmatched);
    QFETCH(int, lostBytes);
    QFETCH(QString, direction);
    const QString editcap = QStandardPaths::findExecutable(QStringLiteral("editcap"));
    if (editcap.isEmpty())
        QSKIP("editcap (Wireshark's, Debian: wireshark-common) is not installed");
    const QString whole = m_dir.filePath(QStringLiteral("long.pcapng"));
    const QString cut = m_dir.filePath(QStringLiteral("long-without-%1.pcapng").arg(packet));
    if (!QFile::exists(whole))
        QVERIFY(writeLongCapture(whole, 1000));
    QProcess p;
    p.start(editcap, {whole, cut, QString::number(packet)});
    QVERIFY(p.waitForFinished(60000));
    QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, p.readAllStandardError().constData());

    const CliResult r = runMbscope({QStringLiteral("analyze"), cut, QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 1000 - (unmatched > 0 ? 1 : 0));
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 999);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), timeouts);
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("unmatched_responses")).toInt(), unmatched);
    QCOMPARE(source.value(QStringLiteral("gaps")).toInt(), 1);
    QCOMPARE(source.value(QStringLiteral("lost_bytes")).toInt(), lostBytes);
    QCOMPARE(source.value(QStringLiteral("packets")).toInt(), 2002);
    const QJsonObject conversation = o.value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QCOMPARE(conversation.value(direction + QStringLiteral("_gaps")).toInt(), 1);
    QCOMPARE(conversation.value(direction + QStringLiteral("_bytes_lost")).toInt(), lostBytes);

    const CliResult text = runMbscope({QStringLiteral("analyze"), cut});
    QVERIFY2(text.outText().contains(QStringLiteral("1 gap(s) to the %1, %2 byte(s) never captured")
                                         .arg(direction == QLatin1String("request") ? QStringLiteral("server") : QStringLiteral("client"))
                                         .arg(lostBytes)),
             text.describe().constData());
}

// Modbus on a port nobody named is found from its bytes: used (and said on stderr) when the
// ports were left at their defaults, offered in an error when the user named others.
void TestCliCapture::otherPort_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::addColumn<QString>("analysed"); // on stdout

    const QString analyze = QStringLiteral("analyze");
    QTest::newRow("modbus/tcp on 1502, no --port") << QStringLiteral("on1502.pcapng") << QStringList{analyze} << 0
        << QStringLiteral("mbscope analyze: no Modbus traffic on port 502; found Modbus/TCP on port 1502 and analysed that "
                          "(--port 1502 to say so)")
        << QStringLiteral("192.168.1.10:1502 (Modbus TCP): 3 transactions, 3 ok");
    QTest::newRow("modbus/tcp on 1502, --port 503") << QStringLiteral("on1502.pcapng")
        << QStringList{analyze, QStringLiteral("--port"), QStringLiteral("503")} << 2
        << QStringLiteral("mbscope analyze: no Modbus traffic on port 503; found Modbus/TCP on port 1502: --port 1502 to use it") << QString();
    QTest::newRow("modbus/tcp on 1502, --port 1502") << QStringLiteral("on1502.pcapng")
        << QStringList{analyze, QStringLiteral("--port"), QStringLiteral("1502")} << 0 << QString()
        << QStringLiteral("3 transactions, 3 ok");
    QTest::newRow("rtu over tcp on 4001, no --rtu-port") << QStringLiteral("rtu4001.pcapng") << QStringList{analyze} << 0
        << QStringLiteral("no Modbus traffic on port 502; found RTU over TCP on port 4001 and analysed that (--rtu-port 4001 to say so)")
        << QStringLiteral("(RTU over TCP): 3 transactions, 3 ok");
    QTest::newRow("export: modbus/tcp on 1502") << QStringLiteral("on1502.pcapng")
        << QStringList{QStringLiteral("export"), QStringLiteral("--csv"), QStringLiteral("-")} << 0
        << QStringLiteral("mbscope export: no Modbus traffic on port 502; found Modbus/TCP on port 1502 and exported that "
                          "(--port 1502 to say so)")
        << QStringLiteral("192.168.1.10:1502");
    QTest::newRow("nothing like modbus") << QStringLiteral("other.pcapng") << QStringList{analyze} << 1
        << QStringLiteral("no Modbus traffic on port 502, and none that looks like Modbus TCP or RTU on any other port")
        << QStringLiteral("none: no traffic on the Modbus ports");
}

void TestCliCapture::otherPort()
{
    QFETCH(QString, file);
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QFETCH(QString, analysed);
    const QString path = m_dir.filePath(file);
    if (!QFile::exists(path)) {
        if (file.startsWith(QLatin1String("on1502")))
            QVERIFY(writeCapture(path, false, Framing::Tcp, 1502));
        else if (file.startsWith(QLatin1String("rtu4001")))
            QVERIFY(writeCapture(path, false, Framing::Rtu));
        else
            QVERIFY(writeOtherTraffic(path));
    }
    arguments.insert(1, path);
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.finished && r.exitCode == exitCode, r.describe().constData());
    if (message.isEmpty())
        QVERIFY2(r.err.isEmpty(), r.describe().constData());
    else
        QVERIFY2(r.errText().contains(message), r.describe().constData());
    if (analysed.isEmpty())
        QVERIFY2(r.out.isEmpty(), r.describe().constData());
    else
        QVERIFY2(r.outText().contains(analysed), r.describe().constData());
}

// Issue 26 item 6: a journal written by `simulate --record` holds the answers as the simulator
// sent them, its fault rule's wrong CRC included; analyze judges them as the poll that got them
// did (CRC errors), not as the simulator's "sent" (ok).
void TestCliCapture::simulatedCrcErrors()
{
    const QString faults = m_dir.filePath(QStringLiteral("crc-faults.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(R"({"seed": 1, "rules": [{"name": "crc", "kind": "wrongChecksum", "probability": 1.0}]})");
    file.close();
    const QString journal = m_dir.filePath(QStringLiteral("crc-served.mbscope.journal"));
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults, QStringLiteral("--record"), journal},
                       &error),
             qPrintable(error));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), sim.url(), QStringLiteral("--unit"), QStringLiteral("1"),
                                       QStringLiteral("--function"), QStringLiteral("3"), QStringLiteral("--address"), QStringLiteral("0x79"),
                                       QStringLiteral("--quantity"), QStringLiteral("2"), QStringLiteral("--count"), QStringLiteral("3"),
                                       QStringLiteral("--interval"), QStringLiteral("0"), QStringLiteral("--json")});
    QVERIFY2(poll.finished, poll.describe().constData());
    QCOMPARE(poll.json().value(QStringLiteral("crc_errors")).toInt(), 3);
    sim.stop();

    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 0);
    QCOMPARE(o.value(QStringLiteral("crc_errors")).toInt(), 3);
    const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
    QVERIFY2(!text.outText().contains(QStringLiteral("3 ok")), text.describe().constData());
}

void TestCliCapture::simulatedPieces_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("rules");
    QTest::addColumn<bool>("duplicates");
    QTest::addColumn<double>("minLatencyUs"); // the gaps between an answer's pieces
    QTest::newRow("chunks, tcp") << QStringLiteral("tcp://127.0.0.1:0")
                                 << QByteArray(R"([{"name": "pieces", "kind": "chunks", "chunkBytes": 3, "gapMs": 3, "probability": 1.0}])")
                                 << false << 4 * 3000.0; // 13 bytes in 5 pieces
    QTest::newRow("trickle, rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0")
                                      << QByteArray(R"([{"name": "slowly", "kind": "trickle", "gapMs": 2, "probability": 1.0}])")
                                      << false << 8 * 2000.0; // 9 bytes, one by one
    QTest::newRow("duplicate in chunks, tcp")
        << QStringLiteral("tcp://127.0.0.1:0")
        << QByteArray(R"([{"name": "twice", "kind": "duplicate", "gapMs": 2, "probability": 1.0},)"
                      R"( {"name": "pieces", "kind": "chunks", "chunkBytes": 5, "gapMs": 2, "probability": 1.0}])")
        << true << 2 * 2000.0;
    QTest::newRow("duplicate, rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0")
                                        << QByteArray(R"([{"name": "twice", "kind": "duplicate", "gapMs": 2, "probability": 1.0}])")
                                        << true << 0.0;
}

// Issue 26: an answer the simulator sends in pieces (fault rules chunks, trickle) is one answer
// to its client, whose framer joins them; `simulate --record` journals each piece as it left,
// with its own time, and analyze joins them into the answer its client got (latency to the last
// piece), as the poll's own journal says. A duplicate answer is a second answer to one request
// (the engine's duplicate, an answer matching no request), not a malformed first one.
void TestCliCapture::simulatedPieces()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, rules);
    QFETCH(bool, duplicates);
    QFETCH(double, minLatencyUs);
    const QString tag = QString::fromLatin1(QTest::currentDataTag()).section(QLatin1Char(','), 0, 0).replace(QLatin1Char(' '), QLatin1Char('-'));
    const QString faults = m_dir.filePath(tag + QStringLiteral("-faults.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(R"({"seed": 1, "rules": )" + rules + "}");
    file.close();
    const QString served = m_dir.filePath(tag + QStringLiteral("-served.mbscope.journal"));
    const QString polled = m_dir.filePath(tag + QStringLiteral("-polled.mbscope.journal"));
    QFile::remove(served);
    QFile::remove(polled);
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"), url,
                        QStringLiteral("--faults"), faults, QStringLiteral("--record"), served},
                       &error),
             qPrintable(error));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), sim.url(), QStringLiteral("--unit"), QStringLiteral("1"),
                                       QStringLiteral("--function"), QStringLiteral("3"), QStringLiteral("--address"), QStringLiteral("0x79"),
                                       QStringLiteral("--quantity"), QStringLiteral("2"), QStringLiteral("--count"), QStringLiteral("4"),
                                       QStringLiteral("--interval"), QStringLiteral("100ms"), QStringLiteral("--record"), polled,
                                       QStringLiteral("--json")});
    QVERIFY2(poll.finished, poll.describe().constData());
    QCOMPARE(poll.json().value(QStringLiteral("ok")).toInt(), 4);
    // Let a last duplicate leave before the simulator stops.
    QTest::qWait(100);
    sim.stop();

    const CliResult a = runMbscope({QStringLiteral("analyze"), served, QStringLiteral("--json")});
    QVERIFY2(a.finished, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 4);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 4);
    QCOMPARE(o.value(QStringLiteral("malformed")).toInt(), 0);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 0);
    // The latency runs to the answer's last piece: at least the gaps between its pieces.
    QVERIFY2(o.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("min")).toDouble() >= minLatencyUs, a.describe().constData());
    const int unmatched = o.value(QStringLiteral("source")).toObject().value(QStringLiteral("unmatched_responses")).toInt();

    const CliResult p = runMbscope({QStringLiteral("analyze"), polled, QStringLiteral("--json")});
    QVERIFY2(p.finished, p.describe().constData());
    const QJsonObject po = p.json();
    QCOMPARE(po.value(QStringLiteral("ok")).toInt(), o.value(QStringLiteral("ok")).toInt());
    QCOMPARE(po.value(QStringLiteral("malformed")).toInt(), 0);
    const int pollUnmatched = po.value(QStringLiteral("source")).toObject().value(QStringLiteral("unmatched_responses")).toInt();
    if (!duplicates) {
        QCOMPARE(unmatched, 0);
        QCOMPARE(pollUnmatched, 0);
        return;
    }
    // Every duplicate the poll got is one in the simulator's journal; the last one may have left
    // after the poll had closed its connection (then the simulator did not send it).
    QVERIFY2(pollUnmatched >= 3 && unmatched >= pollUnmatched && unmatched <= 4, a.describe().constData());
    QCOMPARE(o.value(QStringLiteral("source")).toObject().value(QStringLiteral("duplicate_responses")).toInt(), unmatched);
    const CliResult text = runMbscope({QStringLiteral("analyze"), served});
    QVERIFY2(text.outText().contains(QStringLiteral("4 transactions, 4 ok, 0 failed")), text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("of them duplicates")), text.describe().constData());
}

// Issue 26: a capture that ends after a request whose answer it never caught (cut off
// mid-exchange) does not show that request timing out: its timeout reaches past the end of the
// capture. It is unanswered at the end of the capture, as a journal cut the same way is, and
// counted in no figure; a request whose timeout ran out within the capture is a timeout; replay
// leaves the cut one out.
void TestCliCapture::captureCutMidExchange()
{
    const QString pcap = m_dir.filePath(QStringLiteral("cut-mid-exchange.pcap"));
    {
        CaptureFileWriter writer;
        QString error;
        QVERIFY2(writer.open(pcap, CaptureFileWriter::formatFor(pcap), &error), qPrintable(error));
        ExchangePcapExporter exporter(writer);
        CaptureConversation c;
        c.client.bytes = {192, 168, 1, 5};
        c.server.bytes = {192, 168, 1, 10};
        c.clientPort = 40000;
        c.serverPort = 502;
        exporter.addConversation(c);
        exporter.add(exchange(Framing::Tcp, mbap(1, "0300790002"), kStart, mbap(1, "0304000a01f4"), kStart + 3 * kMs));
        exporter.add(exchange(Framing::Tcp, mbap(2, "0300790002"), kStart + 100 * kMs, {}, 0)); // times out: 1.3 s follow
        exporter.add(exchange(Framing::Tcp, mbap(3, "0300790002"), kStart + 1400 * kMs, mbap(3, "0304000a01f4"), kStart + 1403 * kMs));
        exporter.add(exchange(Framing::Tcp, mbap(4, "0300790002"), kStart + 1500 * kMs, {}, 0)); // the capture ends here
        exporter.finish();
        QVERIFY2(writer.close(&error), qPrintable(error));
    }
    const CliResult a = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--json")});
    QVERIFY2(a.finished, a.describe().constData());
    const QJsonObject o = a.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 1);
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("unanswered_at_end")).toInt(), 1);
    QCOMPARE(source.value(QStringLiteral("requests")).toInt(), 4);
    const CliResult text = runMbscope({QStringLiteral("analyze"), pcap});
    QVERIFY2(text.outText().contains(QStringLiteral("\nunanswered    1 request(s) at the end of the recording")), text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("3 transactions, 2 ok, 1 failed")), text.describe().constData());
    // The exports say which request it is.
    const CliResult rows = runMbscope({QStringLiteral("export"), pcap, QStringLiteral("--csv"), QStringLiteral("-")});
    QVERIFY2(rows.finished && rows.exitCode == 0, rows.describe().constData());
    QVERIFY2(rows.outText().contains(QStringLiteral("unanswered at the end of the capture")), rows.describe().constData());
    // A shorter timeout does not reach past the end from the last request (the capture's last
    // packet): still unanswered at the end, and the one before a timeout.
    const CliResult shorter = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--timeout"), QStringLiteral("50ms"), QStringLiteral("--json")});
    QVERIFY2(shorter.finished, shorter.describe().constData());
    QCOMPARE(shorter.json().value(QStringLiteral("timeouts")).toInt(), 1);
    QCOMPARE(shorter.json().value(QStringLiteral("source")).toObject().value(QStringLiteral("unanswered_at_end")).toInt(), 1);

    // Replayed to a device: the three exchanges the capture completed, not the cut one.
    Background device;
    QString error;
    QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                           QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                          &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("replay"), pcap, QStringLiteral("--target"), device.url(), QStringLiteral("--speed"),
                                    QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(r.finished, r.describe().constData());
    QCOMPARE(r.json().value(QStringLiteral("requests")).toInt(), 3);
    (void)device.stop();
}

// A journal of a TCP link written before journals held endpoints: its client is not known, and
// is said so (analyze: null; export: empty; the capture says which address stands for it).
void TestCliCapture::journalWithoutEndpoints()
{
    const QString journal = m_dir.filePath(QStringLiteral("old.mbscope.journal"));
    {
        TrafficJournalWriter writer;
        QString error;
        QVERIFY2(writer.open(journal, {}, true, &error), qPrintable(error));
        writer.addLink(0, u"tcp://plc.example:1502");
        writer.addFrame(TrafficEntry{0, 1000 * kMs, 1, 0, TrafficDirection::Out, TrafficVerdict::Sent, mbap(1, "0300640002")});
        writer.addFrame(TrafficEntry{1, 1003 * kMs, 1, 0, TrafficDirection::In, TrafficVerdict::Ok, mbap(1, "0304000a01f4")});
        writer.close();
    }
    const CliResult analysed = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(analysed.finished && analysed.exitCode == 0, analysed.describe().constData());
    const QJsonObject conversation = analysed.json().value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QVERIFY2(conversation.value(QStringLiteral("client")).isNull(), analysed.describe().constData());
    QCOMPARE(conversation.value(QStringLiteral("server")).toString(), QStringLiteral("plc.example:1502"));
    const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
    QVERIFY2(text.outText().contains(QStringLiteral("tcp (client not recorded) -> plc.example:1502 (Modbus TCP)")), text.describe().constData());
    QVERIFY2(!text.outText().contains(QStringLiteral("10.0.0.")), text.describe().constData());
    const QString pcap = m_dir.filePath(QStringLiteral("old.pcapng"));
    const CliResult exported = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--pcap"), pcap, QStringLiteral("--csv"), QStringLiteral("-")});
    QVERIFY2(exported.finished && exported.exitCode == 0, exported.describe().constData());
    QVERIFY2(exported.outText().contains(QStringLiteral(",3000.000,,plc.example:1502,tcp,")), exported.describe().constData());
    QVERIFY2(exported.errText().contains(QStringLiteral("plc.example:1502: the journal does not say the client's address: 10.0.0.1:49152 stands for it")),
             exported.describe().constData());
    QVERIFY2(exported.errText().contains(QStringLiteral("plc.example:1502: the journal does not say the server's address: 10.0.0.2:1502 stands for it")),
             exported.describe().constData());
}

// A journal of a serial line (RTU on /dev/ttyUSB0): no invented addresses; the pcapng names the
// port and tshark decodes its frames as Modbus RTU with the option export prints.
void TestCliCapture::serialJournalExported()
{
    const QString journal = m_dir.filePath(QStringLiteral("serial.mbscope.journal"));
    {
        TrafficJournalWriter writer;
        QString error;
        QVERIFY2(writer.open(journal, {}, true, &error), qPrintable(error));
        writer.addLink(0, u"rtu:///dev/ttyUSB0?baud=19200");
        writer.addFrame(TrafficEntry{0, 1000 * kMs, 1, 0, TrafficDirection::Out, TrafficVerdict::Sent, AduBuilder::rtu(QByteArray::fromHex("0300640002"), 1)});
        writer.addFrame(TrafficEntry{1, 1010 * kMs, 1, 0, TrafficDirection::In, TrafficVerdict::Ok, AduBuilder::rtu(QByteArray::fromHex("0304000a01f4"), 1)});
        writer.close();
    }
    const CliResult analysed = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(analysed.finished && analysed.exitCode == 0, analysed.describe().constData());
    const QJsonObject conversation = analysed.json().value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QVERIFY2(conversation.value(QStringLiteral("client")).isNull(), analysed.describe().constData());
    QCOMPARE(conversation.value(QStringLiteral("server")).toString(), QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(conversation.value(QStringLiteral("transport")).toString(), QStringLiteral("serial"));
    const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
    QVERIFY2(text.outText().contains(QStringLiteral("serial /dev/ttyUSB0 (Modbus RTU): 1 transactions, 1 ok")), text.describe().constData());

    const QString pcap = m_dir.filePath(QStringLiteral("serial.pcapng"));
    const CliResult exported = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--pcap"), pcap, QStringLiteral("--csv"), QStringLiteral("-")});
    QVERIFY2(exported.finished && exported.exitCode == 0, exported.describe().constData());
    QVERIFY2(exported.outText().contains(QStringLiteral(",10000.000,,/dev/ttyUSB0,rtu,1,0x03,")), exported.describe().constData());
    QVERIFY2(!exported.outText().contains(QStringLiteral("10.0.0.")), exported.describe().constData());
    QVERIFY2(exported.errText().contains(QStringLiteral("serial port /dev/ttyUSB0 (Modbus RTU): -d rtacser.data,mbrtu")), exported.describe().constData());
    if (QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty())
        QSKIP("tshark is not installed: the capture was written, not decoded");
    QProcess tshark;
    tshark.start(QStringLiteral("tshark"), {QStringLiteral("-r"), pcap, QStringLiteral("-d"), QStringLiteral("rtacser.data,mbrtu"), QStringLiteral("-T"),
                                            QStringLiteral("fields"), QStringLiteral("-E"), QStringLiteral("separator=|"), QStringLiteral("-e"),
                                            QStringLiteral("frame.interface_name"), QStringLiteral("-e"), QStringLiteral("mbrtu.unit_id"),
                                            QStringLiteral("-e"), QStringLiteral("modbus.func_code"), QStringLiteral("-e"),
                                            QStringLiteral("modbus.regval_uint16")});
    QVERIFY(tshark.waitForFinished(120000));
    QCOMPARE(QString::fromUtf8(tshark.readAllStandardOutput()).trimmed().split(QLatin1Char('\n')),
             (QStringList{QStringLiteral("/dev/ttyUSB0|1|3|"), QStringLiteral("/dev/ttyUSB0|1|3|10,500")}));
}

// Both ends record one connection: poll's journal (the engine's socket) and simulate's (its
// client) name the same two endpoints, the real ones, in analyze and in the exported capture.
void TestCliCapture::recordedEndpoints()
{
    const QString served = m_dir.filePath(QStringLiteral("ends-served.mbscope.journal"));
    const QString polled = m_dir.filePath(QStringLiteral("ends-polled.mbscope.journal"));
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--record"), served},
                       &error),
             qPrintable(error));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), sim.url(), QStringLiteral("--unit"), QStringLiteral("1"),
                                       QStringLiteral("--function"), QStringLiteral("3"), QStringLiteral("--address"), QStringLiteral("0x79"),
                                       QStringLiteral("--quantity"), QStringLiteral("2"), QStringLiteral("--count"), QStringLiteral("2"),
                                       QStringLiteral("--interval"), QStringLiteral("0"), QStringLiteral("--record"), polled});
    QVERIFY2(poll.finished && poll.exitCode == 0, poll.describe().constData());
    sim.stop();
    const QString server = sim.url().section(QStringLiteral("://"), 1);
    QString client;
    for (const QString &journal : {polled, served}) {
        const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
        QVERIFY2(a.finished && a.exitCode == 0, a.describe().constData());
        const QJsonArray conversations = a.json().value(QStringLiteral("conversations")).toArray();
        QCOMPARE(conversations.size(), 1);
        const QJsonObject c = conversations.at(0).toObject();
        QCOMPARE(c.value(QStringLiteral("server")).toString(), server);
        QVERIFY2(c.value(QStringLiteral("client")).toString().startsWith(QStringLiteral("127.0.0.1:")), a.describe().constData());
        QVERIFY(c.value(QStringLiteral("client")).toString() != QStringLiteral("127.0.0.1:0"));
        if (client.isEmpty())
            client = c.value(QStringLiteral("client")).toString();
        QCOMPARE(c.value(QStringLiteral("client")).toString(), client); // both ends saw the same connection
        QCOMPARE(c.value(QStringLiteral("transactions")).toInt(), 2);
        const QString pcap = journal + QStringLiteral(".pcapng");
        const CliResult exported = runMbscope({QStringLiteral("export"), journal, QStringLiteral("--pcap"), pcap});
        QVERIFY2(exported.finished && exported.exitCode == 0 && !exported.outText().contains(QStringLiteral("stands for it")),
                 exported.describe().constData());
        const CliResult again = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--port"), server.section(QLatin1Char(':'), 1),
                                            QStringLiteral("--json")});
        const QJsonObject captured = again.json().value(QStringLiteral("conversations")).toArray().at(0).toObject();
        QCOMPARE(captured.value(QStringLiteral("client")).toString(), client);
        QCOMPARE(captured.value(QStringLiteral("server")).toString(), server);
        // The latency says between which points a recording took its times (it said "to the
        // answer's last byte" for the engine's journal, which keeps the answer's first byte).
        const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
        const QString points = journal == polled
                                   ? QStringLiteral("latency from  the start of the request's write to the read that brought the answer's first byte\n")
                                   : QStringLiteral("latency from  the request's arrival (as the server read it) to the write of the answer's last piece\n");
        QVERIFY2(text.outText().contains(points), text.describe().constData());
        const CliResult capture = runMbscope({QStringLiteral("analyze"), pcap, QStringLiteral("--port"), server.section(QLatin1Char(':'), 1)});
        QVERIFY2(capture.outText().contains(QStringLiteral("latency from  the capture time of the packet that completed the request to that of "
                                                           "the packet that completed the answer\n")),
                 capture.describe().constData());
    }
}

// Issue 26 item 11: export overwrote a file that --record refuses to overwrite, and a path the
// permission bits allow but no file can be created at (/proc) passed the checks, the export then
// failing after reading the source. One policy for every output: an existing file is refused
// unless --force; a new one is created (and removed) before the source is read.
void TestCliCapture::outputsUnderOnePolicy()
{
    const QString csv = m_dir.filePath(QStringLiteral("kept.csv"));
    {
        QFile f(csv);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("keep me\n");
    }
    const CliResult refused = runMbscope({QStringLiteral("export"), m_good, QStringLiteral("--csv"), csv});
    QVERIFY2(refused.finished && refused.exitCode == 2, refused.describe().constData());
    QVERIFY2(refused.errText().contains(QStringLiteral("mbscope export: --csv: %1 exists: an output file is never overwritten (give another "
                                                       "name, or --force to replace it)").arg(csv)),
             refused.describe().constData());
    QCOMPARE(readFile(csv), QByteArray("keep me\n"));
    const CliResult forced = runMbscope({QStringLiteral("export"), m_good, QStringLiteral("--csv"), csv, QStringLiteral("--force")});
    QVERIFY2(forced.finished && forced.exitCode == 0, forced.describe().constData());
    QVERIFY(readFile(csv).startsWith("index,kind,"));

    // Under /proc the folder looks writable (and root passes every permission check), but no
    // file can be made there: said before the source is read, and nothing is left behind.
    for (const QString &option : {QStringLiteral("--csv"), QStringLiteral("--jsonl"), QStringLiteral("--pcap"), QStringLiteral("--histogram")}) {
        const QString proc = QStringLiteral("/proc/mbscope-test-out") + (option == QLatin1String("--histogram") ? QStringLiteral(".png") : QString());
        const CliResult r = runMbscope({QStringLiteral("export"), m_good, option, proc});
        QVERIFY2(r.finished && r.exitCode == 2, r.describe().constData());
        QVERIFY2(r.errText().startsWith(QStringLiteral("mbscope export: %1: cannot write %2: ").arg(option, proc)), r.describe().constData());
        QVERIFY2(r.out.isEmpty(), r.describe().constData());
    }
    const CliResult a = runMbscope({QStringLiteral("analyze"), m_good, QStringLiteral("--timeseries"), QStringLiteral("/proc/mbscope-test.png")});
    QVERIFY2(a.finished && a.exitCode == 2, a.describe().constData());
    QVERIFY2(a.errText().startsWith(QStringLiteral("mbscope analyze: --timeseries: cannot write /proc/mbscope-test.png: ")), a.describe().constData());
    QVERIFY2(a.out.isEmpty(), a.describe().constData()); // not analysed, then failed
    // analyze's plots follow the same policy.
    const QString png = m_dir.filePath(QStringLiteral("kept.png"));
    QVERIFY(QFile::copy(csv, png));
    const CliResult again = runMbscope({QStringLiteral("analyze"), m_good, QStringLiteral("--histogram"), png});
    QVERIFY2(again.finished && again.exitCode == 2, again.describe().constData());
    QVERIFY2(again.errText().contains(QStringLiteral("--histogram: %1 exists: ").arg(png)), again.describe().constData());
}

QTEST_GUILESS_MAIN(TestCliCapture)
#include "tst_cli_capture.moc"
