// The command line with mbpoll's habits (issue 30), against the built-in simulator (mbscope
// simulate, the rosrao-gamma profile on a TCP port the system chooses) and mbpoll itself:
// mbpoll's short options mean what they mean in mbpoll (the same request bytes as the long
// options), the target may be a host or a device with its pieces (-m, -p, -b, -P, -d, -s),
// --one-based counts registers from 1 and says so, the hint for a reference that looks counted
// from 1, read -q prints the value lines mbpoll -1 prints, and the live frame log. Start-up: the
// commands of the light `mbscope` load no library of the window, the plots, the simulator or the
// watch service; what needs them runs in mbscope-full, which mbscope execs.
#include "clitest.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpServer>
#include <QtTest/QTest>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

// "PORT" and "TARGET" in an argument list become the simulator's port and URL, "SILENT" a TCP
// port that takes connections and never answers.
QString silentUrl;

QStringList withTarget(QStringList arguments, const QString &url)
{
    const QString port = url.section(QLatin1Char(':'), -1);
    for (QString &a : arguments) {
        a.replace(QStringLiteral("SILENT"), silentUrl);
        a.replace(QStringLiteral("TARGET"), url);
        a.replace(QStringLiteral("PORT"), port);
    }
    return arguments;
}

// The lines of mbpoll's or mbscope's output that carry values: "[122]: \t1050".
QStringList valueLines(const QByteArray &output)
{
    QStringList lines;
    for (const QString &line : QString::fromUtf8(output).split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1Char('[')))
            lines.append(line);
    }
    return lines;
}

// The shared libraries a process initialised, by file name, from the dynamic loader's own
// report (LD_DEBUG=libs: "calling init: /usr/lib/.../libQt6Core.so.6"), exec'd images included.
QStringList initialisedLibraries(const QByteArray &err)
{
    static const QRegularExpression init(QStringLiteral(R"(calling init: (\S+))"));
    QStringList names;
    for (auto it = init.globalMatch(QString::fromUtf8(err)); it.hasNext();)
        names.append(it.next().captured(1).section(QLatin1Char('/'), -1));
    return names;
}

} // namespace

class TestCliHabits : public QObject
{
    Q_OBJECT

    Background m_sim; // rosrao-gamma on tcp: holding registers 121-133 = 1050, 0, 0, 0, 250, 1, 1000, 10000...
    QString m_url;
    QTemporaryDir m_dir;
    QTcpServer m_silent; // the kernel accepts its connections; nothing ever answers

private slots:
    void initTestCase();
    void shortOptionsAreTheLongOnes_data();
    void shortOptionsAreTheLongOnes();
    void usageErrors_data();
    void usageErrors();
    void serialPieces_data();
    void serialPieces();
    void oneBased_data();
    void oneBased();
    void oneBasedHint_data();
    void oneBasedHint();
    void terseAsMbpoll_data();
    void terseAsMbpoll();
    void terseOutput_data();
    void terseOutput();
    void frameLog_data();
    void frameLog();
    void frameLogFile();
    void startLoadsOnlyWhatItUses_data();
    void startLoadsOnlyWhatItUses();
    void withoutTheFullPartSaysWhy();
};

void TestCliHabits::initTestCase()
{
    QVERIFY2(QFileInfo::exists(mbscopePath()), qPrintable(mbscopePath()));
    QVERIFY(m_dir.isValid());
    QString error;
    QVERIFY2(m_sim.start(sl({"simulate", "--profile", "rosrao-gamma", "--listen", "tcp://127.0.0.1:0"}), &error),
             qPrintable(error));
    m_url = m_sim.url();
    QVERIFY2(m_url.startsWith(QLatin1String("tcp://127.0.0.1:")), qPrintable(m_url));
    QVERIFY(m_silent.listen(QHostAddress::LocalHost));
    silentUrl = QStringLiteral("tcp://127.0.0.1:%1").arg(m_silent.serverPort());
}

