// RequestForm and the composer's sync: the Form and the Raw tab produce the same bytes for every
// code the form has; fields appear per code; limits and address notations.
#include "compose/addressfield.h"
#include "guitestsupport.h"
#include "compose/rawrequesteditor.h"
#include "compose/requestcomposer.h"
#include "compose/requestform.h"

#include "protocol/hextext.h"

#include <QtTest/QAbstractItemModelTester>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableWidget>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

QByteArray hex(const char *text)
{
    return HexText::parse(QString::fromLatin1(text)).bytes;
}

// Fills the form for one data row. Columns by code: address and quantity as named; value is the
// single coil (05, 0/1), the single register (06), the write address (17) or the read device id
// code (2B, with quantity the object id); values are the coils (0F), registers (10, 17) or the
// AND and OR masks (16).
void fill(RequestForm &form, int code, int address, int quantity, int value, const QList<int> &values)
{
    form.setFunctionCode(code);
    form.addressField()->setAddress(address);
    switch (code) {
    case 0x01: case 0x02: case 0x03: case 0x04: form.quantitySpin()->setValue(quantity); break;
    case 0x05: form.coilCheck()->setChecked(value != 0); break;
    case 0x06: form.valueEdit()->setText(QString::number(value)); break;
    case 0x0F: {
        QList<bool> coils;
        for (int v : values)
            coils.append(v != 0);
        form.setCoilValues(coils);
        break;
    }
    case 0x10:
    case 0x17: {
        if (code == 0x17) {
            form.quantitySpin()->setValue(quantity);
            form.writeAddressField()->setAddress(value);
        }
        QList<quint16> registers;
        for (int v : values)
            registers.append(quint16(v));
        form.setRegisterValues(registers);
        break;
    }
    case 0x16:
        form.andMaskEdit()->setText(QStringLiteral("0x%1").arg(values.value(0), 4, 16, QLatin1Char('0')));
        form.orMaskEdit()->setText(QStringLiteral("0x%1").arg(values.value(1), 4, 16, QLatin1Char('0')));
        break;
    case 0x2B:
        form.deviceIdCodeCombo()->setCurrentIndex(form.deviceIdCodeCombo()->findData(value));
        form.objectIdSpin()->setValue(quantity);
        break;
    default: break;
    }
}

// Types text into a spin box as a user does: select what is there, type over it.
void typeInto(QSpinBox *spin, const QString &text)
{
    spin->setFocus();
    spin->selectAll();
    QTest::keyClick(spin, Qt::Key_Delete);
    QTest::keyClicks(spin, text);
}

} // namespace

class TestRequestForm : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void formAndRawAgree_data();
    void formAndRawAgree();
    void fieldsFollowTheCode_data();
    void fieldsFollowTheCode();
    void quantityLimits_data();
    void quantityLimits();
    void otherNumbersAreNotCutShort();
    void refusedFormSendsNothing();
    void addressNotations_data();
    void addressNotations();
    void wrongTableReferenceIsNamed();
    void modiconReferenceTypedAsAddress_data();
    void modiconReferenceTypedAsAddress();
    void badRegisterValueIsNamed();
    void rawTabIsNotRewrittenByLinkChanges();
    void valueTableModel();
    void quantityComesBackAfterSingleWrites();
    void functionListShowsHexAndDecimal();
    void quantityComesBackThroughTheComposer();
    void linkChangeOffersConversion();
    void screenshot();
};

void TestRequestForm::initTestCase()
{
    guitest::isolateSettings();
}

