// RegisterTableModel: structure under QAbstractItemModelTester; every display format over the
// RosRao answer (tests/data/published-frames.json) with expected values computed independently
// (Python's struct module, noted per row); change highlighting; edits to the exact write PDU of
// each function; refused input and refused answers with what and where.
#include "registers/registertablemodel.h"

#include "protocol/adubuilder.h"
#include "profile/profileloader.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace Qt::StringLiterals;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

QByteArray readRegistersPdu(quint8 code, int address, const QList<quint16> &values)
{
    QByteArray pdu;
    pdu.append(char(code));
    pdu.append(char(values.size() * 2));
    for (quint16 v : values) {
        pdu.append(char(v >> 8));
        pdu.append(char(v & 0xFF));
    }
    Q_UNUSED(address)
    return pdu;
}

QByteArray readRequestPdu(quint8 code, int address, int quantity)
{
    QByteArray pdu;
    pdu.append(char(code));
    pdu.append(char(address >> 8));
    pdu.append(char(address & 0xFF));
    pdu.append(char(quantity >> 8));
    pdu.append(char(quantity & 0xFF));
    return pdu;
}

QJsonObject publishedFrame(const char *id)
{
    QFile file(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/published-frames.json"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QJsonArray frames = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("frames")).toArray();
    for (const QJsonValue &v : frames) {
        if (v.toObject().value(QStringLiteral("id")).toString() == QLatin1String(id))
            return v.toObject();
    }
    return {};
}

// The RosRao answer: 22 holding registers from 0x0079. The paper printed the first 13 values
// (rosrao-read-response-as-printed, first_registers) and lost two registers of the rest, which
// it shows as 0; the module's other registers are 0 before a measurement (rosrao-gamma profile).
QList<quint16> rosRaoRegisters()
{
    QList<quint16> values;
    const QJsonArray first = publishedFrame("rosrao-read-response-as-printed")
                                 .value(QStringLiteral("expect")).toObject()
                                 .value(QStringLiteral("first_registers")).toArray();
    for (const QJsonValue &v : first)
        values.append(quint16(v.toInt()));
    while (values.size() < 22)
        values.append(0);
    return values;
}

QByteArray rosRaoRequestPdu()
{
    // rosrao-read-request "01 03 00 79 00 16 15 DD" without the unit id and CRC.
    const QByteArray adu = hex(publishedFrame("rosrao-read-request").value(QStringLiteral("hex")).toString().toLatin1());
    return AduBuilder::parseRtu(adu).pdu;
}

QByteArray rosRaoResponsePdu()
{
    return readRegistersPdu(0x03, 0x79, rosRaoRegisters());
}

RegisterFormat format(const QString &name)
{
    const RegisterFormatResult r = RegisterFormat::parse(name);
    if (!r.ok)
        qFatal("bad format in a test row: %s", qPrintable(r.error));
    return r.format;
}

UnitProfile rosRaoProfile()
{
    const ProfileLoadResult r =
        ProfileLoader::loadFile(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/rosrao-gamma.json"));
    if (!r.ok)
        qFatal("rosrao-gamma profile: %s", qPrintable(r.errorText()));
    return *r.profile.unit(1);
}

// A hand-written profile with scaling, an offset, a unit and a two-register float.
UnitProfile scaledProfile()
{
    const QByteArray json = R"({"name": "scaled", "units": [{"id": 1, "tables": {"holding": [
        {"address": 0, "name": "setpoint", "type": "i16", "scale": 0.1, "unit": "degC", "value": 21.5},
        {"address": 1, "name": "pressure", "type": "u16", "scale": 0.01, "offset": 900, "unit": "hPa"},
        {"address": 2, "name": "voltage", "type": "f32-cdab", "unit": "V", "value": 230}
    ]}}]})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("scaled"));
    if (!r.ok)
        qFatal("scaled profile: %s", qPrintable(r.errorText()));
    return *r.profile.unit(1);
}

// Wide values that do not start on the answer's first register: a status word, a float at 1-2,
// a double at 3-6, a counter at 7.
UnitProfile wideProfile()
{
    const QByteArray json = R"({"name": "wide", "units": [{"id": 1, "tables": {"holding": [
        {"address": 0, "name": "status", "type": "u16"},
        {"address": 1, "name": "voltage", "type": "f32-abcd", "unit": "V", "value": 230.5},
        {"address": 3, "name": "energy", "type": "f64", "unit": "kWh", "value": 3},
        {"address": 7, "name": "count", "type": "u16"}
    ]}}]})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("wide"));
    if (!r.ok)
        qFatal("wide profile: %s", qPrintable(r.errorText()));
    return *r.profile.unit(1);
}

// Registers 0-7 of that profile: 7, 230.5 (43668000), 3.0 (4008000000000000), 42.
const QList<quint16> kWideRegisters{7, 0x4366, 0x8000, 0x4008, 0, 0, 0, 42};

QString text(const RegisterTableModel &model, int row, int column)
{
    return model.index(row, column).data().toString();
}

} // namespace

class TestRegisterTableModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void modelTester();
    void rosRaoColumns();
    void formats_data();
    void formats();
    void spans();
    void wideValuesFollowTheProfile_data();
    void wideValuesFollowTheProfile();
    void references_data();
    void references();
    void bitTables();
    void profileNames();
    void scaledValues();
    void highlightChanges();
    void highlightFollowsAddressesWhenRangeMoves();
    void highlightExpires();
    void fromTransaction();
    void refusedAnswers_data();
    void refusedAnswers();
    void writes_data();
    void writes();
    void refusedEdits_data();
    void refusedEdits();
    void updateCost();
};