void TestCliHabits::shortOptionsAreTheLongOnes_data()
{
    QTest::addColumn<QStringList>("shortForm");
    QTest::addColumn<QStringList>("longForm");
    QTest::newRow("-a -r -c") << sl({"read", "-a", "1", "-r", "121", "-c", "3", "--target", "TARGET"})
                              << sl({"read", "--unit", "1", "--address", "121", "--quantity", "3", "--target", "TARGET"});
    QTest::newRow("compacted -a1 -r121 -c3") << sl({"read", "-a1", "-r121", "-c3", "--target", "TARGET"})
                                             << sl({"read", "--unit", "1", "--address", "121", "--quantity", "3", "--target", "TARGET"});
    QTest::newRow("-t 4 is --function 3") << sl({"read", "-t", "4", "-r", "121", "-c", "2", "--target", "TARGET"})
                                          << sl({"read", "--function", "3", "--address", "121", "--quantity", "2", "--target", "TARGET"});
    QTest::newRow("-t 4:hex") << sl({"read", "-t", "4:hex", "-r", "121", "-c", "2", "--target", "TARGET"})
                              << sl({"read", "--function", "3", "--format", "hex", "--address", "121", "--quantity", "2",
                                     "--target", "TARGET"});
    QTest::newRow("-t 4:int -c 2 reads 4 registers, low word first")
        << sl({"read", "-t", "4:int", "-r", "121", "-c", "2", "--target", "TARGET"})
        << sl({"read", "--function", "3", "--format", "i32-cdab", "--address", "121", "--quantity", "4", "--target", "TARGET"});
    QTest::newRow("-t 4:float -B") << sl({"read", "-t", "4:float", "-B", "-r", "121", "-c", "1", "--target", "TARGET"})
                                   << sl({"read", "--function", "3", "--format", "f32", "--address", "121", "--quantity", "2",
                                          "--target", "TARGET"});
    QTest::newRow("-t 4:u32") << sl({"read", "-t", "4:u32", "-r", "121", "-c", "1", "--target", "TARGET"})
                              << sl({"read", "--function", "3", "--format", "u32", "--address", "121", "--quantity", "2",
                                     "--target", "TARGET"});
    QTest::newRow("host and -p, positional") << sl({"read", "-r", "121", "-p", "PORT", "127.0.0.1"})
                                             << sl({"read", "--address", "121", "--target", "TARGET"});
    QTest::newRow("host:port positional") << sl({"read", "-r", "121", "127.0.0.1:PORT"})
                                          << sl({"read", "--address", "121", "--target", "TARGET"});
    QTest::newRow("--target host -m tcp -p") << sl({"read", "-r", "121", "-m", "tcp", "-p", "PORT", "--target", "127.0.0.1"})
                                             << sl({"read", "--address", "121", "--target", "TARGET"});
    QTest::newRow("-0 is the default") << sl({"read", "-0", "-r", "121", "TARGET"})
                                       << sl({"read", "--address", "121", "--target", "TARGET"});
    QTest::newRow("-1 reads once") << sl({"read", "-1", "-r", "121", "TARGET"})
                                   << sl({"read", "--address", "121", "--target", "TARGET"});
    QTest::newRow("write -a -r") << sl({"write", "-a", "1", "-r", "127", "--registers", "1000", "--single", "TARGET"})
                                 << sl({"write", "--unit", "1", "--address", "127", "--registers", "1000", "--single",
                                        "--target", "TARGET"});
    QTest::newRow("poll -l -1") << sl({"poll", "-r", "121", "-c", "2", "-l", "10", "-1", "TARGET"})
                                << sl({"poll", "--address", "121", "--quantity", "2", "--interval", "10ms", "--count", "1",
                                       "--target", "TARGET"});
    QTest::newRow("-o seconds") << sl({"read", "-r", "121", "-o", "0.3", "SILENT"})
                                << sl({"read", "--address", "121", "--timeout", "300", "--target", "SILENT"});
}

// Both forms send the same bytes and end the same way.
void TestCliHabits::shortOptionsAreTheLongOnes()
{
    QFETCH(QStringList, shortForm);
    QFETCH(QStringList, longForm);
    const CliResult a = runMbscope(withTarget(shortForm, m_url) << QStringLiteral("--json"));
    const CliResult b = runMbscope(withTarget(longForm, m_url) << QStringLiteral("--json"));
    QVERIFY2(a.finished && b.finished, a.describe() + b.describe());
    QVERIFY2(a.exitCode == b.exitCode, a.describe() + "\n--- against ---\n" + b.describe());
    QVERIFY2(a.exitCode == 0 || a.exitCode == 1, a.describe());
    const QJsonObject ja = a.json();
    const QJsonObject jb = b.json();
    if (shortForm.constFirst() == QLatin1String("poll")) {
        QCOMPARE(ja.value(QStringLiteral("requests")), jb.value(QStringLiteral("requests")));
        QCOMPARE(ja.value(QStringLiteral("target")), jb.value(QStringLiteral("target")));
        QVERIFY2(a.outText().contains(QLatin1String("\"ok\": 1")), a.out);
        return;
    }
    const auto requestHex = [](const QJsonObject &o) {
        const QJsonValue transactions = o.value(QStringLiteral("transactions"));
        const QJsonObject t = transactions.isArray() ? transactions.toArray().first().toObject() : o;
        return t.value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString();
    };
    QVERIFY2(!requestHex(ja).isEmpty(), a.out);
    QCOMPARE(requestHex(ja), requestHex(jb));
    QCOMPARE(ja.value(QStringLiteral("target")), jb.value(QStringLiteral("target")));
    QCOMPARE(ja.value(QStringLiteral("values")), jb.value(QStringLiteral("values")));
    QCOMPARE(ja.value(QStringLiteral("status")), jb.value(QStringLiteral("status")));
    QCOMPARE(ja.value(QStringLiteral("problem")), jb.value(QStringLiteral("problem")));
    if (ja.value(QStringLiteral("status")).toString() == QLatin1String("timeout"))
        QVERIFY2(ja.value(QStringLiteral("problem")).toString().contains(QLatin1String("300 ms")), a.out);
}

