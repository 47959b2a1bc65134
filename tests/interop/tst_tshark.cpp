// An independent peer for the dissector: tshark's Modbus dissector (Wireshark 4.0, Debian 12).
// Every exchange of tsharkframes.h is written twice into captures with text2pcap, once as
// Modbus TCP (requests to port 502, responses from it, one TCP conversation with growing
// sequence numbers so tshark pairs each response with its request) and once as RTU over TCP
// (port 4001, the RosRao serial server's, read with -o mbrtu.tcp.port:4001 and CRC checking on).
// tshark prints every modbus/mbtcp/mbrtu field it knows (the list comes from `tshark -G fields`),
// and each value it shows must equal what mbscope's dissection of the same bytes says. A tshark
// field that mbscope has no counterpart for fails the row too, so nothing tshark decodes goes
// unchecked.
//
// Where tshark shows a value differently or not at all, the difference is tshark's and is
// handled explicitly (each place says why):
//  - tshark reads the RTU CRC's two bytes as a big-endian number (15 DD -> 0x15dd); mbscope
//    shows the CRC-16 value, sent low byte first (Serial Line v1.02, 2.5.1.2: 0xDD15). Compared
//    byte-swapped.
//  - tshark 4.0.17 leaves RTU-over-TCP frames shorter than 5 bytes as plain Data (requests 07,
//    0B, 0C, 11: unit, code, CRC). Those rows are skipped with that reason.
//  - tshark shows some payloads as raw "data" where mbscope names the fields: 05/06 values,
//    07 status, 0F coils, 11 (its byte count included), 17 and 18 registers, 2B/0D (its MEI
//    type included), user-defined codes. Compared as the bytes mbscope's fields cover.
//  - 14 response: tshark's data for each sub-response runs to the end of the PDU instead of
//    stopping at the sub-response's length (the first group shows both groups' registers), so
//    each of tshark's values must start with mbscope's registers of that group.
#include "protocol/checksum.h"
#include "protocol/dissector.h"
#include "tsharkexpect.h"
#include "tsharkframes.h"

#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QSet>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using namespace mbscope;
using mbscope::interop::Expected;
using mbscope::interop::FieldValues;
using mbscope::interop::kTsharkExchanges;
using mbscope::interop::TsharkExchange;

namespace {

constexpr int kRtuPort = 4001;

struct CapturedFrame {
    Framing framing = Framing::Tcp;
    Direction direction = Direction::Request;
    QByteArray bytes;
    QByteArray request; // the matching request (responses only)
    int exchange = 0;   // index in kTsharkExchanges
    int number = 0;     // frame number in its capture, from 1
};


QByteArray mbapFrame(int tid, int unit, const QByteArray &pdu)
{
    const int length = int(pdu.size()) + 1;
    QByteArray adu;
    adu.append(char(tid >> 8)).append(char(tid & 0xFF)).append('\0').append('\0');
    adu.append(char(length >> 8)).append(char(length & 0xFF)).append(char(unit));
    return adu + pdu;
}

QByteArray rtuFrame(int unit, const QByteArray &pdu, bool badCrc)
{
    QByteArray adu = QByteArray(1, char(unit)) + pdu;
    quint16 crc = checksum::crc16Modbus(adu);
    if (badCrc)
        crc ^= 0x5A5A;
    return adu.append(char(crc & 0xFF)).append(char(crc >> 8));
}

// text2pcap's hexdump: with -D, "I" (to the server's port) or "O" (from it) before a packet's
// first line; an offset, then 16 bytes a line.
QByteArray hexdump(const QList<CapturedFrame> &frames)
{
    QByteArray text;
    for (const CapturedFrame &f : frames) {
        text += f.direction == Direction::Request ? "I " : "O ";
        for (int at = 0; at < f.bytes.size(); at += 16)
            text += QByteArray::number(at, 16).rightJustified(6, '0') + ' ' + f.bytes.mid(at, 16).toHex(' ') + '\n';
    }
    return text;
}

bool run(const QString &program, const QStringList &args, QByteArray &out, QString &error)
{
    QProcess p;
    p.setProgram(program);
    p.setArguments(args);
    p.start();
    // tshark as root prints a warning on stderr: only stdout and the exit status count.
    if (!p.waitForFinished(180000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        error = program + QLatin1Char(' ') + args.join(QLatin1Char(' ')) + QStringLiteral(" failed: ")
                + QString::fromLocal8Bit(p.readAllStandardError());
        return false;
    }
    out = p.readAllStandardOutput();
    return true;
}

// "0x00f2" and "242" are the same number; everything else (bytes, text) compares as text.
QString normalised(const QString &value)
{
    if (value.startsWith(QLatin1String("0x"))) {
        bool ok = false;
        const qulonglong v = value.mid(2).toULongLong(&ok, 16);
        if (ok)
            return QString::number(v);
    }
    return value;
}

QString firstProblem(const FieldTree &t)
{
    for (const Field &f : t.fields()) {
        if (f.severity == Severity::Error)
            return QString::fromLatin1(f.key) + QStringLiteral(": ") + f.message;
    }
    return {};
}

} // namespace

class TestTshark : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void compare_data();
    void compare();
    void cleanupTestCase();

private:
    bool capture(const QString &name, const QList<CapturedFrame> &frames, const QStringList &options);

