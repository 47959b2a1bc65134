// Subcommands run inside the test's process (issue 25, 5), through the light executable's own
// dispatcher (runHeadless, app/commands.cpp): no binary started, the command and a simulator
// serving it share one event loop. What this proves that the tests starting `mbscope` cannot
// prove as cheaply: every option is checked before any I/O (a listening socket sees no connection
// when an option is wrong), and a command is a function a test can call.
#include "inprocess.h"

#include "commands.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "sim/simunit.h"
#include "transport/linkurl.h"

#include <QtNetwork/QTcpServer>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::testcli;

class TestCliInProcess : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void helpOfEveryCommandHere();
    void optionsCheckedBeforeAnyIo_data();
    void optionsCheckedBeforeAnyIo();
    void decodes();
    void readsASimulatorInTheSameProcess();
};

void TestCliInProcess::helpOfEveryCommandHere()
{
    int ran = 0;
    for (const app::SubcommandHelp &command : app::subcommandHelps()) {
        const QByteArray name = command.name.toLatin1();
        if (!app::runsHere(name.constData()))
            continue;
        const InProcessRun run = runInProcess({command.name, QStringLiteral("--help")});
        QVERIFY2(run.exitCode == 0, name + ": " + run.err);
        QVERIFY2(run.out.contains("Usage: mbscope " + name), name + ": " + run.out.left(200));
        QVERIFY2(run.out.contains("Example"), name + " --help has no example");
        ++ran;
    }
    QVERIFY2(ran >= 8, qPrintable(QStringLiteral("only %1 commands run in the light executable").arg(ran)));
}

void TestCliInProcess::optionsCheckedBeforeAnyIo_data()
{
    QTest::addColumn<QStringList>("arguments"); // TARGET is the listening socket's URL
    QTest::addColumn<QString>("message");
    QTest::newRow("read, address") << QStringList{QStringLiteral("read"), QStringLiteral("--target"), QStringLiteral("TARGET"),
                                                  QStringLiteral("--address"), QStringLiteral("12x")}
                                   << QStringLiteral("--address '12x' is not a number");
    QTest::newRow("read, quantity") << QStringList{QStringLiteral("read"), QStringLiteral("--target"), QStringLiteral("TARGET"),
                                                   QStringLiteral("--quantity"), QStringLiteral("126")}
                                    << QStringLiteral("126");
    QTest::newRow("poll, interval") << QStringList{QStringLiteral("poll"), QStringLiteral("--target"), QStringLiteral("TARGET"),
                                                   QStringLiteral("--interval"), QStringLiteral("5q")}
                                    << QStringLiteral("--interval: '5q' is not a duration");
    QTest::newRow("write, no value") << QStringList{QStringLiteral("write"), QStringLiteral("--target"), QStringLiteral("TARGET"),
                                                    QStringLiteral("--address"), QStringLiteral("1")}
                                     << QStringLiteral("nothing to write");
    QTest::newRow("send, odd hex") << QStringList{QStringLiteral("send"), QStringLiteral("--target"), QStringLiteral("TARGET"),
                                                  QStringLiteral("--hex"), QStringLiteral("01 03 0")}
                                   << QStringLiteral("--hex");
}

void TestCliInProcess::optionsCheckedBeforeAnyIo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QTcpServer device;
    QVERIFY(device.listen(QHostAddress::LocalHost, 0));
    arguments.replaceInStrings(QStringLiteral("TARGET"), QStringLiteral("tcp://127.0.0.1:%1").arg(device.serverPort()));
    const InProcessRun run = runInProcess(arguments);
    QCOMPARE(run.exitCode, int(app::ExitUsage));
    QVERIFY2(run.err.contains(message.toUtf8()), run.err.constData());
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    // Refused before the link was opened: the device never heard of it.
    QVERIFY(!device.waitForNewConnection(200));
}

void TestCliInProcess::decodes()
{
    const InProcessRun run = runInProcess({QStringLiteral("decode"), QStringLiteral("01 03 00 79 00 16 15 DD")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("RTU request, unit 1: Read Holding Registers, 22 from address 121 (0x0079)"), run.out.constData());
}

void TestCliInProcess::readsASimulatorInTheSameProcess()
{
    Simulator sim;
    SimUnit *unit = sim.addUnit(7);
    SimRange range;
    range.start = 0x10;
    range.count = 4;
    range.values = {1000, 1001, 1002, 65535};
    QVERIFY(unit->addRange(range));
    QString error;
    SimEndpoint *endpoint = sim.listen(QStringLiteral("tcp://127.0.0.1:0"), {}, &error);
    QVERIFY2(endpoint, qPrintable(error));
    const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(endpoint->boundUrl().port);
    const InProcessRun run = runInProcess({QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--unit"),
                                           QStringLiteral("7"), QStringLiteral("--address"), QStringLiteral("0x10"),
                                           QStringLiteral("--quantity"), QStringLiteral("4"), QStringLiteral("--format"),
                                           QStringLiteral("u16,i16")});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    for (const char *value : {"1000", "1001", "1002", "65535", "-1"})
        QVERIFY2(run.out.contains(value), run.out.constData());
    // An exception is an answer too: the command says so and exits 1.
    const InProcessRun past = runInProcess({QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--unit"),
                                            QStringLiteral("7"), QStringLiteral("--address"), QStringLiteral("0x12"),
                                            QStringLiteral("--quantity"), QStringLiteral("4")});
    QCOMPARE(past.exitCode, int(app::ExitFailure));
    QVERIFY2(past.out.contains("Illegal Data Address") || past.out.contains("02"), past.out.constData());
}

QTEST_GUILESS_MAIN(TestCliInProcess)
#include "tst_cli_inprocess.moc"
