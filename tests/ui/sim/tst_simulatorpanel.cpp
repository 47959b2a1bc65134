// SimulatorPanel against real clients on loopback: fault rules switched in the panel change what a
// plain socket client sees (exception 06, silence, a wrong CRC) and switching back restores
// correct answers; a value edited in the panel is what a client reads; a client's write and a
// generator's ticks show in the panel; the first-run simulator is one entry; the traffic list
// keeps its bound; the models pass QAbstractItemModelTester throughout. Screenshots of the three
// tabs go to the test output.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "shell/mainwindow.h"
#include "sim/simfaultform.h"
#include "sim/simregistermodel.h"
#include "sim/simrunlistmodel.h"
#include "sim/simtrafficmodel.h"
#include "sim/simulatorpanel.h"

#include "protocol/adubuilder.h"
#include "sim/simulatorhost.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtCore/QSettings>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QListWidget>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabWidget>

using namespace mbscope;

namespace {

enum class Seen { Answer, Exception06, NoAnswer, BadCrc };

// One Modbus client on a plain socket, in the framing of the endpoint (MBAP or RTU over TCP).
class Client
{
public:
    Client(const LinkUrl &url) : m_framing(url.framing())
    {
        m_socket.connectToHost(url.host, url.port);
        m_connected = m_socket.waitForConnected(5000);
    }
    [[nodiscard]] bool isConnected() const { return m_connected; }

    // The answer's PDU-level view: its bytes as received (empty: none within waitMs).
    QByteArray exchange(const QByteArray &pdu, quint8 unit = 1, int waitMs = 2000)
    {
        ++m_tid;
        const QByteArray adu = m_framing == Framing::Rtu ? AduBuilder::rtu(pdu, unit) : AduBuilder::mbap(pdu, unit, m_tid);
        m_socket.readAll(); // whatever a delay rule sent late belongs to an earlier request
        m_socket.write(adu);
        QByteArray answer;
        QDeadlineTimer deadline(waitMs);
        while (!deadline.hasExpired()) {
            if (!m_socket.waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime()))))
                break;
            answer += m_socket.readAll();
            // MBAP: answers a delay rule held back arrive later; only this request's counts.
            while (m_framing != Framing::Rtu && complete(answer)) {
                const qsizetype size = 6 + ((quint8(answer.at(4)) << 8) | quint8(answer.at(5)));
                if (((quint8(answer.at(0)) << 8) | quint8(answer.at(1))) == m_tid)
                    return answer.left(size);
                answer.remove(0, size);
            }
            if (m_framing == Framing::Rtu && complete(answer))
                return answer;
        }
        return answer;
    }
    [[nodiscard]] AduParts parse(const QByteArray &answer) const { return AduBuilder::parse(answer, m_framing); }

    Seen classify(const QByteArray &answer) const
    {
        if (answer.isEmpty())
            return Seen::NoAnswer;
        const AduParts parts = parse(answer);
        if (m_framing == Framing::Rtu && !parts.checksumValid())
            return Seen::BadCrc;
        if (parts.pdu.size() >= 2 && (quint8(parts.pdu.at(0)) & 0x80) && parts.pdu.at(1) == 0x06)
            return Seen::Exception06;
        return Seen::Answer;
    }

    // 03 of one holding register: its value, or -1.
    int readHolding(int address, quint8 unit = 1)
    {
        const QByteArray pdu = QByteArray::fromHex("03") + be16(address) + be16(1);
        const AduParts parts = parse(exchange(pdu, unit));
        if (parts.pdu.size() != 4 || parts.pdu.at(0) != 0x03)
            return -1;
        return (quint8(parts.pdu.at(2)) << 8) | quint8(parts.pdu.at(3));
    }

    static QByteArray be16(int value) { return QByteArray(1, char(value >> 8)) + QByteArray(1, char(value & 0xFF)); }

private:
    bool complete(const QByteArray &bytes) const
    {
        if (m_framing != Framing::Rtu)
            return bytes.size() >= 6 && bytes.size() >= 6 + ((quint8(bytes.at(4)) << 8) | quint8(bytes.at(5)));
        if (bytes.size() < 5)
            return false;
        if (quint8(bytes.at(1)) & 0x80)
            return true;
        const quint8 function = quint8(bytes.at(1));
        if (function == 0x03 || function == 0x04)
            return bytes.size() >= 3 + quint8(bytes.at(2)) + 2;
        return bytes.size() >= 8;
    }

    QTcpSocket m_socket;
    Framing m_framing;
    quint16 m_tid = 0;
    bool m_connected = false;
};