    QString m_tshark;
    QString m_text2pcap;
    QTemporaryDir m_dir;
    QStringList m_fieldArgs; // -e for every modbus/mbtcp/mbrtu field this tshark knows
    QList<CapturedFrame> m_frames;
    QMap<QPair<int, int>, FieldValues> m_decoded; // (framing, frame number) -> tshark's fields
    int m_comparedFields = 0;
    int m_comparedFrames = 0;
};

bool TestTshark::capture(const QString &name, const QList<CapturedFrame> &frames, const QStringList &options)
{
    const QString text = m_dir.filePath(name + QStringLiteral(".txt"));
    const QString pcap = m_dir.filePath(name + QStringLiteral(".pcapng"));
    QFile file(text);
    if (!file.open(QIODevice::WriteOnly) || file.write(hexdump(frames)) < 0)
        return false;
    file.close();
    const int serverPort = frames.first().framing == Framing::Tcp ? 502 : kRtuPort;
    QByteArray out;
    QString error;
    if (!run(m_text2pcap, {QStringLiteral("-q"), QStringLiteral("-D"), QStringLiteral("-T"),
                           QStringLiteral("40000,%1").arg(serverPort), text, pcap}, out, error)) {
        qWarning().noquote() << error;
        return false;
    }
    QStringList args = {QStringLiteral("-r"), pcap, QStringLiteral("-T"), QStringLiteral("fields"),
                        QStringLiteral("-E"), QStringLiteral("header=y"), QStringLiteral("-E"),
                        QStringLiteral("aggregator=|"), QStringLiteral("-e"), QStringLiteral("frame.number")};
    args += options;
    args += m_fieldArgs;
    if (!run(m_tshark, args, out, error)) {
        qWarning().noquote() << error;
        return false;
    }
    const QList<QByteArray> lines = out.split('\n');
    const QList<QByteArray> header = lines.value(0).split('\t');
    for (int l = 1; l < lines.size(); ++l) {
        const QList<QByteArray> columns = lines[l].split('\t');
        if (columns.size() != header.size())
            continue;
        FieldValues values;
        for (int c = 1; c < columns.size(); ++c) {
            if (!columns[c].isEmpty())
                values.insert(QString::fromLatin1(header[c]), QString::fromUtf8(columns[c]).split(QLatin1Char('|')));
        }
        m_decoded.insert({int(frames.first().framing), columns[0].toInt()}, values);
    }
    return true;
}

void TestTshark::initTestCase()
{
    m_tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
    m_text2pcap = QStandardPaths::findExecutable(QStringLiteral("text2pcap"));
    if (m_tshark.isEmpty() || m_text2pcap.isEmpty())
        QSKIP("tshark and text2pcap are not installed (Debian: apt-get install tshark)");
    QVERIFY(m_dir.isValid());

    QByteArray fields;
    QString error;
    QVERIFY2(run(m_tshark, {QStringLiteral("-G"), QStringLiteral("fields")}, fields, error), qPrintable(error));
    for (const QByteArray &line : fields.split('\n')) {
        const QList<QByteArray> f = line.split('\t');
        if (f.size() < 4 || f[0] != "F" || f[3] == "FT_NONE" || f[3] == "FT_PROTOCOL")
            continue;
        if (f[2].startsWith("modbus.") || f[2].startsWith("mbtcp.") || f[2].startsWith("mbrtu."))
            m_fieldArgs << QStringLiteral("-e") << QString::fromLatin1(f[2]);
    }
    QVERIFY2(m_fieldArgs.size() > 40, "tshark -G fields lists no Modbus fields");

    QList<CapturedFrame> tcp;
    QList<CapturedFrame> rtu;
    int tid = 0;
    const int count = int(std::size(kTsharkExchanges));
    for (int i = 0; i < count; ++i) {
        const TsharkExchange &ex = kTsharkExchanges[i];
        const QByteArray request = QByteArray::fromHex(ex.request);
        const QByteArray response = ex.response ? QByteArray::fromHex(ex.response) : QByteArray();
        if (ex.tcp) {
            ++tid;
            const QByteArray req = mbapFrame(tid, ex.unit, request);
            tcp.append({Framing::Tcp, Direction::Request, req, {}, i, int(tcp.size()) + 1});
            if (!response.isEmpty())
                tcp.append({Framing::Tcp, Direction::Response, mbapFrame(tid, ex.unit, response), req, i, int(tcp.size()) + 1});
        }
        if (ex.rtu) {
            const QByteArray req = rtuFrame(ex.unit, request, false);
            rtu.append({Framing::Rtu, Direction::Request, req, {}, i, int(rtu.size()) + 1});
            if (!response.isEmpty())
                rtu.append({Framing::Rtu, Direction::Response, rtuFrame(ex.unit, response, ex.badCrc), req, i,
                            int(rtu.size()) + 1});
        }
    }
    QVERIFY(capture(QStringLiteral("tcp"), tcp, {}));
    QVERIFY(capture(QStringLiteral("rtu"), rtu,
                    {QStringLiteral("-o"), QStringLiteral("mbrtu.tcp.port:%1").arg(kRtuPort), QStringLiteral("-o"),
                     QStringLiteral("mbrtu.crc_verification:TRUE")}));
    m_frames = tcp + rtu;
}

