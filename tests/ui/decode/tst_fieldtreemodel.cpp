// FieldTreeModel: the tree structure, checked by QAbstractItemModelTester over real dissections,
// and every data role over a tree built by hand (so the expected values do not depend on the
// dissector's wording).
#include "decode/fieldtreemodel.h"

#include "protocol/dissector.h"

#include <QtGui/QColor>
#include <QtGui/QFontDatabase>
#include <QtGui/QIcon>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

int countRows(const QAbstractItemModel &model, const QModelIndex &parent = {})
{
    int n = 0;
    for (int r = 0; r < model.rowCount(parent); ++r)
        n += 1 + countRows(model, model.index(r, 0, parent));
    return n;
}

// A frame with one field of every severity: offsets and lengths as a real RTU frame would have.
Dissection handMade()
{
    Dissection d;
    d.framing = Framing::Rtu;
    d.direction = Direction::Response;
    FieldTree &t = d.fields;
    t.reset(hex("0103040001000200AABB"));
    t.add(-1, "rtu.unit_id", "Unit id", 0, 1, 1, ValueFormat::Decimal);                                   // 0
    const int pdu = t.add(-1, "modbus.pdu", "PDU", 1, 7);                                                 // 1
    t.add(pdu, "modbus.function_code", "Function code", 1, 1, 3, ValueFormat::Hex, "Read Holding Registers"); // 2
    const int bc = t.add(pdu, "modbus.byte_count", "Byte count", 2, 1, 4, ValueFormat::Decimal);          // 3
    t.flag(bc, Severity::Info, QStringLiteral("an info note"));
    const int r0 = t.add(pdu, "modbus.register_value", "Register", 3, 2, 1, ValueFormat::Decimal);         // 4
    t.setAddress(r0, 121);
    const int r1 = t.add(pdu, "modbus.register_value", "Register", 5, 2, 2, ValueFormat::Decimal);         // 5
    t.setAddress(r1, 122);
    t.flag(r1, Severity::Warning, QStringLiteral("a warning"));
    const int crc = t.add(-1, "rtu.crc", "CRC", 8, 2, 0xBBAA, ValueFormat::Hex);                          // 6
    t.flag(crc, Severity::Error, QStringLiteral("CRC 0xBBAA does not match the computed 0x1234"));
    t.add(-1, "frame.missing", "Missing", 10, 0);                                                          // 7
    return d;
}

} // namespace

class TestFieldTreeModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void modelTester_data();
    void modelTester();
    void resetBetweenDissections();
    void structure();
    void displayColumns();
    void elidedBytes();
    void customRoles();
    void severityRoles();
    void headers();
    void parentAfterChildIsShownAtTop();
    void realRosRaoRequest();
    void realTruncatedResponse();
};

void TestFieldTreeModel::modelTester_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<int>("framing");
    QTest::addColumn<int>("direction");

    const auto row = [](const char *frame, Framing framing, Direction direction) {
        QTest::newRow(frame) << hex(frame) << int(framing) << int(direction);
    };
    // RosRao read request: valid (published-frames.json, rosrao-read-request).
    row("01 03 00 79 00 16 15 DD", Framing::Auto, Direction::Auto);
    // RosRao response as printed: byte count 44, only 42 bytes follow (rosrao-read-response-as-printed).
    row("01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72",
        Framing::Rtu, Direction::Response);
    // Arduino slave read request and an exception response.
    row("01 03 00 00 00 04 44 09", Framing::Rtu, Direction::Request);
    row("01 83 02 C0 F1", Framing::Rtu, Direction::Response);
    // Modbus TCP: write multiple registers request.
    row("00 01 00 00 00 0B 01 10 00 00 00 02 04 00 0A 01 02", Framing::Tcp, Direction::Auto);
    // Garbage in every framing.
    row("FF FF FF", Framing::Auto, Direction::Auto);
    row("00", Framing::Rtu, Direction::Auto);
    row("3A 30 31 0D", Framing::Ascii, Direction::Auto);
    row("DE AD BE EF 00 11 22 33 44 55", Framing::Tcp, Direction::Response);
    row("99", Framing::Pdu, Direction::Request);
}