void TestCliHabits::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("-t 2") << sl({"read", "-t", "2", "TARGET"}) << "mbscope read: -t/--table '2' is not a table";
    QTest::newRow("-t 0:hex") << sl({"read", "-t", "0:hex", "TARGET"}) << "coils and discrete inputs are bits";
    QTest::newRow("-t 4:bogus") << sl({"read", "-t", "4:bogus", "TARGET"}) << "'bogus' is not a display";
    QTest::newRow("-B without :int") << sl({"read", "-t", "4", "-B", "TARGET"}) << "-B/--big-endian orders the words";
    QTest::newRow("-B with --function") << sl({"read", "--function", "3", "-B", "TARGET"}) << "-B/--big-endian orders the words";
    QTest::newRow("-t and --function") << sl({"read", "-t", "4", "--function", "3", "TARGET"})
                                       << "give -t/--table or --function, not both";
    QTest::newRow("-t 4:hex and --format") << sl({"read", "-t", "4:hex", "--format", "u16", "TARGET"})
                                           << "says how values are shown already";
    QTest::newRow("-p with a URL") << sl({"read", "-p", "502", "--target", "TARGET"})
                                   << "-p/--port applies to a target given as a host or a serial device";
    QTest::newRow("-b with a host") << sl({"read", "-b", "9600", "127.0.0.1"}) << "-b/--baud is a serial line setting";
    QTest::newRow("-p with a device") << sl({"read", "-p", "502", "/dev/ttyUSB9"}) << "-p/--port is the port of a host";
    QTest::newRow("-P maybe") << sl({"read", "-P", "maybe", "/dev/ttyUSB9"}) << "-P/--parity 'maybe' is not a parity";
    QTest::newRow("-d 9") << sl({"read", "-d", "9", "/dev/ttyUSB9"}) << "-d/--data-bits 9 is out of range: expected 7 to 8";
    QTest::newRow("-s 3") << sl({"read", "-s", "3", "/dev/ttyUSB9"}) << "-s/--stop-bits 3 is out of range: expected 1 to 2";
    QTest::newRow("-m bogus") << sl({"read", "-m", "bogus", "127.0.0.1"}) << "-m/--mode 'bogus' is not a mode";
    QTest::newRow("-m tcp to a device") << sl({"read", "-m", "tcp", "/dev/ttyUSB9"}) << "is a serial device, which takes rtu or ascii";
    QTest::newRow("-p 70000") << sl({"read", "-p", "70000", "127.0.0.1"}) << "-p/--port 70000 is out of range: expected 1 to 65535";
    QTest::newRow("port twice") << sl({"read", "-p", "502", "127.0.0.1:502"}) << "names its port already: give it once";
    QTest::newRow("two targets") << sl({"read", "127.0.0.1", "extra"}) << "mbscope read: unexpected argument 'extra'";
    QTest::newRow("target twice") << sl({"read", "--target", "TARGET", "127.0.0.1"}) << "unexpected argument '127.0.0.1'";
    QTest::newRow("no target") << sl({"read", "-r", "1"}) << "--target is required";
    QTest::newRow("-o 0") << sl({"read", "-o", "0", "TARGET"}) << "-o/--timeout-s 0 is out of range";
    QTest::newRow("-o and --timeout") << sl({"read", "-o", "1", "--timeout", "1000", "TARGET"})
                                      << "--timeout and -o/--timeout-s both set the response timeout";
    QTest::newRow("poll -1 --count") << sl({"poll", "-1", "--count", "3", "-r", "121", "TARGET"})
                                     << "-1/--once is --count 1: give it without --count and --duration";
    QTest::newRow("--one-based -r 0") << sl({"read", "--one-based", "-r", "0", "TARGET"})
                                      << "--address 0 with --one-based: counted from 1";
    QTest::newRow("--one-based -0") << sl({"read", "--one-based", "-0", "TARGET"}) << "--one-based and -0/--zero-based say the contrary";
    QTest::newRow("--one-based --hex") << sl({"poll", "--one-based", "--hex", "01 03 00 79 00 01", "--complete", "TARGET"})
                                       << "--one-based says how --address counts, but --hex bytes carry their PDU address";
    QTest::newRow("-q --json") << sl({"read", "-q", "--json", "TARGET"}) << "-q/--terse prints values as text lines";
    QTest::newRow("--print values on read") << sl({"read", "--print", "values", "TARGET"})
                                            << "--print 'values': expected frames";
    QTest::newRow("--print bogus on poll") << sl({"poll", "--print", "bogus", "TARGET"})
                                           << "--print 'bogus': expected values (each answer's values as it comes) or frames";
    QTest::newRow("-t 4:float -c 100") << sl({"read", "-t", "4:float", "-c", "100", "TARGET"})
                                       << "(-c 100 values of -t 4:float are 200 registers)";
}

