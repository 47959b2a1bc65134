// The Simulator dock's Script tab with a real client on loopback: a profile file with a script
// started from the panel answers as its script says; the tab lists the script and shows its log
// (log(...) lines, the load); Reload scripts picks up an edited file; a broken edit is logged
// with file, line and column and the unit answers as its profile says; a profile whose script
// does not compile is refused with the located error. A screenshot of the tab goes to the output.
#include "sim/simscriptpanel.h"
#include "sim/simulatorpanel.h"

#include "protocol/adubuilder.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>

using namespace mbscope;

namespace {

void writeFile(const QString &path, const QByteArray &text)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    file.write(text);
}

// Reads holding register 0 of unit 1: its value, or -1 when the answer is no normal one.
int readRegister0(quint16 port)
{
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), port);
    if (!socket.waitForConnected(5000))
        return -2;
    socket.write(AduBuilder::mbap(QByteArray::fromHex("0300000001"), 1, 1));
    QByteArray answer;
    QDeadlineTimer deadline(5000);
    while (answer.size() < 9 && !deadline.hasExpired() && socket.waitForReadyRead(500))
        answer += socket.readAll();
    if (answer.size() < 11)
        return -1;
    return quint8(answer.at(9)) << 8 | quint8(answer.at(10));
}

const QByteArray kProfile = R"({"name": "scripted", "units": [{"id": 1, "script": "s.js",
    "tables": {"holding": [{"address": 0, "values": [5]}]}}]})";

} // namespace

class TestSimScriptPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void loadReloadAndLog();
    void brokenScriptRefusedAtStart();
};

void TestSimScriptPanel::loadReloadAndLog()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString script = dir.filePath(QStringLiteral("s.js"));
    writeFile(script, "log('first version');\nfunction onRequest(r) { log('asked for', r.address); return [111]; }\n");
    const QString profile = dir.filePath(QStringLiteral("p.json"));
    writeFile(profile, kProfile);

    SimulatorPanel panel;
    panel.resize(900, 600);
    panel.show();
    SimulatorHost *host = panel.startSimulator(profile, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    QCOMPARE(host->scripts(), QStringList{QStringLiteral("unit 1: s.js")});
    SimScriptPanel *scripts = panel.scriptPanel();
    QTabWidget *tabs = panel.tabs();
    const int tab = tabs->indexOf(scripts);
    QVERIFY(tab >= 0);
    QCOMPARE(tabs->tabText(tab), QStringLiteral("Script"));
    tabs->setCurrentIndex(tab);
    QCOMPARE(scripts->findChild<QLabel *>(QStringLiteral("simScripts"))->text(), QStringLiteral("Scripts: unit 1: s.js"));
    QVERIFY(scripts->reloadButton()->isEnabled());

    const quint16 port = host->boundUrls().first().port;
    QCOMPARE(readRegister0(port), 111);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  asked for 0")), 5000);
    QVERIFY2(scripts->logText().contains(QLatin1String("unit 1: s.js  first version")), qPrintable(scripts->logText()));
    QVERIFY2(scripts->logText().contains(QLatin1String("unit 1: s.js  loaded")), qPrintable(scripts->logText()));

    // Edited and reloaded: the new answer.
    writeFile(script, "function onRequest(r) { return [222]; }\n");
    QTest::mouseClick(scripts->reloadButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  reloaded")), 5000);
    QCOMPARE(readRegister0(port), 222);

    // A broken edit: the error located in the log; the profile answers meanwhile.
    writeFile(script, "function onRequest(r) {\n  return [333;\n}\n");
    QTest::mouseClick(scripts->reloadButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(scripts->logText().contains(QLatin1String("unit 1: s.js  error: s.js:2:")), 5000);
    QVERIFY2(scripts->logText().contains(QLatin1String("SyntaxError")), qPrintable(scripts->logText()));
    QVERIFY2(scripts->logText().contains(QLatin1String("(the profile answers until the next reload)")), qPrintable(scripts->logText()));
    QCOMPARE(readRegister0(port), 5);

    const QString shot = QDir(QString::fromLocal8Bit(qgetenv("MBSCOPE_TEST_OUTPUT"))).filePath(QStringLiteral("sim-script-tab.png"));
    if (qEnvironmentVariableIsSet("MBSCOPE_TEST_OUTPUT"))
        panel.grab().save(shot);
    panel.stopSimulator(host);
    QCOMPARE(scripts->findChild<QLabel *>(QStringLiteral("simScripts"))->text(), QStringLiteral("No simulator selected."));
}

void TestSimScriptPanel::brokenScriptRefusedAtStart()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir.filePath(QStringLiteral("s.js")), "var x = ;\n");
    const QString profile = dir.filePath(QStringLiteral("p.json"));
    writeFile(profile, kProfile);
    SimulatorPanel panel;
    QVERIFY(!panel.startSimulator(profile, QStringLiteral("tcp://127.0.0.1:0")));
    QVERIFY2(panel.message().contains(QStringLiteral("%1: units[0].script: s.js:1:").arg(profile)), qPrintable(panel.message()));
    QVERIFY2(panel.message().contains(QLatin1String("SyntaxError")), qPrintable(panel.message()));
}

QTEST_MAIN(TestSimScriptPanel)
#include "tst_simscriptpanel.moc"