void TestRegisterTableModel::modelTester()
{
    RegisterTableModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    QCOMPARE(model.rowCount(), 22);
    model.setValueFormats({format(u"u16"_s), format(u"f32-cdab"_s), format(u"f64"_s)});
    model.addValueColumn(format(u"ascii"_s));
    model.removeValueColumn(1);
    model.setValueFormat(0, format(u"i32-dcba"_s));
    model.setOrder(RegisterOrder::BADC);
    model.setProfile(rosRaoProfile(), u"rosrao-gamma"_s);
    QList<quint16> changed = rosRaoRegisters();
    changed[3] = 7;
    QVERIFY(model.update(rosRaoRequestPdu(), readRegistersPdu(0x03, 0x79, changed)));
    QVERIFY(model.update(readRequestPdu(0x03, 0x7A, 3), readRegistersPdu(0x03, 0x7A, {1, 2, 3})));
    QVERIFY(model.update(readRequestPdu(0x01, 0, 10), hex("01020503")));
    model.addValueColumn(format(u"hex"_s));
    QCOMPARE(model.columnCount(), RegisterTableModel::FirstValueColumn + 2);
    model.clearHighlights();
    model.clearProfile();
    model.clear();
    QCOMPARE(model.rowCount(), 0);
}

void TestRegisterTableModel::rosRaoColumns()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s)});
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    QCOMPARE(model.rowCount(), 22);
    QCOMPARE(model.columnCount(), 5);
    const QList<int> published{1050, 0, 0, 0, 250, 1, 1000, 10000, 4, 4, 80, 800, 8000};
    for (int row = 0; row < published.size(); ++row)
        QCOMPARE(text(model, row, RegisterTableModel::FirstValueColumn), QString::number(published.at(row)));
    QCOMPARE(text(model, 0, RegisterTableModel::AddressColumn), u"121 (0x0079)"_s);
    QCOMPARE(text(model, 0, RegisterTableModel::ReferenceColumn), u"40122"_s);
    QCOMPARE(text(model, 21, RegisterTableModel::AddressColumn), u"142 (0x008E)"_s);
    QCOMPARE(text(model, 21, RegisterTableModel::ReferenceColumn), u"40143"_s);
    QCOMPARE(model.headerData(RegisterTableModel::ReferenceColumn, Qt::Horizontal).toString(),
             u"Modicon (4xxxx, from 1)"_s);
    QCOMPARE(model.headerData(RegisterTableModel::FirstValueColumn, Qt::Horizontal).toString(), u"u16"_s);
    QCOMPARE(model.index(0, RegisterTableModel::ReferenceColumn).data(Qt::ToolTipRole).toString(),
             u"PDU address 121 (0x0079), register number 122, Modicon 40122 / 400122"_s);
    QCOMPARE(model.index(5, 0).data(RegisterTableModel::AddressRole).toInt(), 126);
    QCOMPARE(model.index(7, 0).data(RegisterTableModel::RawRole).toInt(), 10000);
    // Without a profile there are no names and nothing to scale.
    QCOMPARE(text(model, 0, RegisterTableModel::NameColumn), QString());
    QCOMPARE(text(model, 0, model.scaledColumn()), QString());
    QVERIFY(model.index(0, RegisterTableModel::FirstValueColumn).flags() & Qt::ItemIsEditable);
    QVERIFY(!(model.index(0, RegisterTableModel::AddressColumn).flags() & Qt::ItemIsEditable));
}

void TestRegisterTableModel::formats_data()
{
    QTest::addColumn<QList<quint16>>("registers");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("expected");

    // RosRao registers: 1050 0 0 0 250 1 1000 10000 4 4 80 800 8000 0 ... (22 in all).
    // Expected integers from Python: struct.unpack('>I', ...) after undoing the order.
    const QList<quint16> r = rosRaoRegisters();
    QTest::newRow("u16 1050") << r << u"u16"_s << 0 << u"1050"_s;
    QTest::newRow("u16 10000") << r << u"u16"_s << 7 << u"10000"_s;
    QTest::newRow("u16-ba 1050 (0x1A04)") << r << u"u16-ba"_s << 0 << u"6660"_s;
    QTest::newRow("i16 250") << r << u"i16"_s << 4 << u"250"_s;
    QTest::newRow("i16-ba 250 (0xFA00)") << r << u"i16-ba"_s << 4 << u"-1536"_s;
    QTest::newRow("hex 1050") << r << u"hex"_s << 0 << u"0x041A"_s;
    QTest::newRow("hex 8000") << r << u"hex"_s << 12 << u"0x1F40"_s;
    QTest::newRow("bin 1050") << r << u"bin"_s << 0 << u"0b0000_0100_0001_1010"_s;
    QTest::newRow("ascii 80 (0x0050)") << r << u"ascii"_s << 10 << u"\\x00P"_s;
    QTest::newRow("ascii 1050 (0x041A)") << r << u"ascii"_s << 0 << u"\\x04\\x1A"_s;
    QTest::newRow("u32-abcd 1000,10000") << r << u"u32-abcd"_s << 6 << u"65546000"_s;
    QTest::newRow("u32-cdab 1000,10000") << r << u"u32-cdab"_s << 6 << u"655361000"_s;
    QTest::newRow("u32-badc 1000,10000") << r << u"u32-badc"_s << 6 << u"3892514855"_s;
    QTest::newRow("u32-dcba 1000,10000") << r << u"u32-dcba"_s << 6 << u"271050755"_s;
    QTest::newRow("u32-cdab 1050,0") << r << u"u32-cdab"_s << 0 << u"1050"_s;
    QTest::newRow("i32-abcd 80,800") << r << u"i32-abcd"_s << 10 << u"5243680"_s;
    QTest::newRow("i32-cdab 80,800") << r << u"i32-cdab"_s << 10 << u"52428880"_s;
    QTest::newRow("i32-badc 80,800") << r << u"i32-badc"_s << 10 << u"1342185475"_s;
    QTest::newRow("i32-dcba 80,800") << r << u"i32-dcba"_s << 10 << u"537088000"_s;
    QTest::newRow("u64-abcd 250,1,1000,10000") << r << u"u64-abcd"_s << 4 << u"70368748538177296"_s;
    QTest::newRow("u64-cdab 250,1,1000,10000") << r << u"u64-cdab"_s << 4 << u"2814754062073921786"_s;
    QTest::newRow("u64-badc 250,1,1000,10000") << r << u"u64-badc"_s << 4 << u"18014399612886126631"_s;
    QTest::newRow("u64-dcba 250,1,1000,10000") << r << u"u64-dcba"_s << 4 << u"1164154128297949696"_s;
    QTest::newRow("i64-badc 250,1,1000,10000") << r << u"i64-badc"_s << 4 << u"-432344460823424985"_s; // 18014399612886126631 - 2^64
    QTest::newRow("u32 continuation") << r << u"u32-abcd"_s << 7 << u"\u2191 u32 from 40128"_s;
    QTest::newRow("f64 continuation") << r << u"f64-abcd"_s << 3 << u"\u2191 f64 from 40122"_s;
    QTest::newRow("f64 cut by the answer's end") << r << u"f64-abcd"_s << 20 << u"(2 of 4 registers)"_s;

    // Floats: float 123.456 is 0x42F6E979, -2.5 is 0xC0200000, double pi 0x400921FB54442D18
    // (struct.pack('>f', 123.456), struct.pack('>d', math.pi)), laid out in each order.
    const QList<quint16> f{0x42F6, 0xE979, 0xE979, 0x42F6, 0xF642, 0x79E9, 0x79E9, 0xF642, 0xC020, 0x0000,
                           0x0000, 0x0000, 0x4009, 0x21FB, 0x5444, 0x2D18, 0x182D, 0x4454, 0xFB21, 0x0940};
    QTest::newRow("f32-abcd 123.456") << f << u"f32-abcd"_s << 0 << u"123.456"_s;
    QTest::newRow("f32-cdab 123.456") << f << u"f32-cdab"_s << 2 << u"123.456"_s;
    QTest::newRow("f32-badc 123.456") << f << u"f32-badc"_s << 4 << u"123.456"_s;
    QTest::newRow("f32-dcba 123.456") << f << u"f32-dcba"_s << 6 << u"123.456"_s;
    QTest::newRow("f32-abcd -2.5") << f << u"f32-abcd"_s << 8 << u"-2.5"_s;
    QTest::newRow("f64-abcd pi") << f << u"f64-abcd"_s << 12 << u"3.141592653589793"_s;
    QTest::newRow("f64-dcba pi") << f << u"f64-dcba"_s << 16 << u"3.141592653589793"_s;
}