void TestCliHabits::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliResult r = runMbscope(withTarget(arguments, m_url));
    QVERIFY2(r.exitCode == 2, r.describe());
    QVERIFY2(r.errText().contains(message), r.describe());
    // With --json, standard output holds the error as a JSON object; else nothing.
    if (arguments.contains(QStringLiteral("--json")))
        QVERIFY2(r.json().value(QStringLiteral("error")).toObject().value(QStringLiteral("message")).toString().contains(message),
                 r.describe());
    else
        QVERIFY2(r.out.isEmpty(), r.describe());
}

void TestCliHabits::serialPieces_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("url");
    // The composed URL, as read's --json names the target even when the device cannot be opened.
    QTest::newRow("device: rtu by default") << sl({"read", "/nonexistent/ttyX"}) << "rtu:///nonexistent/ttyX?baud=9600&parity=E&data=8&stop=1";
    QTest::newRow("-b -P -d -s") << sl({"read", "-b", "19200", "-P", "none", "-d", "8", "-s", "2", "/nonexistent/ttyX"})
                                 << "rtu:///nonexistent/ttyX?baud=19200&parity=N&data=8&stop=2";
    QTest::newRow("-m ascii -P O") << sl({"read", "-m", "ascii", "-P", "O", "/nonexistent/ttyX"})
                                   << "ascii:///nonexistent/ttyX?baud=9600&parity=O&data=7&stop=1";
}

void TestCliHabits::serialPieces()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, url);
    const CliResult r = runMbscope(arguments << QStringLiteral("--json"));
    QVERIFY2(r.exitCode == 2, r.describe());
    QCOMPARE(r.json().value(QStringLiteral("target")).toString(), url);
    QVERIFY2(r.errText().contains(QLatin1String("/nonexistent/ttyX")), r.describe());
}

void TestCliHabits::oneBased_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("request");  // the PDU address 121 (0x0079) on the wire
    QTest::addColumn<QStringList>("said"); // in the text output
    QTest::newRow("read") << sl({"read", "--one-based", "-r", "122", "-c", "2", "TARGET"}) << "00 01 00 00 00 06 01 03 00 79 00 02"
                          << QStringList{QStringLiteral("VALUES Read Holding Registers, unit 1, 2 registers at 122 (1-based; PDU "
                                                        "address 121, 0x0079), 40122-40123"),
                                         QStringLiteral("1-BASED  ADDRESS       REFERENCE   u16"),
                                         QStringLiteral("122      121 (0x0079)  40122      1050")};
    QTest::newRow("write") << sl({"write", "--one-based", "-r", "128", "--registers", "1000", "--single", "TARGET"})
                           << "00 01 00 00 00 06 01 06 00 7F 03 E8"
                           << QStringList{QStringLiteral("VALUES written: unit 1, 1 register at 128 (1-based; PDU address 127, "
                                                         "0x007F), 40128"),
                                          QStringLiteral("128      127 (0x007F)  40128      1000")};
    QTest::newRow("poll") << sl({"poll", "--one-based", "-r", "122", "-c", "2", "--count", "1", "--interval", "0", "--print",
                                 "values", "TARGET"})
                          << QString()
                          << QStringList{QStringLiteral("Read Holding Registers 122 x2 (1-based)"),
                                         QStringLiteral("2 registers at 122 (1-based; PDU address 121, 0x0079)")};
}

