// Session documents round trip: every feature of the document, one row each, written by
// SessionWriter, read back by SessionReader to the same value, and written again to the same
// bytes. A save that fails leaves the previous file as it was (a save killed half way:
// tst_sessionrecovery).

#include "session/sessionreader.h"
#include "session/sessionwriter.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

Q_DECLARE_METATYPE(mbscope::SessionDocument)

namespace {

SessionRequest hexRequest(const QString &name, const QString &hex)
{
    SessionRequest r;
    r.name = name;
    r.hex = hex;
    return r;
}

SessionRequest formRequest(const QString &name, int function, int address, int quantity = 0)
{
    SessionRequest r;
    r.name = name;
    r.kind = SessionRequest::Kind::Form;
    r.function = function;
    r.address = address;
    r.quantity = quantity;
    return r;
}

PlanStep sendStep(const QString &name, const QString &request)
{
    PlanStep s;
    s.kind = PlanStep::Kind::Send;
    s.name = name;
    s.requestName = request;
    return s;
}

FieldExpectation field(const QString &selector, std::optional<qint64> equals, std::optional<qint64> min = {},
                       std::optional<qint64> max = {})
{
    FieldExpectation f;
    QString error;
    if (!FieldExpectation::parseSelector(selector, &f, &error))
        qFatal("%s", qPrintable(error));
    f.equals = equals;
    f.min = min;
    f.max = max;
    return f;
}

PollBound bound(const QString &text)
{
    const PollBound::Parsed p = PollBound::parse(text);
    if (!p.bound)
        qFatal("%s", qPrintable(p.error));
    return *p.bound;
}

SessionDocument base()
{
    SessionDocument d;
    d.requests.append(hexRequest(QStringLiteral("read all"), QStringLiteral("01 03 00 79 00 16 15 DD")));
    return d;
}

} // namespace

class TestSessionDocument : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void writtenDefaultsLeftOut();
    void failedSaveChangesNothing();
    void saveReplaces();
};

