// WatchBlock and WatchDecoder: the request of a watch, its answer read into words or bits (Enron
// answers carry four bytes per address), and the values decoded: formats and byte orders, scale,
// offset, units, bit fields with state names, unnamed addresses.
#include "watch/watchblock.h"
#include "watch/watchdecoder.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

WatchDefinition block(quint8 function, quint16 address, quint16 quantity, bool enron = false)
{
    WatchDefinition w;
    w.name = QStringLiteral("w");
    w.function = function;
    w.address = address;
    w.quantity = quantity;
    w.enron32 = enron;
    return w;
}

WatchPoint point(quint16 address, const QString &name, const QString &format)
{
    WatchPoint p;
    p.address = address;
    p.name = name;
    p.format = RegisterFormat::parse(format).format;
    return p;
}

} // namespace

class TestWatchDecoder : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void limits();
    void requestPdu();
    void readAnswer_data();
    void readAnswer();
    void formats_data();
    void formats();
    void scaleUnitAndUnnamed();
    void enronValues();
    void bitFields();
    void coils();
    void writePdu();
};

void TestWatchDecoder::limits()
{
    QCOMPARE(WatchBlock::maxQuantity(1, false), 2000);
    QCOMPARE(WatchBlock::maxQuantity(3, false), 125);
    QCOMPARE(WatchBlock::maxQuantity(4, true), 62); // 62 x 4 = 248 bytes; 63 x 4 = 252 > 251
    QCOMPARE(WatchBlock::maxQuantity(0x18, false), 31);
    QCOMPARE(WatchBlock::maxQuantity(0x17, false), 0);
}

void TestWatchDecoder::requestPdu()
{
    QCOMPARE(WatchBlock::requestPdu(block(3, 0x79, 22)).toHex(' '), QByteArray("03 00 79 00 16"));
    QCOMPARE(WatchBlock::requestPdu(block(3, 7000, 2, true)).toHex(' '), QByteArray("03 1b 58 00 02"));
    QCOMPARE(WatchBlock::requestPdu(block(0x18, 0x04DE, 31)).toHex(' '), QByteArray("18 04 de"));
}

void TestWatchDecoder::readAnswer_data()
{
    QTest::addColumn<int>("function");
    QTest::addColumn<int>("quantity");
    QTest::addColumn<bool>("enron");
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("words");
    QTest::addColumn<QString>("error");
    QTest::newRow("03 two registers") << 3 << 2 << false << QByteArray::fromHex("0304 041a 0000") << u"041a 0000"_qs << QString();
    QTest::newRow("03 enron two values") << 3 << 2 << true << QByteArray::fromHex("0308 42f6e979 00000001") << u"42f6 e979 0000 0001"_qs << QString();
    QTest::newRow("03 enron read as 16-bit") << 3 << 2 << true << QByteArray::fromHex("0304 42f6 e979") << QString()
                                             << u"the byte count is 4, 8 expected for 2 32-bit registers"_qs;
    QTest::newRow("byte count against bytes") << 3 << 2 << false << QByteArray::fromHex("0304 041a 00") << QString()
                                              << u"the byte count says 4 bytes but 3 follow it"_qs;
    QTest::newRow("exception") << 3 << 2 << false << QByteArray::fromHex("8302") << QString() << u"exception 0x02"_qs;
    QTest::newRow("other function") << 3 << 2 << false << QByteArray::fromHex("0404 0000 0000") << QString()
                                    << u"the answer is to function 0x04, not 0x03"_qs;
    QTest::newRow("fifo of two") << 0x18 << 31 << false << QByteArray::fromHex("18 0006 0002 01b8 1284") << u"01b8 1284"_qs << QString();
    QTest::newRow("fifo count wrong") << 0x18 << 31 << false << QByteArray::fromHex("18 0006 0003 01b8 1284") << QString()
                                      << u"the FIFO answer's byte count 6 does not match its FIFO count 3 and 6 bytes"_qs;
}

void TestWatchDecoder::readAnswer()
{
    QFETCH(int, function);
    QFETCH(int, quantity);
    QFETCH(bool, enron);
    QFETCH(QByteArray, pdu);
    QFETCH(QString, words);
    QFETCH(QString, error);
    const WatchAnswer a = WatchBlock::readAnswer(block(quint8(function), 0, quint16(quantity), enron), pdu);
    QCOMPARE(a.error, error);
    QCOMPARE(a.ok, error.isEmpty());
    QStringList hex;
    for (quint16 w : a.words)
        hex.append(QString::number(w, 16).rightJustified(4, QLatin1Char('0')));
    QCOMPARE(hex.join(QLatin1Char(' ')), words);
}