void TestRegisterTableModel::formats()
{
    QFETCH(QList<quint16>, registers);
    QFETCH(QString, format);
    QFETCH(int, row);
    QFETCH(QString, expected);
    RegisterTableModel model;
    model.setValueFormats({RegisterFormat(RegisterType::UInt16), ::format(format)});
    QVERIFY(model.update(readRequestPdu(0x03, 0x79, int(registers.size())), readRegistersPdu(0x03, 0x79, registers)));
    const int column = RegisterTableModel::FirstValueColumn + 1;
    QCOMPARE(text(model, row, column), expected);
    QCOMPARE(model.index(row, column).data(RegisterTableModel::FormatRole).toString(), ::format(format).name());
    QCOMPARE(model.headerData(column, Qt::Horizontal).toString(), ::format(format).name());
}

void TestRegisterTableModel::spans()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s), format(u"f32-cdab"_s), format(u"f64"_s)});
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    const auto span = [&model](int row, int column) {
        return model.index(row, RegisterTableModel::FirstValueColumn + column).data(RegisterTableModel::SpanRole).toInt();
    };
    QCOMPARE(span(0, 0), 1);
    QCOMPARE(span(0, 1), 2);
    QCOMPARE(span(1, 1), 0);
    QCOMPARE(span(0, 2), 4);
    QCOMPARE(span(3, 2), 0);
    QCOMPARE(span(20, 2), 2); // the answer ends two registers into the last f64
    // The value's tooltip says which registers it spans and what is on the wire.
    const QString tip = model.index(0, RegisterTableModel::FirstValueColumn + 1).data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(u"2 registers 40122-40123"_s) && tip.contains(u"041A 0000"_s), qPrintable(tip));
    // Rows inside a value cannot be edited: the value is edited on its first register.
    QVERIFY(!(model.index(1, RegisterTableModel::FirstValueColumn + 1).flags() & Qt::ItemIsEditable));
    QVERIFY(model.index(2, RegisterTableModel::FirstValueColumn + 1).flags() & Qt::ItemIsEditable);
}

void TestRegisterTableModel::wideValuesFollowTheProfile_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("address"); // of the read
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("span");     // SpanRole on the row
    QTest::addColumn<QString>("shown"); // the cell's text
    QTest::addColumn<QString>("tip");   // in its tooltip

    const QString f32 = QStringLiteral("f32-abcd");
    const QString f64 = QStringLiteral("f64");
    // From the answer's first register f32 would read 0007 4366 and 8000 4093: the profile's
    // float starts at 1, so register 0 stands alone and 1-2 make 230.5.
    QTest::newRow("f32: status alone, cut by the float") << f32 << 0 << 8 << 0 << 1 << u"(1 of 2 registers)"_s
                                                         << u"the profile's next value begins after 1"_s;
    QTest::newRow("f32: the float on its address") << f32 << 0 << 8 << 1 << 2 << u"230.5"_s << u"40002-40003"_s;
    QTest::newRow("f32: inside the float") << f32 << 0 << 8 << 2 << 0 << u"\u2191 f32 from 40002"_s << QString();
    QTest::newRow("f32: first half of the double") << f32 << 0 << 8 << 3 << 2 << u"2.125"_s << u"40004-40005"_s;
    QTest::newRow("f32: the answer ends") << f32 << 0 << 8 << 7 << 1 << u"(1 of 2 registers)"_s
                                          << u"the answer ends after 1"_s;
    QTest::newRow("f64: the double on its address") << f64 << 0 << 8 << 3 << 4 << u"3"_s << u"40004-40007"_s;
    QTest::newRow("f64: float cut by the double") << f64 << 0 << 8 << 1 << 2 << u"(2 of 4 registers)"_s
                                                  << u"the profile's next value begins after 2"_s;
    // A read that begins inside the float: its second register is no value of its own.
    QTest::newRow("f32: answer begins inside the float") << f32 << 2 << 5 << 0 << 1 << u"(1 of 2 registers)"_s
                                                         << u"from 40002; the answer begins 1 registers into it"_s;
    QTest::newRow("f32: after the cut, the double") << f32 << 2 << 5 << 1 << 2 << u"2.125"_s << u"40004-40005"_s;
    QTest::newRow("f64 from the double's second register") << f64 << 4 << 4 << 0 << 3 << u"(3 of 4 registers)"_s
                                                           << u"from 40004; the answer begins 1 registers into it"_s;
}

