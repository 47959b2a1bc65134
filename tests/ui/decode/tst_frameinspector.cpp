// FrameInspector, offscreen, over every published frame: selecting a field highlights exactly its
// bytes; clicking any byte selects the innermost field that covers it (and so highlights that
// field's bytes); a drag selects the innermost field covering the whole range; problems tint their
// bytes. FieldLocator's rule is checked against a definition of its own here.
#include "decode/fieldlocator.h"
#include "decode/fieldtreemodel.h"
#include "decode/fieldtreeview.h"
#include "decode/frameinspector.h"
#include "guitestsupport.h"
#include "decode/hexview.h"
#include "publishedframes.h"

#include "protocol/dissector.h"

#include <QtWidgets/QLabel>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QSplitter>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

bool covers(const Field &f, int first, int last)
{
    return f.length > 0 && f.offset <= first && f.offset + f.length > last;
}

bool isAncestor(const FieldTree &tree, int ancestor, int field)
{
    for (int p = tree.at(field).parent; p >= 0; p = tree.at(p).parent) {
        if (p == ancestor)
            return true;
    }
    return false;
}

// The innermost fields covering [first, last]: those covering it with no descendant that also
// covers it. Usually one; the view may pick any of them.
QList<int> innermost(const FieldTree &tree, int first, int last)
{
    QList<int> result;
    for (int i = 0; i < tree.size(); ++i) {
        if (!covers(tree.at(i), first, last))
            continue;
        bool inner = true;
        for (int j = 0; j < tree.size() && inner; ++j)
            inner = !(j != i && covers(tree.at(j), first, last) && isAncestor(tree, i, j));
        if (inner)
            result.append(i);
    }
    return result;
}

Dissection dissect(const QByteArray &frame, int framing, int direction)
{
    DissectOptions options;
    options.framing = Framing(framing);
    options.direction = Direction(direction);
    return Dissector::dissect(frame, options);
}

} // namespace

class TestFrameInspector : public QObject
{
    Q_OBJECT

private:
    FrameInspector *m_inspector = nullptr;

    void show(const QByteArray &frame, int framing, int direction);

private Q_SLOTS:
    void init();
    void cleanup();
    void fieldSelectsItsBytes_data() { QVERIFY(guitest::addPublishedFrameRows() >= 13); }
    void fieldSelectsItsBytes();
    void byteSelectsInnermostField_data() { QVERIFY(guitest::addPublishedFrameRows() >= 13); }
    void byteSelectsInnermostField();
    void dragSelectsFieldCoveringTheRange_data() { QVERIFY(guitest::addPublishedFrameRows() >= 13); }
    void dragSelectsFieldCoveringTheRange();
    void problemsTintTheirBytes();
    void placeholderInsteadOfAFrame();
    void narrowKeepsTheTreeReadable_data();
    void narrowKeepsTheTreeReadable();
    void screenshot();
};

void TestFrameInspector::init()
{
    m_inspector = new FrameInspector;
    m_inspector->resize(1100, 420);
    m_inspector->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_inspector));
}

void TestFrameInspector::cleanup()
{
    delete m_inspector;
    m_inspector = nullptr;
}

void TestFrameInspector::show(const QByteArray &frame, int framing, int direction)
{
    m_inspector->setDissection(dissect(frame, framing, direction));
    // An ASCII frame's fields count its decoded bytes: those are shown, with the note saying so.
    auto *note = m_inspector->findChild<QLabel *>(QStringLiteral("frameNote"));
    if (Framing(framing) == Framing::Ascii) {
        QCOMPARE(m_inspector->hexView()->bytes(), QByteArray::fromHex(frame.mid(1, frame.size() - 3))); // without ':' and CR LF
        QVERIFY(note->isVisible());
        QCOMPARE(note->text(), m_inspector->dissection().note);
    } else {
        QCOMPARE(m_inspector->hexView()->bytes(), frame);
        QVERIFY(!note->isVisible());
    }
    QVERIFY(m_inspector->treeView()->isVisible());
}