void TestFieldTreeModel::modelTester()
{
    QFETCH(QByteArray, frame);
    QFETCH(int, framing);
    QFETCH(int, direction);

    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    DissectOptions options;
    options.framing = Framing(framing);
    options.direction = Direction(direction);
    const Dissection d = Dissector::dissect(frame, options);
    model.setDissection(d);
    QVERIFY(!d.fields.isEmpty());
    QCOMPARE(countRows(model), d.fields.size());
    // Every field is reachable through its own index, and every role answers without crashing.
    for (int i = 0; i < d.fields.size(); ++i) {
        const QModelIndex idx = model.indexOfField(i);
        QVERIFY(idx.isValid());
        QCOMPARE(model.data(idx, FieldTreeModel::FieldIndexRole).toInt(), i);
        QCOMPARE(model.data(idx, FieldTreeModel::KeyRole).toString(), QString::fromLatin1(d.fields.at(i).key));
        for (int c = 0; c < FieldTreeModel::ColumnCount; ++c) {
            const QModelIndex cell = model.index(idx.row(), c, idx.parent());
            for (int role : {int(Qt::DisplayRole), int(Qt::ToolTipRole), int(Qt::ForegroundRole),
                             int(Qt::BackgroundRole), int(Qt::DecorationRole), int(Qt::FontRole)})
                (void)model.data(cell, role);
        }
    }
    model.setDissection(handMade());
    model.clear();
    QCOMPARE(model.rowCount(), 0);
}

void TestFieldTreeModel::resetBetweenDissections()
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy resets(&model, &QAbstractItemModel::modelReset);
    model.setDissection(handMade());
    QCOMPARE(resets.size(), 1);
    QCOMPARE(model.rowCount(), 4);
    model.setDissection(Dissector::dissect(hex("01 03 00 79 00 16 15 DD")));
    QCOMPARE(resets.size(), 2);
    model.clear();
    QCOMPARE(resets.size(), 3);
    QCOMPARE(model.rowCount(), 0);
    QVERIFY(!model.index(0, 0).isValid());
}

void TestFieldTreeModel::structure()
{
    FieldTreeModel model;
    model.setDissection(handMade());
    QCOMPARE(model.columnCount(), 5);
    QCOMPARE(model.rowCount(), 4); // unit id, PDU, CRC, missing
    const QModelIndex pdu = model.index(1, 0);
    QCOMPARE(model.data(pdu, FieldTreeModel::KeyRole).toString(), QStringLiteral("modbus.pdu"));
    QCOMPARE(model.rowCount(pdu), 4);
    QCOMPARE(model.rowCount(model.index(1, 2)), 0); // only column 0 has children
    const QModelIndex reg = model.index(3, 0, pdu);
    QCOMPARE(model.data(reg, FieldTreeModel::FieldIndexRole).toInt(), 5);
    QCOMPARE(model.parent(reg), pdu);
    QCOMPARE(model.parent(pdu), QModelIndex());
    QVERIFY(model.flags(reg).testFlag(Qt::ItemNeverHasChildren));
    QVERIFY(!model.flags(pdu).testFlag(Qt::ItemNeverHasChildren));
    QCOMPARE(model.indexOfKey("rtu.crc"), model.index(2, 0));
    QCOMPARE(model.indexOfKey("rtu.crc", FieldTreeModel::ValueColumn), model.index(2, FieldTreeModel::ValueColumn));
    QVERIFY(!model.indexOfKey("no.such_key").isValid());
    QVERIFY(!model.indexOfField(8).isValid());
    QVERIFY(!model.indexOfField(-1).isValid());
    QVERIFY(!model.index(4, 0).isValid());
    QVERIFY(!model.index(0, 5).isValid());
}