void TestRegisterTableModel::wideValuesFollowTheProfile()
{
    QFETCH(QString, format);
    QFETCH(int, address);
    QFETCH(int, count);
    QFETCH(int, row);
    QFETCH(int, span);
    QFETCH(QString, shown);
    QFETCH(QString, tip);
    RegisterTableModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setValueFormats({::format(format)});
    model.setProfile(wideProfile(), u"wide"_s);
    QVERIFY(model.update(readRequestPdu(0x03, address, count), readRegistersPdu(0x03, address, kWideRegisters.mid(address, count))));
    const QModelIndex cell = model.index(row, RegisterTableModel::FirstValueColumn);
    QCOMPARE(cell.data(RegisterTableModel::SpanRole).toInt(), span);
    QCOMPARE(cell.data().toString(), shown);
    const QString tooltip = cell.data(Qt::ToolTipRole).toString();
    QVERIFY2(tooltip.contains(tip), qPrintable(tooltip));
    // Only a whole value is edited, on its first register.
    const bool whole = span > 0 && !shown.startsWith(QLatin1Char('('));
    QCOMPARE(bool(cell.flags() & Qt::ItemIsEditable), whole);
    // Without the profile the values count from the answer's first register again.
    model.clearProfile();
    QVERIFY(model.update(readRequestPdu(0x03, address, count), readRegistersPdu(0x03, address, kWideRegisters.mid(address, count))));
    const int width = ::format(format).registerCount();
    QCOMPARE(model.index(row, RegisterTableModel::FirstValueColumn).data(RegisterTableModel::SpanRole).toInt(),
             row % width == 0 ? qMin(width, count - row) : 0);
}

void TestRegisterTableModel::references_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("reference");
    QTest::addColumn<QString>("header");

    QTest::newRow("holding 0") << hex("0300000001") << hex("03020001") << 0 << u"40001"_s << u"Modicon (4xxxx, from 1)"_s;
    QTest::newRow("input 9998 five digits") << hex("04270E0002") << hex("040400010002") << 0 << u"39999"_s
                                            << u"Modicon (3xxxx, from 1)"_s;
    QTest::newRow("input 9999 six digits") << hex("04270E0002") << hex("040400010002") << 1 << u"310000"_s
                                           << u"Modicon (3xxxx, from 1)"_s;
    QTest::newRow("coil 0x0013") << hex("0100130003") << hex("010105") << 1 << u"00021"_s << u"Modicon (0xxxx, from 1)"_s;
    QTest::newRow("discrete 65535") << hex("02FFFF0001") << hex("020101") << 0 << u"165536"_s
                                    << u"Modicon (1xxxx, from 1)"_s;
    QTest::newRow("read/write 17 at 0x0010") << hex("17001000020020000102000A") << hex("170400070008") << 1
                                             << u"40018"_s << u"Modicon (4xxxx, from 1)"_s;
}

void TestRegisterTableModel::references()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(int, row);
    QFETCH(QString, reference);
    QFETCH(QString, header);
    RegisterTableModel model;
    QVERIFY2(model.update(request, response), qPrintable(model.lastProblem()));
    QCOMPARE(text(model, row, RegisterTableModel::ReferenceColumn), reference);
    QCOMPARE(model.headerData(RegisterTableModel::ReferenceColumn, Qt::Horizontal).toString(), header);
}

void TestRegisterTableModel::bitTables()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s), format(u"hex"_s)});
    // 10 coils from 0: 0x05 0x03 -> 1 0 1 0 0 0 0 0, 1 1 (least significant bit first, V1.1b3 6.1).
    QVERIFY(model.update(readRequestPdu(0x01, 0, 10), hex("01020503")));
    QCOMPARE(model.rowCount(), 10);
    QCOMPARE(model.columnCount(), RegisterTableModel::FirstValueColumn + 2);
    QCOMPARE(model.headerData(RegisterTableModel::FirstValueColumn, Qt::Horizontal).toString(), u"Value"_s);
    const QList<bool> expected{true, false, true, false, false, false, false, false, true, true};
    for (int row = 0; row < expected.size(); ++row) {
        const QModelIndex index = model.index(row, RegisterTableModel::FirstValueColumn);
        QCOMPARE(index.data().toString(), expected.at(row) ? u"1  ON"_s : u"0  OFF"_s);
        QCOMPARE(index.data(Qt::CheckStateRole).toInt(), int(expected.at(row) ? Qt::Checked : Qt::Unchecked));
        QVERIFY(index.flags() & Qt::ItemIsUserCheckable);
    }
    QCOMPARE(text(model, 9, RegisterTableModel::ReferenceColumn), u"00010"_s);
    // Coil 2 switched on: marked as changed.
    QVERIFY(model.update(readRequestPdu(0x01, 0, 10), hex("01020703")));
    for (int row = 0; row < 10; ++row)
        QCOMPARE(model.index(row, RegisterTableModel::FirstValueColumn).data(RegisterTableModel::ChangedRole).toBool(),
                 row == 1);
    // Discrete inputs are read-only.
    QVERIFY(model.update(readRequestPdu(0x02, 0, 3), hex("020106")));
    QVERIFY(!(model.index(0, RegisterTableModel::FirstValueColumn).flags() & Qt::ItemIsEditable));
    QVERIFY(!(model.index(0, RegisterTableModel::FirstValueColumn).flags() & Qt::ItemIsUserCheckable));
    // Back to registers: both value columns again.
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    QCOMPARE(model.columnCount(), RegisterTableModel::FirstValueColumn + 3);
}

