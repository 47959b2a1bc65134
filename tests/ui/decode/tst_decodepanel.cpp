// DecodePanel, offscreen: typing hex re-dissects after the debounce, bad hex shows where it is
// wrong and keeps the last tree and the user's text, the options re-dissect at once.
#include "decode/decodepanel.h"
#include "decode/fieldtreemodel.h"
#include "decode/fieldtreeview.h"

#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QTreeView>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

const QString kRosRaoRequest = QStringLiteral("01 03 00 79 00 16 15 DD");
const QString kRosRaoResponse = QStringLiteral(
    "01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 "
    "00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72");

int countRows(const QAbstractItemModel &model, const QModelIndex &parent = {})
{
    int n = 0;
    for (int r = 0; r < model.rowCount(parent); ++r)
        n += 1 + countRows(model, model.index(r, 0, parent));
    return n;
}

bool allExpanded(const QTreeView &view, const QModelIndex &parent = {})
{
    const QAbstractItemModel &model = *view.model();
    for (int r = 0; r < model.rowCount(parent); ++r) {
        const QModelIndex i = model.index(r, 0, parent);
        if (model.rowCount(i) > 0 && (!view.isExpanded(i) || !allExpanded(view, i)))
            return false;
    }
    return true;
}

} // namespace

class TestDecodePanel : public QObject
{
    Q_OBJECT

private:
    DecodePanel *m_panel = nullptr;
    QPlainTextEdit *m_frame = nullptr;
    QLineEdit *m_request = nullptr;
    QLabel *m_verdict = nullptr;
    QLabel *m_summary = nullptr;
    QLabel *m_error = nullptr;
    QLabel *m_reason = nullptr;

    [[nodiscard]] int rows() const { return countRows(*m_panel->model()); }

private Q_SLOTS:
    void init();
    void cleanup();
    void startsEmpty();
    void typingDissectsAfterThePause();
    void badHexShowsWhereAndKeepsTheTree_data();
    void badHexShowsWhereAndKeepsTheTree();
    void fixingTheTextClearsTheError();
    void truncatedResponseIsInvalid();
    void garbageStillShowsFields();
    void optionsApplyAtOnce();
    void matchingRequest();
    void badMatchingRequest();
    void clearingTheTextEmptiesTheTree();
    void columnsFitTheirContents();
    void problemsWrapAndKeepTheirRoom();
};

void TestDecodePanel::init()
{
    m_panel = new DecodePanel;
    m_panel->resize(1000, 600);
    m_panel->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel));
    m_frame = m_panel->findChild<QPlainTextEdit *>(QStringLiteral("frameEdit"));
    m_request = m_panel->findChild<QLineEdit *>(QStringLiteral("requestEdit"));
    m_verdict = m_panel->findChild<QLabel *>(QStringLiteral("verdictLabel"));
    m_summary = m_panel->findChild<QLabel *>(QStringLiteral("summaryLabel"));
    m_error = m_panel->findChild<QLabel *>(QStringLiteral("errorLabel"));
    m_reason = m_panel->findChild<QLabel *>(QStringLiteral("reasonLabel"));
    QVERIFY(m_frame && m_request && m_verdict && m_summary && m_error && m_reason);
}

void TestDecodePanel::cleanup()
{
    delete m_panel;
    m_panel = nullptr;
}

void TestDecodePanel::startsEmpty()
{
    QCOMPARE(rows(), 0);
    QVERIFY(!m_panel->hasInputError());
    QVERIFY(m_error->isHidden());
    QVERIFY(!m_summary->text().isEmpty()); // a hint, not a blank line
    QCOMPARE(m_panel->framing(), Framing::Auto);
    QCOMPARE(m_panel->direction(), Direction::Auto);
}

void TestDecodePanel::typingDissectsAfterThePause()
{
    QSignalSpy decoded(m_panel, &DecodePanel::decoded);
    m_frame->setFocus();
    QTest::keyClicks(m_frame, kRosRaoRequest);
    // Keystrokes only restart the timer: nothing is dissected until the event loop runs it.
    QCOMPARE(decoded.size(), 0);
    QCOMPARE(rows(), 0);
    QTRY_VERIFY(rows() > 0);
    QCOMPARE(m_frame->toPlainText(), kRosRaoRequest);
    QCOMPARE(rows(), m_panel->dissection().fields.size());
    QCOMPARE(m_panel->dissection().framing, Framing::Rtu);
    QVERIFY(m_panel->dissection().isValid());
    QCOMPARE(m_verdict->text(), QStringLiteral("Valid:"));
    QCOMPARE(m_summary->text(), m_panel->dissection().summary());
    QVERIFY(m_summary->text().contains(QStringLiteral("Read Holding Registers")));
    QVERIFY(m_reason->text().contains(QStringLiteral("RTU")));
    QVERIFY(m_reason->text().contains(QStringLiteral("request")));
    QVERIFY(allExpanded(*m_panel->treeView()));
    const FieldTreeModel *model = m_panel->model();
    const QModelIndex crc = model->indexOfKey("rtu.crc", FieldTreeModel::BytesColumn);
    QCOMPARE(model->data(crc).toString(), QStringLiteral("15 DD"));
}

