// mbscope's captures against tshark's Modbus dissector, both ways:
// - a pcapng (or pcap) written by mbscope from exchanges is read by tshark, which must find the
//   same function codes, addresses, register values and exception codes (RTU over TCP with the
//   decode option mbscope prints);
// - tshark captures the loopback while a client talks to pymodbus (Modbus TCP and RTU over
//   TCP); mbscope analyses tshark's file and must pair the same request and response packets
//   as tshark's modbus.request_frame, with latencies equal to its modbus.response_time.
#include "peerprocess.h"
#include "tsharkcapture.h"

#include "capture/capturefilewriter.h"
#include "capture/exchangepcapexporter.h"
#include "capture/exchangesource.h"
#include "protocol/adubuilder.h"

#include <QtCore/QHash>
#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QTest>

#include <vector>

using namespace mbscope;
using namespace mbscope::testpeers;

Q_DECLARE_METATYPE(std::vector<mbscope::CaptureExchange>)

namespace {

constexpr qint64 kStart = 1'750'000'000'000'000'000LL;
constexpr qint64 kMs = 1'000'000;

bool tsharkAvailable(QString *why)
{
    if (!QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty())
        return true;
    *why = QStringLiteral("tshark is not installed (Debian: apt-get install tshark, or scripts/install-deps.sh --tests)");
    return false;
}

// tshark's fields, one line per packet the filter keeps; false with the reason on failure.
bool tsharkFields(const QStringList &arguments, QStringList *lines, QString *error)
{
    QProcess tshark;
    tshark.start(QStringLiteral("tshark"), arguments);
    if (!tshark.waitForFinished(120000) || tshark.exitStatus() != QProcess::NormalExit || tshark.exitCode() != 0) {
        *error = QStringLiteral("tshark %1 failed: %2").arg(arguments.join(QLatin1Char(' ')), QString::fromLocal8Bit(tshark.readAllStandardError()));
        return false;
    }
    lines->clear();
    for (const QByteArray &line : tshark.readAllStandardOutput().split('\n')) {
        if (!line.trimmed().isEmpty())
            lines->append(QString::fromUtf8(line).trimmed());
    }
    return true;
}

CaptureExchange exchange(Framing framing, const QByteArray &request, qint64 sentNs, const QByteArray &response, qint64 doneNs)
{
    CaptureExchange e;
    e.framing = framing;
    e.transaction.request = request;
    e.transaction.response = response;
    e.transaction.sentNs = sentNs;
    e.transaction.doneNs = e.transaction.firstByteNs = doneNs;
    e.transaction.status = response.isEmpty() ? TransactionStatus::Timeout : TransactionStatus::Ok;
    return e;
}

QByteArray mbap(quint16 tid, const char *pduHex)
{
    return AduBuilder::mbap(QByteArray::fromHex(pduHex), 1, tid);
}

QByteArray rtu(quint8 unit, const char *pduHex)
{
    return AduBuilder::rtu(QByteArray::fromHex(pduHex), unit);
}

// "0.000512345" seconds to nanoseconds, exactly.
qint64 secondsTextToNs(const QString &text)
{
    const qsizetype dot = text.indexOf(QLatin1Char('.'));
    const qint64 seconds = (dot < 0 ? text : text.left(dot)).toLongLong();
    const QString fraction = dot < 0 ? QString() : text.mid(dot + 1).left(9).leftJustified(9, QLatin1Char('0'));
    return seconds * 1000000000LL + fraction.toLongLong();
}

// One request, then its whole answer: MBAP by its length field, RTU by the size the caller
// predicts. False with the reason when the answer does not come.
bool exchangeOnSocket(QTcpSocket &socket, const QByteArray &request, qsizetype rtuAnswerSize, QString *error)
{
    socket.write(request);
    if (!socket.waitForBytesWritten(5000)) {
        *error = QStringLiteral("cannot write: %1").arg(socket.errorString());
        return false;
    }
    QByteArray answer;
    for (;;) {
        const qsizetype want = rtuAnswerSize > 0 ? rtuAnswerSize : (answer.size() >= 6 ? 6 + (quint8(answer[4]) << 8 | quint8(answer[5])) : 6);
        if (answer.size() >= want)
            return true;
        if (!socket.waitForReadyRead(5000)) {
            *error = QStringLiteral("no answer to %1 (got %2)").arg(QString::fromLatin1(request.toHex(' ')), QString::fromLatin1(answer.toHex(' ')));
            return false;
        }
        answer += socket.readAll();
    }
}

} // namespace