void TestRegisterTableModel::profileNames()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s)});
    model.setProfile(rosRaoProfile(), u"rosrao-gamma"_s);
    QVERIFY(model.hasProfile());
    QCOMPARE(model.profileName(), u"rosrao-gamma"_s);
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    QCOMPARE(text(model, 0, RegisterTableModel::NameColumn), u"settings[0]"_s);
    QCOMPARE(text(model, 12, RegisterTableModel::NameColumn), u"settings[12]"_s);
    QCOMPARE(text(model, 13, RegisterTableModel::NameColumn), u"gate counts"_s);
    QCOMPARE(text(model, 14, RegisterTableModel::NameColumn), u"results[0]"_s);
    QCOMPARE(text(model, 21, RegisterTableModel::NameColumn), u"results[7]"_s);
    QCOMPARE(text(model, 13, model.scaledColumn()), u"0 counts"_s);
    QCOMPARE(text(model, 0, model.scaledColumn()), u"1050"_s);
    QVERIFY(model.index(13, RegisterTableModel::NameColumn).data(Qt::ToolTipRole).toString().contains(u"Poisson"_s));
    // Names belong to the table the profile gives them to: input registers at 0x0079 have none.
    QVERIFY(model.update(readRequestPdu(0x04, 0x79, 2), readRegistersPdu(0x04, 0x79, {1, 2})));
    QCOMPARE(text(model, 0, RegisterTableModel::NameColumn), QString());
    model.clearProfile();
    QVERIFY(!model.hasProfile());
}

void TestRegisterTableModel::scaledValues()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s)});
    model.setProfile(scaledProfile(), u"scaled"_s);
    // setpoint i16 raw 215 x 0.1 = 21.5 degC; pressure raw 11325 x 0.01 + 900 = 1013.25 hPa;
    // voltage f32-cdab 230.0 = 0x43660000 -> registers 0000 4366.
    QVERIFY(model.update(readRequestPdu(0x03, 0, 4), readRegistersPdu(0x03, 0, {215, 11325, 0x0000, 0x4366})));
    QCOMPARE(text(model, 0, model.scaledColumn()), u"21.5 degC"_s);
    QCOMPARE(text(model, 1, model.scaledColumn()), u"1013.25 hPa"_s);
    QCOMPARE(text(model, 2, model.scaledColumn()), u"230 V"_s);
    QCOMPARE(text(model, 3, model.scaledColumn()), u"\u2191"_s);
    QCOMPARE(text(model, 3, RegisterTableModel::NameColumn), u"voltage (register 2 of 2)"_s);
    // A negative raw value through the scale: -125 (0xFF83) x 0.1.
    QVERIFY(model.update(readRequestPdu(0x03, 0, 1), readRegistersPdu(0x03, 0, {0xFF83})));
    QCOMPARE(text(model, 0, model.scaledColumn()), u"-12.5 degC"_s);
}

void TestRegisterTableModel::highlightChanges()
{
    RegisterTableModel model;
    model.setHighlightDuration(0); // until the next answer
    model.setValueFormats({format(u"u16"_s), format(u"u32-abcd"_s)});
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    const int u16 = RegisterTableModel::FirstValueColumn;
    const int u32 = u16 + 1;
    // The first answer has nothing to compare with.
    for (int row = 0; row < model.rowCount(); ++row)
        QVERIFY(!model.index(row, u16).data(RegisterTableModel::ChangedRole).toBool());

    QList<quint16> next = rosRaoRegisters();
    next[13] = 151; // gate counts, as the simulator's Poisson generator moves it
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
    QVERIFY(model.update(rosRaoRequestPdu(), readRegistersPdu(0x03, 0x79, next)));
    QCOMPARE(reset.count(), 0); // the same rows: updated in place, not reset
    QVERIFY(changed.count() >= 1);
    for (int row = 0; row < model.rowCount(); ++row) {
        QCOMPARE(model.index(row, u16).data(RegisterTableModel::ChangedRole).toBool(), row == 13);
        QCOMPARE(model.index(row, u16).data(Qt::BackgroundRole).isValid(), row == 13);
        // The u32 at rows 12-13 holds the changed register.
        QCOMPARE(model.index(row, u32).data(RegisterTableModel::ChangedRole).toBool(), row == 12 || row == 13);
        QVERIFY(!model.index(row, RegisterTableModel::ReferenceColumn).data(RegisterTableModel::ChangedRole).toBool());
    }
    QCOMPARE(text(model, 13, u16), u"151"_s);

    // The same answer again: nothing changed since the previous one.
    QVERIFY(model.update(rosRaoRequestPdu(), readRegistersPdu(0x03, 0x79, next)));
    for (int row = 0; row < model.rowCount(); ++row)
        QVERIFY(!model.index(row, u16).data(RegisterTableModel::ChangedRole).toBool());
}

void TestRegisterTableModel::highlightFollowsAddressesWhenRangeMoves()
{
    RegisterTableModel model;
    model.setHighlightDuration(0);
    model.setValueFormats({format(u"u16"_s)});
    QVERIFY(model.update(readRequestPdu(0x03, 10, 4), readRegistersPdu(0x03, 10, {1, 2, 3, 4})));
    // Now from 12: address 12 still 3, address 13 changed 4 -> 40, 14 and 15 are new.
    QVERIFY(model.update(readRequestPdu(0x03, 12, 4), readRegistersPdu(0x03, 12, {3, 40, 5, 6})));
    const int c = RegisterTableModel::FirstValueColumn;
    QCOMPARE(model.index(0, c).data(RegisterTableModel::ChangedRole).toBool(), false);
    QCOMPARE(model.index(1, c).data(RegisterTableModel::ChangedRole).toBool(), true);
    QCOMPARE(model.index(2, c).data(RegisterTableModel::ChangedRole).toBool(), false);
    // Another table at the same addresses is not compared with the first.
    QVERIFY(model.update(readRequestPdu(0x04, 12, 4), readRegistersPdu(0x04, 12, {9, 9, 9, 9})));
    for (int row = 0; row < 4; ++row)
        QVERIFY(!model.index(row, c).data(RegisterTableModel::ChangedRole).toBool());
}