QByteArray readSettings()
{
    return QByteArray::fromHex("0300790002"); // 03, 0x0079, two registers (rosrao-gamma's settings)
}

// Fills the panel's fault form as a user would and presses Add rule.
void addRuleThroughForm(SimFaultForm *form, FaultRule::Kind kind, int function, int exceptionCode, double delayMs)
{
    auto *kindBox = form->findChild<QComboBox *>(QStringLiteral("faultKind"));
    kindBox->setCurrentIndex(kindBox->findData(int(kind)));
    form->findChild<QSpinBox *>(QStringLiteral("faultUnit"))->setValue(1);
    form->findChild<QSpinBox *>(QStringLiteral("faultFunction"))->setValue(function);
    form->findChild<QSpinBox *>(QStringLiteral("faultExceptionCode"))->setValue(exceptionCode);
    auto *distribution = form->findChild<QComboBox *>(QStringLiteral("faultDistribution"));
    distribution->setCurrentIndex(distribution->findData(int(DelaySpec::Kind::Fixed)));
    form->findChild<QDoubleSpinBox *>(QStringLiteral("faultDelayMs"))->setValue(delayMs);
    QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("faultAdd")), Qt::LeftButton);
}

bool anyRow(const QAbstractItemModel *model, int role)
{
    for (int row = 0; row < model->rowCount(); ++row) {
        if (model->index(row, 0).data(role).toBool() || model->index(row, 0).data(role).toInt() > 0)
            return true;
    }
    return false;
}

} // namespace

class TestSimulatorPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void init() { QSettings().remove(QStringLiteral("simulator/faultRules")); }
    void faultSwitchedWhileClientPolls_data();
    void faultSwitchedWhileClientPolls();
    void faultsFileReplacesRules();
    void everyFaultKindWithItsParameters();
    void profilesWithIssue15Keys();
    void editedValueIsReadByClient();
    void clientWriteShowsInPanel();
    void generatorValuesArriveInBatches();
    void builtInSimulatorIsOneEntry();
    void builtInFaultsSurviveARestart();
    void trafficListKeepsItsBound();
    void badInputIsRefusedSayingWhy();
    void windowListsTheFirstRunSimulator();
    void screenshots();
};

void TestSimulatorPanel::faultSwitchedWhileClientPolls_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("seen");
    QTest::newRow("exception 06 over tcp") << u"tcp://127.0.0.1:0"_qs << int(FaultRule::Kind::Exception) << int(Seen::Exception06);
    QTest::newRow("exception 06 over rtu-tcp") << u"rtu-tcp://127.0.0.1:0"_qs << int(FaultRule::Kind::Exception) << int(Seen::Exception06);
    QTest::newRow("drop: a timeout") << u"tcp://127.0.0.1:0"_qs << int(FaultRule::Kind::Drop) << int(Seen::NoAnswer);
    QTest::newRow("delay 3 s: a timeout") << u"tcp://127.0.0.1:0"_qs << int(FaultRule::Kind::Delay) << int(Seen::NoAnswer);
    QTest::newRow("wrong CRC over rtu-tcp") << u"rtu-tcp://127.0.0.1:0"_qs << int(FaultRule::Kind::WrongChecksum) << int(Seen::BadCrc);
}

