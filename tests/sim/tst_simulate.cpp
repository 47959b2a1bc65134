// `mbscope simulate` against real clients: pymodbus (tcp, rtu-tcp, udp, rtu-udp, tls, and rtu and
// ascii on socat ptys), mbpoll (tcp, and rtu on a socat pty), and 50 concurrent TCP clients of
// 1000 requests each. The product executable runs as a process (`mbscope simulate`), on ports the
// OS chooses (port 0), and is stopped with SIGINT as a user stops it with Ctrl-C.
#include "peerprocess.h"
#include "simcli.h"

#include "traffic/trafficjournal.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

#include <csignal>
#include <memory>
#include <vector>

using namespace mbscope::testpeers;
using namespace mbscope::simtest;
using mbscope::TrafficDirection;
using mbscope::TrafficEntry;
using mbscope::TrafficJournalReader;
using mbscope::TrafficJournalRecovery;

namespace {

const QList<int> kPublished = {1050, 0, 0, 0, 250, 1, 1000, 10000, 4, 4, 80, 800, 8000};

void checkRosraoValues(const QMap<int, int> &values)
{
    QCOMPARE(values.size(), 22);
    for (int i = 0; i < kPublished.size(); ++i)
        QCOMPARE(values.value(122 + i, -1), kPublished.at(i));
    for (int i = 14; i < 22; ++i) // 0x0087-0x008E; 0x0086 (index 13) is the live gate count
        QCOMPARE(values.value(122 + i, -1), 0);
}

} // namespace

class tst_Simulate : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void listProfiles();
    void errors_data();
    void errors();
    void pymodbus_data();
    void pymodbus();
    void mbpollTcp();
    void mbpollRtu();
    void durationStopsAndQuietSummarises();
    void faultsChangedWhileRunning();
    void load();
};

void tst_Simulate::listProfiles()
{
    const Run r = runSimulate({QStringLiteral("--list-profiles")});
    QCOMPARE(r.exitCode, 0);
    for (const char *name : {"rosrao-gamma", "m221-plc", "arduino-rs485", "conformance"})
        QVERIFY2(r.out.contains(QByteArray(name) + "\n    "), r.out.constData());
    QVERIFY(r.out.contains("Geiger"));
}

void tst_Simulate::errors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QStringList>("expected"); // in stderr
    const QString gamma = QStringLiteral("rosrao-gamma");
    QTest::newRow("unknown profile") << QStringList{QStringLiteral("--profile"), QStringLiteral("rosrao-gama")}
                                     << QStringList{QStringLiteral("unknown profile 'rosrao-gama'"), QStringLiteral("shipped profiles: arduino-rs485, conformance, em340-meter, heatpump-controller, libmodbus-unit-test, m221-plc, rosrao-gamma, scada-rs485, scripted-meter, sdm630-meter, sunspec-inverter"),
                                                    QStringLiteral("conformance")};
    QTest::newRow("no profile") << QStringList{} << QStringList{QStringLiteral("--profile")};
    QTest::newRow("bad url") << QStringList{QStringLiteral("--profile"), gamma, QStringLiteral("--listen"), QStringLiteral("tpc://127.0.0.1:0")}
                             << QStringList{QStringLiteral("tpc")};
    QTest::newRow("port in use") << QStringList{QStringLiteral("--profile"), gamma, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:PORT_IN_USE")}
                                 << QStringList{QStringLiteral(":PORT_IN_USE"), QStringLiteral("--listen tcp://127.0.0.1:0")};
    QTest::newRow("faults syntax") << QStringList{QStringLiteral("--profile"), gamma, QStringLiteral("--faults"), QStringLiteral("FAULTS_SYNTAX")}
                                   << QStringList{QStringLiteral("FAULTS_SYNTAX:3:")};
    QTest::newRow("faults content") << QStringList{QStringLiteral("--profile"), gamma, QStringLiteral("--faults"), QStringLiteral("FAULTS_CONTENT")}
                                    << QStringList{QStringLiteral("rules[1].kind"), QStringLiteral("explode")};
    QTest::newRow("bad duration") << QStringList{QStringLiteral("--profile"), gamma, QStringLiteral("--duration"), QStringLiteral("soon")}
                                  << QStringList{QStringLiteral("--duration: 'soon' is not a duration")};
}

