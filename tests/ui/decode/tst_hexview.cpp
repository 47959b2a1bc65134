// HexView, offscreen: where each byte is drawn and read back, clicks, drags and keys report the
// bytes picked, a selection set by the program scrolls into view without being reported, marks;
// a screenshot for people to look at.
#include "decode/hexview.h"

#include "guitestsupport.h"

#include <QtWidgets/QScrollBar>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// RosRao's answer as printed in the paper (tests/data/published-frames.json): 45 bytes, 3 lines.
const QByteArray kRosRaoResponse = QByteArray::fromHex(
    "01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 "
    "00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72");

} // namespace

class TestHexView : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyByteIsWhereItIsDrawn_data();
    void everyByteIsWhereItIsDrawn();
    void clickPicksOneByte();
    void dragPicksARange();
    void keysMoveThePick();
    void programSelectionScrollsAndIsNotReported();
    void outsideTheBytesPicksNothing();
    void screenshot();
};

void TestHexView::everyByteIsWhereItIsDrawn_data()
{
    QTest::addColumn<int>("bytesPerLine");
    QTest::addColumn<int>("area");
    QTest::newRow("16 a line, hex") << 16 << int(HexView::Area::Hex);
    QTest::newRow("16 a line, ascii") << 16 << int(HexView::Area::Ascii);
    QTest::newRow("8 a line, hex") << 8 << int(HexView::Area::Hex);
    QTest::newRow("8 a line, ascii") << 8 << int(HexView::Area::Ascii);
}

void TestHexView::everyByteIsWhereItIsDrawn()
{
    QFETCH(int, bytesPerLine);
    QFETCH(int, area);
    HexView view;
    view.setBytesPerLine(bytesPerLine);
    view.setBytes(kRosRaoResponse);
    view.resize(700, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QCOMPARE(view.bytesPerLine(), bytesPerLine);
    for (int offset = 0; offset < kRosRaoResponse.size(); ++offset) {
        const QRect r = view.byteRect(offset, HexView::Area(area));
        QVERIFY2(!r.isNull(), qPrintable(QString::number(offset)));
        QCOMPARE(r.top(), (offset / bytesPerLine) * r.height());
        QCOMPARE(view.byteAt(r.center()), offset);
        QCOMPARE(view.byteAt(r.topLeft()), offset);
    }
}

void TestHexView::clickPicksOneByte()
{
    HexView view;
    view.setBytes(kRosRaoResponse);
    view.resize(700, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy picked(&view, &HexView::bytesPicked);
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, view.byteRect(17).center());
    QCOMPARE(picked.size(), 1);
    QCOMPARE(picked.at(0), (QList<QVariant>{17, 1}));
    QCOMPARE(view.selectionOffset(), 17);
    QCOMPARE(view.selectionLength(), 1);
    // In the ASCII column too.
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, view.byteRect(40, HexView::Area::Ascii).center());
    QCOMPARE(picked.last(), (QList<QVariant>{40, 1}));
}

void TestHexView::dragPicksARange()
{
    HexView view;
    view.setBytes(kRosRaoResponse);
    view.resize(700, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy picked(&view, &HexView::bytesPicked);
    // Backwards over a line break: from byte 20 to byte 5.
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, view.byteRect(20).center());
    QMouseEvent move(QEvent::MouseMove, view.byteRect(5).center(), view.viewport()->mapToGlobal(view.byteRect(5).center()),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(view.viewport(), &move);
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.byteRect(5).center());
    QCOMPARE(picked.last(), (QList<QVariant>{5, 16}));
    QCOMPARE(view.selectionOffset(), 5);
    QCOMPARE(view.selectionLength(), 16);
}

void TestHexView::keysMoveThePick()
{
    HexView view;
    view.setBytes(kRosRaoResponse);
    view.resize(700, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setFocus();
    QSignalSpy picked(&view, &HexView::bytesPicked);
    view.setSelection(3, 2); // a two-byte field
    QTest::keyClick(&view, Qt::Key_Right);
    QCOMPARE(picked.last(), (QList<QVariant>{5, 1})); // the byte after the field
    QTest::keyClick(&view, Qt::Key_Down);
    QCOMPARE(picked.last(), (QList<QVariant>{21, 1}));
    QTest::keyClick(&view, Qt::Key_Left);
    QCOMPARE(picked.last(), (QList<QVariant>{20, 1}));
    QTest::keyClick(&view, Qt::Key_End);
    QCOMPARE(picked.last(), (QList<QVariant>{44, 1}));
    QTest::keyClick(&view, Qt::Key_Right); // stays on the last byte
    QCOMPARE(picked.last(), (QList<QVariant>{44, 1}));
    QTest::keyClick(&view, Qt::Key_Home);
    QCOMPARE(picked.last(), (QList<QVariant>{0, 1}));
}

void TestHexView::programSelectionScrollsAndIsNotReported()
{
    HexView view;
    QByteArray garbage(600, '\x55'); // a long run of skipped bytes: 38 lines
    view.setBytes(garbage);
    view.resize(700, 120);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy picked(&view, &HexView::bytesPicked);
    QVERIFY(view.byteRect(590).isNull()); // scrolled out
    view.setSelection(590, 4);
    QCOMPARE(picked.size(), 0);
    QVERIFY(view.verticalScrollBar()->value() > 0);
    QVERIFY(!view.byteRect(590).isNull());
    // Out-of-range selections are clamped to the frame.
    view.setSelection(598, 10);
    QCOMPARE(view.selectionOffset(), 598);
    QCOMPARE(view.selectionLength(), 2);
    view.setSelection(0, 0);
    QCOMPARE(view.selectionLength(), 0);
    // New bytes clear the selection and the marks.
    view.setMarks({{0, 4, Qt::red}});
    view.setSelection(1, 1);
    view.setBytes(kRosRaoResponse);
    QCOMPARE(view.selectionLength(), 0);
    QVERIFY(view.marks().isEmpty());
    QCOMPARE(view.verticalScrollBar()->value(), 0);
}

void TestHexView::outsideTheBytesPicksNothing()
{
    HexView view;
    view.setBytes(QByteArray::fromHex("01030079001615DD"));
    view.resize(700, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy picked(&view, &HexView::bytesPicked);
    const QRect last = view.byteRect(7);
    QCOMPARE(view.byteAt(last.center() + QPoint(3 * last.width(), 0)), -1); // past the last byte
    QCOMPARE(view.byteAt(QPoint(2, last.center().y())), -1);                // the offset column
    QCOMPARE(view.byteAt(last.center() + QPoint(0, 3 * last.height())), -1); // below the last line
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, QPoint(2, 2));
    QCOMPARE(picked.size(), 0);
}

void TestHexView::screenshot()
{
    HexView view;
    view.setBytes(kRosRaoResponse);
    view.setMarks({{43, 2, QColor(255, 200, 200)}}); // as a bad CRC is tinted
    view.setSelection(3, 2);
    view.resize(view.sizeHint());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // Everything fits: 16 bytes a line, the ASCII column included, no horizontal scrolling.
    QCOMPARE(view.horizontalScrollBar()->maximum(), 0);
    QVERIFY(!view.byteRect(44, HexView::Area::Ascii).isNull());
    QVERIFY(view.viewport()->rect().contains(view.byteRect(15, HexView::Area::Ascii)));
    QVERIFY(guitest::saveShot(&view, QStringLiteral("hexview.png")));
}

QTEST_MAIN(TestHexView)
#include "tst_hexview.moc"