void TestSessionDocument::roundTrip_data()
{
    QTest::addColumn<SessionDocument>("document");

    QTest::newRow("empty") << SessionDocument{};
    {
        SessionDocument d;
        d.target.url = QStringLiteral("rtu-tcp://127.0.0.1:4001");
        SessionTap tap;
        tap.listen = {QStringLiteral("tcp://127.0.0.1:5020"), QStringLiteral("udp://127.0.0.1:5020")};
        tap.routes = {QStringLiteral("1-10=rtu:///dev/ttyUSB0?baud=19200"), QStringLiteral("20:1=tcp://10.0.0.5:502")};
        tap.readOnly = true;
        tap.refuse = QStringLiteral("silence");
        tap.noAnswer = QStringLiteral("exception");
        tap.retries = 3;
        d.tap = tap;
        QTest::newRow("tap") << d;
        SessionTap plain;
        plain.listen = {QStringLiteral("tcp://0.0.0.0:502")};
        d.tap = plain;
        QTest::newRow("tap, defaults") << d;
    }
    {
        SessionDocument d;
        d.name = QStringLiteral("RosRao bench \u00b5 \"quoted\"");
        d.notes = QStringLiteral("two\nlines");
        QTest::newRow("name and notes") << d;
    }
    {
        SessionDocument d;
        d.target.url = QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=N&data=8&stop=2");
        d.target.timeoutMs = 250;
        d.target.retries = 2;
        d.target.pipelineDepth = 4;
        QTest::newRow("target") << d;
    }
    {
        SessionDocument d = base();
        d.requests[0].notes = QStringLiteral("the request typed by hand");
        QTest::newRow("hex request") << d;
    }
    {
        SessionDocument d;
        SessionRequest r = hexRequest(QStringLiteral("pdu"), QStringLiteral("03 00 79 00 16"));
        r.complete = true;
        r.unit = 3;
        d.requests.append(r);
        QTest::newRow("hex request completed") << d;
    }
    {
        SessionDocument d;
        for (int function : {1, 2, 3, 4})
            d.requests.append(formRequest(QStringLiteral("read %1").arg(function), function, 121, 22));
        d.requests[2].unit = 247;
        QTest::newRow("form reads") << d;
    }
    {
        SessionDocument d;
        SessionRequest single = formRequest(QStringLiteral("coil"), 5, 7);
        single.coils = {true};
        SessionRequest coils = formRequest(QStringLiteral("coils"), 15, 0);
        coils.coils = {true, false, true};
        SessionRequest reg = formRequest(QStringLiteral("register"), 6, 0x7F);
        reg.values = {2000};
        SessionRequest regs = formRequest(QStringLiteral("registers"), 16, 0x79);
        regs.values = {1050, 0, 65535};
        d.requests = {single, coils, reg, regs};
        QTest::newRow("form writes") << d;
    }
    {
        SessionDocument d = base();
        d.poll = SessionPoll{{QStringLiteral("read all")}, 500, 100, 0};
        QTest::newRow("poll") << d;
    }
    {
        SessionDocument d = base();
        d.poll = SessionPoll{{QStringLiteral("read all"), QStringLiteral("read all")}, 0, 0, 60000};
        d.sweep = SessionSweep{SessionPoll{{QStringLiteral("read all")}, 0, 300, 0}, {100, 200, 333}};
        QTest::newRow("poll by duration and sweep") << d;
    }
    {
        SessionDocument d;
        d.profile.kind = SessionProfile::Kind::Reference;
        d.profile.reference = QStringLiteral("rosrao-gamma");
        QTest::newRow("profile reference") << d;
    }
    {
        SessionDocument d;
        d.profile.kind = SessionProfile::Kind::Inline;
        d.profile.profile = QJsonDocument::fromJson(R"({"name": "tiny", "units": [{"id": 1,
            "tables": {"holding": [{"address": 0, "values": [1, 2, 3]}]}}]})").object();
        QTest::newRow("profile inline") << d;
    }
    {
        SessionDocument d;
        d.capture = SessionCapture{QStringLiteral("bench.mbscope.journal"), QStringLiteral("kill -9 at 12:00"), {}};
        QTest::newRow("capture") << d;
        d.capture->ignore = {QStringLiteral("modbus.register_value@0x0086"), QStringLiteral("modbus.byte_count")};
        QTest::newRow("capture with fields replay ignores") << d;
    }
    {
        SessionDocument d = base();
        PlanStep plain = sendStep(QStringLiteral("plain"), QStringLiteral("read all"));
        PlanStep bytes = sendStep(QStringLiteral("bytes"), QStringLiteral("read all"));
        bytes.expect.bytes = QStringLiteral("01 06 00 7F 07 D0 BB BE");
        PlanStep fields = sendStep(QStringLiteral("fields"), QStringLiteral("read all"));
        // Fields come back in key order (a JSON object's members have none).
        fields.expect.fields = {field(QStringLiteral("modbus.byte_count"), {}, 40, {}),
                                field(QStringLiteral("modbus.register_value@121"), 1050),
                                field(QStringLiteral("modbus.register_value@134"), {}, 0, 1000),
                                field(QStringLiteral("modbus.register_value[3]"), {}, {}, 7)};
        PlanStep exception = sendStep(QStringLiteral("exception"), QStringLiteral("read all"));
        exception.expect.exception = 11;
        exception.expect.fields = {field(QStringLiteral("modbus.function_code"), 0x83)};
        PlanStep silent = sendStep(QStringLiteral("silent"), QStringLiteral("read all"));
        silent.expect.noAnswer = true;
        d.plan = {plain, bytes, fields, exception, silent};
        QTest::newRow("send steps and expectations") << d;
    }
    {
        SessionDocument d = base();
        PlanStep own;
        own.name = QStringLiteral("own form");
        own.notes = QStringLiteral("not in the list");
        own.request = formRequest(QString(), 3, 0x200, 1);
        own.expect.exception = 2;
        PlanStep ownHex;
        ownHex.name = QStringLiteral("own hex");
        ownHex.request = hexRequest(QString(), QStringLiteral("09 03 00 79 00 01 54 9B"));
        PlanStep expect;
        expect.kind = PlanStep::Kind::Expect;
        expect.name = QStringLiteral("again");
        expect.expect.exception = 11;
        d.plan = {own, ownHex, expect};
        QTest::newRow("own requests and an expect step") << d;
    }
    {
        SessionDocument d = base();
        PlanStep poll;
        poll.kind = PlanStep::Kind::Poll;
        poll.name = QStringLiteral("latency");
        poll.poll = SessionPoll{{QStringLiteral("read all")}, 10, 50, 0};
        poll.bounds = {bound(QStringLiteral("p95 < 20 ms")), bound(QStringLiteral("timeouts == 0")),
                       bound(QStringLiteral("error_rate <= 1.5 %")), bound(QStringLiteral("p99.9 < 250us"))};
        PlanStep wait;
        wait.kind = PlanStep::Kind::Wait;
        wait.name = QStringLiteral("settle");
        wait.waitMs = 1500;
        PlanStep repeat;
        repeat.kind = PlanStep::Kind::Repeat;
        repeat.name = QStringLiteral("three times");
        repeat.times = 3;
        PlanStep inner;
        inner.kind = PlanStep::Kind::Repeat;
        inner.name = QStringLiteral("nested");
        inner.times = 2;
        inner.steps = {sendStep(QStringLiteral("read"), QStringLiteral("read all")), wait};
        repeat.steps = {inner, poll};
        d.plan = {poll, wait, repeat};
        QTest::newRow("poll, wait and repeat steps") << d;
    }
}