void tst_Simulate::errors()
{
    QFETCH(QStringList, args);
    QFETCH(QStringList, expected);
    QTcpServer busy;
    QVERIFY(busy.listen(QHostAddress::LocalHost, 0));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString syntax = dir.filePath(QStringLiteral("syntax.json"));
    const QString content = dir.filePath(QStringLiteral("content.json"));
    QFile f1(syntax);
    QVERIFY(f1.open(QIODevice::WriteOnly));
    f1.write("{\"seed\": 7,\n \"rules\": [\n   {\"kind\": \"drop\",, \"probability\": 0.5}\n ]}\n");
    f1.close();
    QFile f2(content);
    QVERIFY(f2.open(QIODevice::WriteOnly));
    f2.write("{\"seed\": 7, \"rules\": [{\"kind\": \"drop\"}, {\"kind\": \"explode\"}]}\n");
    f2.close();
    auto substitute = [&](QString s) {
        return s.replace(QStringLiteral("PORT_IN_USE"), QString::number(busy.serverPort()))
            .replace(QStringLiteral("FAULTS_SYNTAX"), syntax)
            .replace(QStringLiteral("FAULTS_CONTENT"), content);
    };
    for (QString &a : args)
        a = substitute(a);
    const Run r = runSimulate(args);
    QCOMPARE(r.exitCode, 2);
    for (const QString &e : expected)
        QVERIFY2(QString::fromUtf8(r.err).contains(substitute(e)), r.err.constData());
}

void tst_Simulate::pymodbus_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("scheme");
    QTest::addColumn<QString>("scenario");
    const QString gamma = QStringLiteral("rosrao-gamma");
    const QString conformance = QStringLiteral("conformance");
    const QString rosrao = QStringLiteral("rosrao");
    for (const char *scheme : {"tcp", "rtu-tcp", "udp", "rtu-udp", "tls", "rtu", "ascii"}) {
        QTest::newRow(qPrintable(QStringLiteral("rosrao-gamma ") + QLatin1String(scheme))) << gamma << QString::fromLatin1(scheme) << rosrao;
        QTest::newRow(qPrintable(QStringLiteral("conformance ") + QLatin1String(scheme))) << conformance << QString::fromLatin1(scheme) << conformance;
    }
}