void TestCliHabits::oneBased()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, request);
    QFETCH(QStringList, said);
    const CliResult text = runMbscope(withTarget(arguments, m_url));
    QVERIFY2(text.exitCode == 0, text.describe());
    for (const QString &line : said)
        QVERIFY2(text.outText().contains(line), qPrintable(line + QStringLiteral("\n---\n") + text.outText()));
    if (request.isEmpty())
        return;
    const CliResult json = runMbscope(withTarget(arguments, m_url) << QStringLiteral("--json"));
    QVERIFY2(json.exitCode == 0, json.describe());
    const QJsonObject o = json.json();
    const QJsonValue transactions = o.value(QStringLiteral("transactions"));
    const QJsonObject t = transactions.isArray() ? transactions.toArray().first().toObject() : o;
    // The transaction id is the engine's: compare from the MBAP length on.
    QCOMPARE(t.value(QStringLiteral("request")).toObject().value(QStringLiteral("hex")).toString().mid(6), request.mid(6));
    const QJsonObject first = o.value(QStringLiteral("values")).toArray().first().toObject();
    QCOMPARE(first.value(QStringLiteral("one_based")).toInt(), first.value(QStringLiteral("address")).toInt() + 1);
}

void TestCliHabits::oneBasedHint_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("hint"); // empty: none
    // rosrao-gamma holds registers 121-142 only: every read below is answered with exception 02.
    QTest::newRow("1") << sl({"read", "-r", "1", "TARGET"})
                       << "HINT 1 looks counted from 1, as mbpoll and many device manuals number registers; counted from 0, as "
                          "on the wire, it is PDU address 0 (0x0000): give --address 0, or --one-based to type the manual's "
                          "numbers";
    QTest::newRow("101") << sl({"read", "-r", "101", "TARGET"}) << "HINT 101 looks counted from 1";
    QTest::newRow("1001 write") << sl({"write", "-r", "1001", "--registers", "5", "TARGET"}) << "HINT 1001 looks counted from 1";
    QTest::newRow("40001 Modicon") << sl({"read", "-r", "40001", "TARGET"})
                                   << "HINT 40001 looks like a Modicon reference; its PDU address is 0 (0x0000): give --address 0";
    QTest::newRow("40122 Modicon, 1-based") << sl({"read", "--one-based", "-r", "40001", "TARGET"})
                                            << "give --address 1 with --one-based";
    QTest::newRow("100: no hint") << sl({"read", "-r", "100", "TARGET"}) << QString();
    QTest::newRow("1 counted from 1: no hint") << sl({"read", "--one-based", "-r", "1", "TARGET"}) << QString();
    QTest::newRow("terse: on stderr") << sl({"read", "-q", "-r", "11", "TARGET"}) << "HINT 11 looks counted from 1";
}

void TestCliHabits::oneBasedHint()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, hint);
    const CliResult r = runMbscope(withTarget(arguments, m_url));
    QVERIFY2(r.exitCode == 1, r.describe());
    const QString all = r.outText() + r.errText();
    QVERIFY2(all.contains(QLatin1String("exception")) || all.contains(QLatin1String("Exception")), r.describe());
    if (hint.isEmpty())
        QVERIFY2(!all.contains(QLatin1String("HINT")), r.describe());
    else
        QVERIFY2(all.contains(hint), r.describe());
}

void TestCliHabits::terseAsMbpoll_data()
{
    QTest::addColumn<QStringList>("mbpoll");
    QTest::addColumn<QStringList>("mbscope");
    QTest::newRow("-t 4") << sl({"-a", "1", "-r", "122", "-c", "5", "-t", "4"}) << sl({"-a", "1", "-r", "122", "-c", "5", "-t", "4"});
    QTest::newRow("-t 4:hex") << sl({"-r", "122", "-c", "3", "-t", "4:hex"}) << sl({"-r", "122", "-c", "3", "-t", "4:hex"});
    QTest::newRow("-t 4:int") << sl({"-r", "122", "-c", "2", "-t", "4:int"}) << sl({"-r", "122", "-c", "2", "-t", "4:int"});
    QTest::newRow("-t 4:int -B") << sl({"-r", "122", "-c", "2", "-t", "4:int", "-B"}) << sl({"-r", "122", "-c", "2", "-t", "4:int", "-B"});
    QTest::newRow("-0") << sl({"-0", "-r", "121", "-c", "2"}) << sl({"-r", "121", "-c", "2"});
}

