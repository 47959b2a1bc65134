// The dissector's automatic detection of framing and direction, held to a golden file
// (tests/data/dissector-detection.golden, issue 32): for a few hundred frames (valid RTU, Modbus
// TCP and ASCII requests and responses of many function codes, exceptions, write echoes that read
// the same both ways, truncated and padded frames, wrong CRC and LRC, frames that fit both an MBAP
// header and a CRC, the fuzz seeds of tests/fuzz/corpus/dissector, seeded random bytes) and six
// ways of asking (framing and direction detected, one of them given), the framing and direction
// chosen, both reasons in full, and a SHA-1 (its first 16 digits) of the table and JSON forms (every field, value and
// problem). The file was written by the detection as it was before it was made fast; it is what
// "the same behaviour" means.
//
// The frames live in the golden file: the test reads nothing else. MBSCOPE_UPDATE_EXPECTED=1
// rebuilds the frame list (from the seeds below and the fuzz corpus) and rewrites the file; read
// every line of the diff before committing it.
#include "protocol/checksum.h"
#include "protocol/dissectionformat.h"
#include "protocol/dissector.h"

#include <QtCore/QCryptographicHash>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtTest/QtTest>

#include <array>
#include <random>

using namespace mbscope;

namespace {

QString goldenPath() { return QStringLiteral(MBSCOPE_TEST_DATA_DIR "/dissector-detection.golden"); }
QString fuzzCorpusDir() { return QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../fuzz/corpus/dissector"); }

struct Ask {
    const char *name;
    Framing framing;
    Direction direction;
};
constexpr Ask kAsks[] = {
    {"auto/auto", Framing::Auto, Direction::Auto},       {"auto/request", Framing::Auto, Direction::Request},
    {"auto/response", Framing::Auto, Direction::Response}, {"rtu/auto", Framing::Rtu, Direction::Auto},
    {"tcp/auto", Framing::Tcp, Direction::Auto},         {"ascii/auto", Framing::Ascii, Direction::Auto},
};

QByteArray hex(const char *text) { return QByteArray::fromHex(QByteArray(text)); }

QByteArray withCrc(const QByteArray &body)
{
    const quint16 crc = checksum::crc16Modbus(body);
    return body + char(crc & 0xFF) + char(crc >> 8);
}

QByteArray mbap(quint16 transaction, quint8 unit, const QByteArray &pdu)
{
    QByteArray b;
    const int length = int(pdu.size()) + 1;
    b += char(transaction >> 8);
    b += char(transaction & 0xFF);
    b += '\0';
    b += '\0';
    b += char(length >> 8);
    b += char(length & 0xFF);
    b += char(unit);
    return b + pdu;
}

QByteArray ascii(quint8 unit, const QByteArray &pdu, bool lower = false)
{
    const QByteArray body = char(unit) + pdu;
    QByteArray text = (body + char(checksum::lrc(body))).toHex().toUpper();
    if (lower)
        text = text.toLower();
    return ':' + text + "\r\n";
}

// Escapes what would break a tab-separated line.
QString escaped(const QString &s)
{
    QString out = s;
    out.replace(QLatin1Char('\\'), QStringLiteral("\\\\"));
    out.replace(QLatin1Char('\t'), QStringLiteral("\\t"));
    out.replace(QLatin1Char('\n'), QStringLiteral("\\n"));
    out.replace(QLatin1Char('\r'), QStringLiteral("\\r"));
    return out;
}

// One line of the golden file: ask, frame, framing, direction, digest, framing reason, direction
// reason. The frame and the reasons are written out on the first ask's line (both detected); the
// other asks' lines say "^" for the frame and hold their reasons in the digest alone, which keeps
// the file a readable size.
QString describe(const QByteArray &frame, const Ask &ask)
{
    const bool full = &ask == &kAsks[0];
    const Dissection d = Dissector::dissect(frame, {ask.framing, ask.direction, {}});
    const QByteArray forms = DissectionFormat::toTable(d, 1 << 20).toUtf8() + '\n'
                             + QJsonDocument(DissectionFormat::toJson(d)).toJson(QJsonDocument::Compact);
    const QString digest = QString::fromLatin1(QCryptographicHash::hash(forms, QCryptographicHash::Sha1).toHex().left(16));
    return QStringList{QString::fromLatin1(ask.name),
                       !full ? QStringLiteral("^") : frame.isEmpty() ? QStringLiteral("-") : QString::fromLatin1(frame.toHex()),
                       framingName(d.framing),
                       directionName(d.direction),
                       digest,
                       full ? escaped(QString(d.framingReason)) : QStringLiteral("^"),
                       full ? escaped(QString(d.directionReason)) : QStringLiteral("^")}
        .join(QLatin1Char('\t'));
}

// The PDUs the seeds are built from: requests and responses of the public function codes
// (V1.1b3, 6.1-6.21), write echoes, exceptions.
QList<QByteArray> pdus()
{
    QList<QByteArray> p = {
        hex("0100130013"), hex("01030DFE20"), hex("0102000007D0"), hex("01020003"),          // 01
        hex("020000C40016"), hex("020300AC DB35"), hex("0200000800"),                         // 02
        hex("0300790016"), hex("03006B0003"), hex("0306022B00000064"), hex("0300000000"),     // 03
        hex("040008 0001"), hex("040200 0A"), hex("04007D"),                                  // 04
        hex("0500ACFF00"), hex("0500AC1234"), hex("06000100 03"), hex("0600010003"),          // 05, 06
        hex("07"), hex("076D"), hex("080000A537"), hex("080001 0000"), hex("0B"), hex("0B00000108"),
        hex("0C"), hex("0C080000010800 0121 0020 00"), hex("11"), hex("1108 0000FF"),
        hex("0F0013000A02CD01"), hex("0F0013000A"), hex("100001000204000A0102"), hex("1000010002"),
        hex("14 0E 06 0004 0001 0002 06 0003 0009 0002"), hex("150D06000400070003 06AF04BE100D"),
        hex("16000400F20025"), hex("17000300060000E0003FF"), hex("170C00FE0ACD00010003000D00FF"),
        hex("18 04DE"), hex("1800060002 01B8 1284"), hex("2B0E0100"), hex("2B0E01010000030016"),
        hex("8102"), hex("8302"), hex("8601"), hex("9004"), hex("AB01"), hex("8B0B"),
        hex("4100"), hex("64"), hex("FF0102"),
    };
    // Register reads of several sizes, up to the largest (125 registers, byte count 250).
    for (int count : {1, 2, 10, 22, 60, 124, 125}) {
        QByteArray r = hex("03") + char(2 * count);
        for (int i = 0; i < count; ++i)
            r += char((i * 37) & 0xFF) + QByteArray(1, char((i * 91) & 0xFF));
        p += r;
        r[0] = 0x04;
        p += r;
    }
    return p;
}

QList<QByteArray> seedFrames()
{
    QList<QByteArray> out;
    const auto add = [&out](const QByteArray &f) {
        if (!out.contains(f))
            out += f;
    };
    // Edge sizes and starts.
    for (const QByteArray &f : {QByteArray(), hex("00"), hex("01"), hex("3A"), hex("0103"), hex("010315"),
                                QByteArray(":"), QByteArray(":\r\n"), QByteArray("\r\n"), hex("0000"),
                                hex("00000000000000"), hex("0000000000000000")})
        add(f);
    const QList<QByteArray> p = pdus();
    int i = 0;
    for (const QByteArray &pdu : p) {
        const quint8 unit = std::array<quint8, 5>{1, 17, 0, 247, 255}[size_t(i % 5)];
        const QByteArray rtu = withCrc(char(unit) + pdu);
        add(rtu);
        add(mbap(quint16(i * 257 + 1), unit, pdu));
        add(ascii(unit, pdu));
        if (i % 3 == 0) {
            // Damaged copies: the CRC wrong, cut short, one byte too many, the MBAP length off.
            QByteArray bad = rtu;
            bad[bad.size() - 1] = char(bad.at(bad.size() - 1) ^ 0x5A);
            add(bad);
            add(rtu.left(rtu.size() - 1));
            add(rtu.left(rtu.size() / 2));
            add(rtu + char(0x42));
            add(rtu + withCrc(hex("0103")));
            QByteArray tcp = mbap(quint16(i), unit, pdu);
            tcp[5] = char(tcp.at(5) + 1);
            add(tcp);
            tcp[5] = char(0);
            add(tcp);
            add(mbap(quint16(i), unit, pdu).left(7 + int(pdu.size()) / 2));
            QByteArray proto = mbap(quint16(i), unit, pdu);
            proto[3] = char(1);
            add(proto);
            add(mbap(quint16(i), unit, pdu) + hex("00"));
            QByteArray a = ascii(unit, pdu);
            add(a.left(a.size() - 2));
            a[a.size() - 3] = a.at(a.size() - 3) == '0' ? '1' : '0';
            add(a);
            add(ascii(unit, pdu, true));
            add(ascii(unit, pdu).mid(1));
        }
        ++i;
    }
    // Ambiguous: an MBAP frame whose last two bytes are the CRC of those before them (a write
    // whose value is chosen to be that CRC), and the same with the length one off.
    for (quint16 tid : {quint16(1), quint16(0x1234), quint16(0xFFFF)}) {
        const QByteArray head = mbap(tid, 1, hex("060010"));
        QByteArray both = head;
        both[5] = char(both.at(5) + 2);
        add(withCrc(both));
        QByteArray lengthOff = withCrc(both);
        lengthOff[5] = char(lengthOff.at(5) + 1);
        add(lengthOff);
        QByteArray read = mbap(tid, 1, hex("03000A"));
        read[5] = char(read.at(5) + 2);
        add(withCrc(read));
    }
    // Too long for any framing.
    add(withCrc(hex("0110") + QByteArray(300, '\x11')));
    add(mbap(7, 1, hex("10") + QByteArray(260, '\x22')));
    add(':' + QByteArray(600, 'A') + "\r\n");
    // Seeded random bytes, some of them with a ':' start or an MBAP-like header.
    std::mt19937 rng(32);
    for (int k = 0; k < 90; ++k) {
        const int size = int(rng() % (k < 60 ? 24 : 300));
        QByteArray b;
        for (int j = 0; j < size; ++j)
            b += char(rng() & 0xFF);
        if (k % 9 == 1 && !b.isEmpty())
            b[0] = ':';
        if (k % 9 == 2 && b.size() >= 8) {
            b[2] = 0;
            b[3] = 0;
            b[4] = char((b.size() - 6) >> 8);
            b[5] = char((b.size() - 6) & 0xFF);
        }
        if (k % 9 == 3 && b.size() >= 4)
            b = withCrc(b.left(b.size() - 2));
        add(b);
    }
    // The fuzz seeds: the frame part of each input (the layout of tests/fuzz/fuzz_dissector.cpp).
    const QDir corpus(fuzzCorpusDir());
    for (const QString &name : corpus.entryList(QDir::Files, QDir::Name)) {
        QFile file(corpus.filePath(name));
        if (!file.open(QIODevice::ReadOnly))
            continue;
        const QByteArray data = file.readAll();
        if (data.isEmpty())
            continue;
        qsizetype at = 1;
        if ((quint8(data.at(0)) & 0x20) && at < data.size())
            at += 1 + qMin<qsizetype>(quint8(data.at(at)), data.size() - at - 1);
        add(data.mid(at));
    }
    return out;
}

} // namespace

class TestDissectorDetect : public QObject
{
    Q_OBJECT

private slots:
    void golden();
    void longReadCodeNeverReadsCleanAsRequest();
};

// The rule detection takes as given when it reads an RTU frame of a read code (01-04) longer
// than 8 bytes with a valid CRC as a response first: read as a request, such a frame always has
// an error (issue 32). Held here for any length and content, so that a change to the PDU layer
// that broke it shows.
void TestDissectorDetect::longReadCodeNeverReadsCleanAsRequest()
{
    std::mt19937 rng(3201);
    for (int k = 0; k < 4000; ++k) {
        QByteArray body;
        body += char(rng() % 256);
        body += char(1 + k % 4);
        const int more = 5 + int(rng() % 252); // the frame: 2 + more + 2 > 8 bytes
        for (int j = 0; j < more; ++j)
            body += char(rng() & 0xFF);
        if (k % 5 == 0 && body.size() >= 8) {
            // A valid CRC right after the 5-byte PDU as well: the RTU layer ends the request there.
            const QByteArray head = withCrc(body.left(6));
            body.replace(0, 8, head);
        }
        const QByteArray frame = withCrc(body);
        const Dissection d = Dissector::dissect(frame, {Framing::Rtu, Direction::Request, {}});
        QVERIFY2(d.fields.worstSeverity() == Severity::Error, qPrintable(DissectionFormat::toTable(d)));
    }
}

void TestDissectorDetect::golden()
{
    if (qEnvironmentVariableIsSet("MBSCOPE_UPDATE_EXPECTED")) {
        QStringList lines;
        for (const QByteArray &frame : seedFrames()) {
            for (const Ask &ask : kAsks)
                lines += describe(frame, ask);
        }
        QFile out(goldenPath());
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write("# ask\tframe\tframing\tdirection\tsha1(table, json), 16 digits\tframing reason\tdirection reason\n"
                  "# written by tst_dissectordetect with MBSCOPE_UPDATE_EXPECTED=1; see its header\n");
        out.write(lines.join(QLatin1Char('\n')).toUtf8() + '\n');
        return;
    }
    QFile in(goldenPath());
    QVERIFY2(in.open(QIODevice::ReadOnly), qPrintable(goldenPath() + QStringLiteral(": missing")));
    int checked = 0;
    int frames = 0;
    QByteArray frame;
    const QList<QByteArray> lines = in.readAll().split('\n');
    for (const QByteArray &raw : lines) {
        if (raw.isEmpty() || raw.startsWith('#'))
            continue;
        const QString expected = QString::fromUtf8(raw);
        const QStringList cells = expected.split(QLatin1Char('\t'));
        QCOMPARE(cells.size(), 7);
        const Ask *ask = nullptr;
        for (const Ask &a : kAsks)
            ask = cells.at(0) == QLatin1String(a.name) ? &a : ask;
        QVERIFY2(ask, qPrintable(cells.at(0)));
        if (cells.at(1) != QLatin1String("^"))
            frame = cells.at(1) == QLatin1String("-") ? QByteArray() : QByteArray::fromHex(cells.at(1).toLatin1());
        QVERIFY2(ask == &kAsks[0] || cells.at(1) == QLatin1String("^"), "only the first ask of a frame names it");
        const QString actual = describe(frame, *ask);
        if (actual != expected) {
            const Dissection d = Dissector::dissect(frame, {ask->framing, ask->direction, {}});
            QFAIL(qPrintable(QStringLiteral("%1 %2\nexpected: %3\nactual:   %4\n%5")
                                 .arg(cells.at(0), cells.at(1), expected, actual, DissectionFormat::toTable(d))));
        }
        ++checked;
        frames += ask == &kAsks[0] ? 1 : 0;
    }
    qInfo("%d frames, %d readings checked", frames, checked);
    QVERIFY2(frames >= 300, "the golden file holds too few frames");
    QCOMPARE(checked, frames * int(std::size(kAsks)));
}

QTEST_GUILESS_MAIN(TestDissectorDetect)
#include "tst_dissectordetect.moc"