void TestWatchDecoder::formats_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<QList<quint16>>("words");
    QTest::addColumn<QString>("text");
    // float 123.456 is 0x42F6E979 (registerformat.h's table)
    QTest::newRow("f32-abcd") << u"f32-abcd"_qs << QList<quint16>{0x42F6, 0xE979} << u"123.456"_qs;
    QTest::newRow("f32-cdab") << u"f32-cdab"_qs << QList<quint16>{0xE979, 0x42F6} << u"123.456"_qs;
    QTest::newRow("f32-badc") << u"f32-badc"_qs << QList<quint16>{0xF642, 0x79E9} << u"123.456"_qs;
    QTest::newRow("f32-dcba") << u"f32-dcba"_qs << QList<quint16>{0x79E9, 0xF642} << u"123.456"_qs;
    QTest::newRow("i16") << u"i16"_qs << QList<quint16>{0xFFFF, 0} << u"-1"_qs;
    QTest::newRow("u16-ba") << u"u16-ba"_qs << QList<quint16>{0x0100, 0} << u"1"_qs;
    QTest::newRow("u32-cdab") << u"u32-cdab"_qs << QList<quint16>{0x0001, 0x0002} << u"131073"_qs;
    QTest::newRow("hex") << u"hex"_qs << QList<quint16>{0x002A, 0} << u"0x002A"_qs;
}

void TestWatchDecoder::formats()
{
    QFETCH(QString, format);
    QFETCH(QList<quint16>, words);
    QFETCH(QString, text);
    WatchDefinition w = block(3, 10, 2);
    w.points.append(point(10, QStringLiteral("v"), format));
    const QList<WatchPointValue> values = WatchDecoder::decode(w, words, {});
    QVERIFY(!values.isEmpty());
    QCOMPARE(values.first().name, QStringLiteral("v"));
    QCOMPARE(values.first().text, text);
    // A two-register value takes both addresses; a one-register value leaves the next unnamed.
    QCOMPARE(values.size(), RegisterFormat::parse(format).format.registerCount() == 2 ? 1 : 2);
}

void TestWatchDecoder::scaleUnitAndUnnamed()
{
    WatchDefinition w = block(3, 0x79, 4);
    WatchPoint t = point(0x7A, QStringLiteral("temperature"), QStringLiteral("i16"));
    t.scale = 0.1;
    t.offset = -40;
    t.unit = QStringLiteral("°C");
    w.points.append(t);
    const QList<WatchPointValue> values = WatchDecoder::decode(w, {1050, 650, 7, 8}, {});
    QCOMPARE(values.size(), 4);
    QCOMPARE(values.at(0).address, quint16(0x79));
    QCOMPARE(values.at(0).point, -1);
    QCOMPARE(values.at(0).text, QStringLiteral("1050"));
    QCOMPARE(values.at(1).point, 0);
    QCOMPARE(values.at(1).value, 25.0);
    QCOMPARE(values.at(1).text, QStringLiteral("25"));
    QCOMPARE(values.at(1).unit, QStringLiteral("°C"));
    QCOMPARE(values.at(1).raw, quint64(650));
    QCOMPARE(values.at(3).address, quint16(0x7C));
}

void TestWatchDecoder::enronValues()
{
    // Enron/Daniel: each address one 32-bit value, two registers in the answer.
    WatchDefinition w = block(3, 7000, 3, true);
    w.points.append(point(7000, QStringLiteral("flow"), QStringLiteral("f32")));
    w.points.append(point(7001, QStringLiteral("total"), QStringLiteral("u16"))); // read as u32
    const QList<WatchPointValue> values = WatchDecoder::decode(w, {0x42F6, 0xE979, 0x0001, 0x0000, 0xFFFF, 0xFFFF}, {});
    QCOMPARE(values.size(), 3);
    QCOMPARE(values.at(0).text, QStringLiteral("123.456"));
    QCOMPARE(values.at(0).width, 1);
    QCOMPARE(values.at(1).address, quint16(7001));
    QCOMPARE(values.at(1).value, 65536.0);
    QCOMPARE(values.at(2).address, quint16(7002));
    QCOMPARE(values.at(2).text, QStringLiteral("4294967295")); // unnamed: u32
    QCOMPARE(WatchBlock::effectiveFormat(w, w.points.at(1)).name(), QStringLiteral("u32-abcd"));
}