// The value lines of read -q are mbpoll -1's, character for character.
void TestCliHabits::terseAsMbpoll()
{
    QFETCH(QStringList, mbpoll);
    QFETCH(QStringList, mbscope);
    const QString program = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (program.isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    const QString port = m_url.section(QLatin1Char(':'), -1);
    QProcess peer;
    peer.start(program, mbpoll + QStringList{QStringLiteral("-1"), QStringLiteral("-p"), port, QStringLiteral("127.0.0.1")});
    QVERIFY(peer.waitForFinished(30000));
    const QByteArray peerOut = peer.readAllStandardOutput();
    QVERIFY2(peer.exitCode() == 0, peerOut + peer.readAllStandardError());
    const bool oneBased = !mbpoll.contains(QStringLiteral("-0"));
    QStringList arguments{QStringLiteral("read")};
    arguments += mbscope;
    if (oneBased)
        arguments.append(QStringLiteral("--one-based"));
    arguments += QStringList{QStringLiteral("-q"), QStringLiteral("-p"), port, QStringLiteral("127.0.0.1")};
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.exitCode == 0, r.describe());
    QVERIFY2(!valueLines(peerOut).isEmpty(), peerOut);
    QCOMPARE(valueLines(r.out), valueLines(peerOut));
    // Nothing but the value lines.
    QCOMPARE(r.outText(), valueLines(r.out).join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

void TestCliHabits::terseOutput_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("out");
    QTest::addColumn<QString>("err"); // contained in standard error; empty: standard error is empty
    QTest::newRow("u16") << sl({"read", "-q", "-r", "121", "-c", "3", "TARGET"}) << 0 << "[121]: \t1050\n[122]: \t0\n[123]: \t0\n"
                         << QString();
    QTest::newRow("1-based") << sl({"read", "-q", "--one-based", "-r", "122", "-c", "2", "TARGET"}) << 0
                             << "[122]: \t1050\n[123]: \t0\n" << QString();
    QTest::newRow("two formats") << sl({"read", "-q", "-r", "125", "-c", "2", "--format", "u16,hex", "TARGET"}) << 0
                                 << "[125]: \t250\t0x00FA\n[126]: \t1\t0x0001\n" << QString();
    QTest::newRow("exception") << sl({"read", "-q", "-r", "0", "TARGET"}) << 1 << QString()
                               << "mbscope read: Read Holding Registers, unit 1, 1 register at 0 (0x0000), 40001: exception";
    QTest::newRow("timeout") << sl({"read", "-q", "-r", "121", "-o", "0.2", "SILENT"}) << 1 << QString()
                             << "timeout: no answer within 200 ms";
}

void TestCliHabits::terseOutput()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, out);
    QFETCH(QString, err);
    const CliResult r = runMbscope(withTarget(arguments, m_url));
    QVERIFY2(r.exitCode == exitCode, r.describe());
    QCOMPARE(r.outText(), out);
    if (err.isEmpty())
        QVERIFY2(r.err.isEmpty(), r.describe());
    else
        QVERIFY2(r.errText().contains(err), r.describe());
}

void TestCliHabits::frameLog_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("lines"); // patterns, one per frame expected, in order
    const QString t = QStringLiteral(R"(^\d\d:\d\d:\d\d\.\d{6} )");
    QTest::newRow("send") << sl({"send", "--hex", "00 07 00 00 00 06 01 03 00 79 00 01", "--print", "frames", "TARGET"})
                          << QStringList{t + QStringLiteral(R"(out sent {8}00 07 00 00 00 06 01 03 00 79 00 01$)"),
                                         t + QStringLiteral(R"(in  ok {10}00 07 00 00 00 05 01 03 02 04 1A$)")};
    QTest::newRow("read") << sl({"read", "-r", "121", "-c", "1", "--print", "frames", "TARGET"})
                          << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 03 00 79 00 01$)"),
                                         t + QStringLiteral(R"(in  ok {10}00 01 00 00 00 05 01 03 02 04 1A$)")};
    QTest::newRow("read, exception") << sl({"read", "-r", "0", "--print", "frames", "TARGET"})
                                     << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 03 00 00 00 01$)"),
                                                    t + QStringLiteral(R"(in  exception {3}00 01 00 00 00 03 01 83 02$)")};
    QTest::newRow("read, timeout") << sl({"read", "-r", "121", "-o", "0.2", "--print", "frames", "SILENT"})
                                   << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 03 00 79 00 01$)"),
                                                  t + QStringLiteral(R"(in  timeout$)")};
    QTest::newRow("write") << sl({"write", "-r", "127", "--registers", "1000", "--single", "--print", "frames", "TARGET"})
                           << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 06 00 7F 03 E8$)"),
                                          t + QStringLiteral(R"(in  ok {10}00 01 00 00 00 06 01 06 00 7F 03 E8$)")};
    QTest::newRow("poll, values and frames") << sl({"poll", "-r", "121", "--count", "2", "-l", "0", "--print", "values,frames", "TARGET"})
                                             << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 03 00 79 00 01$)"),
                                                            t + QStringLiteral(R"(in  ok {10}00 01 00 00 00 05 01 03 02 04 1A$)"),
                                                            t + QStringLiteral(R"(out sent {8}00 02 00 00 00 06 01 03 00 79 00 01$)"),
                                                            t + QStringLiteral(R"(in  ok {10}00 02 00 00 00 05 01 03 02 04 1A$)")};
    QTest::newRow("sweep") << sl({"sweep", "-r", "121", "--intervals", "0,1", "--count", "1", "--print", "frames", "TARGET"})
                           << QStringList{t + QStringLiteral(R"(out sent {8}00 01 00 00 00 06 01 03 00 79 00 01$)"),
                                          t + QStringLiteral(R"(in  ok {10}00 01 00 00 00 05 01 03 02 04 1A$)"),
                                          t + QStringLiteral(R"(out sent {8}00 02 00 00 00 06 01 03 00 79 00 01$)"),
                                          t + QStringLiteral(R"(in  ok {10}00 02 00 00 00 05 01 03 02 04 1A$)")};
}

