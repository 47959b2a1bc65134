// mbscope send, read and write as users run them, against pymodbus servers on 127.0.0.1 (tcp,
// udp, rtu-tcp, ascii-tcp): bytes sent exactly or completed, answers decoded, values in the
// formats asked with Modicon references, writes read back, and the exit statuses: 0 ok, 1 a
// failed transaction, 2 a usage or link error with a message that names the option at fault.
#include "clitest.h"

#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtTest/QTest>

#include <cstring>
#include <map>

using namespace mbscope;
using namespace mbscope::testcli;

class TestCliExchange : public QObject
{
    Q_OBJECT

    std::map<QString, std::unique_ptr<PymodbusTarget>> m_targets;
    QString m_closed; // a target URL nothing listens on

    // The server for a mode, started on first use; empty with QSKIP-able reason on failure.
    QString target(const QString &mode, QString *error);

private slots:
    void initTestCase();
    void sendExact_data();
    void sendExact();
    void sendWrongCrcIsSentAsTyped();
    void sendComplete_data();
    void sendComplete();
    void sendText();
    void readFormats_data();
    void readFormats();
    void readText();
    void readException();
    void writeThenRead_data();
    void writeThenRead();
    void usageErrors_data();
    void usageErrors();
    void linkRefused_data();
    void linkRefused();
    void readOverSerialPty_data();
    void readOverSerialPty();
    void help_data();
    void help();
    void usageLine_data();
    void usageLine();
    void topLevelHelp_data();
    void topLevelHelp();
    void helpAll();
};

QString TestCliExchange::target(const QString &mode, QString *error)
{
    auto found = m_targets.find(mode);
    if (found != m_targets.end())
        return found->second->url();
    auto t = std::make_unique<PymodbusTarget>();
    if (!t->start(mode, error))
        return {};
    const QString url = t->url();
    m_targets.emplace(mode, std::move(t));
    return url;
}

void TestCliExchange::initTestCase()
{
    QVERIFY2(QFileInfo::exists(mbscopePath()), qPrintable(mbscopePath()));
    const quint16 port = closedPort();
    QVERIFY(port != 0);
    m_closed = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
}