void TestSessionDocument::roundTrip()
{
    QFETCH(SessionDocument, document);
    const QByteArray written = SessionWriter::toBytes(document);
    const SessionLoadResult loaded = SessionReader::parse(written, QStringLiteral("round.mbscope.json"));
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText() + QLatin1Char('\n') + QString::fromUtf8(written)));
    QVERIFY2(*loaded.document == document, written.constData());
    QCOMPARE(SessionWriter::toBytes(*loaded.document), written);
}

void TestSessionDocument::writtenDefaultsLeftOut()
{
    const QJsonObject json = SessionWriter::toJson(base());
    QCOMPARE(json.value(QLatin1String("format")).toString(), QStringLiteral("mbscope-session"));
    // Without a tap, the version an mbscope reading version 2 still opens.
    QCOMPARE(json.value(QLatin1String("version")).toInt(), 2);
    QCOMPARE(json.keys(), (QStringList{QStringLiteral("format"), QStringLiteral("requests"), QStringLiteral("version")}));
    SessionDocument tapped = base();
    tapped.tap = SessionTap{{QStringLiteral("tcp://127.0.0.1:5020")}, {}, false, QStringLiteral("exception"), QStringLiteral("auto"), 0};
    const QJsonObject withTap = SessionWriter::toJson(tapped);
    QCOMPARE(withTap.value(QLatin1String("version")).toInt(), SessionDocument::kVersion);
    QCOMPARE(withTap.value(QLatin1String("tap")).toObject().keys(), (QStringList{QStringLiteral("listen"), QStringLiteral("noAnswer")}));
}

void TestSessionDocument::saveReplaces()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("s.mbscope.json"));
    SessionDocument one = base();
    one.name = QStringLiteral("one");
    SessionDocument two = base();
    two.name = QStringLiteral("two");
    QString error;
    QVERIFY2(SessionWriter::save(one, path, &error), qPrintable(error));
    QVERIFY2(SessionWriter::save(two, path, &error), qPrintable(error));
    const SessionLoadResult loaded = SessionReader::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(loaded.document->name, QStringLiteral("two"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("s.mbscope.json")}); // no temporary left
}

void TestSessionDocument::failedSaveChangesNothing()
{
    // A save that cannot complete (its folder is gone) fails with a message and changes nothing;
    // a save over a path that is a folder refuses without touching it.
    QTemporaryDir dir;
    const QString gone = dir.filePath(QStringLiteral("no/such/folder/s.mbscope.json"));
    QString error;
    QVERIFY(!SessionWriter::save(base(), gone, &error));
    QVERIFY2(error.startsWith(gone + QStringLiteral(": cannot save the session: ")), qPrintable(error));

    const QString path = dir.filePath(QStringLiteral("s.mbscope.json"));
    SessionDocument one = base();
    one.name = QStringLiteral("one");
    QVERIFY2(SessionWriter::save(one, path, &error), qPrintable(error));
    const QByteArray before = SessionWriter::toBytes(one);
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("s.mbscope.json.folder")));
    QVERIFY(!SessionWriter::save(base(), dir.filePath(QStringLiteral("s.mbscope.json.folder")), &error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), before);
}

QTEST_GUILESS_MAIN(TestSessionDocument)
#include "tst_sessiondocument.moc"
