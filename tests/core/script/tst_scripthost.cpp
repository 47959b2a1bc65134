// ScriptHost: a device script's answers of every kind, its sandbox, its time limit and its
// errors located with file, line and (for syntax errors) column.
#include "script/scripthost.h"
#include "script/scripttables.h"

#include <QtCore/QFile>
#include <QtCore/QMap>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace mbscope;

namespace {

// Holding registers 0-9 and coils 0-7, as a unit's tables.
class Tables : public ScriptTables
{
public:
    QMap<int, quint16> holding;
    QMap<int, quint16> coils;
    Tables()
    {
        for (int i = 0; i < 10; ++i)
            holding.insert(i, quint16(100 + i));
        for (int i = 0; i < 8; ++i)
            coils.insert(i, 0);
    }
    [[nodiscard]] int unitId() const override { return 7; }
    [[nodiscard]] std::optional<quint16> value(ScriptTable table, int address) const override
    {
        const QMap<int, quint16> &m = table == ScriptTable::Coils ? coils : holding;
        if ((table != ScriptTable::Coils && table != ScriptTable::HoldingRegisters) || !m.contains(address))
            return std::nullopt;
        return m.value(address);
    }
    bool setValues(ScriptTable table, int address, const QList<quint16> &values) override
    {
        QMap<int, quint16> &m = table == ScriptTable::Coils ? coils : holding;
        for (int i = 0; i < values.size(); ++i) {
            if (!m.contains(address + i) || (table != ScriptTable::Coils && table != ScriptTable::HoldingRegisters))
                return false;
        }
        for (int i = 0; i < values.size(); ++i)
            m[address + i] = table == ScriptTable::Coils ? quint16(values.at(i) != 0) : values.at(i);
        return true;
    }
};

QByteArray pdu(const char *hex)
{
    return QByteArray::fromHex(hex);
}

} // namespace

class TestScriptHost : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    Tables m_tables;

    ScriptSettings write(const QString &name, const QByteArray &source)
    {
        QFile f(m_dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly))
            qFatal("cannot write %s", qPrintable(f.fileName()));
        f.write(source);
        ScriptSettings s;
        s.path = f.fileName();
        s.name = name;
        return s;
    }

    std::unique_ptr<ScriptHost> host(const QByteArray &source, double timeoutMs = 100)
    {
        ScriptSettings s = write(QStringLiteral("t.js"), source);
        s.timeoutMs = timeoutMs;
        auto h = std::make_unique<ScriptHost>(s, &m_tables);
        ScriptProblem problem;
        if (!h->load(&problem))
            qWarning("load: %s", qPrintable(problem.toString()));
        return h;
    }

    static ScriptRequest request(const char *hex)
    {
        ScriptRequest r = ScriptRequest::fromPdu(pdu(hex));
        r.unit = 7;
        r.endpoint = QStringLiteral("tcp://127.0.0.1:1502");
        r.peer = QStringLiteral("127.0.0.1:40000");
        r.transactionId = 9;
        return r;
    }