void TestDecodePanel::badHexShowsWhereAndKeepsTheTree_data()
{
    QTest::addColumn<QString>("appended");
    QTest::addColumn<QString>("where");
    QTest::addColumn<QString>("marked");

    // The frame is the RosRao request (23 characters) followed by the appended text.
    QTest::newRow("stray letter G") << QStringLiteral(" 0G") << QStringLiteral("line 1, column 26") << QStringLiteral("G");
    QTest::newRow("stray character on line 2") << QStringLiteral("\n00 x1") << QStringLiteral("line 2, column 4")
                                               << QStringLiteral("x");
}

void TestDecodePanel::badHexShowsWhereAndKeepsTheTree()
{
    QFETCH(QString, appended);
    QFETCH(QString, where);
    QFETCH(QString, marked);

    m_panel->setFrameText(kRosRaoRequest);
    QTRY_VERIFY(rows() > 0);
    const int goodRows = rows();

    m_frame->moveCursor(QTextCursor::End);
    m_frame->insertPlainText(appended); // as a paste would
    QTRY_VERIFY(m_panel->hasInputError());
    QVERIFY2(m_panel->inputError().contains(where), qPrintable(m_panel->inputError()));
    QVERIFY(m_panel->inputError().startsWith(QStringLiteral("Frame: ")));
    QVERIFY(m_error->isVisible());
    QVERIFY(m_error->text().contains(where));
    QVERIFY(m_error->palette().color(QPalette::WindowText).red() > m_error->palette().color(QPalette::WindowText).green());
    // The last good tree and the user's text both stay.
    QCOMPARE(rows(), goodRows);
    QCOMPARE(m_panel->dissection().framing, Framing::Rtu);
    QCOMPARE(m_frame->toPlainText(), kRosRaoRequest + appended);
    // The bad character is marked in the editor.
    const QList<QTextEdit::ExtraSelection> marks = m_frame->extraSelections();
    QCOMPARE(marks.size(), 1);
    QCOMPARE(marks.first().cursor.selectedText(), marked);
}

void TestDecodePanel::fixingTheTextClearsTheError()
{
    m_panel->setFrameText(kRosRaoRequest + QStringLiteral(" Z"));
    QTRY_VERIFY(m_panel->hasInputError());
    QCOMPARE(rows(), 0); // nothing good has been read yet
    QVERIFY(!m_error->text().contains(QStringLiteral("last input")));
    m_frame->moveCursor(QTextCursor::End);
    QTest::keyClick(m_frame, Qt::Key_Backspace);
    QTRY_VERIFY(!m_panel->hasInputError());
    QVERIFY(m_error->isHidden());
    QVERIFY(m_frame->extraSelections().isEmpty());
    QVERIFY(rows() > 0);
    QCOMPARE(m_verdict->text(), QStringLiteral("Valid:"));
}

void TestDecodePanel::truncatedResponseIsInvalid()
{
    m_panel->setFraming(Framing::Rtu);
    m_panel->setDirection(Direction::Response);
    m_panel->setFrameText(kRosRaoResponse);
    QTRY_VERIFY(rows() > 0);
    QVERIFY(!m_panel->dissection().isValid());
    QCOMPARE(m_verdict->text(), QStringLiteral("Invalid:"));
    QVERIFY(m_summary->text().contains(QStringLiteral("error")));
    QVERIFY(m_verdict->palette().color(QPalette::WindowText).red() > m_verdict->palette().color(QPalette::WindowText).green());
    QVERIFY(m_panel->model()->indexOfKey("modbus.byte_count").isValid());
    QVERIFY(allExpanded(*m_panel->treeView()));
}

void TestDecodePanel::garbageStillShowsFields()
{
    m_panel->setFrameText(QStringLiteral("FF FF FF"));
    QTRY_VERIFY(rows() > 0);
    QVERIFY(!m_panel->hasInputError());
    QCOMPARE(m_verdict->text(), QStringLiteral("Invalid:"));
}