// A pymodbus client (sim_client.py) checks what the simulator serves in each framing: values
// against the profile, writes read back, exceptions. rtu:// and ascii:// run on a socat pty pair,
// tls:// with a throwaway CA and client certificate (mutual TLS, MODBUS/TCP Security).
void tst_Simulate::pymodbus()
{
    QFETCH(QString, profile);
    QFETCH(QString, scheme);
    QFETCH(QString, scenario);
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    const bool serial = scheme == QLatin1String("rtu") || scheme == QLatin1String("ascii");
    const bool tls = scheme == QLatin1String("tls");
    if (serial && !socatAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    if (tls && !makeTestCertificates(dir.path(), &why)) {
        if (why.contains(QLatin1String("not installed")))
            QSKIP(qPrintable(why));
        QFAIL(qPrintable(why));
    }
    PtyPair pty;
    QString listen = scheme + QStringLiteral("://127.0.0.1:0");
    QString target; // what sim_client.py is pointed at: a port or a device
    if (serial) {
        QVERIFY2(pty.start(), qPrintable(pty.error()));
        listen = QStringLiteral("%1://%2?baud=19200&parity=N").arg(scheme, pty.ourEnd());
        target = pty.peerEnd();
    } else if (tls) {
        listen += QStringLiteral("?cert=%1&key=%2&ca=%3")
                      .arg(dir.filePath(QStringLiteral("server.pem")), dir.filePath(QStringLiteral("server.key")),
                           dir.filePath(QStringLiteral("ca.pem")));
    }
    const QString logPath = dir.filePath(QStringLiteral("traffic.mbscope.journal"));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), listen, QStringLiteral("--record"), logPath},
                       1, &why),
             qPrintable(why));
    QVERIFY2(sim.listening().first().startsWith(serial ? scheme + QStringLiteral("://") + pty.ourEnd()
                                                       : scheme + QStringLiteral("://127.0.0.1:")),
             qPrintable(sim.listening().first()));
    if (!serial) {
        QVERIFY(sim.port(0) != 0);
        target = QString::number(sim.port(0));
    }
    QStringList clientArgs = {QStringLiteral(MBSCOPE_SIM_TEST_DIR "/sim_client.py"), scenario, target, scheme};
    if (tls)
        clientArgs << QStringLiteral("--ca") << dir.filePath(QStringLiteral("ca.pem")) << QStringLiteral("--cert")
                   << dir.filePath(QStringLiteral("client.pem")) << QStringLiteral("--key") << dir.filePath(QStringLiteral("client.key"));
    const Run client = runProcess(systemPython(), clientArgs, 120000);
    QVERIFY2(client.exitCode == 0 && client.out.contains("done"), (client.out + client.err + sim.output()).constData());
    QCOMPARE(sim.stop(), 0);
    const QByteArray out = sim.output();
    QVERIFY2(out.contains("  unit 1  03 Read Holding Registers  answered\n"), out.constData());
    QVERIFY2(out.contains("exception 0"), out.constData());
    QVERIFY2(out.contains("interrupted: "), out.constData());

    // The recording (--record): requests in and answers out, in pairs, each answer carrying its
    // request's transaction id; the endpoint named, the journal clean.
    int in = 0;
    int outFrames = 0;
    bool paired = true;
    QSet<quint64> requests;
    const TrafficJournalRecovery journal = TrafficJournalReader::read(logPath, [&](const TrafficEntry &e) {
        if (e.direction == TrafficDirection::In) {
            ++in;
            requests.insert(e.transactionId);
        } else if (!e.bytes.isEmpty()) {
            ++outFrames;
            paired = paired && requests.contains(e.transactionId);
        }
    });
    QVERIFY2(journal.isClean(), qPrintable(journal.message));
    QCOMPARE(journal.links.size(), 1);
    QVERIFY(journal.metadata.contains("\"role\":\"server\""));
    QVERIFY(in > 5);
    QCOMPARE(outFrames, in);
    QVERIFY(paired);
}

void tst_Simulate::mbpollTcp()
{
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    QString why;
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0")},
                       1, &why),
             qPrintable(why));
    const Run r = runProcess(mbpoll, {QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-p"), QString::number(sim.port(0)),
                                      QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"), QStringLiteral("122"),
                                      QStringLiteral("-c"), QStringLiteral("22"), QStringLiteral("-1"), QStringLiteral("127.0.0.1")});
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    checkRosraoValues(mbpollValues(r.out));
    QCOMPARE(sim.stop(), 0);
}

void tst_Simulate::mbpollRtu()
{
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    QString why;
    if (!socatAvailable(&why))
        QSKIP(qPrintable(why));
    PtyPair pty;
    QVERIFY2(pty.start(), qPrintable(pty.error()));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("rtu://%1?baud=9600&parity=N").arg(pty.ourEnd())},
                       1, &why),
             qPrintable(why));
    const Run r = runProcess(mbpoll, {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"), QStringLiteral("9600"),
                                      QStringLiteral("-P"), QStringLiteral("none"), QStringLiteral("-a"), QStringLiteral("3"),
                                      QStringLiteral("-r"), QStringLiteral("122"), QStringLiteral("-c"), QStringLiteral("22"),
                                      QStringLiteral("-1"), pty.peerEnd()});
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    checkRosraoValues(mbpollValues(r.out));
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("  unit 3  03 Read Holding Registers  answered"), sim.output().constData());
}

