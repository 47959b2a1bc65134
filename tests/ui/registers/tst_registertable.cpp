// RegisterTable: the panel as a user drives it (offscreen): the toolbar's format, order and write
// function, values spanning their registers, an edit typed into the view becoming the exact write
// PDU, a refused edit shown in words, and a screenshot written to the test's output directory
// (MBSCOPE_TEST_OUTPUT_DIR, else the working directory) for people to look at.
#include "registers/registertable.h"

#include "guitestsupport.h"
#include "registers/registertablemodel.h"
#include "profile/profileloader.h"

#include <QtWidgets/QVBoxLayout>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMenu>
#include <QtWidgets/QTableView>

using namespace mbscope;
using namespace Qt::StringLiterals;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

// RosRao read (tests/data/published-frames.json, rosrao-read-request) and its 22 registers: the
// 13 published values, then 0 as the module holds them before a measurement.
const QByteArray kRosRaoRequest = hex("0300790016");

QByteArray rosRaoResponse(quint16 gateCounts = 0)
{
    const QList<quint16> values{1050, 0, 0, 0, 250, 1, 1000, 10000, 4, 4, 80, 800, 8000, gateCounts,
                                0, 0, 0, 0, 0, 0, 0, 0};
    QByteArray pdu = hex("032C");
    for (quint16 v : values) {
        pdu.append(char(v >> 8));
        pdu.append(char(v & 0xFF));
    }
    return pdu;
}

UnitProfile rosRaoProfile()
{
    const ProfileLoadResult r =
        ProfileLoader::loadFile(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/rosrao-gamma.json"));
    if (!r.ok)
        qFatal("rosrao-gamma profile: %s", qPrintable(r.errorText()));
    return *r.profile.unit(1);
}

QComboBox *box(const RegisterTable &table, const char *name)
{
    return table.findChild<QComboBox *>(QLatin1String(name));
}

QStringList items(const QComboBox *combo)
{
    QStringList out;
    for (int i = 0; i < combo->count(); ++i)
        out.append(combo->itemText(i));
    return out;
}

} // namespace

class TestRegisterTable : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void toolbarSetsFormatAndOrder();
    void headerMenuSetsFormat();
    void writeChoicesFollowTheTable();
    void editTypedInTheView_data();
    void editTypedInTheView();
    void refusedEditIsShown();
    void tabSkipsReadOnlyCells_data();
    void tabSkipsReadOnlyCells();
    void refusedAnswerIsShown();
    void screenshot();
    void screenshotCoils();
};

void TestRegisterTable::toolbarSetsFormatAndOrder()
{
    RegisterTable table;
    table.model()->setValueFormats({RegisterFormat(RegisterType::UInt16), RegisterFormat(RegisterType::Hex16)});
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    QComboBox *type = box(table, "registerTableFormat");
    QComboBox *order = box(table, "registerTableOrder");
    QVERIFY(type && order);
    QCOMPARE(type->currentText(), u"u16"_s);
    QCOMPARE(items(order), QStringList({u"AB (high byte first)"_s, u"BA (byte swap)"_s}));

    type->setCurrentIndex(type->findText(u"f32"_s));
    QCOMPARE(table.model()->valueFormats().at(0).name(), u"f32-abcd"_s);
    QCOMPARE(order->count(), 4);
    order->setCurrentIndex(order->findData(int(RegisterOrder::CDAB)));
    QCOMPARE(table.model()->valueFormats().at(0).name(), u"f32-cdab"_s);
    const int column = RegisterTableModel::FirstValueColumn;
    QCOMPARE(table.model()->headerData(column, Qt::Horizontal).toString(), u"f32-cdab"_s);
    // The view draws each float as one cell over its two registers.
    QCOMPARE(table.view()->rowSpan(0, column), 2);
    QCOMPARE(table.view()->rowSpan(12, column), 2);
    QCOMPARE(table.view()->rowSpan(0, column + 1), 1);

    // The second column becomes current by clicking its header; its format is its own.
    table.setCurrentValueIndex(1);
    QCOMPARE(type->currentText(), u"hex"_s);
    type->setCurrentIndex(type->findText(u"u64"_s));
    QCOMPARE(table.model()->valueFormats().at(1).name(), u"u64-abcdefgh"_s);
    QCOMPARE(table.view()->rowSpan(4, column + 1), 4);
    QCOMPARE(table.model()->valueFormats().at(0).name(), u"f32-cdab"_s);
}

