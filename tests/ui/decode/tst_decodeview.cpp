// DecodeView, offscreen: a request and its answer shown together with the verdict and latency,
// the answer checked against its request, placeholders when a side is missing, the engine's
// transactions shown the same way, selection sync in both frames, Copy as text, JSON and hex
// (also through the clipboard); a screenshot.
#include "decode/decodeview.h"
#include "common/exchangeformat.h"
#include "decode/fieldtreemodel.h"
#include "decode/frameinspector.h"
#include "guitestsupport.h"
#include "decode/hexview.h"

#include "protocol/dissectionformat.h"
#include "protocol/hextext.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QLabel>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// The tutorial's exchange (tests/data/published-frames.json): unit 7 reads 4 registers from 200.
const QByteArray kTutorialRequest = QByteArray::fromHex("07 03 00 C8 00 04 C5 91");
const QByteArray kTutorialResponse = QByteArray::fromHex("07 03 08 00 07 00 06 00 05 00 04 64 5D");
// The Arduino's answer to another request: checked against the tutorial request it is wrong.
const QByteArray kArduinoResponse = QByteArray::fromHex("01 03 08 00 45 00 4E 00 01 00 01 79 1D");

FrameExchange tutorialExchange()
{
    FrameExchange e;
    e.request = kTutorialRequest;
    e.response = kTutorialResponse;
    e.framing = Framing::Rtu;
    e.selected = TrafficDirection::In;
    e.verdict = TrafficVerdict::Ok;
    e.latencyNs = 12'345'000;
    e.transactionId = 42;
    e.link = QStringLiteral("rtu-tcp://127.0.0.1:4001");
    return e;
}

QLabel *label(const QWidget *w, const char *name)
{
    return w->findChild<QLabel *>(QLatin1String(name));
}

} // namespace

class TestDecodeView : public QObject
{
    Q_OBJECT

private:
    DecodeView *m_view = nullptr;

private Q_SLOTS:
    void init();
    void cleanup();
    void startsEmpty();
    void showsRequestAndAnswerTogether();
    void answerIsCheckedAgainstItsRequest();
    void missingSides_data();
    void missingSides();
    void transactionFromTheEngine();
    void selectionSyncInBothFrames();
    void copyAsText();
    void copyAsJson();
    void copyAsHex();
    void copyGoesToTheClipboard_data();
    void copyGoesToTheClipboard();
    void screenshot();
};

void TestDecodeView::init()
{
    m_view = new DecodeView;
    m_view->resize(1100, 700);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view));
}

void TestDecodeView::cleanup()
{
    delete m_view;
    m_view = nullptr;
}

void TestDecodeView::startsEmpty()
{
    QVERIFY(m_view->requestDissection().fields.isEmpty());
    QVERIFY(m_view->responseDissection().fields.isEmpty());
    QVERIFY(!label(m_view, "exchangeHeader")->text().isEmpty());
    QCOMPARE(m_view->copyText(DecodeView::CopyFormat::Hex), QString());
    QCOMPARE(m_view->copyText(DecodeView::CopyFormat::Json).trimmed(), QStringLiteral("{\n}"));
}