void TestRegisterTableModel::highlightExpires()
{
    RegisterTableModel model;
    model.setHighlightDuration(30);
    model.setValueFormats({format(u"u16"_s)});
    QVERIFY(model.update(readRequestPdu(0x03, 0, 2), readRegistersPdu(0x03, 0, {1, 2})));
    QVERIFY(model.update(readRequestPdu(0x03, 0, 2), readRegistersPdu(0x03, 0, {1, 3})));
    const QModelIndex index = model.index(1, RegisterTableModel::FirstValueColumn);
    QVERIFY(index.data(RegisterTableModel::ChangedRole).toBool());
    QSignalSpy cleared(&model, &QAbstractItemModel::dataChanged);
    // The highlight goes when its timer fires, without a new answer.
    QTRY_VERIFY(!index.data(RegisterTableModel::ChangedRole).toBool());
    QCOMPARE(cleared.count(), 1);
    QVERIFY(!index.data(Qt::BackgroundRole).isValid());
}

void TestRegisterTableModel::fromTransaction()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s)});
    Transaction t;
    t.status = TransactionStatus::Ok;
    t.request = hex(publishedFrame("rosrao-read-request").value(QStringLiteral("hex")).toString().toLatin1());
    t.response = AduBuilder::rtu(rosRaoResponsePdu(), 1);
    QVERIFY2(model.updateFromTransaction(t, Framing::Rtu), qPrintable(model.lastProblem()));
    QCOMPARE(model.rowCount(), 22);
    QCOMPARE(text(model, 6, RegisterTableModel::FirstValueColumn), u"1000"_s);

    // Modbus TCP: the same PDUs behind MBAP headers.
    t.request = AduBuilder::mbap(rosRaoRequestPdu(), 1, 7);
    QList<quint16> next = rosRaoRegisters();
    next[0] = 1100;
    t.response = AduBuilder::mbap(readRegistersPdu(0x03, 0x79, next), 1, 7);
    QVERIFY(model.updateFromTransaction(t, Framing::Tcp));
    QCOMPARE(text(model, 0, RegisterTableModel::FirstValueColumn), u"1100"_s);

    Transaction timeout;
    timeout.request = t.request;
    timeout.status = TransactionStatus::Timeout;
    timeout.problem = u"no answer within 1000 ms"_s;
    QSignalSpy refused(&model, &RegisterTableModel::answerRefused);
    QVERIFY(!model.updateFromTransaction(timeout, Framing::Tcp));
    QCOMPARE(refused.count(), 1);
    QCOMPARE(model.lastProblem(), u"answer not shown: the transaction ended with timeout: no answer within 1000 ms"_s);
    QCOMPARE(text(model, 0, RegisterTableModel::FirstValueColumn), u"1100"_s); // kept
}

void TestRegisterTableModel::refusedAnswers_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<QString>("problem");

    // The RosRao answer as the paper printed it: the byte count says 44, 40 data bytes follow
    // (the last two printed bytes are its CRC).
    const QByteArray printed =
        hex(publishedFrame("rosrao-read-response-as-printed").value(QStringLiteral("hex")).toString().toLatin1());
    QTest::newRow("rosrao as printed") << rosRaoRequestPdu() << printed.mid(1, printed.size() - 3)
                                       << u"answer not shown: the byte count (offset 1 of the answer) says 44 bytes but 40 follow it"_s;
    QTest::newRow("exception 02") << rosRaoRequestPdu() << hex("8302")
                                  << u"answer not shown: the answer is exception 0x02 (Illegal Data Address) to 0x03 "
                                     u"(Read Holding Registers)"_s;
    QTest::newRow("fewer registers than asked") << readRequestPdu(0x03, 0, 3) << hex("030400010002")
                                                << u"answer not shown: the answer holds 4 data bytes (2 registers) but 3 "
                                                   u"registers were asked"_s;
    QTest::newRow("answer to another function") << rosRaoRequestPdu() << hex("04020001")
                                                << u"answer not shown: the answer is function 0x04 (Read Input Registers) "
                                                   u"to a 0x03 (Read Holding Registers) request"_s;
    QTest::newRow("write is not a read") << hex("0600790001") << hex("0600790001")
                                         << u"answer not shown: the request is function 0x06 (Write Single Register), "
                                            u"not a read of a table (01, 02, 03, 04 or 17)"_s;
    QTest::newRow("short request") << hex("030079") << rosRaoResponsePdu()
                                   << u"answer not shown: the request is 3 bytes long: a read carries the function "
                                      u"code, the starting address and the quantity (5 bytes)"_s;
    QTest::newRow("coils: byte count for 10 bits") << readRequestPdu(0x01, 0, 10) << hex("010105")
                                                   << u"answer not shown: the answer holds 1 data bytes but 10 bits take 2"_s;
}

void TestRegisterTableModel::refusedAnswers()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(QString, problem);
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s)});
    QVERIFY(model.update(rosRaoRequestPdu(), rosRaoResponsePdu()));
    QSignalSpy refused(&model, &RegisterTableModel::answerRefused);
    QVERIFY(!model.update(request, response));
    QCOMPARE(model.lastProblem(), problem);
    QCOMPARE(refused.count(), 1);
    QCOMPARE(refused.at(0).at(0).toString(), problem);
    // What was shown stays.
    QCOMPARE(model.rowCount(), 22);
    QCOMPARE(text(model, 0, RegisterTableModel::FirstValueColumn), u"1050"_s);
}