void TestRequestForm::formAndRawAgree_data()
{
    QTest::addColumn<int>("framing");
    QTest::addColumn<int>("unit");
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("address");
    QTest::addColumn<int>("quantity");
    QTest::addColumn<int>("value");
    QTest::addColumn<QList<int>>("values");
    QTest::addColumn<QByteArray>("expected");
    const int rtu = int(Framing::Rtu);
    const int tcp = int(Framing::Tcp);
    QTest::newRow("01 03 00 79 00 16 15 DD") << rtu << 1 << 0x03 << 0x79 << 22 << 0 << QList<int>{}
                                             << hex("01 03 00 79 00 16 15 DD");
    QTest::newRow("tcp 01 read coils") << tcp << 17 << 0x01 << 19 << 37 << 0 << QList<int>{}
                                       << hex("00 01 00 00 00 06 11 01 00 13 00 25");
    QTest::newRow("11 05 00 AC FF 00 4E 8B") << rtu << 17 << 0x05 << 172 << 0 << 1 << QList<int>{}
                                             << hex("11 05 00 AC FF 00 4E 8B");
    QTest::newRow("tcp 06 write register") << tcp << 1 << 0x06 << 1 << 0 << 3 << QList<int>{}
                                           << hex("00 01 00 00 00 06 01 06 00 01 00 03");
    QTest::newRow("11 0F 00 13 00 0A 02 CD 01 BF 0B") << rtu << 17 << 0x0F << 19 << 0 << 0
                                                      << QList<int>{1, 0, 1, 1, 0, 0, 1, 1, 1, 0}
                                                      << hex("11 0F 00 13 00 0A 02 CD 01 BF 0B");
    QTest::newRow("tcp 10 write registers") << tcp << 1 << 0x10 << 1 << 0 << 0 << QList<int>{0x000A, 0x0102}
                                            << hex("00 01 00 00 00 0B 01 10 00 01 00 02 04 00 0A 01 02");
    QTest::newRow("01 16 00 04 00 F2 00 25 67 EE") << rtu << 1 << 0x16 << 4 << 0 << 0 << QList<int>{0xF2, 0x25}
                                                   << hex("01 16 00 04 00 F2 00 25 67 EE");
    QTest::newRow("tcp 17 read/write") << tcp << 1 << 0x17 << 3 << 6 << 14 << QList<int>{0xFF, 0xFF, 0xFF}
                                       << hex("00 01 00 00 00 11 01 17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF");
    QTest::newRow("01 2B 0E 01 00 70 77") << rtu << 1 << 0x2B << 0 << 0 << 1 << QList<int>{}
                                          << hex("01 2B 0E 01 00 70 77");
    QTest::newRow("ascii 04 read input") << int(Framing::Ascii) << 1 << 0x04 << 8 << 1 << 0 << QList<int>{}
                                         << QByteArray(":010400080001F2\r\n");
}

void TestRequestForm::formAndRawAgree()
{
    QFETCH(int, framing);
    QFETCH(int, unit);
    QFETCH(int, code);
    QFETCH(int, address);
    QFETCH(int, quantity);
    QFETCH(int, value);
    QFETCH(QList<int>, values);
    QFETCH(QByteArray, expected);

    // Form -> bytes, and the Raw tab follows while the Form is in use.
    RequestComposer composer;
    composer.setFraming(Framing(framing));
    composer.setUnitId(unit);
    composer.showFormTab();
    fill(*composer.form(), code, address, quantity, value, values);
    QVERIFY2(composer.form()->errorText().isEmpty(), qPrintable(composer.form()->errorText()));
    QCOMPARE(composer.form()->bytes().toHex(' '), expected.toHex(' '));
    QCOMPARE(composer.bytes().toHex(' '), expected.toHex(' '));
    QVERIFY2(composer.form()->previewText().contains(HexText::format(expected)), qPrintable(composer.form()->previewText()));

    // Raw -> Form: typing the same bytes in a fresh composer fills the form with the same request.
    RequestComposer typed;
    typed.setFraming(Framing(framing));
    typed.setUnitId(unit == 1 ? 2 : 1); // the unit comes from the bytes, not from the bar
    QSignalSpy unitSpy(&typed, &RequestComposer::unitIdSeen);
    typed.rawEditor()->setText(HexText::format(expected));
    QCOMPARE(typed.form()->functionCode(), code);
    QVERIFY(unitSpy.count() >= 1);
    QCOMPARE(unitSpy.last().first().toInt(), unit);
    QCOMPARE(typed.form()->bytes().toHex(' '), expected.toHex(' '));
}

void TestRequestForm::fieldsFollowTheCode_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<bool>("address");
    QTest::addColumn<bool>("quantity");
    QTest::addColumn<bool>("coil");
    QTest::addColumn<bool>("table");
    QTest::newRow("03") << 0x03 << true << true << false << false;
    QTest::newRow("05") << 0x05 << true << false << true << false;
    QTest::newRow("0F") << 0x0F << true << true << false << true;
    QTest::newRow("10") << 0x10 << true << true << false << true;
    QTest::newRow("11") << 0x11 << false << false << false << false;
    QTest::newRow("2B") << 0x2B << false << false << false << false;
}