void TestFieldTreeModel::displayColumns()
{
    FieldTreeModel model;
    model.setDissection(handMade());
    const QModelIndex pdu = model.index(1, 0);
    const auto text = [&](const QModelIndex &parent, int row, int column) {
        return model.data(model.index(row, column, parent)).toString();
    };
    QCOMPARE(text({}, 0, FieldTreeModel::OffsetColumn), QStringLiteral("0"));
    QCOMPARE(text({}, 0, FieldTreeModel::BytesColumn), QStringLiteral("01"));
    QCOMPARE(text({}, 0, FieldTreeModel::FieldColumn), QStringLiteral("Unit id"));
    QCOMPARE(text({}, 0, FieldTreeModel::ValueColumn), QStringLiteral("1"));
    QCOMPARE(text({}, 0, FieldTreeModel::ProblemColumn), QString());
    QCOMPARE(text(pdu, 0, FieldTreeModel::ValueColumn), QStringLiteral("0x03 Read Holding Registers"));
    QCOMPARE(text(pdu, 2, FieldTreeModel::OffsetColumn), QStringLiteral("3"));
    QCOMPARE(text(pdu, 2, FieldTreeModel::BytesColumn), QStringLiteral("00 01"));
    QCOMPARE(text(pdu, 2, FieldTreeModel::FieldColumn), QStringLiteral("Register 121"));
    QCOMPARE(text(pdu, 3, FieldTreeModel::FieldColumn), QStringLiteral("Register 122"));
    QCOMPARE(text(pdu, 3, FieldTreeModel::ProblemColumn), QStringLiteral("a warning"));
    QCOMPARE(text({}, 2, FieldTreeModel::BytesColumn), QStringLiteral("AA BB"));
    QCOMPARE(text({}, 2, FieldTreeModel::ValueColumn), QStringLiteral("0xBBAA"));
    QCOMPARE(text({}, 2, FieldTreeModel::ProblemColumn), QStringLiteral("CRC 0xBBAA does not match the computed 0x1234"));
    // A field about missing bytes has an offset but no bytes.
    QCOMPARE(text({}, 3, FieldTreeModel::OffsetColumn), QStringLiteral("10"));
    QCOMPARE(text({}, 3, FieldTreeModel::BytesColumn), QString());
    QCOMPARE(model.data(model.index(0, FieldTreeModel::OffsetColumn), Qt::TextAlignmentRole).value<Qt::Alignment>(),
             Qt::AlignRight | Qt::AlignVCenter);
    QCOMPARE(model.data(model.index(0, FieldTreeModel::BytesColumn), Qt::FontRole).value<QFont>(),
             QFontDatabase::systemFont(QFontDatabase::FixedFont));
    QVERIFY(!model.data(model.index(0, FieldTreeModel::FieldColumn), Qt::FontRole).isValid());
}

void TestFieldTreeModel::elidedBytes()
{
    FieldTreeModel model;
    model.setDissection(handMade());
    // The PDU covers 7 bytes: shown whole. Shrink the limit's neighbourhood with a longer field.
    QCOMPARE(model.data(model.index(1, FieldTreeModel::BytesColumn)).toString(), QStringLiteral("03 04 00 01 00 02 00"));
    QVERIFY(!model.data(model.index(1, FieldTreeModel::BytesColumn), Qt::ToolTipRole).isValid());

    Dissection d;
    FieldTree &t = d.fields;
    t.reset(hex("00 01 02 03 04 05 06 07 08 09"));
    t.add(-1, "modbus.data", "Data", 0, 10, 0, ValueFormat::Bytes);
    model.setDissection(d);
    QCOMPARE(model.data(model.index(0, FieldTreeModel::BytesColumn)).toString(),
             QStringLiteral("00 01 02 03 04 05 06 07 \u2026"));
    QCOMPARE(model.data(model.index(0, FieldTreeModel::BytesColumn), Qt::ToolTipRole).toString(),
             QStringLiteral("00 01 02 03 04 05 06 07 08 09"));
    // The value column shows the whole bytes: it is the field's value, not a preview.
    QCOMPARE(model.data(model.index(0, FieldTreeModel::ValueColumn)).toString(),
             QStringLiteral("00 01 02 03 04 05 06 07 08 09"));
}