void TestFrameInspector::fieldSelectsItsBytes()
{
    QFETCH(QByteArray, frame);
    QFETCH(int, framing);
    QFETCH(int, direction);
    QAbstractItemModelTester tester(m_inspector->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    show(frame, framing, direction);
    const FieldTree &tree = m_inspector->dissection().fields;
    QVERIFY(tree.size() > 2);
    QSignalSpy selected(m_inspector, &FrameInspector::fieldSelected);
    HexView *hex = m_inspector->hexView();
    QSignalSpy picked(hex, &HexView::bytesPicked);
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        m_inspector->selectField(i);
        QCOMPARE(m_inspector->selectedField(), i);
        QCOMPARE(selected.last().at(0).toInt(), i);
        QCOMPARE(hex->selectionLength(), f.length);
        if (f.length > 0)
            QCOMPARE(hex->selectionOffset(), f.offset);
    }
    QCOMPARE(picked.size(), 0); // what the program selects is not a pick
    // Clicking a field row in the tree does the same as selecting it.
    const int last = tree.size() - 1;
    const QModelIndex index = m_inspector->model()->indexOfField(last);
    m_inspector->treeView()->scrollTo(index);
    QTest::mouseClick(m_inspector->treeView()->viewport(), Qt::LeftButton, {},
                      m_inspector->treeView()->visualRect(m_inspector->model()->indexOfField(last, FieldTreeModel::FieldColumn)).center());
    QCOMPARE(m_inspector->selectedField(), last);
    QCOMPARE(hex->selectionLength(), tree.at(last).length);
}

void TestFrameInspector::byteSelectsInnermostField()
{
    QFETCH(QByteArray, frame);
    QFETCH(int, framing);
    QFETCH(int, direction);
    show(frame, framing, direction);
    const FieldTree &tree = m_inspector->dissection().fields;
    HexView *hex = m_inspector->hexView();
    const int size = int(hex->bytes().size());
    for (int offset = 0; offset < size; ++offset) {
        const QList<int> expected = innermost(tree, offset, offset);
        const QString where = QStringLiteral("byte %1").arg(offset);
        QVERIFY2(!expected.isEmpty(), qPrintable(where + QStringLiteral(": no field covers it")));
        const HexView::Area area = offset % 2 ? HexView::Area::Ascii : HexView::Area::Hex;
        QTest::mouseClick(hex->viewport(), Qt::LeftButton, {}, hex->byteRect(offset, area).center());
        const int field = m_inspector->selectedField();
        QVERIFY2(expected.contains(field), qPrintable(where + QStringLiteral(" selected field %1 (%2)").arg(field).arg(
                                                          field >= 0 ? tree.name(field) : QString())));
        QCOMPARE(FieldLocator::innermostField(tree, offset), field);
        // The selection becomes the field's bytes.
        QCOMPARE(hex->selectionOffset(), tree.at(field).offset);
        QCOMPARE(hex->selectionLength(), tree.at(field).length);
    }
}