void TestRequestForm::fieldsFollowTheCode()
{
    QFETCH(int, code);
    QFETCH(bool, address);
    QFETCH(bool, quantity);
    QFETCH(bool, coil);
    QFETCH(bool, table);
    RequestForm form;
    form.setFunctionCode(code);
    QCOMPARE(form.isFieldVisible(form.addressField()), address);
    QCOMPARE(form.isFieldVisible(form.quantitySpin()), quantity);
    QCOMPARE(form.isFieldVisible(form.coilCheck()), coil);
    QCOMPARE(form.isFieldVisible(form.valueTable()), table);
}

void TestRequestForm::quantityLimits_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("max");
    QTest::newRow("01 2000 coils") << 0x01 << 2000;
    QTest::newRow("03 125 registers") << 0x03 << 125;
    QTest::newRow("0F 1968 coils") << 0x0F << 1968;
    QTest::newRow("10 123 registers") << 0x10 << 123;
}

// Try-out 8, item 3: with the limit as the spin box's maximum, typing 126 gave 12 and 200 gave
// 20, without a word. What is typed stays; the form refuses it and says why (requests.md).
void TestRequestForm::quantityLimits()
{
    QFETCH(int, code);
    QFETCH(int, max);
    RequestForm form;
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    form.setFunctionCode(code);
    for (const int typed : {max + 1, 10 * max, 0}) {
        typeInto(form.quantitySpin(), QString::number(typed));
        QCOMPARE(form.quantitySpin()->text(), QString::number(typed));
        QCOMPARE(form.quantitySpin()->value(), typed);
        QVERIFY(!form.build().isValid());
        QVERIFY(form.bytes().isEmpty());
        const QString why = form.errorText();
        QVERIFY2(why.contains(QStringLiteral("quantity %1 is refused").arg(typed)), qPrintable(why));
        QVERIFY2(why.contains(QStringLiteral("1-%1").arg(max)), qPrintable(why));
        QVERIFY2(form.findChild<QLabel *>(QStringLiteral("formErrorLabel"))->isVisible(), qPrintable(why));
        QVERIFY(form.valueTable()->rowCount() <= max); // the value table never passes the limit
    }
    typeInto(form.quantitySpin(), QString::number(max));
    QVERIFY2(form.build().isValid(), qPrintable(form.errorText()));
    QCOMPARE(form.quantitySpin()->value(), max);
}

// The other numbers typed into the form: 06's value, 17's write quantity and 2B's object id keep
// every digit typed and are refused with a reason, not cut short.
void TestRequestForm::otherNumbersAreNotCutShort()
{
    RequestForm form;
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    form.setFunctionCode(0x06);
    form.valueEdit()->clear();
    QTest::keyClicks(form.valueEdit(), QStringLiteral("70000"));
    QCOMPARE(form.valueEdit()->text(), QStringLiteral("70000"));
    QVERIFY(form.bytes().isEmpty());
    QVERIFY2(form.errorText().contains(QLatin1String("value '70000' is not a register value")), qPrintable(form.errorText()));
    form.valueEdit()->setText(QStringLiteral("-1"));
    QCOMPARE(form.build().pdu.toHex(' '), QByteArray("06 00 00 ff ff"));
    form.valueEdit()->setText(QStringLiteral("0x1234"));
    QCOMPARE(form.build().pdu.toHex(' '), QByteArray("06 00 00 12 34"));

    form.setFunctionCode(0x17);
    typeInto(form.writeQuantitySpin(), QStringLiteral("122"));
    QCOMPARE(form.writeQuantitySpin()->value(), 122);
    QVERIFY2(form.errorText().contains(QLatin1String("write quantity 122 is refused")), qPrintable(form.errorText()));
    QVERIFY2(form.errorText().contains(QLatin1String("1-121")), qPrintable(form.errorText()));
    typeInto(form.writeQuantitySpin(), QStringLiteral("2"));
    QVERIFY2(form.build().isValid(), qPrintable(form.errorText()));
    QCOMPARE(form.valueTable()->rowCount(), 2);

    form.setFunctionCode(0x2B);
    form.deviceIdCodeCombo()->setCurrentIndex(form.deviceIdCodeCombo()->findData(4));
    typeInto(form.objectIdSpin(), QStringLiteral("100"));
    QCOMPARE(form.objectIdSpin()->value(), 0x100);
    QVERIFY(form.bytes().isEmpty());
    QVERIFY2(form.errorText().contains(QLatin1String("object id 0x100 is refused")), qPrintable(form.errorText()));
    typeInto(form.objectIdSpin(), QStringLiteral("82"));
    QCOMPARE(form.build().pdu.toHex(' '), QByteArray("2b 0e 04 82"));
}