#define TARGET(mode, var)                                                                                                  \
    QString var##Error;                                                                                                    \
    const QString var = target(QStringLiteral(mode), &var##Error);                                                         \
    if (var.isEmpty())                                                                                                     \
        QSKIP(qPrintable(var##Error));

void TestCliExchange::sendExact_data()
{
    QTest::addColumn<QString>("mode");
    QTest::addColumn<QString>("request");
    QTest::addColumn<QString>("response");
    // hr(121) = 1000 + 3 * 121 = 1363 = 0x0553, hr(122) = 0x0556 (peer_datamap.h).
    QTest::newRow("00 2A 00 00 00 06 01 03 00 79 00 02") << "tcp" << "00 2A 00 00 00 06 01 03 00 79 00 02"
                                                         << "00 2A 00 00 00 07 01 03 04 05 53 05 56";
    QTest::newRow("01 03 00 79 00 02 15 D2") << "rtu-tcp" << "01 03 00 79 00 02 15 D2"
                                             << "01 03 04 05 53 05 56 89 80";
    QTest::newRow("udp 12 34 00 00 00 06 01 03 00 79 00 02") << "udp" << "12 34 00 00 00 06 01 03 00 79 00 02"
                                                             << "12 34 00 00 00 07 01 03 04 05 53 05 56";
    // On an ASCII link the frame may be typed as its characters; CR LF is added.
    QTest::newRow(":01030079000281") << "ascii-tcp" << ":01030079000281"
                                     << QString::fromLatin1(QByteArray(":0103040553055645\r\n").toHex(' ').toUpper());
}

void TestCliExchange::sendExact()
{
    QFETCH(QString, mode);
    QFETCH(QString, request);
    QFETCH(QString, response);
    QString error;
    const QString url = target(mode, &error);
    if (url.isEmpty())
        QSKIP(qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), url, QStringLiteral("--hex"), request,
                                    QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
    const QString sent = request.startsWith(QLatin1Char(':'))
                             ? QString::fromLatin1((request.toLatin1() + "\r\n").toHex(' ').toUpper())
                             : request;
    QCOMPARE(o.value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString(), sent);
    QCOMPARE(o.value(QStringLiteral("response")).toObject().value(QStringLiteral("hex")).toString(), response);
    QVERIFY(o.value(QStringLiteral("latency_us")).toDouble() > 0);
    QCOMPARE(o.value(QStringLiteral("target")).toString(), url);
    const QJsonObject dissection = o.value(QStringLiteral("response")).toObject().value(QStringLiteral("dissection")).toObject();
    QCOMPARE(dissection.value(QStringLiteral("valid")).toBool(), true);
    QCOMPARE(dissection.value(QStringLiteral("direction")).toString(), QStringLiteral("response"));
}

void TestCliExchange::sendWrongCrcIsSentAsTyped()
{
    TARGET("rtu-tcp", url);
    // A wrong CRC on purpose: sent as typed (never "fixed"); the server drops it, so: timeout, exit 1.
    const QString bad = QStringLiteral("01 03 00 79 00 02 00 00");
    const CliResult r = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), url, QStringLiteral("--hex"), bad,
                                    QStringLiteral("--timeout"), QStringLiteral("300ms"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 1, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("status")).toString(), QStringLiteral("timeout"));
    QCOMPARE(o.value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString(), bad);
    QVERIFY(o.value(QStringLiteral("response")).isNull());
    QVERIFY(o.value(QStringLiteral("latency_us")).isNull());
}

void TestCliExchange::sendComplete_data()
{
    QTest::addColumn<QString>("mode");
    QTest::addColumn<QString>("request");
    QTest::addColumn<QString>("response");
    QTest::newRow("tcp 03 0079 0002") << "tcp" << "00 01 00 00 00 06 01 03 00 79 00 02"
                                      << "00 01 00 00 00 07 01 03 04 05 53 05 56";
    QTest::newRow("udp 03 0079 0002") << "udp" << "00 01 00 00 00 06 01 03 00 79 00 02"
                                      << "00 01 00 00 00 07 01 03 04 05 53 05 56";
    QTest::newRow("rtu-tcp 03 0079 0002") << "rtu-tcp" << "01 03 00 79 00 02 15 D2" << "01 03 04 05 53 05 56 89 80";
    // ":010300790002" LRC 81 CR LF; the answer ":01030405530556" LRC 45 CR LF.
    QTest::newRow("ascii-tcp 03 0079 0002") << "ascii-tcp"
                                            << QString::fromLatin1(QByteArray(":01030079000281\r\n").toHex(' ').toUpper())
                                            << QString::fromLatin1(QByteArray(":0103040553055645\r\n").toHex(' ').toUpper());
}

void TestCliExchange::sendComplete()
{
    QFETCH(QString, mode);
    QFETCH(QString, request);
    QFETCH(QString, response);
    QString error;
    const QString url = target(mode, &error);
    if (url.isEmpty())
        QSKIP(qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), url, QStringLiteral("--hex"),
                                    QStringLiteral("03 0079 0002"), QStringLiteral("--complete"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString(), request);
    QCOMPARE(o.value(QStringLiteral("response")).toObject().value(QStringLiteral("hex")).toString(), response);
}

void TestCliExchange::sendText()
{
    TARGET("tcp", url);
    const CliResult r = runMbscope({QStringLiteral("send"), QStringLiteral("--target"), url, QStringLiteral("--hex"),
                                    QStringLiteral("00 01 00 00 00 06 01 03 00 79 00 02")});
    QVERIFY2(r.exitCode == 0, r.describe());
    const QString text = r.outText();
    for (const char *expected : {"REQUEST to tcp://127.0.0.1:", "12 bytes: 00 01 00 00 00 06 01 03 00 79 00 02",
                                 "Read Holding Registers", "RESPONSE after", "05 53", "RESULT ok: answered in"})
        QVERIFY2(text.contains(QLatin1String(expected)), qPrintable(QStringLiteral("%1 not in\n%2").arg(QLatin1String(expected), text)));
    QVERIFY(r.err.isEmpty());
}

void TestCliExchange::readFormats_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<QString>("reference");
    const auto args = [](const char *function, const char *address, const char *quantity, const char *format) {
        QStringList a{QStringLiteral("--function"), QLatin1String(function), QStringLiteral("--address"),
                      QLatin1String(address), QStringLiteral("--quantity"), QLatin1String(quantity)};
        if (format)
            a << QStringLiteral("--format") << QLatin1String(format);
        return a;
    };
    QTest::newRow("03 0x79 x4 u16") << args("3", "0x79", "4", nullptr) << 0 << "u16" << QVariant(1363) << "40122";
    QTest::newRow("03 0x79 x4 hex") << args("3", "0x79", "4", "u16,hex") << 1 << "hex" << QVariant(QStringLiteral("0x0556"))
                                    << "40123";
    QTest::newRow("03 121 x4 raw") << args("3", "121", "4", "hex") << 3 << "raw" << QVariant(1000 + 3 * 124) << "40125";
    // 0x0553 0x0556 as one IEEE 754 single, most significant register first.
    float f = 0;
    const quint32 bits = 0x05530556u;
    std::memcpy(&f, &bits, sizeof f);
    QTest::newRow("03 0x79 x4 f32-abcd") << args("3", "0x79", "4", "f32") << 0 << "f32-abcd" << QVariant(double(f)) << "40122";
    // ir(100) = 40000 + 200 = 40200, as i16: 40200 - 65536 = -25336.
    QTest::newRow("04 100 x3 i16") << args("4", "100", "3", "i16") << 0 << "i16" << QVariant(-25336) << "30101";
    QTest::newRow("04 100 x3 u32") << args("4", "100", "4", "u32") << 2 << "u32-abcd"
                                   << QVariant(double((quint32(inputRegister(102)) << 16) | inputRegister(103))) << "30103";
    QTest::newRow("01 0 x5 coil 3") << args("1", "0", "5", nullptr) << 3 << "value" << QVariant(1) << "00004";
    QTest::newRow("01 0 x5 coil 4") << args("1", "0", "5", nullptr) << 4 << "value" << QVariant(0) << "00005";
    QTest::newRow("02 7 x3 input 7") << args("2", "7", "3", nullptr) << 0 << "value" << QVariant(1) << "10008";
    QTest::newRow("02 7 x3 input 8") << args("2", "7", "3", nullptr) << 1 << "value" << QVariant(0) << "10009";
}