void tst_Simulate::durationStopsAndQuietSummarises()
{
    const Run r = runSimulate({QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                              QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"),
                              QStringLiteral("--duration"), QStringLiteral("300ms"), QStringLiteral("--quiet"),
                              QStringLiteral("--seed"), QStringLiteral("9")},
                             30000);
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("simulating conformance (:/profiles/conformance.json, seed 9)"), r.out.constData());
    QCOMPARE(r.out.count("listening "), 2);
    QVERIFY2(r.out.contains("stopped: 0 requests"), r.out.constData());
}

// 50 TCP clients at once, 1000 requests each, one after the other per client: every answer
// checked (transaction id, unit, values), none missing. The rate is printed, never asserted.
namespace {

// One Read Holding Registers of register 0x0079 over MBAP; the whole answer (empty on timeout).
QByteArray readFirstRegister(QTcpSocket &socket, quint16 tid)
{
    const char request[] = {char(tid >> 8), char(tid & 0xFF), 0, 0, 0, 6, 1, 3, 0, 0x79, 0, 1};
    socket.write(request, sizeof request);
    QByteArray answer;
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 10000) {
        if (answer.size() >= 6 && answer.size() >= 6 + ((quint8(answer[4]) << 8) | quint8(answer[5])))
            return answer;
        socket.waitForReadyRead(100);
        answer += socket.readAll();
    }
    return {};
}

void writeFile(const QString &path, const QByteArray &text)
{
    // Written elsewhere and renamed over the old file, as editors save.
    QFile file(path + QStringLiteral(".new"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
    file.close();
    QFile::remove(path);
    QVERIFY(QFile::rename(path + QStringLiteral(".new"), path));
}

} // namespace

// The faults file is read again when it is saved: new rules take effect at once, and a file that
// no longer reads is reported with where it is wrong while the rules in force stay.
void tst_Simulate::faultsChangedWhileRunning()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString faults = dir.filePath(QStringLiteral("faults.json"));
    writeFile(faults, "{\"seed\": 3, \"rules\": []}\n");
    QString why;
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults, QStringLiteral("--quiet")},
                       1, &why),
             qPrintable(why));
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, sim.port(0));
    QVERIFY(socket.waitForConnected(5000));

    QByteArray answer = readFirstRegister(socket, 1);
    QCOMPARE(answer.toHex(' '), QByteArray("00 01 00 00 00 05 01 03 02 04 1a"));

    writeFile(faults, "{\"seed\": 3, \"rules\": [{\"kind\": \"exception\", \"functions\": [\"0x03\"], \"code\": 6}]}\n");
    QVERIFY2(sim.waitForOutput("faults: reloaded", 10000), sim.output().constData());
    QVERIFY2(sim.output().contains(": 1 rule, seed 3"), sim.output().constData());
    answer = readFirstRegister(socket, 2);
    QCOMPARE(answer.toHex(' '), QByteArray("00 02 00 00 00 03 01 83 06"));

    writeFile(faults, "{\"seed\": 3, \"rules\": [{\"kind\": \"explode\"}]}\n");
    QVERIFY2(sim.waitForOutput("the rules in force stay", 10000), sim.output().constData());
    QVERIFY2(sim.output().contains("rules[0].kind"), sim.output().constData());
    answer = readFirstRegister(socket, 3);
    QCOMPARE(answer.toHex(' '), QByteArray("00 03 00 00 00 03 01 83 06"));

    writeFile(faults, "{\"seed\": 3, \"rules\": []}\n");
    QVERIFY2(sim.waitForOutput(": 0 rules, seed 3", 10000), sim.output().constData());
    answer = readFirstRegister(socket, 4);
    QCOMPARE(answer.toHex(' '), QByteArray("00 04 00 00 00 05 01 03 02 04 1a"));
    QCOMPARE(sim.stop(), 0);
}