void TestRequestForm::addressNotations_data()
{
    QTest::addColumn<int>("notation");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("address");
    QTest::newRow("decimal 121") << int(AddressField::Notation::Decimal) << QStringLiteral("121") << 121;
    QTest::newRow("hex 0x0079") << int(AddressField::Notation::Hex) << QStringLiteral("0x0079") << 121;
    QTest::newRow("hex 79") << int(AddressField::Notation::Hex) << QStringLiteral("79") << 121;
    QTest::newRow("modicon 40122") << int(AddressField::Notation::Modicon) << QStringLiteral("40122") << 121;
    QTest::newRow("modicon 400122") << int(AddressField::Notation::Modicon) << QStringLiteral("400122") << 121;
}

void TestRequestForm::addressNotations()
{
    QFETCH(int, notation);
    QFETCH(QString, text);
    QFETCH(int, address);
    RequestForm form;
    form.setFunctionCode(0x03);
    form.addressField()->setNotation(AddressField::Notation(notation));
    form.addressField()->setText(text);
    QCOMPARE(form.addressField()->address().value_or(-1), address);
    // The base is said in words: 0-based PDU address and the 1-based register number.
    QVERIFY2(form.addressField()->baseText().contains(QLatin1String("PDU address 121")), qPrintable(form.addressField()->baseText()));
    QVERIFY(form.addressField()->baseText().contains(QLatin1String("register number 122")));
    // Switching notation keeps the address and rewrites the text.
    form.addressField()->setNotation(AddressField::Notation::Decimal);
    QCOMPARE(form.addressField()->text(), QStringLiteral("121"));
    form.addressField()->setNotation(AddressField::Notation::Hex);
    QCOMPARE(form.addressField()->text(), QStringLiteral("0x0079"));
    form.addressField()->setNotation(AddressField::Notation::Modicon);
    QCOMPARE(form.addressField()->text(), QStringLiteral("40122"));
}

void TestRequestForm::wrongTableReferenceIsNamed()
{
    RequestForm form;
    form.setFunctionCode(0x01);
    form.addressField()->setNotation(AddressField::Notation::Modicon);
    form.addressField()->setText(QStringLiteral("40122"));
    QVERIFY(!form.addressField()->address());
    QVERIFY(form.bytes().isEmpty());
    QVERIFY2(form.errorText().contains(QLatin1String("holding registers")), qPrintable(form.errorText()));
    QVERIFY2(form.errorText().contains(QLatin1String("coils")), qPrintable(form.errorText()));
}

void TestRequestForm::modiconReferenceTypedAsAddress_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("sendable");
    QTest::addColumn<QString>("hint");
    // Sendable (the device would answer exception 02), and refused (beyond 65535): both say it.
    QTest::newRow("40122") << QStringLiteral("40122") << true
                           << QStringLiteral("40122 looks like a Modicon reference; its PDU address is 121 (0x0079)");
    QTest::newRow("400122") << QStringLiteral("400122") << false
                            << QStringLiteral("400122 looks like a Modicon reference; its PDU address is 121 (0x0079)");
    QTest::newRow("9999") << QStringLiteral("9999") << true << QString();
    QTest::newRow("20000") << QStringLiteral("20000") << true << QString(); // 2xxxx is no table
}

void TestRequestForm::modiconReferenceTypedAsAddress()
{
    QFETCH(QString, text);
    QFETCH(bool, sendable);
    QFETCH(QString, hint);
    RequestForm form;
    form.setFunctionCode(0x03);
    form.addressField()->setNotation(AddressField::Notation::Decimal);
    form.addressField()->setText(text);
    QCOMPARE(form.addressField()->address().has_value(), sendable);
    const QString base = form.addressField()->baseText();
    if (hint.isEmpty())
        QVERIFY2(!base.contains(QLatin1String("Modicon reference;")), qPrintable(base));
    else
        QVERIFY2(base.contains(hint), qPrintable(base));
}