void TestCliExchange::readFormats()
{
    QFETCH(QStringList, args);
    QFETCH(int, row);
    QFETCH(QString, key);
    QFETCH(QVariant, value);
    QFETCH(QString, reference);
    TARGET("tcp", url);
    const CliResult r = runMbscope(QStringList{QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--json")}
                                   + args);
    QVERIFY2(r.exitCode == 0, r.describe());
    const QJsonArray values = r.json().value(QStringLiteral("values")).toArray();
    QVERIFY2(row < values.size(), r.describe());
    const QJsonObject v = values.at(row).toObject();
    QCOMPARE(v.value(QStringLiteral("reference")).toString(), reference);
    QVERIFY2(v.contains(key), r.describe());
    if (value.typeId() == QMetaType::QString)
        QCOMPARE(v.value(key).toString(), value.toString());
    else
        QCOMPARE(v.value(key).toDouble(), value.toDouble());
}

void TestCliExchange::readText()
{
    TARGET("tcp", url);
    const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--unit"),
                                    QStringLiteral("1"), QStringLiteral("--function"), QStringLiteral("3"),
                                    QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--quantity"),
                                    QStringLiteral("22"), QStringLiteral("--format"), QStringLiteral("u16,hex,f32-cdab")});
    QVERIFY2(r.exitCode == 0, r.describe());
    const QString text = r.outText();
    for (const char *expected : {"VALUES Read Holding Registers, unit 1, 22 registers at 121 (0x0079), 40122-40143",
                                 "ADDRESS", "REFERENCE", "f32-cdab", "121 (0x0079)  40122", "0x0553", "40143",
                                 "RESULT ok"})
        QVERIFY2(text.contains(QLatin1String(expected)), qPrintable(QStringLiteral("%1 not in\n%2").arg(QLatin1String(expected), text)));
}