void TestTshark::compare_data()
{
    QTest::addColumn<int>("index");
    for (int i = 0; i < m_frames.size(); ++i) {
        const CapturedFrame &f = m_frames[i];
        QByteArray hex = f.bytes.left(20).toHex(' ').toUpper();
        if (f.bytes.size() > 20)
            hex += " ...";
        QTest::addRow("%s #%d %s", f.framing == Framing::Tcp ? "tcp" : "rtu", f.number, hex.constData()) << i;
    }
}

void TestTshark::compare()
{
    QFETCH(int, index);
    const CapturedFrame &frame = m_frames[index];
    const TsharkExchange &ex = kTsharkExchanges[frame.exchange];
    const FieldValues tshark = m_decoded.value({int(frame.framing), frame.number});
    if (frame.framing == Framing::Rtu && frame.bytes.size() < 5 && !tshark.contains(QStringLiteral("modbus.func_code")))
        QSKIP("tshark 4.0 leaves RTU-over-TCP frames shorter than 5 bytes undissected (shown as Data)");
    QVERIFY2(tshark.contains(QStringLiteral("modbus.func_code")),
             qPrintable(QStringLiteral("tshark did not decode the frame (%1)").arg(QString::fromLatin1(ex.source))));

    const Dissection d = Dissector::dissect(frame.bytes, {frame.framing, frame.direction, frame.request});
    if (!ex.badCrc)
        QVERIFY2(d.isValid(), qPrintable(QStringLiteral("mbscope flags a frame of %1: %2")
                                             .arg(QString::fromLatin1(ex.source), firstProblem(d.fields))));
    const Expected ours = interop::translate(d);

    static const QSet<QString> ignored = {QStringLiteral("modbus.request_frame"), QStringLiteral("modbus.response_time")};
    QSet<QString> keys(ours.values.keyBegin(), ours.values.keyEnd());
    for (auto it = tshark.keyBegin(); it != tshark.keyEnd(); ++it) {
        if (!ignored.contains(*it))
            keys.insert(*it);
    }
    QStringList problems;
    int compared = 0;
    for (const QString &key : std::as_const(keys)) {
        const QStringList theirs = tshark.value(key);
        const QStringList mine = ours.values.value(key);
        bool same = theirs.size() == mine.size();
        for (int i = 0; same && i < theirs.size(); ++i) {
            const QString a = normalised(theirs[i]);
            const QString b = normalised(mine[i]);
            same = ours.prefixKeys.contains(key) ? a.startsWith(b) : a == b;
        }
        if (same) {
            compared += int(theirs.size());
            continue;
        }
        problems << QStringLiteral("%1: tshark [%2], mbscope [%3]")
                        .arg(key, theirs.isEmpty() ? QStringLiteral("none") : theirs.join(QLatin1Char(',')),
                             mine.isEmpty() ? QStringLiteral("no such field") : mine.join(QLatin1Char(',')));
    }
    QVERIFY2(problems.isEmpty(), qPrintable(QString::fromLatin1(ex.source) + QStringLiteral(": ")
                                            + problems.join(QStringLiteral("; "))));
    m_comparedFields += compared;
    ++m_comparedFrames;
}

void TestTshark::cleanupTestCase()
{
    if (m_comparedFrames > 0)
        qInfo("compared %d values in %d frames with tshark", m_comparedFields, m_comparedFrames);
}

QTEST_GUILESS_MAIN(TestTshark)
#include "tst_tshark.moc"
