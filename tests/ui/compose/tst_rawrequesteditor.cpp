// RawRequestEditor: validation as you type (the bad character marked, with the reason), the byte
// count, completion that shows what it added, and the saved requests.
#include "guitestsupport.h"
#include "compose/rawrequesteditor.h"

#include "protocol/hextext.h"

#include <QtCore/QSettings>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;

class TestRawRequestEditor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void badCharacterIsMarked_data();
    void badCharacterIsMarked();
    void typingShowsByteCount();
    void frameInfo_data();
    void frameInfo();
    void completeAddsWhatTheLinkNeeds_data();
    void completeAddsWhatTheLinkNeeds();
    void appendCrcOnly();
    void savedRequests();
    void screenshot();
};

void TestRawRequestEditor::initTestCase()
{
    guitest::isolateSettings();
    QSettings().clear();
}

void TestRawRequestEditor::badCharacterIsMarked_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("reason");
    QTest::newRow("01 03 0G") << QStringLiteral("01 03 0G") << 8 << QStringLiteral("'G'");
    QTest::newRow("01 03 ZZ 79") << QStringLiteral("01 03 ZZ 79") << 7 << QStringLiteral("'Z'");
    QTest::newRow("odd digits") << QStringLiteral("01 030") << 4 << QStringLiteral("odd");
}

void TestRawRequestEditor::badCharacterIsMarked()
{
    QFETCH(QString, text);
    QFETCH(int, column);
    QFETCH(QString, reason);
    RawRequestEditor editor;
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QSignalSpy spy(&editor, &RawRequestEditor::bytesChanged);
    editor.editor()->setFocus();
    QTest::keyClicks(editor.editor(), text);
    QVERIFY(!editor.isValid());
    QVERIFY(editor.bytes().isEmpty());
    QCOMPARE(spy.last().at(1).toBool(), false);
    QCOMPARE(editor.error().column, column);
    QVERIFY2(editor.errorText().contains(reason, Qt::CaseInsensitive), qPrintable(editor.errorText()));
    // The character is marked in the editor, and the reason is shown below it.
    const QList<QTextEdit::ExtraSelection> marks = editor.editor()->extraSelections();
    QCOMPARE(marks.size(), 1);
    QCOMPARE(marks.first().cursor.selectionStart(), column - 1);
    QCOMPARE(marks.first().format.underlineStyle(), QTextCharFormat::WaveUnderline);
    QVERIFY2(editor.infoText().contains(editor.errorText()), qPrintable(editor.infoText()));
    // Fixing the text clears the mark.
    editor.setText(QStringLiteral("01 03 00 79 00 16 15 DD"));
    QVERIFY(editor.isValid());
    QVERIFY(editor.editor()->extraSelections().isEmpty());
}

void TestRawRequestEditor::typingShowsByteCount()
{
    RawRequestEditor editor;
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QTest::keyClicks(editor.editor(), QStringLiteral("01 03 00 79"));
    QVERIFY(editor.infoText().startsWith(QLatin1String("4 bytes")));
    QTest::keyClicks(editor.editor(), QStringLiteral(" 00 16 15 DD"));
    QVERIFY(editor.infoText().startsWith(QLatin1String("8 bytes")));
    QCOMPARE(editor.bytes(), HexText::parse(u"01 03 00 79 00 16 15 DD").bytes);
}

void TestRawRequestEditor::frameInfo_data()
{
    QTest::addColumn<int>("framing");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("info");
    QTest::newRow("rtu crc correct") << int(Framing::Rtu) << QStringLiteral("01 03 00 79 00 16 15 DD") << QStringLiteral("CRC correct");
    QTest::newRow("rtu crc wrong") << int(Framing::Rtu) << QStringLiteral("01 03 00 79 00 16 00 00")
                                   << QStringLiteral("is wrong (expected 15 DD); it is sent as typed");
    QTest::newRow("tcp fits") << int(Framing::Tcp) << QStringLiteral("00 01 00 00 00 06 01 03 00 00 00 0A") << QStringLiteral("(fits)");
    QTest::newRow("tcp pdu only") << int(Framing::Tcp) << QStringLiteral("03 00 00 00 0A") << QStringLiteral("Add MBAP header");
}