void TestCliExchange::readException()
{
    TARGET("tcp", url);
    // The table ends at 9999: exception 02, a failed transaction (exit 1), explained.
    const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--address"),
                                    QStringLiteral("9999"), QStringLiteral("--quantity"), QStringLiteral("2")});
    QVERIFY2(r.exitCode == 1, r.describe());
    QVERIFY2(r.outText().contains(QLatin1String("RESULT exception 0x02 Illegal Data Address")), r.describe());
    QVERIFY2(!r.outText().contains(QLatin1String("VALUES")), r.describe());
}

void TestCliExchange::writeThenRead_data()
{
    QTest::addColumn<QStringList>("write");
    QTest::addColumn<int>("requests");
    QTest::addColumn<QString>("function"); // of the write, as the request's hex shows it after the unit
    QTest::addColumn<QStringList>("read");
    QTest::addColumn<QList<int>>("expected");
    const auto sl = [](std::initializer_list<const char *> items) {
        QStringList l;
        for (const char *i : items)
            l << QLatin1String(i);
        return l;
    };
    // Addresses 0x100.. differ from the data map's values, so a write that did nothing fails.
    QTest::newRow("0F coils 1,0,0,1 at 0x100") << sl({"--coils", "1,0,0,1", "--address", "0x100"}) << 1 << "0F"
                                              << sl({"--function", "1", "--address", "0x100", "--quantity", "4"})
                                              << QList<int>{1, 0, 0, 1};
    QTest::newRow("10 registers 205,172,73 at 0x200") << sl({"--registers", "205,172,73", "--address", "0x200"}) << 1 << "10"
                                                     << sl({"--address", "0x200", "--quantity", "3"})
                                                     << QList<int>{205, 172, 73};
    QTest::newRow("06 x3 registers 205,172,73 at 0x210") << sl({"--registers", "205,172,73", "--address", "0x210", "--single"})
                                                        << 3 << "06" << sl({"--address", "0x210", "--quantity", "3"})
                                                        << QList<int>{205, 172, 73};
    QTest::newRow("05 x2 coils on,on at 0x220") << sl({"--coils", "on,on", "--address", "0x220", "--single"}) << 2 << "05"
                                               << sl({"--function", "1", "--address", "0x220", "--quantity", "2"})
                                               << QList<int>{1, 1};
    // 123.456 is 0x42F6E979; word swapped (CDAB) it travels as E979 42F6.
    QTest::newRow("10 f32-cdab 123.456 at 0x230") << sl({"--registers", "123.456", "--format", "f32-cdab", "--address", "0x230"})
                                                 << 1 << "10" << sl({"--address", "0x230", "--quantity", "2"})
                                                 << QList<int>{0xE979, 0x42F6};
    QTest::newRow("10 i16 -2 at 0x240") << sl({"--registers", "-2", "--format", "i16", "--address", "0x240"}) << 1 << "10"
                                       << sl({"--address", "0x240", "--quantity", "1"}) << QList<int>{0xFFFE};
}