void TestWatchDecoder::bitFields()
{
    WatchDefinition w = block(3, 0, 1);
    WatchPoint status = point(0, QStringLiteral("status"), QStringLiteral("hex"));
    status.bitFields.append(WatchBitField{QStringLiteral("door open"), 3, 1, {}});
    status.bitFields.append(WatchBitField{QStringLiteral("mode"), 8, 4, {u"off"_qs, u"manual"_qs, u"auto"_qs}});
    status.bitFields.append(WatchBitField{QStringLiteral("spare"), 12, 4, {u"none"_qs}});
    w.points.append(status);
    const QList<WatchPointValue> values = WatchDecoder::decode(w, {0x0208 | 0x5000}, {});
    QCOMPARE(values.size(), 1);
    QCOMPARE(values.at(0).bitFields.size(), 3);
    QCOMPARE(values.at(0).bitFields.at(0).value, 1u);
    QCOMPARE(values.at(0).bitFields.at(1).value, 2u);
    QCOMPARE(values.at(0).bitFields.at(1).state, QStringLiteral("auto"));
    QCOMPARE(values.at(0).bitFields.at(2).value, 5u);
    QCOMPARE(values.at(0).bitFields.at(2).state, QString()); // no name for 5
}

void TestWatchDecoder::coils()
{
    WatchDefinition w = block(1, 100, 10);
    WatchPoint pump;
    pump.address = 102;
    pump.name = QStringLiteral("pump");
    w.points.append(pump);
    const WatchAnswer a = WatchBlock::readAnswer(w, QByteArray::fromHex("0102 0402"));
    QVERIFY(a.ok);
    QCOMPARE(a.bits.size(), 10);
    const QList<WatchPointValue> values = WatchDecoder::decode(w, {}, a.bits);
    QCOMPARE(values.size(), 10);
    QCOMPARE(values.at(2).name, QStringLiteral("pump"));
    QCOMPARE(values.at(2).text, QStringLiteral("1"));
    QCOMPARE(values.at(9).text, QStringLiteral("1"));
    QCOMPARE(values.at(0).text, QStringLiteral("0"));
}

void TestWatchDecoder::writePdu()
{
    WatchDefinition w = block(3, 0, 4);
    WatchPoint setpoint = point(1, QStringLiteral("setpoint"), QStringLiteral("f32"));
    setpoint.writable = true;
    w.points.append(setpoint);
    w.points.append(point(3, QStringLiteral("fixed"), QStringLiteral("u16")));
    QString error;
    QCOMPARE(WatchBlock::writePdu(w, 1, {0x42F6, 0xE979}, &error).toHex(' '), QByteArray("10 00 01 00 02 04 42 f6 e9 79"));
    QVERIFY(WatchBlock::writePdu(w, 1, {0x42F6}, &error).isEmpty());
    QCOMPARE(error, QStringLiteral("w address 1: the point holds 2 registers, 1 given"));
    QVERIFY(WatchBlock::writePdu(w, 3, {1}, &error).isEmpty());
    QVERIFY(error.contains(QLatin1String("no writable point")));

    WatchDefinition c = block(1, 0, 8);
    WatchPoint relay;
    relay.address = 5;
    relay.writable = true;
    c.points.append(relay);
    QCOMPARE(WatchBlock::writePdu(c, 5, {1}, &error).toHex(' '), QByteArray("05 00 05 ff 00"));
    QVERIFY(WatchBlock::writePdu(c, 5, {2}, &error).isEmpty());

    WatchDefinition e = block(3, 7000, 2, true);
    WatchPoint limit = point(7001, QStringLiteral("limit"), QStringLiteral("u32"));
    limit.writable = true;
    e.points.append(limit);
    // Enron: one 32-bit register, so the quantity is 1 and the byte count 4.
    QCOMPARE(WatchBlock::writePdu(e, 7001, {0, 500}, &error).toHex(' '), QByteArray("10 1b 59 00 01 04 00 00 01 f4"));
}

QTEST_GUILESS_MAIN(TestWatchDecoder)
#include "tst_watchdecoder.moc"