void TestRegisterTableModel::writes_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("choice");
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("role");
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("description");

    const int edit = Qt::EditRole;
    const int check = Qt::CheckStateRole;
    const int automatic = int(WriteChoice::Automatic);
    const int single = int(WriteChoice::Single);
    const int multiple = int(WriteChoice::Multiple);
    const QByteArray rq = rosRaoRequestPdu();
    const QByteArray rs = rosRaoResponsePdu();
    // V1.1b3 6.6: 06, address, value. 6.12: 10, address, quantity, byte count, values.
    QTest::newRow("06 u16 by width") << rq << rs << u"u16"_s << automatic << 0 << edit << QVariant(u"1051"_s)
                                     << hex("060079041B")
                                     << u"06 Write Single Register: register 40122 (PDU address 121) = 1051"_s;
    QTest::newRow("06 chosen") << rq << rs << u"u16"_s << single << 4 << edit << QVariant(u" 300 "_s)
                               << hex("06007D012C")
                               << u"06 Write Single Register: register 40126 (PDU address 125) = 300"_s;
    QTest::newRow("10 chosen for one register") << rq << rs << u"u16"_s << multiple << 0 << edit << QVariant(u"1051"_s)
                                                << hex("1000790001 02 041B")
                                                << u"10 Write Multiple Registers: register 40122 (PDU address 121) = 1051"_s;
    QTest::newRow("06 i16 -1") << rq << rs << u"i16"_s << automatic << 1 << edit << QVariant(u"-1"_s)
                               << hex("06007AFFFF")
                               << u"06 Write Single Register: register 40123 (PDU address 122) = 65535"_s;
    QTest::newRow("06 hex") << rq << rs << u"hex"_s << automatic << 3 << edit << QVariant(u"0xBEEF"_s)
                            << hex("06007CBEEF")
                            << u"06 Write Single Register: register 40125 (PDU address 124) = 48879"_s;
    QTest::newRow("06 bin") << rq << rs << u"bin"_s << automatic << 5 << edit << QVariant(u"0b1000_0000_0000_0001"_s)
                            << hex("06007E8001")
                            << u"06 Write Single Register: register 40127 (PDU address 126) = 32769"_s;
    QTest::newRow("06 ascii") << rq << rs << u"ascii"_s << automatic << 2 << edit << QVariant(u"OK"_s)
                              << hex("06007B4F4B")
                              << u"06 Write Single Register: register 40124 (PDU address 123) = 20299"_s;
    QTest::newRow("06 u16-ba") << rq << rs << u"u16-ba"_s << automatic << 0 << edit << QVariant(u"1050"_s)
                               << hex("0600791A04")
                               << u"06 Write Single Register: register 40122 (PDU address 121) = 6660"_s;
    QTest::newRow("10 u32-abcd by width") << rq << rs << u"u32-abcd"_s << automatic << 0 << edit << QVariant(u"70000"_s)
                                          << hex("1000790002 04 00011170")
                                          << u"10 Write Multiple Registers: 2 registers from 40122 (PDU address 121)"_s;
    QTest::newRow("10 f32-cdab 123.456") << rq << rs << u"f32-cdab"_s << automatic << 6 << edit << QVariant(u"123.456"_s)
                                         << hex("10007F0002 04 E97942F6")
                                         << u"10 Write Multiple Registers: 2 registers from 40128 (PDU address 127)"_s;
    QTest::newRow("10 f32-dcba -2.5") << rq << rs << u"f32-dcba"_s << multiple << 2 << edit << QVariant(u"-2.5"_s)
                                      << hex("10007B0002 04 000020C0")
                                      << u"10 Write Multiple Registers: 2 registers from 40124 (PDU address 123)"_s;
    QTest::newRow("10 f64-abcd pi") << rq << rs << u"f64"_s << automatic << 4 << edit << QVariant(u"3.141592653589793"_s)
                                    << hex("10007D0004 08 400921FB54442D18")
                                    << u"10 Write Multiple Registers: 4 registers from 40126 (PDU address 125)"_s;
    QTest::newRow("10 i64-cdab -2") << rq << rs << u"i64-cdab"_s << automatic << 8 << edit << QVariant(u"-2"_s)
                                    << hex("1000810004 08 FFFEFFFFFFFFFFFF")
                                    << u"10 Write Multiple Registers: 4 registers from 40130 (PDU address 129)"_s;

    // Coils (V1.1b3 6.5: 05, address, FF00 or 0000; 6.11: 0F, address, quantity, byte count, bits).
    const QByteArray cq = readRequestPdu(0x01, 0x13, 10);
    const QByteArray cs = hex("01020503");
    QTest::newRow("05 coil on") << cq << cs << u"u16"_s << automatic << 3 << edit << QVariant(u"on"_s)
                                << hex("050016FF00") << u"05 Write Single Coil: coil 00023 (PDU address 22) = ON"_s;
    QTest::newRow("05 coil off by checkbox") << cq << cs << u"u16"_s << single << 0 << check
                                             << QVariant(int(Qt::Unchecked)) << hex("0500130000")
                                             << u"05 Write Single Coil: coil 00020 (PDU address 19) = OFF"_s;
    QTest::newRow("0F coil on") << cq << cs << u"u16"_s << multiple << 9 << edit << QVariant(u"1"_s)
                                << hex("0F001C0001 01 01") << u"0F Write Multiple Coils: coil 00029 (PDU address 28) = ON"_s;
    QTest::newRow("0F coil off by checkbox") << cq << cs << u"u16"_s << multiple << 8 << check
                                             << QVariant(int(Qt::Unchecked)) << hex("0F001B0001 01 00")
                                             << u"0F Write Multiple Coils: coil 00028 (PDU address 27) = OFF"_s;
}

void TestRegisterTableModel::writes()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(QString, format);
    QFETCH(int, choice);
    QFETCH(int, row);
    QFETCH(int, role);
    QFETCH(QVariant, value);
    QFETCH(QByteArray, pdu);
    QFETCH(QString, description);
    RegisterTableModel model;
    model.setValueFormats({::format(format)});
    model.setWriteChoice(WriteChoice(choice));
    QVERIFY(model.update(request, response));
    QSignalSpy writes(&model, &RegisterTableModel::writeRequested);
    QSignalSpy refused(&model, &RegisterTableModel::editRefused);
    const QModelIndex index = model.index(row, RegisterTableModel::FirstValueColumn);
    QVERIFY2(model.setData(index, value, role), qPrintable(model.lastProblem()));
    QCOMPARE(refused.count(), 0);
    QCOMPARE(writes.count(), 1);
    QCOMPARE(writes.at(0).at(0).toByteArray().toHex(' '), pdu.toHex(' '));
    QCOMPARE(writes.at(0).at(1).toString(), description);
    // Writing never changes what the table shows: the next answer does.
    QCOMPARE(model.index(row, RegisterTableModel::FirstValueColumn).data(RegisterTableModel::RawRole).toInt(),
             model.answer().isBits() ? int(model.answer().bits.at(row)) : int(model.answer().registers.at(row)));
}