class TestCaptureTshark : public QObject
{
    Q_OBJECT

private slots:
    void writtenCaptureDecodedByTshark_data();
    void writtenCaptureDecodedByTshark();
    void tsharkCaptureAnalysed_data();
    void tsharkCaptureAnalysed();
};

void TestCaptureTshark::writtenCaptureDecodedByTshark_data()
{
    QTest::addColumn<std::vector<CaptureExchange>>("exchanges");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("expected"); // func|reference|word count|register values|exception|data, per Modbus packet
    QTest::addColumn<QString>("serialPort"); // a serial line's conversation (a journal of an rtu:// link)

    const Framing tcp = Framing::Tcp;
    const std::vector<CaptureExchange> mbapExchanges{
        // 03: 2 registers from 100, answered 10 and 500.
        exchange(tcp, mbap(1, "0300640002"), kStart, mbap(1, "0304000a01f4"), kStart + 2 * kMs),
        // 10: 3 registers from 7 written 1, 2, 65535.
        exchange(tcp, mbap(2, "100007000306000100 02ffff"), kStart + 10 * kMs, mbap(2, "1000070003"), kStart + 12 * kMs),
        // 03 past the end: exception 02.
        exchange(tcp, mbap(3, "0327100001"), kStart + 20 * kMs, mbap(3, "8302"), kStart + 21 * kMs),
        // 06: register 5 set to 4660.
        exchange(tcp, mbap(4, "0600051234"), kStart + 30 * kMs, mbap(4, "0600051234"), kStart + 31 * kMs),
    };
    // tshark shows a single write's value as bytes (modbus.data), the others as registers.
    const QStringList mbapExpected{
        QStringLiteral("3|100|2|||"),        QStringLiteral("3|||10,500||"),
        QStringLiteral("16|7|3|1,2,65535||"), QStringLiteral("16|7|3|||"),
        QStringLiteral("3|10000|1|||"),      QStringLiteral("3||||2|"), // tshark's func_code is the 7-bit code
        QStringLiteral("6|5||||1234"),       QStringLiteral("6|5||||1234"),
    };
    QTest::newRow("modbus tcp, pcapng") << mbapExchanges << QStringLiteral("x.pcapng") << mbapExpected << QString();
    QTest::newRow("modbus tcp, classic pcap") << mbapExchanges << QStringLiteral("x.pcap") << mbapExpected << QString();

    const Framing r = Framing::Rtu;
    QTest::newRow("rtu over tcp on port 4001, with the option mbscope prints")
        << std::vector{exchange(r, rtu(1, "0300790003"), kStart, rtu(1, "0306000100020003"), kStart + 40 * kMs),
                       exchange(r, rtu(1, "0400000001"), kStart + 100 * kMs, rtu(1, "8402"), kStart + 130 * kMs)}
        << QStringLiteral("x.pcapng")
        << QStringList{QStringLiteral("3|121|3|||"), QStringLiteral("3|||1,2,3||"), QStringLiteral("4|0|1|||"), QStringLiteral("4||||2|")}
        << QString();
    // Issue 26 item 9: a serial line's RTU on an interface named after its port (RTAC serial link
    // type, tshark -d rtacser.data,mbrtu), and in a pcap file as RTU over TCP on 4001.
    const std::vector serial{exchange(r, rtu(1, "0300790003"), kStart, rtu(1, "0306000100020003"), kStart + 40 * kMs),
                             exchange(r, rtu(1, "0400000001"), kStart + 100 * kMs, rtu(1, "8402"), kStart + 130 * kMs)};
    const QStringList serialExpected{QStringLiteral("3|121|3|||"), QStringLiteral("3|||1,2,3||"), QStringLiteral("4|0|1|||"),
                                     QStringLiteral("4||||2|")};
    QTest::newRow("rtu on a serial port, pcapng") << serial << QStringLiteral("x.pcapng") << serialExpected << QStringLiteral("/dev/ttyUSB0");
    QTest::newRow("rtu on a serial port, classic pcap") << serial << QStringLiteral("x.pcap") << serialExpected << QStringLiteral("/dev/ttyUSB0");
}