void TestRegisterTable::headerMenuSetsFormat()
{
    RegisterTable table;
    table.model()->setValueFormats({RegisterFormat(RegisterType::UInt16), RegisterFormat(RegisterType::Hex16)});
    table.resize(800, 400);
    table.show();
    QVERIFY(QTest::qWaitForWindowExposed(&table));
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    QHeaderView *header = table.view()->horizontalHeader();
    const int column = RegisterTableModel::FirstValueColumn + 1;
    const QPoint position(header->sectionViewportPosition(column) + 5, header->height() / 2);
    QStringList offered;
    bool triggered = false;
    // The menu runs its own event loop: pick "i32-abcd" from inside it.
    QTimer::singleShot(0, this, [&] {
        auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        if (!menu)
            return;
        for (QAction *a : menu->actions()) {
            if (!a->text().isEmpty())
                offered.append(a->text());
        }
        for (QAction *a : menu->actions()) {
            if (a->text() == u"i32-abcd"_s) {
                a->trigger();
                triggered = true;
            }
        }
        menu->close();
    });
    Q_EMIT header->customContextMenuRequested(position);
    QVERIFY2(triggered, qPrintable(offered.join(u", "_s)));
    QVERIFY(offered.contains(u"f64-abcdefgh"_s));
    QVERIFY(offered.contains(u"BA (byte swap)"_s));
    QCOMPARE(table.model()->valueFormats().at(1).name(), u"i32-abcd"_s);
    QCOMPARE(table.currentValueIndex(), 1);
    QCOMPARE(box(table, "registerTableFormat")->currentText(), u"i32"_s);
    QCOMPARE(table.view()->rowSpan(0, column), 2);
}

void TestRegisterTable::writeChoicesFollowTheTable()
{
    RegisterTable table;
    QComboBox *write = box(table, "registerTableWriteFunction");
    QVERIFY(write);
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    QCOMPARE(items(write), QStringList({u"06 or 10 by width"_s, u"06 Write Single Register"_s,
                                        u"10 Write Multiple Registers"_s}));
    QCOMPARE(write->currentIndex(), 0);
    write->setCurrentIndex(2);
    QCOMPARE(table.model()->writeChoice(), WriteChoice::Multiple);

    QVERIFY(table.showAnswer(hex("0100000008"), hex("010155")));
    QCOMPARE(items(write), QStringList({u"05 Write Single Coil"_s, u"0F Write Multiple Coils"_s}));
    QVERIFY(write->isEnabled());
    QCOMPARE(table.model()->writeChoice(), WriteChoice::Multiple); // kept across tables
    QVERIFY(!box(table, "registerTableFormat")->isEnabled());       // bits have no format

    QVERIFY(table.showAnswer(hex("0400000002"), hex("040400010002")));
    QCOMPARE(items(write), QStringList({u"read-only (input registers)"_s}));
    QVERIFY(!write->isEnabled());
}

void TestRegisterTable::editTypedInTheView_data()
{
    QTest::addColumn<int>("writeIndex");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QByteArray>("pdu");

    QTest::newRow("06 by width") << 0 << u"1051"_s << hex("060079041B");
    QTest::newRow("06 chosen") << 1 << u"1"_s << hex("0600790001");
    QTest::newRow("10 chosen") << 2 << u"1051"_s << hex("100079000102041B");
}

void TestRegisterTable::editTypedInTheView()
{
    QFETCH(int, writeIndex);
    QFETCH(QString, typed);
    QFETCH(QByteArray, pdu);
    RegisterTable table;
    table.model()->setValueFormats({RegisterFormat(RegisterType::UInt16)});
    table.resize(800, 400);
    table.show();
    QVERIFY(QTest::qWaitForWindowExposed(&table));
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    box(table, "registerTableWriteFunction")->setCurrentIndex(writeIndex);
    QSignalSpy writes(&table, &RegisterTable::writeRequested);

    const QModelIndex index = table.model()->index(0, RegisterTableModel::FirstValueColumn);
    table.view()->setCurrentIndex(index);
    table.view()->edit(index);
    auto *editor = table.view()->viewport()->findChild<QLineEdit *>();
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, typed);
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits an editor's data from a queued call (QStyledItemDelegate::eventFilter).
    QTRY_COMPARE(writes.count(), 1);
    QCOMPARE(writes.at(0).at(0).toByteArray().toHex(' '), pdu.toHex(' '));
    QVERIFY(table.message().startsWith(u"Write requested: "_s));
}

void TestRegisterTable::tabSkipsReadOnlyCells_data()
{
    QTest::addColumn<int>("fromRow");
    QTest::addColumn<int>("fromValue"); // index of the value column, -1 the address column
    QTest::addColumn<bool>("back");
    QTest::addColumn<int>("toRow"); // -1: the table lets the focus go
    QTest::addColumn<int>("toValue");
    QTest::newRow("tab to the next value") << 0 << 0 << false << 0 << 1;
    QTest::newRow("tab past the row's last value") << 0 << 1 << false << 1 << 0;
    QTest::newRow("shift+tab to the row above") << 1 << 0 << true << 0 << 1;
    QTest::newRow("tab from the address") << 3 << -1 << false << 3 << 0;
    QTest::newRow("tab past the last row") << 21 << 1 << false << -1 << 0;
}