void TestFieldTreeModel::customRoles()
{
    FieldTreeModel model;
    model.setDissection(handMade());
    const QModelIndex pdu = model.index(1, 0);
    const QModelIndex reg = model.index(3, FieldTreeModel::ValueColumn, pdu);
    QCOMPARE(model.data(reg, FieldTreeModel::KeyRole).toString(), QStringLiteral("modbus.register_value"));
    QCOMPARE(model.data(reg, FieldTreeModel::SeverityRole).toInt(), int(Severity::Warning));
    QCOMPARE(model.data(reg, FieldTreeModel::FieldIndexRole).toInt(), 5);
    QCOMPARE(model.data(reg, FieldTreeModel::OffsetRole).toInt(), 5);
    QCOMPARE(model.data(reg, FieldTreeModel::LengthRole).toInt(), 2);
    QCOMPARE(model.data(model.index(0, 0), FieldTreeModel::SeverityRole).toInt(), int(Severity::Ok));
    QCOMPARE(model.data(model.index(1, 0, pdu), FieldTreeModel::SeverityRole).toInt(), int(Severity::Info));
    QCOMPARE(model.data(model.index(2, 0), FieldTreeModel::SeverityRole).toInt(), int(Severity::Error));
    const QHash<int, QByteArray> names = model.roleNames();
    QCOMPARE(names.value(FieldTreeModel::KeyRole), QByteArray("key"));
    QCOMPARE(names.value(FieldTreeModel::SeverityRole), QByteArray("severity"));
    QCOMPARE(names.value(Qt::DisplayRole), QByteArray("display"));
}

void TestFieldTreeModel::severityRoles()
{
    FieldTreeModel model;
    model.setDissection(handMade());
    const QModelIndex pdu = model.index(1, 0);
    const QModelIndex ok = model.index(0, FieldTreeModel::ProblemColumn);
    const QModelIndex info = model.index(1, FieldTreeModel::ProblemColumn, pdu);
    const QModelIndex warning = model.index(3, FieldTreeModel::ProblemColumn, pdu);
    const QModelIndex error = model.index(2, FieldTreeModel::ProblemColumn);

    // Tooltips carry the message, on every column of the field.
    QVERIFY(!model.data(ok, Qt::ToolTipRole).isValid());
    QCOMPARE(model.data(error, Qt::ToolTipRole).toString(), QStringLiteral("CRC 0xBBAA does not match the computed 0x1234"));
    QCOMPARE(model.data(error.siblingAtColumn(FieldTreeModel::FieldColumn), Qt::ToolTipRole).toString(),
             QStringLiteral("CRC 0xBBAA does not match the computed 0x1234"));
    QCOMPARE(model.data(info, Qt::ToolTipRole).toString(), QStringLiteral("an info note"));

    // No colour for a sound field; a tint on every column of a flagged one.
    QVERIFY(!model.data(ok, Qt::BackgroundRole).isValid());
    QVERIFY(!model.data(ok, Qt::ForegroundRole).isValid());
    QVERIFY(!model.data(ok.siblingAtColumn(FieldTreeModel::FieldColumn), Qt::DecorationRole).isValid());
    const auto background = [&](const QModelIndex &i) { return model.data(i, Qt::BackgroundRole).value<QColor>(); };
    const auto foreground = [&](const QModelIndex &i) { return model.data(i, Qt::ForegroundRole).value<QColor>(); };
    for (const QModelIndex &i : {info, warning, error}) {
        QVERIFY(background(i).isValid());
        QCOMPARE(background(i.siblingAtColumn(FieldTreeModel::OffsetColumn)), background(i));
        QVERIFY(foreground(i).isValid());
        const QIcon icon = model.data(i.siblingAtColumn(FieldTreeModel::FieldColumn), Qt::DecorationRole).value<QIcon>();
        QVERIFY(!icon.isNull());
    }
    // Each severity looks different, and the error tint leans red, the info tint blue.
    QVERIFY(background(info) != background(warning));
    QVERIFY(background(warning) != background(error));
    QVERIFY(foreground(error) != foreground(warning));
    QVERIFY(background(error).red() > background(error).blue());
    QVERIFY(background(info).blue() > background(info).red());
    QVERIFY(foreground(error).red() > foreground(error).green());
    // Only the problem text is coloured; other columns keep the palette's text colour.
    QVERIFY(!model.data(error.siblingAtColumn(FieldTreeModel::ValueColumn), Qt::ForegroundRole).isValid());
}