// The frames on standard error, one line each in order; standard output as without them.
void TestCliHabits::frameLog()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, lines);
    const CliResult r = runMbscope(withTarget(arguments, m_url));
    QVERIFY2(r.exitCode == 0 || r.exitCode == 1, r.describe());
    QStringList frames;
    for (const QString &line : r.errText().split(QLatin1Char('\n'))) {
        static const QRegularExpression stamp(QStringLiteral(R"(^\d\d:\d\d:\d\d\.\d{6} )"));
        if (stamp.match(line).hasMatch())
            frames.append(line);
    }
    QVERIFY2(frames.size() == lines.size(), r.describe());
    for (qsizetype i = 0; i < lines.size(); ++i)
        QVERIFY2(QRegularExpression(lines.at(i)).match(frames.at(i)).hasMatch(),
                 qPrintable(QStringLiteral("line %1 '%2' does not match %3").arg(i + 1).arg(frames.at(i), lines.at(i))));
    // The frame log changes nothing on standard output.
    QStringList without = withTarget(arguments, m_url);
    const qsizetype at = without.indexOf(QStringLiteral("--print"));
    const QString print = without.at(at + 1);
    without.remove(at, 2);
    if (print.contains(QLatin1String("values")))
        without += QStringList{QStringLiteral("--print"), QStringLiteral("values")};
    const CliResult plain = runMbscope(without);
    QCOMPARE(plain.exitCode, r.exitCode);
    static const QRegularExpression variable(QStringLiteral(R"(\d+(\.\d+)? ?(ms|µs|s)\b|\d\d:\d\d:\d\d\.\d+)"));
    QCOMPARE(r.outText().replace(variable, QStringLiteral("T")).count(QLatin1Char('\n')),
             plain.outText().replace(variable, QStringLiteral("T")).count(QLatin1Char('\n')));
}

void TestCliHabits::frameLogFile()
{
    const QString path = m_dir.filePath(QStringLiteral("frames.log"));
    const QStringList arguments{QStringLiteral("poll"), QStringLiteral("-r"), QStringLiteral("121"), QStringLiteral("--count"),
                                QStringLiteral("5"), QStringLiteral("-l"), QStringLiteral("0"), QStringLiteral("--frame-log"),
                                path, m_url};
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.exitCode == 0, r.describe());
    QVERIFY2(!r.errText().contains(QLatin1String(" out sent ")), r.describe());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 10);
    QCOMPARE(lines.filter(QStringLiteral(" out sent ")).size(), 5);
    QCOMPARE(lines.filter(QStringLiteral(" in  ok ")).size(), 5);
    // The file exists now: refused without --force, replaced with it.
    const CliResult again = runMbscope(arguments);
    QVERIFY2(again.exitCode == 2 && again.errText().contains(QLatin1String("--frame-log")), again.describe());
    const CliResult forced = runMbscope(QStringList(arguments) << QStringLiteral("--force"));
    QVERIFY2(forced.exitCode == 0, forced.describe());
}