void tst_Simulate::load()
{
    constexpr int kClients = 50;
    constexpr int kRequests = 1000;
    QString why;
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       1, &why),
             qPrintable(why));
    const quint16 port = sim.port(0);

    struct Client {
        std::unique_ptr<QTcpSocket> socket;
        QByteArray buffer;
        int sent = 0;
        int answered = 0;
        int address = 0;
        QString error;
    };
    std::vector<Client> clients(kClients);
    int done = 0;
    QEventLoop loop;
    auto send = [](Client &c, int index) {
        c.address = (index * 7 + c.sent * 13) % 90;
        const quint16 tid = quint16(c.sent);
        const char request[] = {char(tid >> 8), char(tid & 0xFF), 0, 0, 0, 6, 1, 3, 0, char(c.address), 0, 10};
        c.socket->write(request, sizeof request);
        ++c.sent;
    };
    auto finishOne = [&] {
        if (++done == kClients)
            loop.quit();
    };
    for (int i = 0; i < kClients; ++i) {
        Client &c = clients[size_t(i)];
        c.socket = std::make_unique<QTcpSocket>();
        c.socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        QObject::connect(c.socket.get(), &QTcpSocket::connected, &loop, [&c, i, &send] { send(c, i); });
        QObject::connect(c.socket.get(), &QTcpSocket::errorOccurred, &loop, [&c, &finishOne] {
            if (c.error.isEmpty() && c.answered < kRequests) {
                c.error = c.socket->errorString();
                finishOne();
            }
        });
        QObject::connect(c.socket.get(), &QTcpSocket::readyRead, &loop, [&c, i, &send, &finishOne] {
            c.buffer += c.socket->readAll();
            while (c.buffer.size() >= 9 && c.error.isEmpty()) {
                const int length = (quint8(c.buffer[4]) << 8) | quint8(c.buffer[5]);
                if (c.buffer.size() < 6 + length)
                    return;
                const QByteArray frame = c.buffer.left(6 + length);
                c.buffer.remove(0, 6 + length);
                const int tid = (quint8(frame[0]) << 8) | quint8(frame[1]);
                QByteArray expected = QByteArray::fromHex("010314");
                for (int k = 0; k < 10; ++k) {
                    const int v = 1000 + 3 * (c.address + k);
                    expected += char(v >> 8);
                    expected += char(v & 0xFF);
                }
                if (tid != c.answered || frame.mid(6) != expected) {
                    c.error = QStringLiteral("client %1 request %2: answer %3").arg(i).arg(c.answered).arg(QString::fromLatin1(frame.toHex(' ')));
                    finishOne();
                    return;
                }
                if (++c.answered == kRequests) {
                    c.socket->disconnectFromHost();
                    finishOne();
                    return;
                }
                send(c, i);
            }
        });
    }
    QTimer::singleShot(240000, &loop, &QEventLoop::quit); // a bound, not a speed requirement
    QElapsedTimer timer;
    timer.start();
    for (Client &c : clients)
        c.socket->connectToHost(QHostAddress::LocalHost, port);
    loop.exec();
    const double seconds = double(timer.nsecsElapsed()) / 1e9;
    int answered = 0;
    for (const Client &c : clients) {
        QVERIFY2(c.error.isEmpty(), qPrintable(c.error));
        answered += c.answered;
    }
    QCOMPARE(answered, kClients * kRequests);
    qInfo("load: %d clients x %d requests = %d answers in %.2f s: %.0f requests/s served", kClients, kRequests, answered,
          seconds, double(answered) / seconds);
    clients.clear();
    QCOMPARE(sim.stop(), 0);
    // The simulator counted the same: every request answered.
    QVERIFY2(sim.output().contains("interrupted: 50000 requests"), sim.output().constData());
    QVERIFY2(sim.output().contains(": 50000 answered, 0 exceptions"), sim.output().constData());
}

QTEST_GUILESS_MAIN(tst_Simulate)
#include "tst_simulate.moc"