void TestFieldTreeModel::headers()
{
    FieldTreeModel model;
    const QStringList expected{QStringLiteral("Offset"), QStringLiteral("Bytes"), QStringLiteral("Field"),
                               QStringLiteral("Value"), QStringLiteral("Problem")};
    for (int c = 0; c < FieldTreeModel::ColumnCount; ++c) {
        QCOMPARE(model.headerData(c, Qt::Horizontal).toString(), expected.at(c));
        QVERIFY(!model.headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString().isEmpty());
    }
    QVERIFY(!model.headerData(5, Qt::Horizontal).isValid());
    QVERIFY(!model.headerData(0, Qt::Vertical).isValid());
}

void TestFieldTreeModel::parentAfterChildIsShownAtTop()
{
    Dissection d;
    d.fields.reset(hex("01 02"));
    d.fields.add(3, "a.b", "A", 0, 1);  // a parent that does not come first: cannot be a tree
    d.fields.add(0, "a.c", "C", 1, 1);  // a proper child of field 0
    d.fields.add(-7, "a.d", "D", 1, 1); // nonsense parent
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setDissection(d);
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.rowCount(model.index(0, 0)), 1);
    QCOMPARE(countRows(model), 3);
}

void TestFieldTreeModel::realRosRaoRequest()
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setDissection(Dissector::dissect(hex("01 03 00 79 00 16 15 DD")));
    QCOMPARE(model.dissection().framing, Framing::Rtu);
    const QModelIndex unit = model.indexOfKey("rtu.unit_id", FieldTreeModel::ValueColumn);
    QVERIFY(unit.isValid());
    QCOMPARE(model.data(unit).toString(), QStringLiteral("1"));
    const QModelIndex fc = model.indexOfKey("modbus.function_code", FieldTreeModel::ValueColumn);
    QVERIFY(model.data(fc).toString().contains(QStringLiteral("Read Holding Registers")));
    const QModelIndex start = model.indexOfKey("modbus.start_address", FieldTreeModel::BytesColumn);
    QCOMPARE(model.data(start).toString(), QStringLiteral("00 79"));
    QCOMPARE(model.data(start.siblingAtColumn(FieldTreeModel::OffsetColumn)).toInt(), 2);
    QVERIFY(model.data(start.siblingAtColumn(FieldTreeModel::ValueColumn)).toString().startsWith(QStringLiteral("121 (0x0079)")));
    const QModelIndex crc = model.indexOfKey("rtu.crc", FieldTreeModel::BytesColumn);
    QCOMPARE(model.data(crc).toString(), QStringLiteral("15 DD"));
    QCOMPARE(model.data(crc, FieldTreeModel::SeverityRole).toInt(), int(Severity::Ok));
    QVERIFY(!model.data(crc, Qt::BackgroundRole).isValid());
}

void TestFieldTreeModel::realTruncatedResponse()
{
    FieldTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    DissectOptions options;
    options.framing = Framing::Rtu;
    options.direction = Direction::Response;
    model.setDissection(Dissector::dissect(
        hex("01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 "
            "00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72"), options));
    const QModelIndex bc = model.indexOfKey("modbus.byte_count");
    QVERIFY(bc.isValid());
    QCOMPARE(model.data(bc.siblingAtColumn(FieldTreeModel::ValueColumn)).toString().left(2), QStringLiteral("44"));
    // Somewhere a field is an error whose message names the 44 announced bytes; the model shows it
    // as text, tooltip and tint.
    bool found = false;
    for (int i = 0; i < model.dissection().fields.size() && !found; ++i) {
        const QModelIndex problem = model.indexOfField(i, FieldTreeModel::ProblemColumn);
        if (model.data(problem, FieldTreeModel::SeverityRole).toInt() != int(Severity::Error))
            continue;
        const QString text = model.data(problem).toString();
        if (!text.contains(QStringLiteral("44")))
            continue;
        found = true;
        QCOMPARE(model.data(problem, Qt::ToolTipRole).toString(), text);
        QVERIFY(model.data(problem, Qt::BackgroundRole).value<QColor>().isValid());
    }
    QVERIFY2(found, "no error field names the 44 announced bytes");
    // The first register as printed: 0x041A = 1050.
    const QModelIndex first = model.indexOfKey("modbus.register_value", FieldTreeModel::ValueColumn);
    QCOMPARE(model.data(first).toString(), QStringLiteral("1050"));
}

QTEST_MAIN(TestFieldTreeModel)
#include "tst_fieldtreemodel.moc"