void TestRequestForm::badRegisterValueIsNamed()
{
    RequestForm form;
    form.setFunctionCode(0x10);
    form.setRegisterValues({1, 2, 3});
    form.valueTable()->item(1, 1)->setText(QStringLiteral("70000"));
    QVERIFY(form.bytes().isEmpty());
    QVERIFY2(form.errorText().contains(QLatin1String("row 2")), qPrintable(form.errorText()));
    form.valueTable()->item(1, 1)->setText(QStringLiteral("-1"));
    QCOMPARE(form.build().pdu.toHex(' '), QByteArray("10 00 00 00 03 06 00 01 ff ff 00 03"));
}

void TestRequestForm::rawTabIsNotRewrittenByLinkChanges()
{
    RequestComposer composer;
    composer.setFraming(Framing::Rtu);
    composer.showRawTab();
    // A wrong CRC on purpose: it must stay as typed when the unit or the link changes.
    composer.rawEditor()->setText(QStringLiteral("01 03 00 79 00 16 00 00"));
    composer.setUnitId(5);
    composer.setFraming(Framing::Tcp);
    QCOMPARE(composer.rawEditor()->text(), QStringLiteral("01 03 00 79 00 16 00 00"));
    QCOMPARE(composer.bytes(), hex("01 03 00 79 00 16 00 00"));
}