void TestSimulatorPanel::faultSwitchedWhileClientPolls()
{
    QFETCH(QString, url);
    QFETCH(int, kind);
    QFETCH(int, seen);
    SimulatorPanel panel;
    QAbstractItemModelTester runsTester(panel.runsModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester trafficTester(panel.trafficModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), url);
    QVERIFY2(host, qPrintable(panel.message()));
    QCOMPARE(panel.runsModel()->rowCount(), 1);
    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    const int waitMs = 400; // the client's timeout; the delay rule waits 3 s

    // Before: correct answers.
    QCOMPARE(int(client.classify(client.exchange(readSettings(), 1, 3000))), int(Seen::Answer));
    // The rule set in the panel's form: the next request sees it (unit 1, function 03).
    addRuleThroughForm(panel.faultForm(), FaultRule::Kind(kind), 0x03, 0x06, 3000);
    QCOMPARE(host->faultRules().rules.size(), 1);
    for (int i = 0; i < 3; ++i)
        QCOMPARE(int(client.classify(client.exchange(readSettings(), 1, waitMs))), seen);
    // Another unit is not concerned by a rule for unit 1.
    QCOMPARE(int(client.classify(client.exchange(readSettings(), 3, 3000))), int(Seen::Answer));
    // The simulator's traffic says which answers the rule changed.
    QTRY_VERIFY(anyRow(panel.trafficModel(), SimTrafficModel::FaultedRole));
    QTRY_COMPARE(panel.runsModel()->index(0, SimRunListModel::FaultedColumn).data().toString(), QStringLiteral("3"));

    // Back: no faults, correct answers again.
    QTest::mouseClick(panel.faultForm()->findChild<QPushButton *>(QStringLiteral("faultClear")), Qt::LeftButton);
    QVERIFY(host->faultRules().rules.isEmpty());
    for (int i = 0; i < 3; ++i) {
        const QByteArray answer = client.exchange(readSettings(), 1, 5000);
        QCOMPARE(int(client.classify(answer)), int(Seen::Answer));
        QCOMPARE(client.parse(answer).pdu.toHex(), QByteArray("0304041a0000")); // 0x0079 = 1050, 0x007A = 0
    }
}

// Issue 14, item 13: the form offered 4 of the profile language's 12 fault kinds.
void TestSimulatorPanel::everyFaultKindWithItsParameters()
{
    SimulatorPanel panel;
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), u"tcp://127.0.0.1:0"_qs);
    QVERIFY2(host, qPrintable(panel.message()));
    SimFaultForm *form = panel.faultForm();
    auto *kindBox = form->findChild<QComboBox *>(QStringLiteral("faultKind"));
    QStringList names;
    for (int i = 0; i < kindBox->count(); ++i)
        names << FaultRule::kindName(FaultRule::Kind(kindBox->itemData(i).toInt()));
    names.sort();
    QStringList all = FaultRule::kindNames().split(QStringLiteral(", "));
    all.sort();
    QCOMPARE(names, all);

    auto spin = [form](const char *name) { return form->findChild<QSpinBox *>(QLatin1String(name)); };
    auto choose = [kindBox](FaultRule::Kind kind) { kindBox->setCurrentIndex(kindBox->findData(int(kind))); };
    auto add = [form] { QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("faultAdd")), Qt::LeftButton); };
    choose(FaultRule::Kind::WrongUnit);
    QVERIFY(form->findChild<QSpinBox *>(QStringLiteral("faultDelta"))->isVisibleTo(form));
    spin("faultDelta")->setValue(2);
    add();
    choose(FaultRule::Kind::Duplicate);
    spin("faultCopies")->setValue(3);
    form->findChild<QDoubleSpinBox *>(QStringLiteral("faultGapMs"))->setValue(7);
    add();
    choose(FaultRule::Kind::Junk);
    spin("faultJunkBefore")->setValue(0);
    spin("faultJunkAfter")->setValue(5);
    add();
    choose(FaultRule::Kind::Close);
    auto *when = form->findChild<QComboBox *>(QStringLiteral("faultCloseWhen"));
    when->setCurrentIndex(when->findData(int(FaultRule::CloseWhen::Midway)));
    spin("faultFirstAddress")->setValue(0x200);
    spin("faultLastAddress")->setValue(0x210);
    add();
    const QList<FaultRule> rules = host->faultRules().rules;
    QCOMPARE(rules.size(), 4);
    QCOMPARE(rules.at(0).delta, 2);
    QCOMPARE(rules.at(1).copies, 3);
    QCOMPARE(rules.at(1).gapMs, 7.0);
    QCOMPARE(rules.at(2).junkAfterCount, 5);
    QCOMPARE(int(rules.at(3).closeWhen), int(FaultRule::CloseWhen::Midway));
    QCOMPARE(rules.at(3).firstAddress, 0x200);
    QCOMPARE(rules.at(3).lastAddress, 0x210);
    QVERIFY2(SimFaultForm::describe(rules.at(1)).contains(QLatin1String("3 extra copies")), qPrintable(SimFaultForm::describe(rules.at(1))));

    // One seen by a client: fewer registers, for the two asked only one comes back.
    QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("faultClear")), Qt::LeftButton);
    spin("faultFirstAddress")->setValue(-1);
    spin("faultLastAddress")->setValue(-1);
    choose(FaultRule::Kind::FewerRegisters);
    spin("faultFewer")->setValue(1);
    add();
    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    const QByteArray answer = client.exchange(readSettings(), 1, 3000);
    QCOMPARE(client.parse(answer).pdu.toHex(), QByteArray("0302041a"));
}