private Q_SLOTS:
    void requestFromPdu_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<int>("function");
        QTest::addColumn<int>("address");
        QTest::addColumn<int>("quantity");
        QTest::addColumn<QList<quint16>>("values");
        QTest::newRow("03 0010 x2") << pdu("0300100002") << 3 << 16 << 2 << QList<quint16>{};
        QTest::newRow("05 0003 FF00") << pdu("050003FF00") << 5 << 3 << 1 << QList<quint16>{1};
        QTest::newRow("06 0001 1234") << pdu("0600011234") << 6 << 1 << 1 << QList<quint16>{0x1234};
        QTest::newRow("0F 0000 x10 bits") << pdu("0F0000000A02CD01") << 15 << 0 << 10
                                          << QList<quint16>{1, 0, 1, 1, 0, 0, 1, 1, 1, 0};
        QTest::newRow("10 0002 x2") << pdu("100002000204000A0102") << 16 << 2 << 2 << QList<quint16>{10, 0x0102};
        QTest::newRow("17 read 3 x1 write 5") << pdu("17000300010005000102ABCD") << 0x17 << 3 << 1 << QList<quint16>{0xABCD};
        QTest::newRow("03 truncated") << pdu("0300") << 3 << -1 << -1 << QList<quint16>{};
        QTest::newRow("10 short of values") << pdu("1000020003060001") << 16 << 2 << 3 << QList<quint16>{1};
        QTest::newRow("11 no address") << pdu("11") << 0x11 << -1 << -1 << QList<quint16>{};
        QTest::newRow("empty") << QByteArray() << -1 << -1 << -1 << QList<quint16>{};
    }
    void requestFromPdu()
    {
        QFETCH(QByteArray, pdu);
        const ScriptRequest r = ScriptRequest::fromPdu(pdu);
        QTEST(r.function, "function");
        QTEST(r.address, "address");
        QTEST(r.quantity, "quantity");
        QTEST(r.values, "values");
    }

    void requestObjectFields()
    {
        auto h = host("function onRequest(r) {\n"
                      "  log(r.unit, r.function, r.address, r.quantity, JSON.stringify(r.values), JSON.stringify(r.pdu),\n"
                      "      r.endpoint, r.peer, r.transactionId, typeof r.time, r.writeAddress);\n"
                      "}\n");
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        const ScriptAnswer a = h->request(request("100002000204000A0102"));
        QCOMPARE(int(a.kind), int(ScriptAnswer::Kind::Normal));
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toString(),
                 QStringLiteral("7 16 2 2 [10,258] [16,0,2,0,2,4,0,10,1,2] tcp://127.0.0.1:1502 127.0.0.1:40000 9 number undefined"));
        QCOMPARE(spy.at(0).at(1).toBool(), false);
    }

    void answers_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QList<quint16>>("values");
        QTest::addColumn<int>("exception");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<qint64>("delayNs");
        using K = ScriptAnswer::Kind;
        QTest::newRow("undefined") << QByteArray("return undefined;") << int(K::Normal) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("null") << QByteArray("return null;") << int(K::Silence) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("silent") << QByteArray("return {silent: true};") << int(K::Silence) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("array") << QByteArray("return [1, 2, 65535];") << int(K::Values) << QList<quint16>{1, 2, 65535} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("values from the request") << QByteArray("return {values: [r.address, r.quantity, true]};") << int(K::Values)
                                                 << QList<quint16>{16, 2, 1} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("exception") << QByteArray("return {exception: 4};") << int(K::Exception) << QList<quint16>{} << 4 << QByteArray() << qint64(-1);
        QTest::newRow("pdu array") << QByteArray("return {pdu: [3, 2, 0, 7]};") << int(K::Pdu) << QList<quint16>{} << 0 << pdu("03020007") << qint64(-1);
        QTest::newRow("adu hex") << QByteArray("return {adu: '01 03 02 00 07 F9 86'};") << int(K::Adu) << QList<quint16>{} << 0
                                 << pdu("0103020007F986") << qint64(-1);
        QTest::newRow("delay alone") << QByteArray("return {delay: 2.5};") << int(K::Normal) << QList<quint16>{} << 0 << QByteArray() << qint64(2500000);
        QTest::newRow("delay 0.125 and exception") << QByteArray("return {delay: 0.125, exception: 6};") << int(K::Exception)
                                                   << QList<quint16>{} << 6 << QByteArray() << qint64(125000);
        QTest::newRow("string") << QByteArray("return 'x';") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("unknown key") << QByteArray("return {value: 1};") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("two answers") << QByteArray("return {values: [1], exception: 2};") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("value too big") << QByteArray("return [65536];") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("exception 0") << QByteArray("return {exception: 0};") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("negative delay") << QByteArray("return {delay: -1};") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
        QTest::newRow("bad hex") << QByteArray("return {adu: '01 0G'};") << int(K::Failed) << QList<quint16>{} << 0 << QByteArray() << qint64(-1);
    }
    void answers()
    {
        QFETCH(QByteArray, body);
        QFETCH(int, kind);
        auto h = host("function onRequest(r) { " + body + " }\n");
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        const ScriptAnswer a = h->request(request("0300100002"));
        QCOMPARE(int(a.kind), kind);
        if (kind == int(ScriptAnswer::Kind::Failed)) {
            QVERIFY2(a.note.startsWith(QLatin1String("t.js: onRequest returned ")), qPrintable(a.note));
            QCOMPARE(spy.size(), 1);
            QCOMPARE(spy.at(0).at(1).toBool(), true);
            QCOMPARE(h->failures(), quint64(1));
            return;
        }
        QTEST(a.values, "values");
        QTEST(a.exceptionCode, "exception");
        QTEST(a.bytes, "bytes");
        QTEST(a.delayNs, "delayNs");
    }

    void noOnRequestIsNormal()
    {
        auto h = host("var x = 1;\n");
        QVERIFY(h->isLoaded());
        QVERIFY(!h->handlesRequests());
        QCOMPARE(int(h->request(request("0300000001")).kind), int(ScriptAnswer::Kind::Normal));
    }

    void sandbox()
    {
        auto h = host("function onRequest(r) {\n"
                      "  log([typeof require, typeof XMLHttpRequest, typeof Qt, typeof importScripts, typeof process,\n"
                      "       typeof fetch, typeof print, typeof gc, typeof unit.deleteLater, typeof unit.objectName,\n"
                      "       Object.isFrozen(unit), typeof console.log].join(' '));\n"
                      "  unit.read = function () { return 0; };\n"
                      "  log(typeof unit.read('holding', 0));\n"
                      "}\n");
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        h->request(request("0300000001"));
        QCOMPARE(spy.size(), 2);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("undefined undefined undefined undefined undefined undefined "
                                                            "undefined undefined undefined undefined true function"));
        QCOMPARE(spy.at(1).at(0).toString(), QStringLiteral("number")); // the frozen unit kept its read
        QCOMPARE(m_tables.holding.value(0), quint16(100));
    }

    void importIsASyntaxError()
    {
        ScriptSettings s = write(QStringLiteral("imp.js"), "import x from '/etc/passwd';\n");
        const auto problem = ScriptHost::check(s);
        QVERIFY(problem);
        QCOMPARE(problem->file, QStringLiteral("imp.js"));
        QCOMPARE(problem->line, 1);
        QVERIFY2(problem->message.startsWith(QLatin1String("SyntaxError")), qPrintable(problem->message));
    }

    void tablesReadAndWritten()
    {
        auto h = host("function onTick(t) { unit.write('holding', 3, unit.read('holding', 3) + 1); unit.write('coils', 0, [1, true, 0]); }\n"
                      "function onRequest(r) { return unit.read('holding', r.address, r.quantity); }\n");
        QVERIFY(h->handlesTicks());
        QVERIFY(h->tick());
        QVERIFY(h->tick());
        QCOMPARE(m_tables.holding.value(3), quint16(105));
        QCOMPARE(m_tables.coils.value(1), quint16(1));
        const ScriptAnswer a = h->request(request("0300020003"));
        QCOMPARE(a.values, (QList<quint16>{102, 105, 104}));
    }

    void tableErrorsAreThrownIntoTheScript()
    {
        auto h = host("function onRequest(r) {\n"
                      "  return unit.read('holding', 50);\n"
                      "}\n");
        const ScriptAnswer a = h->request(request("0300000001"));
        QCOMPARE(int(a.kind), int(ScriptAnswer::Kind::Failed));
        QCOMPARE(a.note, QStringLiteral("t.js:2: RangeError: unit.read: address 50 is not in the unit's holding table"));
    }

    void endlessLoopInterruptedAndNextRequestServed()
    {
        auto h = host("var calls = 0;\n"
                      "function onRequest(r) {\n"
                      "  calls++;\n"
                      "  if (r.address === 1) { while (true) {} }\n"
                      "  return [calls];\n"
                      "}\n", 50);
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        const ScriptAnswer stuck = h->request(request("0300010001"));
        QCOMPARE(int(stuck.kind), int(ScriptAnswer::Kind::Failed));
        QVERIFY(stuck.timedOut);
        QVERIFY2(stuck.note.startsWith(QLatin1String("t.js")), qPrintable(stuck.note));
        QVERIFY2(stuck.note.endsWith(QLatin1String("onRequest ran longer than 50 ms: interrupted")), qPrintable(stuck.note));
        QCOMPARE(spy.size(), 1);
        const ScriptAnswer next = h->request(request("0300000001"));
        QCOMPARE(int(next.kind), int(ScriptAnswer::Kind::Values));
        QCOMPARE(next.values, QList<quint16>{2}); // the engine kept its state
    }

    void endlessTopLevelInterrupted()
    {
        ScriptSettings s = write(QStringLiteral("loop.js"), "for (;;) {}\n");
        s.timeoutMs = 30;
        const auto problem = ScriptHost::check(s);
        QVERIFY(problem);
        QCOMPARE(problem->toString().left(8), QStringLiteral("loop.js:"));
        QVERIFY2(problem->message.contains(QLatin1String("interrupted")), qPrintable(problem->message));
    }

    void syntaxErrorLocated()
    {
        ScriptSettings s = write(QStringLiteral("gamma.js"), "var a = 1;\n\nfunction onRequest(r {\n  return null;\n}\n");
        const auto problem = ScriptHost::check(s);
        QVERIFY(problem);
        QCOMPARE(problem->file, QStringLiteral("gamma.js"));
        QCOMPARE(problem->line, 3);
        QVERIFY2(problem->column > 0, qPrintable(problem->toString()));
        QVERIFY2(problem->toString().startsWith(QStringLiteral("gamma.js:3:%1: SyntaxError: ").arg(problem->column)),
                 qPrintable(problem->toString()));
    }

    void runtimeErrorLocated()
    {
        auto h = host("function helper() {\n"
                      "  return missing.value;\n"
                      "}\n"
                      "function onRequest(r) { return helper(); }\n");
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        const ScriptAnswer a = h->request(request("0300000001"));
        QCOMPARE(int(a.kind), int(ScriptAnswer::Kind::Failed));
        QCOMPARE(a.note, QStringLiteral("t.js:2: ReferenceError: missing is not defined"));
        QCOMPARE(spy.at(0).at(0).toString(), a.note);
        // and the host goes on
        QCOMPARE(int(h->request(request("0300000001")).kind), int(ScriptAnswer::Kind::Failed));
        QCOMPARE(h->failures(), quint64(2));
    }

    void topLevelErrorLocated()
    {
        ScriptSettings s = write(QStringLiteral("top.js"), "var a = 1;\nundefinedFunction();\n");
        const auto problem = ScriptHost::check(s);
        QVERIFY(problem);
        QCOMPARE(problem->toString(), QStringLiteral("top.js:2: ReferenceError: undefinedFunction is not defined"));
    }

    void missingFile()
    {
        ScriptSettings s;
        s.path = m_dir.filePath(QStringLiteral("nothing.js"));
        s.name = QStringLiteral("nothing.js");
        const auto problem = ScriptHost::check(s);
        QVERIFY(problem);
        QVERIFY2(problem->toString().startsWith(QLatin1String("nothing.js: no such script file")), qPrintable(problem->toString()));
    }

    void reloadStartsFresh()
    {
        ScriptSettings s = write(QStringLiteral("r.js"), "var n = 0; function onRequest(r) { return [++n]; }\n");
        ScriptHost h(s, &m_tables);
        QVERIFY(h.load());
        QCOMPARE(h.request(request("0300000001")).values, QList<quint16>{1});
        QCOMPARE(h.request(request("0300000001")).values, QList<quint16>{2});
        write(QStringLiteral("r.js"), "var n = 10; function onRequest(r) { return [++n]; }\n");
        QVERIFY(h.load());
        QCOMPARE(h.request(request("0300000001")).values, QList<quint16>{11});
        // a broken reload leaves the host without a script: the profile's answers
        write(QStringLiteral("r.js"), "function onRequest(r) {\n");
        ScriptProblem problem;
        QVERIFY(!h.load(&problem));
        QCOMPARE(problem.line, 2);
        QVERIFY(!h.isLoaded());
        QCOMPARE(int(h.request(request("0300000001")).kind), int(ScriptAnswer::Kind::Normal));
    }

    void frames()
    {
        auto h = host("function onFrame(f) {\n"
                      "  var m = /^\\$(\\d\\d)R$/.exec(f);\n"
                      "  if (!m) return null;\n"
                      "  if (m[1] === '09') return undefined;\n"
                      "  if (m[1] === '08') return [0x24, 0x41];\n"
                      "  return '$' + m[1] + ' ' + unit.read('holding', 0);\n"
                      "}\n");
        QVERIFY(h->handlesFrames());
        ScriptAnswer a = h->frame("$01R");
        QCOMPARE(int(a.kind), int(ScriptAnswer::Kind::Adu));
        QCOMPARE(a.bytes, QByteArray("$01 100"));
        QCOMPARE(h->frame("$08R").bytes, QByteArray("$A"));
        QCOMPARE(int(h->frame("junk").kind), int(ScriptAnswer::Kind::Silence));
        QCOMPARE(int(h->frame("$09R").kind), int(ScriptAnswer::Kind::Normal));
    }

    void consoleAndObjectsLogged()
    {
        auto h = host("console.log('loaded', {a: 1}, [2], null);\n");
        QVERIFY(h->isLoaded());
        // the load's own line went out before anyone listened; a second load says it again
        QSignalSpy spy(h.get(), &ScriptHost::logged);
        QVERIFY(h->load());
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("loaded {\"a\":1} [2] null"));
    }
};

QTEST_GUILESS_MAIN(TestScriptHost)
#include "tst_scripthost.moc"