void TestCliExchange::writeThenRead()
{
    QFETCH(QStringList, write);
    QFETCH(int, requests);
    QFETCH(QString, function);
    QFETCH(QStringList, read);
    QFETCH(QList<int>, expected);
    TARGET("tcp", url);
    const CliResult w = runMbscope(QStringList{QStringLiteral("write"), QStringLiteral("--target"), url, QStringLiteral("--json")}
                                   + write);
    QVERIFY2(w.exitCode == 0, w.describe());
    const QJsonArray transactions = w.json().value(QStringLiteral("transactions")).toArray();
    QCOMPARE(transactions.size(), requests);
    for (const QJsonValue &t : transactions) {
        QCOMPARE(t.toObject().value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
        // MBAP header (7 bytes) then the function code.
        const QStringList bytes = t.toObject().value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString().split(QLatin1Char(' '));
        QCOMPARE(bytes.value(7), function);
    }
    const CliResult r = runMbscope(QStringList{QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--json")}
                                   + read);
    QVERIFY2(r.exitCode == 0, r.describe());
    const QJsonArray values = r.json().value(QStringLiteral("values")).toArray();
    QList<int> got;
    for (const QJsonValue &v : values)
        got.append(v.toObject().contains(QStringLiteral("raw")) ? v.toObject().value(QStringLiteral("raw")).toInt()
                                                                 : v.toObject().value(QStringLiteral("value")).toInt());
    QCOMPARE(got, expected);

    const CliResult text = runMbscope(QStringList{QStringLiteral("write"), QStringLiteral("--target"), url} + write);
    QVERIFY2(text.exitCode == 0, text.describe());
    QVERIFY2(text.outText().contains(QLatin1String("VALUES written:")), text.describe());
}

void TestCliExchange::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    const QString t = QStringLiteral("tcp://127.0.0.1:9"); // never reached: the options are refused first
    const auto row = [&](const char *name, QStringList args, const char *message) {
        for (QString &a : args)
            a.replace(QLatin1String("TARGET"), t);
        QTest::newRow(name) << args << QString::fromUtf8(message);
    };
    const auto sl = [](std::initializer_list<const char *> items) {
        QStringList l;
        for (const char *i : items)
            l << QLatin1String(i);
        return l;
    };
    row("send without --target", sl({"send", "--hex", "01"}), "mbscope send: --target is required");
    row("bad scheme", sl({"read", "--target", "foo://x"}), "mbscope read: --target: ");
    row("quantity 126", sl({"read", "--target", "TARGET", "--quantity", "126"}),
        "mbscope read: --quantity: quantity 126 is out of range");
    row("address 70000", sl({"read", "--target", "TARGET", "--address", "70000"}), "mbscope read: --address: ");
    row("function 5", sl({"read", "--target", "TARGET", "--function", "5"}), "mbscope read: --function 5 is not a read");
    row("unit 256", sl({"read", "--target", "TARGET", "--unit", "256"}), "--unit 256 is out of range: expected 0 to 255");
    row("format f33", sl({"read", "--target", "TARGET", "--format", "f33"}), "mbscope read: --format: ");
    // Issue 26 item 10: a value wider than the registers read printed a blank column, exit 0.
    row("f32 of 1 register", sl({"read", "--target", "TARGET", "--quantity", "1", "--format", "f32"}),
        "mbscope read: --format f32-abcd needs 2 registers for one value, but --quantity 1 reads only 1: give --quantity 2 or more");
    row("u16,f64 of 3 registers", sl({"read", "--target", "TARGET", "--quantity", "3", "--format", "u16,f64"}),
        "--format f64-abcdefgh needs 4 registers for one value, but --quantity 3 reads only 3");
    row("poll f32 of 1 register", sl({"poll", "--target", "TARGET", "--quantity", "1", "--format", "f32-cdab", "--count", "1"}),
        "mbscope poll: --format f32-cdab needs 2 registers for one value");
    row("format on coils", sl({"read", "--target", "TARGET", "--function", "1", "--format", "u16"}),
        "--format applies to registers");
    row("hex 01 0G", sl({"send", "--target", "TARGET", "--hex", "01 0G"}), "mbscope send: --hex: ");
    row("send without --hex", sl({"send", "--target", "TARGET"}), "mbscope send: --hex is required");
    row("unit without complete", sl({"send", "--target", "TARGET", "--hex", "01", "--unit", "3"}),
        "--unit applies to built requests");
    row("timeout abc", sl({"send", "--target", "TARGET", "--hex", "01", "--timeout", "abc"}),
        "mbscope send: --timeout: 'abc' is not a duration");
    row("coils 1,2", sl({"write", "--target", "TARGET", "--coils", "1,2"}),
        "mbscope write: --coils value 2 of 2 '2' is not a coil value");
    row("registers 70000", sl({"write", "--target", "TARGET", "--registers", "1,70000"}),
        "mbscope write: --registers value 2 of 2: ");
    row("write nothing", sl({"write", "--target", "TARGET"}), "nothing to write");
    row("coils and registers", sl({"write", "--target", "TARGET", "--coils", "1", "--registers", "1"}), "not both");
    row("unknown option", sl({"read", "--target", "TARGET", "--bogus"}), "mbscope read: Unknown option 'bogus'");
    row("stray argument", sl({"read", "--target", "TARGET", "40001"}), "mbscope read: unexpected argument '40001'");
    row("poll nothing", sl({"poll", "--target", "TARGET"}), "mbscope poll: nothing to send");
    row("poll hex and read", sl({"poll", "--target", "TARGET", "--hex", "01", "--quantity", "2"}), "give one kind of request");
    row("interval abc", sl({"poll", "--target", "TARGET", "--hex", "01", "--interval", "abc"}),
        "mbscope poll: --interval: 'abc' is not a duration");
    row("interval -5ms", sl({"poll", "--target", "TARGET", "--hex", "01", "--interval", "-5ms"}), "negative duration");
    row("count 0", sl({"poll", "--target", "TARGET", "--hex", "01", "--count", "0"}), "--count 0 is out of range");
    row("pipeline on rtu-tcp", sl({"poll", "--target", "rtu-tcp://127.0.0.1:9", "--hex", "01", "--pipeline", "4"}),
        "mbscope poll: --pipeline 4: pipelining needs MBAP transaction ids");
    row("histogram in a missing folder", sl({"poll", "--target", "TARGET", "--hex", "01", "--histogram", "/nonexistent-mbscope/x.png"}),
        "the folder does not exist");
    row("sweep without intervals", sl({"sweep", "--target", "TARGET", "--hex", "01", "--count", "3"}),
        "mbscope sweep: --intervals is required");
    row("sweep without count", sl({"sweep", "--target", "TARGET", "--hex", "01", "--intervals", "100,200"}),
        "mbscope sweep: give --count");
    row("sweep empty item", sl({"sweep", "--target", "TARGET", "--hex", "01", "--intervals", "100,,200", "--count", "3"}),
        "mbscope sweep: --intervals: item 2 of '100,,200' is empty");
    row("complete on delimited", sl({"send", "--target", "tcp://127.0.0.1:9?framing=delimited&start=24&end=23", "--hex",
                                     "01", "--complete"}),
        "uses delimited framing");
}

void TestCliExchange::usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const CliResult r = runMbscope(args);
    QVERIFY2(r.exitCode == 2, r.describe());
    QVERIFY2(r.errText().contains(message), r.describe());
    QVERIFY2(r.out.isEmpty(), r.describe());
}