void TestCaptureTshark::writtenCaptureDecodedByTshark()
{
    QFETCH(std::vector<CaptureExchange>, exchanges);
    QFETCH(QString, file);
    QFETCH(QStringList, expected);
    QFETCH(QString, serialPort);
    QString why;
    if (!tsharkAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(file);
    CaptureFileWriter writer;
    QString error;
    QVERIFY2(writer.open(path, CaptureFileWriter::formatFor(path), &error), qPrintable(error));
    ExchangePcapExporter exporter(writer);
    if (!serialPort.isEmpty()) {
        CaptureConversation line;
        line.framing = Framing::Rtu;
        line.serialPort = serialPort;
        line.clientKnown = line.serverKnown = false;
        line.client.bytes = {10, 0, 0, 1};
        line.server.bytes = {10, 0, 0, 2};
        line.clientPort = 49152;
        line.serverPort = 4001;
        exporter.addConversation(line);
    }
    for (const CaptureExchange &e : exchanges)
        exporter.add(e);
    exporter.finish();
    QVERIFY2(writer.close(&error), qPrintable(error));
    if (!serialPort.isEmpty() && file.endsWith(QLatin1String(".pcapng"))) {
        // The port names the interface its frames are on, and nothing else is in the file.
        QStringList names;
        QVERIFY2(tsharkFields({QStringLiteral("-r"), path, QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"),
                               QStringLiteral("frame.interface_name"), QStringLiteral("-e"), QStringLiteral("frame.interface_description"),
                               QStringLiteral("-E"), QStringLiteral("separator=|")},
                              &names, &error),
                 qPrintable(error));
        QCOMPARE(names, QStringList(4, QStringLiteral("/dev/ttyUSB0|Modbus RTU on serial port /dev/ttyUSB0")));
        QCOMPARE(exporter.decodeOptions(), QStringList{QStringLiteral("serial port /dev/ttyUSB0 (Modbus RTU): -d rtacser.data,mbrtu")});
    }

    QStringList arguments{QStringLiteral("-r"), path};
    // The option mbscope export prints for each port tshark does not know.
    for (const QString &option : exporter.decodeOptions())
        arguments << option.section(QStringLiteral(": "), 1).split(QLatin1Char(' '));
    arguments << QStringLiteral("-Y") << QStringLiteral("modbus") << QStringLiteral("-T") << QStringLiteral("fields")
              << QStringLiteral("-E") << QStringLiteral("separator=|");
    for (const char *field :
         {"modbus.func_code", "modbus.reference_num", "modbus.word_cnt", "modbus.regval_uint16", "modbus.exception_code", "modbus.data"})
        arguments << QStringLiteral("-e") << QString::fromLatin1(field);
    QStringList lines;
    QVERIFY2(tsharkFields(arguments, &lines, &error), qPrintable(error));
    QCOMPARE(lines, expected);

    // tshark finds nothing wrong with the packets themselves (checksums, sequence numbers).
    QVERIFY2(tsharkFields({QStringLiteral("-r"), path, QStringLiteral("-o"), QStringLiteral("tcp.check_checksum:TRUE"),
                           QStringLiteral("-o"), QStringLiteral("ip.check_checksum:TRUE"), QStringLiteral("-Y"),
                           QStringLiteral("tcp.analysis.flags || tcp.checksum.status == 0 || ip.checksum.status == 0 || _ws.malformed"),
                           QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"), QStringLiteral("frame.number")},
                          &lines, &error),
             qPrintable(error));
    QVERIFY2(lines.isEmpty(), qPrintable(QStringLiteral("packets tshark finds fault with: ") + lines.join(QLatin1Char(' '))));
}

void TestCaptureTshark::tsharkCaptureAnalysed_data()
{
    QTest::addColumn<QString>("mode");
    QTest::newRow("pymodbus, modbus tcp") << QStringLiteral("tcp");
    QTest::newRow("pymodbus, rtu over tcp") << QStringLiteral("rtu-tcp");
}

void TestCaptureTshark::tsharkCaptureAnalysed()
{
    QFETCH(QString, mode);
    const bool rtuMode = mode == QLatin1String("rtu-tcp");
    QString why;
    if (!tsharkAvailable(&why) || !pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    PeerProcess server;
    QVERIFY2(server.start(systemPython(), {peersDir() + QStringLiteral("/pymodbus_server.py"), mode}), qPrintable(server.error()));
    TsharkCapture capture;
    if (!capture.start(server.port()))
        QSKIP(qPrintable(capture.error()));

    // 150 exchanges: reads of 5 registers, reads past the end (exception 02), single writes.
    constexpr int kCount = 150;
    int exceptions = 0;
    {
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), server.port());
        QVERIFY2(socket.waitForConnected(5000), qPrintable(socket.errorString()));
        for (int i = 0; i < kCount; ++i) {
            QByteArray pdu;
            qsizetype rtuAnswer = 0;
            if (i % 10 == 9) {
                pdu = QByteArray::fromHex("03270f0005"); // 9999..10003: past the end
                rtuAnswer = 5;
                ++exceptions;
            } else if (i % 10 == 5) {
                pdu = QByteArray::fromHex("060100") + char(i >> 8) + char(i);
                rtuAnswer = 8;
            } else {
                pdu = QByteArray::fromHex("03") + char(i >> 8) + char(i) + QByteArray::fromHex("0005");
                rtuAnswer = 15;
            }
            const QByteArray request = rtuMode ? AduBuilder::rtu(pdu, 1) : AduBuilder::mbap(pdu, 1, quint16(i + 1));
            QString error;
            QVERIFY2(exchangeOnSocket(socket, request, rtuMode ? rtuAnswer : 0, &error), qPrintable(error));
        }
        socket.disconnectFromHost();
    }
    QList<WireSegment> segments;
    QVERIFY2(capture.stopAndRead(&segments), qPrintable(capture.error()));

    CaptureOptions options;
    options.mbapPorts.clear();
    (rtuMode ? options.rtuPorts : options.mbapPorts) = {server.port()};
    std::vector<CaptureExchange> pairs;
    const ExchangeSourceReport report = ExchangeSource::read(capture.filePath(), options, [&](const CaptureExchange &e) { pairs.push_back(e); });
    QVERIFY2(report.isComplete(), qPrintable(report.error));
    QCOMPARE(report.frames.lostBytes, qint64(0));
    QCOMPARE(report.frames.skippedBytes, qint64(0));
    QCOMPARE(int(pairs.size()), kCount);
    int seenExceptions = 0;
    for (const CaptureExchange &e : pairs) {
        QVERIFY2(e.transaction.status == TransactionStatus::Ok || e.transaction.status == TransactionStatus::Exception,
                 qPrintable(transactionStatusName(e.transaction.status) + QStringLiteral(": ") + e.transaction.problem));
        seenExceptions += e.transaction.status == TransactionStatus::Exception;
    }
    QCOMPARE(seenExceptions, exceptions);

    QStringList arguments{QStringLiteral("-r"), capture.filePath()};
    arguments << QStringLiteral("-o") << QStringLiteral("%1.tcp.port:%2").arg(rtuMode ? QStringLiteral("mbrtu") : QStringLiteral("mbtcp")).arg(server.port());
    arguments << QStringLiteral("-Y") << QStringLiteral("modbus.request_frame") << QStringLiteral("-T") << QStringLiteral("fields")
              << QStringLiteral("-e") << QStringLiteral("modbus.request_frame") << QStringLiteral("-e") << QStringLiteral("frame.number")
              << QStringLiteral("-e") << QStringLiteral("modbus.response_time");
    QStringList lines;
    QString error;
    QVERIFY2(tsharkFields(arguments, &lines, &error), qPrintable(error));
    // tshark pairs every answer but exceptions (it gives those no request_frame): every pair it
    // makes must be mbscope's, with the same latency; the rest must be mbscope's exceptions.
    QHash<quint64, QPair<quint64, qint64>> tsharkPairs; // response frame -> request frame, ns
    for (const QString &line : lines) {
        const QStringList f = line.split(QLatin1Char('\t'));
        QCOMPARE(f.size(), 3);
        tsharkPairs.insert(f.at(1).toULongLong(), {f.at(0).toULongLong(), secondsTextToNs(f.at(2))});
    }
    QCOMPARE(int(tsharkPairs.size()), kCount - exceptions);
    qint64 largestDifference = 0;
    int compared = 0;
    for (const CaptureExchange &e : pairs) {
        const auto found = tsharkPairs.constFind(e.responsePacket);
        const QString where = QStringLiteral("mbscope packets %1 -> %2 (%3)")
                                  .arg(e.requestPacket).arg(e.responsePacket).arg(transactionStatusName(e.transaction.status));
        if (found == tsharkPairs.cend()) {
            QVERIFY2(e.transaction.status == TransactionStatus::Exception, qPrintable(where + QStringLiteral(": not paired by tshark")));
            continue;
        }
        QVERIFY2(e.requestPacket == found->first, qPrintable(where + QStringLiteral(", tshark's request %1").arg(found->first)));
        largestDifference = std::max(largestDifference, std::abs(e.transaction.latencyNs() - found->second));
        ++compared;
    }
    QCOMPARE(compared, kCount - exceptions);
    // Both are differences of the same two capture time stamps (microseconds on a pcapng from
    // dumpcap): they agree exactly.
    QCOMPARE(largestDifference, qint64(0));
}

QTEST_GUILESS_MAIN(TestCaptureTshark)
#include "tst_capture_tshark.moc"
