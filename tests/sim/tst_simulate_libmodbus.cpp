// libmodbus against `mbscope simulate --profile conformance`: libmodbus_conformance
// (tests/sim/libmodbus_conformance.c) calls every function code libmodbus has (01, 02, 03, 04,
// 05, 06, 0F, 10, 11, 16, 17) over tcp and over rtu on a socat pty, checks each answer against
// the profile and reads every write back; the simulator's own lines must show each code answered.
#include "peerprocess.h"
#include "simcli.h"

#include <QtCore/QFileInfo>
#include <QtTest/QtTest>

using namespace mbscope::testpeers;
using namespace mbscope::simtest;

class tst_SimulateLibmodbus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyFunctionCode_data();
    void everyFunctionCode();
};

void tst_SimulateLibmodbus::everyFunctionCode_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::newRow("tcp") << QStringLiteral("tcp");
    QTest::newRow("rtu on a pty") << QStringLiteral("rtu");
}

void tst_SimulateLibmodbus::everyFunctionCode()
{
    QFETCH(QString, scheme);
    const QString client = QStringLiteral(MBSCOPE_LIBMODBUS_CONFORMANCE);
    if (client.isEmpty() || !QFileInfo::exists(client))
        QSKIP("libmodbus is not installed (Debian: libmodbus-dev): libmodbus_conformance was not built");
    QString why;
    const bool serial = scheme == QLatin1String("rtu");
    if (serial && !socatAvailable(&why))
        QSKIP(qPrintable(why));
    PtyPair pty;
    QString listen = QStringLiteral("tcp://127.0.0.1:0");
    if (serial) {
        QVERIFY2(pty.start(), qPrintable(pty.error()));
        listen = QStringLiteral("rtu://%1?baud=115200&parity=N").arg(pty.ourEnd());
    }
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"), listen}, 1, &why),
             qPrintable(why));
    const QStringList args = serial ? QStringList{QStringLiteral("rtu"), pty.peerEnd(), QStringLiteral("115200")}
                                    : QStringList{QStringLiteral("tcp"), QStringLiteral("127.0.0.1"), QString::number(sim.port(0))};
    const Run run = runProcess(client, args, 120000);
    QVERIFY2(run.exitCode == 0 && run.out.endsWith("done\n"), (run.out + run.err).constData());
    QVERIFY2(!run.out.contains("FAIL"), run.out.constData());
    int checks = 0;
    for (const QByteArray &line : run.out.split('\n'))
        checks += line.startsWith("ok ") ? 1 : 0;
    QCOMPARE(checks, 23); // every check of libmodbus_conformance.c ran
    QCOMPARE(sim.stop(), 0);

    // The simulator saw each function code and answered it, normally and with the exceptions asked for.
    const QByteArray out = sim.output();
    for (const char *line : {"unit 1  01 Read Coils  answered", "unit 1  02 Read Discrete Inputs  answered",
                             "unit 1  03 Read Holding Registers  answered", "unit 1  04 Read Input Registers  answered",
                             "unit 1  05 Write Single Coil  answered", "unit 1  06 Write Single Register  answered",
                             "unit 1  0F Write Multiple Coils  answered", "unit 1  10 Write Multiple Registers  answered",
                             "unit 1  11 Report Server ID  answered", "unit 1  16 Mask Write Register  answered",
                             "unit 1  17 Read/Write Multiple Registers  answered",
                             "unit 1  03 Read Holding Registers  exception 02", "unit 1  16 Mask Write Register  exception 02",
                             "unit 2  03 Read Holding Registers  answered", "unit 2  01 Read Coils  exception 01"})
        QVERIFY2(out.contains(line), qPrintable(QStringLiteral("no line with '%1' in:\n%2").arg(QLatin1String(line), QString::fromUtf8(out))));
}

QTEST_GUILESS_MAIN(tst_SimulateLibmodbus)
#include "tst_simulate_libmodbus.moc"