void TestCliExchange::linkRefused_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("send") << QStringList{QStringLiteral("send"), QStringLiteral("--hex"), QStringLiteral("00 01 00 00 00 06 01 03 00 00 00 01")};
    QTest::newRow("read") << QStringList{QStringLiteral("read")};
    QTest::newRow("write") << QStringList{QStringLiteral("write"), QStringLiteral("--registers"), QStringLiteral("1,2,3"),
                                          QStringLiteral("--single")};
    // A long poll still ends at once: the link never worked.
    QTest::newRow("poll") << QStringList{QStringLiteral("poll"), QStringLiteral("--quantity"), QStringLiteral("2"),
                                         QStringLiteral("--interval"), QStringLiteral("1s"), QStringLiteral("--count"),
                                         QStringLiteral("1000")};
    QTest::newRow("sweep") << QStringList{QStringLiteral("sweep"), QStringLiteral("--quantity"), QStringLiteral("2"),
                                          QStringLiteral("--intervals"), QStringLiteral("1s,2s"), QStringLiteral("--count"),
                                          QStringLiteral("1000"), QStringLiteral("--json")};
}

void TestCliExchange::linkRefused()
{
    QFETCH(QStringList, args);
    args << QStringLiteral("--target") << m_closed;
    const CliResult r = runMbscope(args, 60000);
    QVERIFY2(r.exitCode == 2, r.describe());
    QVERIFY2(r.errText().contains(m_closed) && r.errText().contains(QLatin1String("refused")), r.describe());
    // send, read and write still show the request they could not deliver; poll and sweep have no
    // statistics: with --json, standard output holds the error object instead (still one document).
    if (args.contains(QLatin1String("--json")) && (args.constFirst() == QLatin1String("poll") || args.constFirst() == QLatin1String("sweep"))) {
        const QJsonObject error = r.json().value(QLatin1String("error")).toObject();
        QCOMPARE(error.value(QLatin1String("exit_status")).toInt(), 2);
        QVERIFY2(error.value(QLatin1String("message")).toString().contains(QLatin1String("refused")), r.describe());
    } else if (args.constFirst() == QLatin1String("poll") || args.constFirst() == QLatin1String("sweep"))
        QVERIFY2(r.out.isEmpty(), r.describe());
    else {
        QVERIFY2(r.outText().contains(QLatin1String("RESULT link_error: ")), r.describe());
        // Nothing was written: no latency and no timing line (they said "answered in 43648.517 s",
        // the host's uptime, and "latency from the request's write to the link").
        QVERIFY2(!r.outText().contains(QLatin1String("answered in")), r.describe());
        QVERIFY2(!r.outText().contains(QLatin1String("TIMING")), r.describe());
    }
}