void TestSimulatorPanel::faultsFileReplacesRules()
{
    QTemporaryDir dir;
    const QString good = dir.filePath(QStringLiteral("faults.json"));
    const QString bad = dir.filePath(QStringLiteral("broken.json"));
    QFile file(good);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 7, "rules": [{"kind": "exception", "code": 6, "functions": ["0x03"]}]})");
    file.close();
    QFile broken(bad);
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write(R"({"seed": 7, "rules": [{"kind": "explode"}]})");
    broken.close();

    SimulatorPanel panel;
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    QVERIFY(panel.faultForm()->loadRulesFile(good));
    QCOMPARE(int(client.classify(client.exchange(readSettings()))), int(Seen::Exception06));
    // A file that does not read says where, and the rules in force stay.
    QVERIFY(!panel.faultForm()->loadRulesFile(bad));
    QVERIFY2(panel.faultForm()->message().contains(QLatin1String("rules[0].kind")), qPrintable(panel.faultForm()->message()));
    QCOMPARE(host->faultRules().rules.size(), 1);
    QCOMPARE(int(client.classify(client.exchange(readSettings()))), int(Seen::Exception06));
}

// Issue 15: profiles with exact rules, an unknown-unit policy, time-dependent faults, noise and a
// delimited protocol load in the panel, their rules are listed as they are, and a delimited
// endpoint answers.
void TestSimulatorPanel::profilesWithIssue15Keys()
{
    SimulatorPanel panel;
    SimulatorHost *libmodbus = panel.startSimulator(QStringLiteral("libmodbus-unit-test"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(libmodbus, qPrintable(panel.message()));
    const QList<FaultRule> rules = libmodbus->faultRules().rules;
    QCOMPARE(rules.size(), 5);
    QVERIFY2(SimFaultForm::describe(rules.at(0)).contains(QLatin1String("starting at 368")), qPrintable(SimFaultForm::describe(rules.at(0))));
    QVERIFY2(SimFaultForm::describe(rules.at(4)).contains(QLatin1String("quantity 2")), qPrintable(SimFaultForm::describe(rules.at(4))));
    auto *list = panel.faultForm()->findChild<QListWidget *>(QStringLiteral("faultRules"));
    QVERIFY(list);

    SimulatorHost *scada = panel.startSimulator(QStringLiteral("scada-rs485"),
                                                QStringLiteral("tcp://127.0.0.1:0?framing=delimited&start=24&end=23"));
    QVERIFY2(scada, qPrintable(panel.message()));
    const QList<FaultRule> bus = scada->faultRules().rules;
    QCOMPARE(bus.size(), 2);
    QVERIFY2(SimFaultForm::describe(bus.at(0)).contains(QLatin1String("turnaround of 112 ms")), qPrintable(SimFaultForm::describe(bus.at(0))));
    QVERIFY2(SimFaultForm::describe(bus.at(1)).contains(QLatin1String("line noise on requests")), qPrintable(SimFaultForm::describe(bus.at(1))));
    scada->setFaultRules({}); // a quiet bus, for one sure answer
    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, scada->boundUrls().first().port);
    QVERIFY(socket.waitForConnected(5000));
    socket.write("$01R#");
    QByteArray answer;
    QTRY_VERIFY_WITH_TIMEOUT((answer += socket.readAll()).endsWith('#'), 5000);
    QCOMPARE(answer, QByteArray("$01 293 295 363 353 342 335 329 347 0 1 0 0 0 1 0 0 #"));
}

void TestSimulatorPanel::editedValueIsReadByClient()
{
    SimulatorPanel panel;
    SimRegisterModel *model = panel.registerModel();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    const int row = model->rowOf(SimTable::HoldingRegisters, 0x007A);
    QVERIFY(row >= 0);
    QCOMPARE(model->index(row, SimRegisterModel::NameColumn).data().toString(), QStringLiteral("settings[1]"));
    QSignalSpy edited(model, &SimRegisterModel::valueEdited);
    QVERIFY(model->setData(model->index(row, SimRegisterModel::ValueColumn), QStringLiteral("4321")));
    QCOMPARE(edited.count(), 1);
    // Hex in the Hex column.
    const int other = model->rowOf(SimTable::HoldingRegisters, 0x007B);
    QVERIFY(model->setData(model->index(other, SimRegisterModel::HexColumn), QStringLiteral("BEEF")));

    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    QTRY_COMPARE(client.readHolding(0x007A), 4321);
    QCOMPARE(client.readHolding(0x007B), 0xBEEF);
    // The panel shows the simulator's value once its batch arrives.
    QTRY_COMPARE(model->value(SimTable::HoldingRegisters, 0x007A).value_or(0), quint16(4321));
    QCOMPARE(model->index(other, SimRegisterModel::HexColumn).data().toString(), QStringLiteral("0xBEEF"));
}

void TestSimulatorPanel::clientWriteShowsInPanel()
{
    SimulatorPanel panel;
    SimRegisterModel *model = panel.registerModel();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    QCOMPARE(model->value(SimTable::HoldingRegisters, 0x007B).value_or(1), quint16(0));
    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    const QByteArray write = QByteArray::fromHex("06") + Client::be16(0x007B) + Client::be16(777);
    QCOMPARE(client.parse(client.exchange(write)).pdu, write); // 06 echoes the request
    QTRY_COMPARE(model->value(SimTable::HoldingRegisters, 0x007B).value_or(0), quint16(777));
    const int row = model->rowOf(SimTable::HoldingRegisters, 0x007B);
    QCOMPARE(model->index(row, SimRegisterModel::ValueColumn).data().toString(), QStringLiteral("777"));
    // Unit 3 is another table: the panel shows the unit chosen.
    panel.selectUnit(3);
    QCOMPARE(model->unit(), quint8(3));
    QCOMPARE(model->value(SimTable::HoldingRegisters, 0x007B).value_or(1), quint16(0));
}

void TestSimulatorPanel::generatorValuesArriveInBatches()
{
    SimulatorPanel panel;
    SimRegisterModel *model = panel.registerModel();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    QSignalSpy batches(host, &SimulatorHost::valuesUpdated);
    QSignalSpy changed(model, &QAbstractItemModel::dataChanged);
    // Unit 1's gate counts (0x0086) are Poisson at 150 counts/s over a 1 s gate: a new count each
    // second, which the panel shows.
    const quint16 first = model->value(SimTable::HoldingRegisters, 0x0086).value_or(0);
    QTRY_VERIFY_WITH_TIMEOUT(model->value(SimTable::HoldingRegisters, 0x0086).value_or(first) != first, 5000);
    const int row = model->rowOf(SimTable::HoldingRegisters, 0x0086);
    QVERIFY(model->index(row, 0).data(SimRegisterModel::ChangedRole).toBool());
    // One dataChanged per batch, not one per value.
    QVERIFY(batches.count() >= 1);
    QCOMPARE(changed.count(), batches.count());
}

void TestSimulatorPanel::builtInSimulatorIsOneEntry()
{
    EmbeddedSimulator builtIn;
    SimulatorPanel panel;
    QAbstractItemModelTester runsTester(panel.runsModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    connect(&builtIn, &EmbeddedSimulator::hostStarted, &panel,
            [&](SimulatorHost *host) { panel.addRunning(host, builtIn.profileName(), true); });
    const EmbeddedSimulator::Started started = builtIn.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    QCOMPARE(panel.runsModel()->rowCount(), 1);
    QVERIFY(panel.runsModel()->isBuiltIn(0));
    QCOMPARE(panel.runsModel()->index(0, SimRunListModel::EndpointColumn).data().toString(), started.url.toString());
    QCOMPARE(panel.currentHost(), builtIn.host());
    QVERIFY(panel.registerModel()->rowCount() > 0);

    // A second simulator beside it.
    SimulatorHost *second = panel.startSimulator(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(second, qPrintable(panel.message()));
    QCOMPARE(panel.runsModel()->rowCount(), 2);
    QCOMPARE(panel.currentHost(), second);

    // Stopping the built-in one from the panel stops it.
    panel.stopSimulator(builtIn.host());
    QVERIFY(!builtIn.isRunning());
    QCOMPARE(panel.runsModel()->rowCount(), 1);
    QCOMPARE(panel.runsModel()->hostAt(0), second);
    panel.stopSimulator(second);
    QCOMPARE(panel.runsModel()->rowCount(), 0);
    QVERIFY(!panel.currentHost());
    QCOMPARE(panel.registerModel()->rowCount(), 0);
}

// Issue 14, item 3: the built-in simulator's fault rules are in force again at the next start,
// and the panel says so; another simulator does not take them; Remove all clears them for good.
void TestSimulatorPanel::builtInFaultsSurviveARestart()
{
    {
        EmbeddedSimulator builtIn;
        SimulatorPanel panel;
        connect(&builtIn, &EmbeddedSimulator::hostStarted, &panel,
                [&](SimulatorHost *host) { panel.addRunning(host, builtIn.profileName(), true); });
        QVERIFY(builtIn.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0")).ok);
        addRuleThroughForm(panel.faultForm(), FaultRule::Kind::Exception, 0x03, 0x06, 0);
        QCOMPARE(builtIn.host()->faultRules().rules.size(), 1);
    }
    EmbeddedSimulator builtIn;
    SimulatorPanel panel;
    connect(&builtIn, &EmbeddedSimulator::hostStarted, &panel,
            [&](SimulatorHost *host) { panel.addRunning(host, builtIn.profileName(), true); });
    QVERIFY(builtIn.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0")).ok);
    const FaultRuleSet rules = builtIn.host()->faultRules();
    QCOMPARE(rules.rules.size(), 1);
    QCOMPARE(rules.rules.first().kind, FaultRule::Kind::Exception);
    QCOMPARE(rules.rules.first().exceptionCode, quint8(6));
    QCOMPARE(panel.faultForm()->rules(), rules);
    QVERIFY2(panel.message().contains(QLatin1String("in force again")), qPrintable(panel.message()));

    SimulatorHost *other = panel.startSimulator(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(other, qPrintable(panel.message()));
    QVERIFY(other->faultRules().rules.isEmpty());
    panel.stopSimulator(other);

    QTest::mouseClick(panel.faultForm()->findChild<QPushButton *>(QStringLiteral("faultClear")), Qt::LeftButton);
    QVERIFY(builtIn.host()->faultRules().rules.isEmpty());
    EmbeddedSimulator again;
    SimulatorPanel third;
    connect(&again, &EmbeddedSimulator::hostStarted, &third,
            [&](SimulatorHost *host) { third.addRunning(host, again.profileName(), true); });
    QVERIFY(again.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0")).ok);
    QVERIFY(again.host()->faultRules().rules.isEmpty());
}

void TestSimulatorPanel::trafficListKeepsItsBound()
{
    SimulatorPanel panel;
    SimTrafficModel *traffic = panel.trafficModel();
    QAbstractItemModelTester tester(traffic, QAbstractItemModelTester::FailureReportingMode::QtTest);
    traffic->setRowLimit(5);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    Client client(host->boundUrls().first());
    QVERIFY(client.isConnected());
    for (int i = 0; i < 8; ++i)
        QVERIFY(!client.exchange(readSettings()).isEmpty());
    QTRY_COMPARE(panel.runsModel()->index(0, SimRunListModel::RequestsColumn).data().toString(), QStringLiteral("8"));
    QCOMPARE(traffic->rowCount(), 5);
    QVERIFY(traffic->droppedCount() >= 4); // 8 requests and a connection opened
    const int last = traffic->rowCount() - 1;
    QCOMPARE(traffic->index(last, SimTrafficModel::OutcomeColumn).data().toString(), QStringLiteral("answered"));
    QCOMPARE(traffic->index(last, SimTrafficModel::FunctionColumn).data().toString(), QStringLiteral("03 Read Holding Registers"));
    QCOMPARE(traffic->index(last, SimTrafficModel::RequestColumn).data().toString(), QStringLiteral("00 08 00 00 00 06 01 03 00 79 00 02"));
}

void TestSimulatorPanel::badInputIsRefusedSayingWhy()
{
    SimulatorPanel panel;
    QVERIFY(!panel.startSimulator(QStringLiteral("no-such-profile"), QStringLiteral("tcp://127.0.0.1:0")));
    QVERIFY2(panel.message().contains(QLatin1String("no-such-profile")), qPrintable(panel.message()));
    QVERIFY(!panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:99999")));
    QVERIFY2(panel.message().contains(QLatin1String("99999")), qPrintable(panel.message()));
    QCOMPARE(panel.runsModel()->rowCount(), 0);

    SimulatorHost *host = panel.startSimulator(QStringLiteral("rosrao-gamma"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(host);
    SimRegisterModel *model = panel.registerModel();
    QSignalSpy refused(model, &SimRegisterModel::editRefused);
    const int row = model->rowOf(SimTable::HoldingRegisters, 0x0079);
    QVERIFY(!model->setData(model->index(row, SimRegisterModel::ValueColumn), QStringLiteral("70000")));
    QVERIFY(!model->setData(model->index(row, SimRegisterModel::ValueColumn), QStringLiteral("12a")));
    QCOMPARE(refused.count(), 2);
    QVERIFY2(refused.at(0).at(0).toString().contains(QLatin1String("'70000'")), qPrintable(refused.at(0).at(0).toString()));
    QVERIFY2(refused.at(0).at(0).toString().contains(QLatin1String("121")), qPrintable(refused.at(0).at(0).toString()));
}

void TestSimulatorPanel::windowListsTheFirstRunSimulator()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:0")));
    SimulatorPanel *panel = window.simulatorPanel();
    QVERIFY(panel);
    QCOMPARE(panel->runsModel()->rowCount(), 1);
    QVERIFY(panel->runsModel()->isBuiltIn(0));
    QCOMPARE(panel->currentHost(), window.simulator()->host());
    // The dock has its toggle in the View menu.
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("simulatorDock"));
    QVERIFY(dock);
    bool inViewMenu = false;
    for (QAction *menuAction : window.menuBar()->actions()) {
        if (menuAction->text() == QLatin1String("&View") && menuAction->menu())
            inViewMenu = menuAction->menu()->actions().contains(dock->toggleViewAction());
    }
    QVERIFY(inViewMenu);
    // A fault switched in the window's panel reaches the window's own link: exception 06.
    addRuleThroughForm(panel->faultForm(), FaultRule::Kind::Exception, 0x03, 0x06, 0);
    Client client(window.simulator()->started().url);
    QVERIFY(client.isConnected());
    QCOMPARE(int(client.classify(client.exchange(readSettings()))), int(Seen::Exception06));
}

void TestSimulatorPanel::screenshots()
{
    SimulatorPanel panel;
    panel.resize(1100, 620);
    EmbeddedSimulator builtIn;
    const EmbeddedSimulator::Started started = builtIn.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    panel.addRunning(builtIn.host(), builtIn.profileName(), true);
    SimulatorHost *host = panel.startSimulator(QStringLiteral("m221-plc"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(host, qPrintable(panel.message()));
    panel.selectHost(builtIn.host());
    addRuleThroughForm(panel.faultForm(), FaultRule::Kind::Exception, 0x03, 0x06, 0);
    auto *probability = panel.faultForm()->findChild<QDoubleSpinBox *>(QStringLiteral("faultProbability"));
    probability->setValue(0.25);
    auto *kindBox = panel.faultForm()->findChild<QComboBox *>(QStringLiteral("faultKind"));
    kindBox->setCurrentIndex(kindBox->findData(int(FaultRule::Kind::Delay)));
    auto *distribution = panel.faultForm()->findChild<QComboBox *>(QStringLiteral("faultDistribution"));
    distribution->setCurrentIndex(distribution->findData(int(DelaySpec::Kind::Normal)));
    QTest::mouseClick(panel.faultForm()->findChild<QPushButton *>(QStringLiteral("faultAdd")), Qt::LeftButton);
    Client client(started.url);
    QVERIFY(client.isConnected());
    for (int i = 0; i < 12; ++i)
        client.exchange(readSettings(), i % 4 == 3 ? 3 : 1, 400);
    client.exchange(QByteArray::fromHex("06") + Client::be16(0x007B) + Client::be16(777), 1, 400);
    QTRY_VERIFY(panel.trafficModel()->rowCount() >= 13);
    QTRY_COMPARE(panel.registerModel()->value(SimTable::HoldingRegisters, 0x007B).value_or(0), quint16(777));
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.tabs()->setCurrentIndex(0);
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("simulatorpanel-registers.png")));
    panel.tabs()->setCurrentIndex(1);
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("simulatorpanel-faults.png")));
    panel.tabs()->setCurrentIndex(2);
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("simulatorpanel-traffic.png")));
}

QTEST_MAIN(TestSimulatorPanel)
#include "tst_simulatorpanel.moc"