void TestRegisterTableModel::refusedEdits_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("choice");
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("message");

    const QByteArray rq = rosRaoRequestPdu();
    const QByteArray rs = rosRaoResponsePdu();
    const int automatic = int(WriteChoice::Automatic);
    QTest::newRow("70000 for u16") << rq << rs << u"u16"_s << automatic << 0 << u"70000"_s
                                   << u"not written: register 40122 (PDU address 121), u16: '70000' is out of range "
                                      u"for u16 (0 to 65535)"_s;
    QTest::newRow("abc for u16") << rq << rs << u"u16"_s << automatic << 2 << u"abc"_s
                                 << u"not written: register 40124 (PDU address 123), u16: 'abc' is not a whole number: "
                                    u"u16 takes decimal digits with an optional sign, or a 0x or 0b bit pattern"_s;
    QTest::newRow("empty for i16") << rq << rs << u"i16"_s << automatic << 0 << u""_s
                                   << u"not written: register 40122 (PDU address 121), i16: no value given for i16"_s;
    QTest::newRow("40000 for i16") << rq << rs << u"i16"_s << automatic << 0 << u"40000"_s
                                   << u"not written: register 40122 (PDU address 121), i16: '40000' is out of range "
                                      u"for i16 (-32768 to 32767)"_s;
    QTest::newRow("1.5 for u32") << rq << rs << u"u32-cdab"_s << automatic << 0 << u"1.5"_s
                                 << u"not written: register 40122 (PDU address 121), u32-cdab: '1.5' is not a whole "
                                    u"number: u32 takes decimal digits with an optional sign, or a 0x or 0b bit pattern"_s;
    QTest::newRow("f32 through 06") << rq << rs << u"f32-abcd"_s << int(WriteChoice::Single) << 0 << u"1.5"_s
                                    << u"not written: 06 (Write Single Register) writes one register, but the value "
                                       u"spans 2 registers from 40122 (PDU address 121): choose 10 (Write Multiple "
                                       u"Registers)"_s;
    QTest::newRow("inside a u32") << rq << rs << u"u32-abcd"_s << automatic << 1 << u"5"_s
                                  << u"not written: register 40123 (PDU address 122): this cell cannot be written (edit "
                                     u"a value's first register)"_s;
    QTest::newRow("input registers") << readRequestPdu(0x04, 0, 2) << hex("040400010002") << u"u16"_s << automatic << 1
                                     << u"5"_s
                                     << u"not written: register 30002 (PDU address 1): input registers are read-only; "
                                        u"only coils and holding registers can be written"_s;
    QTest::newRow("discrete inputs") << readRequestPdu(0x02, 0, 3) << hex("020106") << u"u16"_s << automatic << 0
                                     << u"1"_s
                                     << u"not written: discrete input 10001 (PDU address 0): discrete inputs are "
                                        u"read-only; only coils and holding registers can be written"_s;
    QTest::newRow("coil maybe") << readRequestPdu(0x01, 0, 3) << hex("010105") << u"u16"_s << automatic << 2
                                << u"maybe"_s
                                << u"not written: coil 00003 (PDU address 2): 'maybe' is not a coil value: expected 1 "
                                   u"or 0 (on/off, true/false)"_s;
}

void TestRegisterTableModel::refusedEdits()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(QString, format);
    QFETCH(int, choice);
    QFETCH(int, row);
    QFETCH(QString, value);
    QFETCH(QString, message);
    RegisterTableModel model;
    model.setValueFormats({::format(format)});
    model.setWriteChoice(WriteChoice(choice));
    QVERIFY(model.update(request, response));
    QSignalSpy writes(&model, &RegisterTableModel::writeRequested);
    QSignalSpy refused(&model, &RegisterTableModel::editRefused);
    QVERIFY(!model.setData(model.index(row, RegisterTableModel::FirstValueColumn), value, Qt::EditRole));
    QCOMPARE(writes.count(), 0);
    QCOMPARE(refused.count(), 1);
    QCOMPARE(refused.at(0).at(0).toString(), message);
    QCOMPARE(model.lastProblem(), message);
}

// What one poll answer costs the GUI thread: a 125-register answer (the most 03 reads) into a
// model of four value columns, then every cell's text, as a view painting it all would ask.
// Prints the figure; asserts only that every cell was asked.
void TestRegisterTableModel::updateCost()
{
    RegisterTableModel model;
    model.setValueFormats({format(u"u16"_s), format(u"hex"_s), format(u"f32-cdab"_s), format(u"u32-abcd"_s)});
    model.setProfile(rosRaoProfile(), u"rosrao-gamma"_s);
    QList<quint16> a(125);
    QList<quint16> b(125);
    for (int i = 0; i < 125; ++i) {
        a[i] = quint16(i * 7);
        b[i] = quint16(i % 3 == 0 ? i * 7 + 1 : i * 7);
    }
    const QByteArray request = readRequestPdu(0x03, 0x79, 125);
    const QByteArray answers[2] = {readRegistersPdu(0x03, 0x79, a), readRegistersPdu(0x03, 0x79, b)};
    int cells = 0;
    int turn = 0;
    QBENCHMARK {
        model.update(request, answers[turn++ % 2]);
        cells = 0;
        for (int row = 0; row < model.rowCount(); ++row) {
            for (int column = 0; column < model.columnCount(); ++column) {
                cells += model.index(row, column).data().isValid() ? 1 : 0;
                (void)model.index(row, column).data(Qt::BackgroundRole);
            }
        }
    }
    QCOMPARE(cells, 125 * model.columnCount());
}

QTEST_MAIN(TestRegisterTableModel)
#include "tst_registertablemodel.moc"