void TestCliExchange::readOverSerialPty_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::newRow("rtu") << "rtu";
    QTest::newRow("ascii") << "ascii";
}

void TestCliExchange::readOverSerialPty()
{
    QFETCH(QString, scheme);
    QString why;
    if (!testpeers::pymodbusAvailable(&why) || !testpeers::socatAvailable(&why))
        QSKIP(qPrintable(why));
    testpeers::PtyPair pty;
    QVERIFY2(pty.start(), qPrintable(pty.error()));
    testpeers::PeerProcess peer;
    QVERIFY2(peer.start(testpeers::systemPython(), {testpeers::peersDir() + QStringLiteral("/pymodbus_server.py"), scheme,
                                                    QStringLiteral("--device"), pty.peerEnd()}),
             qPrintable(peer.error()));
    // The peer runs 8N1 (pymodbus_server.py); the pty ignores the rate, the engine's t3.5 follows it.
    const QString url = QStringLiteral("%1://%2?baud=115200&parity=N&data=8&stop=1").arg(scheme, pty.ourEnd());
    const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--address"),
                                    QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("2"),
                                    QStringLiteral("--timeout"), QStringLiteral("3s"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.describe());
    const QJsonArray values = r.json().value(QStringLiteral("values")).toArray();
    QCOMPARE(values.size(), 2);
    QCOMPARE(values.at(0).toObject().value(QStringLiteral("raw")).toInt(), int(holdingRegister(121)));
    QCOMPARE(values.at(1).toObject().value(QStringLiteral("raw")).toInt(), int(holdingRegister(122)));
}

void TestCliExchange::help_data()
{
    QTest::addColumn<QString>("command");
    for (const char *c : {"send", "read", "write", "poll", "sweep"})
        QTest::newRow(c) << QString::fromLatin1(c);
}

void TestCliExchange::help()
{
    QFETCH(QString, command);
    const CliResult r = runMbscope({command, QStringLiteral("--help")});
    QVERIFY2(r.exitCode == 0, r.describe());
    // The target may be the last argument, as mbpoll takes it.
    QVERIFY2(r.outText().startsWith(QStringLiteral("Usage: mbscope %1 [options] [target]\n").arg(command)), r.describe());
    for (const char *expected : {"--target <url>", "--timeout <duration>", "--json", "Exit status: 0"})
        QVERIFY2(r.outText().contains(QLatin1String(expected)), r.describe());
}