void TestFrameInspector::dragSelectsFieldCoveringTheRange()
{
    QFETCH(QByteArray, frame);
    QFETCH(int, framing);
    QFETCH(int, direction);
    show(frame, framing, direction);
    const FieldTree &tree = m_inspector->dissection().fields;
    HexView *hex = m_inspector->hexView();
    // From the second byte to the second-to-last: in every framing that spans the PDU's parts.
    const int first = 1;
    const int last = int(hex->bytes().size()) - 2;
    const QPoint from = hex->byteRect(first).center();
    const QPoint to = hex->byteRect(last).center();
    QTest::mousePress(hex->viewport(), Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, to, hex->viewport()->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(hex->viewport(), &move);
    QTest::mouseRelease(hex->viewport(), Qt::LeftButton, {}, to);
    const QList<int> expected = innermost(tree, first, last);
    const int field = m_inspector->selectedField();
    if (expected.isEmpty()) {
        QCOMPARE(field, -1);
    } else {
        QVERIFY2(expected.contains(field), qPrintable(QStringLiteral("selected %1").arg(field)));
        QVERIFY(covers(tree.at(field), first, last));
    }
}

void TestFrameInspector::problemsTintTheirBytes()
{
    // RosRao's answer as printed: the byte count says 44, 40 data bytes follow; the CRC is wrong.
    const QByteArray printed = QByteArray::fromHex(
        "01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 "
        "00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72");
    show(printed, int(Framing::Rtu), int(Direction::Response));
    const FieldTree &tree = m_inspector->dissection().fields;
    QVERIFY(tree.worstSeverity() == Severity::Error);
    const QList<HexView::Mark> marks = m_inspector->hexView()->marks();
    QVERIFY(!marks.isEmpty());
    int flagged = 0;
    for (int i = 0; i < tree.size(); ++i) {
        if (tree.at(i).severity >= Severity::Warning && tree.at(i).length > 0)
            ++flagged;
    }
    QCOMPARE(marks.size(), flagged);
    // A sound frame has none.
    show(QByteArray::fromHex("01030079001615DD"), int(Framing::Rtu), int(Direction::Request));
    QVERIFY(m_inspector->hexView()->marks().isEmpty());
}

void TestFrameInspector::placeholderInsteadOfAFrame()
{
    m_inspector->setPlaceholder(QStringLiteral("No answer: timeout"));
    QVERIFY(!m_inspector->treeView()->isVisible());
    QVERIFY(!m_inspector->hexView()->isVisible());
    auto *label = m_inspector->findChild<QLabel *>(QStringLiteral("framePlaceholder"));
    QVERIFY(label && label->isVisible());
    QCOMPARE(label->text(), QStringLiteral("No answer: timeout"));
    QCOMPARE(m_inspector->model()->rowCount(), 0);
    QCOMPARE(m_inspector->selectedField(), -1);
}

void TestFrameInspector::narrowKeepsTheTreeReadable_data()
{
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("bytesPerLine");
    // The Answer pane of a 1000 px window is about 520 px wide, of a 1400 px one about 880.
    QTest::newRow("420 px") << 420 << 4;
    QTest::newRow("520 px (1000 px window)") << 520 << 4;
    QTest::newRow("880 px (1400 px window)") << 880 << 8;
    QTest::newRow("1400 px") << 1400 << 16;
}

// In a narrow window the field tree keeps most of the width and the hex view lays out fewer bytes
// a line, all of them visible; a split the user chose is kept.
void TestFrameInspector::narrowKeepsTheTreeReadable()
{
    QFETCH(int, width);
    QFETCH(int, bytesPerLine);
    // The RosRao answer: 49 bytes (tests/data/published-frames.json).
    show(QByteArray::fromHex("01032C041A00000000000000FA000103E8271000040004005003201F400000000000000000000000000000000000001572"),
         int(Framing::Rtu), int(Direction::Response));
    QCOMPARE(m_inspector->hexView()->bytes().size(), 49);
    m_inspector->resize(width, 300);
    QCoreApplication::processEvents();
    HexView *hex = m_inspector->hexView();
    QTreeView *tree = m_inspector->treeView();
    QVERIFY2(tree->width() >= width / 2, qPrintable(QStringLiteral("tree %1 px of %2").arg(tree->width()).arg(width)));
    QCOMPARE(hex->bytesPerLine(), bytesPerLine);
    QCOMPARE(hex->horizontalScrollBar()->maximum(), 0); // nothing of a line is cut off
    QVERIFY(hex->viewport()->rect().contains(hex->byteRect(bytesPerLine - 1, HexView::Area::Ascii)));
    QVERIFY(guitest::saveShot(m_inspector, QStringLiteral("frameinspector-%1px.png").arg(width)));
    // A split the user moved stays theirs when the window changes.
    auto *splitter = m_inspector->findChild<QSplitter *>();
    QVERIFY(splitter);
    splitter->setSizes({width / 4, width - width / 4});
    emit splitter->splitterMoved(width / 4, 1);
    const int chosen = tree->width();
    m_inspector->resize(width + 40, 300);
    QCoreApplication::processEvents();
    QVERIFY2(qAbs(tree->width() - chosen) <= 40, qPrintable(QStringLiteral("tree %1 px, chosen %2").arg(tree->width()).arg(chosen)));
}

void TestFrameInspector::screenshot()
{
    m_inspector->setTitle(QStringLiteral("Response"));
    show(QByteArray::fromHex("07 03 08 00 07 00 06 00 05 00 04 64 5D"), int(Framing::Rtu), int(Direction::Response));
    m_inspector->selectField(m_inspector->dissection().fields.indexOf("modbus.byte_count"));
    QVERIFY(m_inspector->selectedField() >= 0);
    QVERIFY(guitest::saveShot(m_inspector, QStringLiteral("frameinspector.png")));
}

QTEST_MAIN(TestFrameInspector)
#include "tst_frameinspector.moc"