void TestDecodeView::showsRequestAndAnswerTogether()
{
    QAbstractItemModelTester requestTester(m_view->requestInspector()->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester responseTester(m_view->responseInspector()->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy shown(m_view, &DecodeView::shown);
    m_view->showExchange(tutorialExchange());
    QCOMPARE(shown.size(), 1);
    QCOMPARE(m_view->requestDissection().fields.frame(), kTutorialRequest);
    QCOMPARE(m_view->responseDissection().fields.frame(), kTutorialResponse);
    QCOMPARE(m_view->requestDissection().direction, Direction::Request);
    QCOMPARE(m_view->responseDissection().direction, Direction::Response);
    QVERIFY(m_view->requestDissection().isValid());
    QVERIFY(m_view->responseDissection().isValid());
    QCOMPARE(m_view->requestInspector()->hexView()->bytes(), kTutorialRequest);
    QCOMPARE(m_view->responseInspector()->hexView()->bytes(), kTutorialResponse);
    const QString header = label(m_view, "exchangeHeader")->text();
    QVERIFY2(header.contains(QStringLiteral("12.345 ms")), qPrintable(header));
    QVERIFY2(header.contains(QStringLiteral("ok")), qPrintable(header));
    QVERIFY2(header.contains(QStringLiteral("Read Holding Registers")), qPrintable(header));
    QVERIFY2(header.contains(QStringLiteral("rtu-tcp://127.0.0.1:4001")), qPrintable(header));
    QCOMPARE(m_view->responseInspector()->title(), QStringLiteral("Response \u00B7 after 12.345 ms \u25C0"));
    QCOMPARE(m_view->requestInspector()->title(), QStringLiteral("Request"));
    // Picking the request marks it instead.
    FrameExchange e = tutorialExchange();
    e.selected = TrafficDirection::Out;
    m_view->showExchange(e);
    QCOMPARE(m_view->requestInspector()->title(), QStringLiteral("Request \u25C0"));
}

void TestDecodeView::answerIsCheckedAgainstItsRequest()
{
    FrameExchange e = tutorialExchange();
    e.response = kArduinoResponse; // unit 1 answering a request to unit 7
    m_view->showExchange(e);
    const Dissection &d = m_view->responseDissection();
    QVERIFY(d.fields.worstSeverity() >= Severity::Warning);
    // Without its request the same answer reads as a sound frame.
    e.request.clear();
    m_view->showExchange(e);
    QVERIFY(m_view->responseDissection().isValid());
    QCOMPARE(m_view->responseDissection().fields.worstSeverity(), Severity::Ok);
}

void TestDecodeView::missingSides_data()
{
    QTest::addColumn<bool>("withRequest");
    QTest::addColumn<bool>("withResponse");
    QTest::addColumn<int>("verdict");
    QTest::addColumn<QString>("requestText");  // placeholder, empty: a frame is shown
    QTest::addColumn<QString>("responseText"); // placeholder, empty: a frame is shown

    QTest::newRow("timeout") << true << false << int(TrafficVerdict::Timeout) << QString() << QStringLiteral("No answer: timeout");
    QTest::newRow("link error") << true << false << int(TrafficVerdict::LinkError) << QString()
                                << QStringLiteral("No answer: link error");
    QTest::newRow("waiting") << true << false << int(TrafficVerdict::Sent) << QString() << QStringLiteral("No answer yet");
    QTest::newRow("broadcast") << true << false << int(TrafficVerdict::Broadcast) << QString()
                               << QStringLiteral("Broadcast: no answer is expected");
    QTest::newRow("unsolicited") << false << true << int(TrafficVerdict::Unsolicited)
                                 << QStringLiteral("No request: this frame answers none that was sent (unsolicited)") << QString();
}

void TestDecodeView::missingSides()
{
    QFETCH(bool, withRequest);
    QFETCH(bool, withResponse);
    QFETCH(int, verdict);
    QFETCH(QString, requestText);
    QFETCH(QString, responseText);

    FrameExchange e = tutorialExchange();
    if (!withRequest)
        e.request.clear();
    if (!withResponse)
        e.response.clear();
    e.selected = withResponse ? TrafficDirection::In : TrafficDirection::Out;
    e.verdict = TrafficVerdict(verdict);
    e.latencyNs = withRequest && withResponse ? e.latencyNs : -1;
    m_view->showExchange(e);
    const auto check = [](FrameInspector *inspector, const QString &placeholder) {
        QLabel *p = label(inspector, "framePlaceholder");
        QCOMPARE(p->isVisible(), !placeholder.isEmpty());
        QCOMPARE(inspector->hexView()->isVisible(), placeholder.isEmpty());
        if (!placeholder.isEmpty())
            QCOMPARE(p->text(), placeholder);
    };
    check(m_view->requestInspector(), requestText);
    check(m_view->responseInspector(), responseText);
    QVERIFY(!label(m_view, "exchangeHeader")->text().contains(QStringLiteral("latency")));
}

void TestDecodeView::transactionFromTheEngine()
{
    Transaction t;
    t.id = 9;
    t.request = kTutorialRequest;
    t.response = kTutorialResponse;
    t.status = TransactionStatus::Ok;
    t.sentNs = 1'000'000;
    t.doneNs = 1'850'000;
    m_view->showTransaction(t, Framing::Rtu);
    QCOMPARE(m_view->exchange().latencyNs, 850'000);
    QCOMPARE(m_view->exchange().selected, TrafficDirection::In);
    QVERIFY(label(m_view, "exchangeHeader")->text().contains(QStringLiteral("850.0 µs")));
    QVERIFY(m_view->responseDissection().isValid());
    t.response.clear();
    t.status = TransactionStatus::Timeout;
    t.doneNs = 0;
    m_view->showTransaction(t, Framing::Rtu);
    QCOMPARE(label(m_view->responseInspector(), "framePlaceholder")->text(), QStringLiteral("No answer: timeout"));
    QCOMPARE(m_view->exchange().latencyNs, -1);
}

void TestDecodeView::selectionSyncInBothFrames()
{
    m_view->showExchange(tutorialExchange());
    for (FrameInspector *inspector : {m_view->requestInspector(), m_view->responseInspector()}) {
        HexView *hex = inspector->hexView();
        const FieldTree &tree = inspector->dissection().fields;
        // The second byte is the function code in RTU.
        QTest::mouseClick(hex->viewport(), Qt::LeftButton, {}, hex->byteRect(1).center());
        QCOMPARE(inspector->selectedField(), tree.indexOf("modbus.function_code"));
        const int crc = tree.indexOf("rtu.crc");
        inspector->selectField(crc);
        QCOMPARE(hex->selectionOffset(), int(inspector->dissection().fields.frame().size()) - 2);
        QCOMPARE(hex->selectionLength(), 2);
    }
}

void TestDecodeView::copyAsText()
{
    m_view->showExchange(tutorialExchange());
    const QString text = m_view->copyText(DecodeView::CopyFormat::Text);
    QVERIFY(text.startsWith(QStringLiteral("== Request ==\n")));
    QVERIFY(text.contains(DissectionFormat::toTable(m_view->requestDissection())));
    QVERIFY(text.contains(QStringLiteral("\n== Response ==\n") + DissectionFormat::toTable(m_view->responseDissection())));
    QVERIFY(text.endsWith(QStringLiteral("Verdict: ok, Latency: 12.345 ms\n")));
    QVERIFY(text.indexOf(QStringLiteral("Request")) < text.indexOf(QStringLiteral("Response")));
}

void TestDecodeView::copyAsJson()
{
    m_view->showExchange(tutorialExchange());
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(m_view->copyText(DecodeView::CopyFormat::Json).toUtf8(), &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    const QJsonObject o = doc.object();
    QCOMPARE(o.value(QStringLiteral("request")).toObject(), DissectionFormat::toJson(m_view->requestDissection()));
    QCOMPARE(o.value(QStringLiteral("response")).toObject(), DissectionFormat::toJson(m_view->responseDissection()));
    QCOMPARE(o.value(QStringLiteral("latency_ns")).toInteger(), 12'345'000);
    QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("ok"));
    QCOMPARE(o.value(QStringLiteral("response")).toObject().value(QStringLiteral("direction")).toString(), QStringLiteral("response"));
    // A timeout has no response and no latency.
    FrameExchange e = tutorialExchange();
    e.response.clear();
    e.latencyNs = -1;
    e.verdict = TrafficVerdict::Timeout;
    m_view->showExchange(e);
    const QJsonObject t = QJsonDocument::fromJson(m_view->copyText(DecodeView::CopyFormat::Json).toUtf8()).object();
    QVERIFY(t.contains(QStringLiteral("request")));
    QVERIFY(!t.contains(QStringLiteral("response")));
    QVERIFY(!t.contains(QStringLiteral("latency_ns")));
    QCOMPARE(t.value(QStringLiteral("verdict")).toString(), QStringLiteral("timeout"));
}

void TestDecodeView::copyAsHex()
{
    m_view->showExchange(tutorialExchange());
    QCOMPARE(m_view->copyText(DecodeView::CopyFormat::Hex),
             QStringLiteral("07 03 00 C8 00 04 C5 91\n07 03 08 00 07 00 06 00 05 00 04 64 5D"));
    // What is copied parses back to the frames.
    const QStringList lines = m_view->copyText(DecodeView::CopyFormat::Hex).split(QLatin1Char('\n'));
    QCOMPARE(HexText::parse(lines.at(0)).bytes, kTutorialRequest);
    QCOMPARE(HexText::parse(lines.at(1)).bytes, kTutorialResponse);
}

void TestDecodeView::copyGoesToTheClipboard_data()
{
    QTest::addColumn<int>("format");
    QTest::newRow("text") << int(DecodeView::CopyFormat::Text);
    QTest::newRow("json") << int(DecodeView::CopyFormat::Json);
    QTest::newRow("hex") << int(DecodeView::CopyFormat::Hex);
}

void TestDecodeView::copyGoesToTheClipboard()
{
    QFETCH(int, format);
    m_view->showExchange(tutorialExchange());
    QGuiApplication::clipboard()->clear();
    // Through the Copy menu's action, as a user does.
    auto *action = m_view->findChild<QAction *>(QStringLiteral("copyAs") + QString::number(format));
    QVERIFY(action);
    action->trigger();
    QCOMPARE(QGuiApplication::clipboard()->text(), m_view->copyText(DecodeView::CopyFormat(format)));
    QVERIFY(!QGuiApplication::clipboard()->text().isEmpty());
}

void TestDecodeView::screenshot()
{
    FrameExchange e = tutorialExchange();
    m_view->showExchange(e);
    m_view->responseInspector()->selectField(m_view->responseDissection().fields.indexOf("modbus.byte_count"));
    QVERIFY(guitest::saveShot(m_view, QStringLiteral("decodeview.png")));
    // A bad answer: the problems in the tree and tinted in the bytes.
    e.response = QByteArray::fromHex(
        "01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 20 1F 40 "
        "00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72");
    e.request = QByteArray::fromHex("01 03 00 79 00 16 15 DD");
    e.verdict = TrafficVerdict::Malformed;
    m_view->showExchange(e);
    QVERIFY(guitest::saveShot(m_view, QStringLiteral("decodeview-malformed.png")));
}

QTEST_MAIN(TestDecodeView)
#include "tst_decodeview.moc"