// Issue 31: Tab goes from value to value; it stopped on the Address (and Reference, Name) cells
// of every row, which cannot be edited.
void TestRegisterTable::tabSkipsReadOnlyCells()
{
    QFETCH(int, fromRow);
    QFETCH(int, fromValue);
    QFETCH(bool, back);
    QFETCH(int, toRow);
    QFETCH(int, toValue);
    QWidget window;
    auto *before = new QLineEdit(&window);
    auto *table = new RegisterTable(&window);
    auto *after = new QLineEdit(&window);
    auto *layout = new QVBoxLayout(&window);
    layout->addWidget(before);
    layout->addWidget(table);
    layout->addWidget(after);
    table->model()->setValueFormats({RegisterFormat(RegisterType::UInt16), RegisterFormat(RegisterType::Int16)});
    window.resize(800, 500);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(table->showAnswer(kRosRaoRequest, rosRaoResponse()));
    const int first = RegisterTableModel::FirstValueColumn;
    QVERIFY(table->model()->flags(table->model()->index(0, first)) & Qt::ItemIsEditable);
    QVERIFY(!(table->model()->flags(table->model()->index(0, RegisterTableModel::AddressColumn)) & Qt::ItemIsEditable));
    table->view()->setFocus();
    table->view()->setCurrentIndex(table->model()->index(fromRow, fromValue < 0 ? RegisterTableModel::AddressColumn : first + fromValue));
    QTest::keyClick(QApplication::focusWidget(), back ? Qt::Key_Backtab : Qt::Key_Tab, back ? Qt::ShiftModifier : Qt::NoModifier);
    if (toRow < 0) {
        QVERIFY(!table->view()->hasFocus());
        return;
    }
    const QModelIndex current = table->view()->currentIndex();
    QCOMPARE(current.row(), toRow);
    QCOMPARE(current.column(), first + toValue);
}

void TestRegisterTable::refusedEditIsShown()
{
    RegisterTable table;
    table.model()->setValueFormats({RegisterFormat(RegisterType::UInt16)});
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    QSignalSpy writes(&table, &RegisterTable::writeRequested);
    QVERIFY(!table.model()->setData(table.model()->index(0, RegisterTableModel::FirstValueColumn), u"70000"_s));
    QCOMPARE(writes.count(), 0);
    const auto *label = table.findChild<QLabel *>(u"registerTableMessage"_s);
    QVERIFY(label && !label->isHidden());
    QCOMPARE(label->text(), u"not written: register 40122 (PDU address 121), u16: '70000' is out of range for u16 "
                            u"(0 to 65535)"_s);
    // A good answer afterwards clears a problem that is no longer current.
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse(3)));
    QVERIFY(label->isHidden());
}

void TestRegisterTable::refusedAnswerIsShown()
{
    RegisterTable table;
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse()));
    QVERIFY(!table.showAnswer(kRosRaoRequest, hex("8302")));
    QCOMPARE(table.message(), u"answer not shown: the answer is exception 0x02 (Illegal Data Address) to 0x03 (Read "
                              u"Holding Registers)"_s);
    QCOMPARE(table.model()->rowCount(), 22);
}

void TestRegisterTable::screenshot()
{
    RegisterTable table;
    table.model()->setHighlightDuration(0);
    table.model()->setValueFormats({RegisterFormat(RegisterType::UInt16), RegisterFormat(RegisterType::Hex16),
                                    RegisterFormat(RegisterType::Float32, RegisterOrder::CDAB),
                                    RegisterFormat(RegisterType::UInt32, RegisterOrder::ABCD)});
    table.setProfile(rosRaoProfile(), u"rosrao-gamma"_s);
    table.resize(1100, 640);
    table.show();
    QVERIFY(QTest::qWaitForWindowExposed(&table));
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse(148)));
    QVERIFY(table.showAnswer(kRosRaoRequest, rosRaoResponse(153))); // gate counts moved: highlighted
    QVERIFY(!table.model()->setData(table.model()->index(0, RegisterTableModel::FirstValueColumn), u"70000"_s));
    QCOMPARE(table.findChild<QLabel *>(u"registerTableProfile"_s)->text(), u"Profile: rosrao-gamma"_s);
    QCoreApplication::processEvents();

    const QImage image = table.grab().toImage();
    QVERIFY(!image.isNull());
    const QString path = guitest::outputPath(u"registertable.png"_s);
    QVERIFY2(image.save(path), qPrintable(path));
    qInfo("screenshot: %s", qPrintable(path));
}

void TestRegisterTable::screenshotCoils()
{
    RegisterTable table;
    table.resize(700, 300);
    table.show();
    QVERIFY(QTest::qWaitForWindowExposed(&table));
    // M221 memory bits %M0-%M9 (m221-plc profile): 0x05 0x03 -> 1 0 1 0 0 0 0 0 1 1.
    QVERIFY(table.showAnswer(hex("0100000010"), hex("01020503")));
    QVERIFY(table.showAnswer(hex("0100000010"), hex("01020703")));
    QCOMPARE(table.model()->rowCount(), 16);
    QVERIFY(table.model()->index(1, RegisterTableModel::FirstValueColumn).data(RegisterTableModel::ChangedRole).toBool());
    QCoreApplication::processEvents();
    const QString path = guitest::outputPath(u"registertable-coils.png"_s);
    QVERIFY2(table.grab().toImage().save(path), qPrintable(path));
    qInfo("screenshot: %s", qPrintable(path));
}

QTEST_MAIN(TestRegisterTable)
#include "tst_registertable.moc"