void TestCliExchange::usageLine_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("usage");
    // Tryout 8, item 10: decode and simulate showed the executable's path, not their name, and
    // analyze, export and replay left their source out.
    QTest::newRow("decode") << QStringLiteral("decode") << QStringLiteral("Usage: mbscope decode [options] [hex...]");
    QTest::newRow("simulate") << QStringLiteral("simulate") << QStringLiteral("Usage: mbscope simulate [options]");
    QTest::newRow("analyze") << QStringLiteral("analyze") << QStringLiteral("Usage: mbscope analyze [options] capture");
    QTest::newRow("export") << QStringLiteral("export") << QStringLiteral("Usage: mbscope export [options] source");
    QTest::newRow("replay") << QStringLiteral("replay") << QStringLiteral("Usage: mbscope replay [options] source");
    QTest::newRow("run") << QStringLiteral("run") << QStringLiteral("Usage: mbscope run [options] SESSION");
    QTest::newRow("monitor") << QStringLiteral("monitor") << QStringLiteral("Usage: mbscope monitor [options] url");
    QTest::newRow("watch") << QStringLiteral("watch") << QStringLiteral("Usage: mbscope watch [options] session");
    QTest::newRow("poll") << QStringLiteral("poll") << QStringLiteral("Usage: mbscope poll [options] [target]");
}

void TestCliExchange::usageLine()
{
    QFETCH(QString, command);
    QFETCH(QString, usage);
    const CliResult r = runMbscope({command, QStringLiteral("--help")});
    QVERIFY2(r.exitCode == 0, r.describe());
    QCOMPARE(r.outText().section(QLatin1Char('\n'), 0, 0), usage);
}

void TestCliExchange::topLevelHelp_data()
{
    QTest::addColumn<QString>("option");
    QTest::newRow("--help") << QStringLiteral("--help");
    QTest::newRow("--help-all") << QStringLiteral("--help-all"); // opened the window, and hung offscreen
    QTest::newRow("-h") << QStringLiteral("-h");
}

// The top-level help lists the subcommands and the window's own options, and never opens the window.
void TestCliExchange::topLevelHelp()
{
    QFETCH(QString, option);
    const CliResult r = runMbscope({option});
    QVERIFY2(r.exitCode == 0, r.describe());
    QVERIFY2(r.outText().startsWith(QLatin1String("Usage: mbscope [SUBCOMMAND] [OPTIONS]")), r.describe());
    for (const char *expected : {"  watch ", "  scan ", "--theme NAME", "--tab NAME", "--start-watches", "--screenshot FILE"})
        QVERIFY2(r.outText().contains(QLatin1String(expected)), r.describe());
}

// Issue 26 item 12: --help-all printed the short usage, as --help does: it prints every
// subcommand's help too, each under its own heading.
void TestCliExchange::helpAll()
{
    const CliResult all = runMbscope({QStringLiteral("--help-all")});
    QVERIFY2(all.finished && all.exitCode == 0, all.describe());
    const CliResult brief = runMbscope({QStringLiteral("--help")});
    QVERIFY2(all.outText().startsWith(brief.outText()), all.describe());
    for (const char *command : {"decode", "send", "read", "write", "poll", "monitor", "watch", "sweep", "scan", "run", "simulate",
                                "analyze", "export", "replay"}) {
        const CliResult one = runMbscope({QLatin1String(command), QStringLiteral("--help")});
        QVERIFY2(one.exitCode == 0, one.describe());
        QVERIFY2(all.outText().contains(one.outText()), command);
        QVERIFY2(all.outText().contains(QStringLiteral("\n== mbscope %1 ==\n").arg(QLatin1String(command))), command);
    }
    QVERIFY2(all.err.isEmpty(), all.describe());
    // `mbscope help NAME` is NAME's --help (it printed the general usage), one of mbscope-full's
    // too; an unknown name is a usage error.
    for (const char *command : {"scan", "simulate"}) {
        const CliResult help = runMbscope({QStringLiteral("help"), QLatin1String(command)});
        const CliResult own = runMbscope({QLatin1String(command), QStringLiteral("--help")});
        QVERIFY2(help.exitCode == 0 && help.out == own.out && !help.out.isEmpty(), help.describe());
    }
    const CliResult bogus = runMbscope({QStringLiteral("help"), QStringLiteral("bogus")});
    QCOMPARE(bogus.exitCode, 2);
    QVERIFY2(bogus.errText().startsWith(QLatin1String("mbscope help: unknown subcommand 'bogus'\n")), bogus.describe());
}

QTEST_GUILESS_MAIN(TestCliExchange)
#include "tst_cli_exchange.moc"