void TestRawRequestEditor::frameInfo()
{
    QFETCH(int, framing);
    QFETCH(QString, text);
    QFETCH(QString, info);
    RawRequestEditor editor;
    editor.setFraming(Framing(framing));
    editor.setText(text);
    QVERIFY(editor.isValid());
    QVERIFY2(editor.infoText().contains(info), qPrintable(editor.infoText()));
}

void TestRawRequestEditor::completeAddsWhatTheLinkNeeds_data()
{
    QTest::addColumn<int>("framing");
    QTest::addColumn<int>("unit");
    QTest::addColumn<QString>("pdu");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<int>("addedBytes");
    QTest::newRow("rtu") << int(Framing::Rtu) << 1 << QStringLiteral("03 00 79 00 16") << QStringLiteral("01 03 00 79 00 16 15 DD") << 3;
    QTest::newRow("tcp") << int(Framing::Tcp) << 1 << QStringLiteral("03 00 00 00 0A")
                         << QStringLiteral("00 01 00 00 00 06 01 03 00 00 00 0A") << 7;
    QTest::newRow("ascii") << int(Framing::Ascii) << 1 << QStringLiteral("04 00 08 00 01")
                           << QStringLiteral("3A 30 31 30 34 30 30 30 38 30 30 30 31 46 32 0D 0A") << 7;
}

void TestRawRequestEditor::completeAddsWhatTheLinkNeeds()
{
    QFETCH(int, framing);
    QFETCH(int, unit);
    QFETCH(QString, pdu);
    QFETCH(QString, expected);
    QFETCH(int, addedBytes);
    RawRequestEditor editor;
    editor.setFraming(Framing(framing));
    editor.setUnitId(unit);
    editor.setText(pdu);
    QVERIFY(editor.completePdu());
    QCOMPARE(editor.text(), expected);
    int added = 0;
    for (const auto &range : editor.addedRanges())
        added += range.second;
    QCOMPARE(added, addedBytes);
    // Visibly: the added bytes are marked and a note says what was added.
    QCOMPARE(editor.editor()->extraSelections().size(), editor.addedRanges().size());
    auto *note = editor.findChild<QLabel *>(QStringLiteral("completionNoteLabel"));
    QVERIFY(note && !note->text().isEmpty() && note->isVisibleTo(&editor));
    // An edit afterwards removes the marks: they describe the completion only.
    editor.editor()->moveCursor(QTextCursor::End);
    editor.editor()->insertPlainText(QStringLiteral(" "));
    QVERIFY(editor.addedRanges().isEmpty());
}

void TestRawRequestEditor::appendCrcOnly()
{
    RawRequestEditor editor;
    editor.setFraming(Framing::Rtu);
    editor.setText(QStringLiteral("01 03 00 79 00 16"));
    QVERIFY2(editor.infoText().contains(QLatin1String("but no CRC")), qPrintable(editor.infoText()));
    QVERIFY(editor.addChecksum());
    QCOMPARE(editor.text(), QStringLiteral("01 03 00 79 00 16 15 DD"));
}

void TestRawRequestEditor::savedRequests()
{
    RawRequestEditor editor;
    QVERIFY(editor.savedCombo()->findText(QStringLiteral("RosRao read")) > 0);
    QVERIFY(editor.loadSaved(QStringLiteral("RosRao read")));
    QCOMPARE(editor.text(), QStringLiteral("01 03 00 79 00 16 15 DD"));
    QVERIFY(!editor.loadSaved(QStringLiteral("no such request")));
}

void TestRawRequestEditor::screenshot()
{
    RawRequestEditor editor;
    editor.resize(470, 260);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setText(QStringLiteral("01 03 00 79 00 1G 15 DD"));
    QVERIFY(guitest::saveShot(&editor, QStringLiteral("raw-bad-hex.png")));
    editor.setText(QStringLiteral("03 00 79 00 16"));
    editor.completePdu();
    QVERIFY(guitest::saveShot(&editor, QStringLiteral("raw-completed-rtu.png")));
}

QTEST_MAIN(TestRawRequestEditor)
#include "tst_rawrequesteditor.moc"