// What a command loads: the light commands none of the window (Qt Gui, Widgets, QCustomPlot),
// the simulator (Qt SerialBus, the script engine Qt Qml) or the watch service (Qt HttpServer,
// libmosquitto); simulate and the plots run in mbscope-full, which loads them.
void TestCliHabits::startLoadsOnlyWhatItUses_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("mustLoad");
    QTest::addColumn<QStringList>("mustNotLoad");
    const QStringList heavy = sl({"libQt6Gui.so.6", "libQt6Widgets.so.6", "libQCustomPlotQt6.so.2.1", "libQt6Qml.so.6",
                                  "libQt6SerialBus.so.6", "libQt6HttpServer.so.6", "libmosquitto.so.1"});
    QTest::newRow("read") << sl({"read", "-r", "121", "-c", "2", "TARGET"}) << sl({"libQt6Network.so.6"}) << heavy;
    QTest::newRow("read -1 -q, as mbpoll") << sl({"read", "-1", "-q", "-r", "121", "-c", "2", "TARGET"})
                                           << sl({"libQt6Network.so.6"}) << heavy;
    QTest::newRow("send") << sl({"send", "--target", "TARGET", "--hex", "00 01 00 00 00 06 01 03 00 79 00 01"}) << sl({"libQt6Network.so.6"})
                          << heavy;
    QTest::newRow("poll") << sl({"poll", "-r", "121", "-c", "2", "-l", "10", "-1", "TARGET"})
                          << sl({"libQt6Network.so.6"}) << heavy;
    QTest::newRow("decode") << sl({"decode", "01 03 00 79 00 16 15 DD"}) << sl({"libQt6Core.so.6"}) << heavy;
    QTest::newRow("--version") << sl({"--version"}) << sl({"libQt6Core.so.6"}) << heavy;
    QTest::newRow("read --help") << sl({"read", "--help"}) << sl({"libQt6Core.so.6"}) << heavy;
    QTest::newRow("simulate runs in mbscope-full")
        << sl({"simulate", "--list-profiles"}) << sl({"libQt6SerialBus.so.6", "libQt6Qml.so.6"}) << QStringList();
#ifdef MBSCOPE_HAVE_UI
    QTest::newRow("a plot runs in mbscope-full")
        << sl({"poll", "-r", "121", "-c", "2", "-1", "--histogram", "DIR/startup.png", "--force", "TARGET"})
        << sl({"libQt6Widgets.so.6", "libQCustomPlotQt6.so.2.1"}) << QStringList();
#endif
}

void TestCliHabits::startLoadsOnlyWhatItUses()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, mustLoad);
    QFETCH(QStringList, mustNotLoad);
    for (QString &a : arguments)
        a.replace(QStringLiteral("DIR"), m_dir.path());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LD_DEBUG"), QStringLiteral("libs"));
    const CliResult run = runMbscope(withTarget(arguments, m_url), 60000, env);
    QVERIFY2(run.finished && run.exitCode == 0, run.describe().right(4000).constData());
    const QStringList loaded = initialisedLibraries(run.err);
    for (const QString &library : mustLoad)
        QVERIFY2(loaded.contains(library), qPrintable(library + QStringLiteral(" not loaded: ") + loaded.join(QLatin1Char(' '))));
    for (const QString &library : mustNotLoad)
        QVERIFY2(!loaded.contains(library), qPrintable(library + QStringLiteral(" loaded: ") + loaded.join(QLatin1Char(' '))));
}

// mbscope alone, without mbscope-full beside it (a copy taken out of its folder): the light
// commands run, the others say what is missing and where it was looked for.
void TestCliHabits::withoutTheFullPartSaysWhy()
{
    const QString alone = m_dir.filePath(QStringLiteral("alone/mbscope"));
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("alone"))));
    QFile::remove(alone);
    QVERIFY(QFile::copy(mbscopePath(), alone));
    QProcess light;
    light.start(alone, withTarget(sl({"read", "-1", "-q", "-r", "121", "-c", "2", "TARGET"}), m_url));
    QVERIFY(light.waitForFinished(60000));
    const QByteArray lightOut = light.readAllStandardOutput();
    QVERIFY2(light.exitCode() == 0, (lightOut + light.readAllStandardError()).constData());
    QCOMPARE(valueLines(lightOut).size(), 2);
    QProcess heavy;
    heavy.start(alone, sl({"simulate", "--list-profiles"}));
    QVERIFY(heavy.waitForFinished(60000));
    QCOMPARE(heavy.exitCode(), 2);
    const QString err = QString::fromUtf8(heavy.readAllStandardError());
    QVERIFY2(err.startsWith(QStringLiteral("mbscope: cannot start %1-full,").arg(alone)), qPrintable(err));
    QVERIFY2(err.contains(QLatin1String("No such file or directory")), qPrintable(err));
}

QTEST_GUILESS_MAIN(TestCliHabits)
#include "tst_cli_habits.moc"