void TestDecodePanel::optionsApplyAtOnce()
{
    m_panel->setFrameText(kRosRaoRequest);
    QTRY_VERIFY(rows() > 0);
    QCOMPARE(m_panel->dissection().framing, Framing::Rtu);
    QSignalSpy decoded(m_panel, &DecodePanel::decoded);
    m_panel->setFraming(Framing::Pdu);
    QCOMPARE(decoded.size(), 1); // no pause: a combo change is one deliberate act
    QCOMPARE(m_panel->dissection().framing, Framing::Pdu);
    QVERIFY(!m_panel->model()->indexOfKey("rtu.crc").isValid());
    QVERIFY(m_reason->text().contains(QStringLiteral("PDU")));
    m_panel->setDirection(Direction::Response);
    QCOMPARE(decoded.size(), 2);
    QCOMPARE(m_panel->dissection().direction, Direction::Response);
    QVERIFY(m_reason->text().contains(QStringLiteral("response")));
}

void TestDecodePanel::matchingRequest()
{
    // Arduino slave (published-frames.json, arduino-read-*): read 4 registers from 0.
    m_panel->setFraming(Framing::Rtu);
    m_panel->setRequestText(QStringLiteral("01 03 00 00 00 04 44 09"));
    m_panel->setFrameText(QStringLiteral("01 03 08 00 45 00 4E 00 01 00 01 79 1D"));
    QTRY_VERIFY(rows() > 0);
    QVERIFY(!m_panel->hasInputError());
    QCOMPARE(m_panel->dissection().direction, Direction::Response);
    QVERIFY(m_panel->dissection().isValid());
    QCOMPARE(m_panel->dissection().fields.indexesOf("modbus.register_value").size(), 4);
    const QModelIndex first = m_panel->model()->indexOfKey("modbus.register_value", FieldTreeModel::ValueColumn);
    QCOMPARE(m_panel->model()->data(first).toString(), QStringLiteral("69"));
}

void TestDecodePanel::badMatchingRequest()
{
    m_panel->setFrameText(kRosRaoRequest);
    QTRY_VERIFY(rows() > 0);
    const int goodRows = rows();
    m_request->setFocus();
    QTest::keyClicks(m_request, QStringLiteral("01 0"));
    QTRY_VERIFY(m_panel->hasInputError());
    QVERIFY2(m_panel->inputError().startsWith(QStringLiteral("Matching request: ")), qPrintable(m_panel->inputError()));
    QVERIFY(m_panel->inputError().contains(QStringLiteral("line 1")));
    QVERIFY(m_error->isVisible());
    QCOMPARE(rows(), goodRows);
    QCOMPARE(m_request->text(), QStringLiteral("01 0"));
}

void TestDecodePanel::clearingTheTextEmptiesTheTree()
{
    m_panel->setFrameText(kRosRaoRequest);
    QTRY_VERIFY(rows() > 0);
    m_frame->selectAll();
    QTest::keyClick(m_frame, Qt::Key_Delete);
    QTRY_COMPARE(rows(), 0);
    QVERIFY(!m_panel->hasInputError());
    QVERIFY(m_verdict->isHidden());
    QVERIFY(m_reason->text().isEmpty());
}

void TestDecodePanel::columnsFitTheirContents()
{
    m_panel->setFrameText(kRosRaoResponse);
    QTRY_VERIFY(rows() > 0);
    QTreeView *view = m_panel->treeView();
    // Fitting a column again must not widen it: the panel already fitted it after the dissection.
    for (int c = FieldTreeModel::OffsetColumn; c < FieldTreeModel::ValueColumn; ++c) {
        const int shown = view->header()->sectionSize(c);
        view->resizeColumnToContents(c);
        QVERIFY2(shown >= view->header()->sectionSize(c),
                 qPrintable(QStringLiteral("column %1 is narrower than its contents").arg(c)));
    }
}

void TestDecodePanel::problemsWrapAndKeepTheirRoom()
{
    // Reserved unit 250 (a warning) followed by a second frame (trailing bytes, an error).
    m_panel->setFrameText(QStringLiteral("FA 03 00 00 00 01 91 81 00 06 00 01 00 03 99 DA"));
    QTRY_VERIFY(rows() > 0);
    QTreeView *view = m_panel->treeView();
    const int viewport = view->viewport()->width();
    QVERIFY2(view->columnWidth(FieldTreeModel::ProblemColumn) >= viewport / 4,
             qPrintable(QStringLiteral("problem column %1 of %2").arg(view->columnWidth(FieldTreeModel::ProblemColumn)).arg(viewport)));
    // A message longer than its column wraps onto more lines instead of being cut.
    const FieldTreeModel *model = m_panel->model();
    const QModelIndex sound = model->indexOfKey("modbus.function_code", FieldTreeModel::ProblemColumn);
    const QModelIndex trailing = model->indexOfKey("frame.trailing", FieldTreeModel::ProblemColumn);
    QVERIFY(trailing.isValid());
    view->resize(500, view->height()); // narrow enough for every real message to need two lines
    QTRY_VERIFY(view->visualRect(trailing).height() > view->visualRect(sound).height());
}

QTEST_MAIN(TestDecodePanel)
#include "tst_decodepanel.moc"