void TestRequestForm::valueTableModel()
{
    RequestForm form;
    form.setFunctionCode(0x10);
    QAbstractItemModelTester tester(form.valueTable()->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    form.setRegisterValues({1, 2, 3, 4});
    form.quantitySpin()->setValue(2);
    form.setFunctionCode(0x0F);
    form.setCoilValues({true, false, true});
    QCOMPARE(form.valueTable()->rowCount(), 3);
}

void TestRequestForm::screenshot()
{
    RequestComposer composer;
    composer.resize(470, 640);
    composer.setLinkReady(true);
    composer.show();
    QVERIFY(QTest::qWaitForWindowExposed(&composer));
    composer.showFormTab();
    fill(*composer.form(), 0x10, 0x79, 0, 0, {1050, 0, 0, 250});
    QVERIFY(guitest::saveShot(&composer, QStringLiteral("composer-form-10.png")));
    composer.form()->setFunctionCode(0x03);
    composer.form()->addressField()->setNotation(AddressField::Notation::Modicon);
    QVERIFY(guitest::saveShot(&composer, QStringLiteral("composer-form-03-modicon.png")));
}

// Issue 14, item 2: after 05 or 06 the Quantity field came back neither for 10 nor for 03.
void TestRequestForm::quantityComesBackAfterSingleWrites()
{
    RequestForm form;
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    auto *combo = form.findChild<QComboBox *>(QStringLiteral("functionCombo"));
    QVERIFY(combo);
    for (const int code : {0x05, 0x10, 0x06, 0x03, 0x05, 0x17, 0x06, 0x0F}) {
        combo->setCurrentIndex(combo->findData(code));
        const bool wanted = code != 0x05 && code != 0x06;
        QCOMPARE(form.quantitySpin()->isVisible(), wanted);
        QCOMPARE(form.isFieldVisible(form.quantitySpin()), wanted);
    }
}

// The same through the composer: 05 on the Form tab, a read loaded in Raw, back to the Form.
void TestRequestForm::quantityComesBackThroughTheComposer()
{
    RequestComposer composer;
    composer.setFraming(Framing::Rtu);
    composer.show();
    QVERIFY(QTest::qWaitForWindowExposed(&composer));
    composer.showFormTab();
    auto *combo = composer.form()->findChild<QComboBox *>(QStringLiteral("functionCombo"));
    combo->setCurrentIndex(combo->findData(0x05));
    QVERIFY(!composer.form()->quantitySpin()->isVisible());
    combo->setCurrentIndex(combo->findData(0x06));
    composer.showRawTab();
    composer.rawEditor()->setText(QStringLiteral("01 03 00 79 00 16 15 DD"));
    composer.showFormTab();
    QCOMPARE(composer.form()->functionCode(), 0x03);
    QVERIFY(composer.form()->quantitySpin()->isVisible());
    combo->setCurrentIndex(combo->findData(0x10));
    QVERIFY(composer.form()->quantitySpin()->isVisible());
}

// Issue 14, item 15: "0x10 (16) Write Multiple Registers", never a bare "10" beside "16".
void TestRequestForm::functionListShowsHexAndDecimal()
{
    RequestForm form;
    auto *combo = form.findChild<QComboBox *>(QStringLiteral("functionCombo"));
    QVERIFY(combo);
    QVERIFY2(combo->itemText(combo->findData(0x10)).startsWith(QLatin1String("0x10 (16)")),
             qPrintable(combo->itemText(combo->findData(0x10))));
    QVERIFY(combo->itemText(combo->findData(0x16)).startsWith(QLatin1String("0x16 (22)")));
    QVERIFY(combo->itemText(combo->findData(0x03)).startsWith(QLatin1String("0x03 (3)")));
}

// Issue 14, item 8: an RTU frame typed in Raw is not sent as is to a Modbus TCP link (where it
// read as "MBAP ... unit 21, function DD"): the conversion is offered, shown, and Send waits.
void TestRequestForm::linkChangeOffersConversion()
{
    RequestComposer composer;
    composer.show();
    QVERIFY(QTest::qWaitForWindowExposed(&composer));
    composer.setFraming(Framing::Rtu);
    composer.setRequestText(QStringLiteral("01 03 00 79 00 16 15 DD"));
    composer.setLinkReady(true);
    QSignalSpy sent(&composer, &RequestComposer::sendRequested);
    composer.setFraming(Framing::Tcp);
    QCOMPARE(composer.pendingConversion(), hex("00 01 00 00 00 06 01 03 00 79 00 16"));
    QVERIFY(composer.conversionBar()->isVisible());
    composer.send();
    QCOMPARE(sent.count(), 0);
    QVERIFY(!composer.sendAction()->isEnabled());
    auto *convert = composer.findChild<QPushButton *>(QStringLiteral("convertButton"));
    QVERIFY(convert);
    convert->click();
    QCOMPARE(composer.bytes(), hex("00 01 00 00 00 06 01 03 00 79 00 16"));
    QVERIFY(!composer.conversionBar()->isVisible());
    composer.send();
    QCOMPARE(sent.count(), 1);
    // And back: the MBAP header goes, the CRC comes.
    composer.setFraming(Framing::Rtu);
    QCOMPARE(composer.pendingConversion(), hex("01 03 00 79 00 16 15 DD"));
    composer.acceptConversion();
    QCOMPARE(composer.bytes(), hex("01 03 00 79 00 16 15 DD"));
    // Keep as typed sends the old bytes, on purpose.
    composer.setFraming(Framing::Tcp);
    composer.keepAsTyped();
    QCOMPARE(composer.pendingConversion(), QByteArray());
    composer.send();
    QCOMPARE(sent.count(), 2);
    QCOMPARE(sent.last().first().toByteArray(), hex("01 03 00 79 00 16 15 DD"));
}

// A refused form sends nothing: not the last bytes it made, which the Raw tab still holds.
void TestRequestForm::refusedFormSendsNothing()
{
    RequestComposer composer;
    composer.setFraming(Framing::Rtu);
    composer.setLinkReady(true);
    composer.show();
    QVERIFY(QTest::qWaitForWindowExposed(&composer));
    composer.setRequestText(QStringLiteral("01 03 00 79 00 16 15 DD"));
    composer.showFormTab();
    QCOMPARE(composer.form()->quantitySpin()->value(), 22);
    QVERIFY(composer.sendAction()->isEnabled());
    QSignalSpy sent(&composer, &RequestComposer::sendRequested);
    typeInto(composer.form()->quantitySpin(), QStringLiteral("126"));
    QCOMPARE(composer.form()->quantitySpin()->value(), 126);
    QVERIFY(composer.bytes().isEmpty());
    QVERIFY(!composer.sendAction()->isEnabled());
    QVERIFY(!composer.pollAction()->isEnabled());
    composer.send();
    QCOMPARE(sent.count(), 0);
    auto *hint = composer.findChild<QLabel *>(QStringLiteral("sendHintLabel"));
    QVERIFY(hint);
    QVERIFY2(hint->text().contains(QLatin1String("refuses")), qPrintable(hint->text()));
    QVERIFY(guitest::saveShot(&composer, QStringLiteral("composer-form-refused.png")));
    typeInto(composer.form()->quantitySpin(), QStringLiteral("125"));
    QVERIFY(composer.sendAction()->isEnabled());
    composer.send();
    QCOMPARE(sent.count(), 1);
    QCOMPARE(sent.last().first().toByteArray().mid(1, 5).toHex(' '), QByteArray("03 00 79 00 7d"));
}

QTEST_MAIN(TestRequestForm)
#include "tst_requestform.moc"
