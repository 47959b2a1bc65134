// RegisterTrendPanel and TrendSeries: a profile register polled from the built-in simulator is
// plotted at its scaled value under its profile name; values come out of answers in any format.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "common/plotcursor.h"
#include "analysis/registertrendpanel.h"
#include "analysis/trendseries.h"

#include "protocol/adubuilder.h"
#include "profile/profileloader.h"

#include <QtTest/QSignalSpy>
#include <QtCore/QSettings>
#include <QtTest/QtTest>
#include <qcustomplot.h>

using namespace mbscope;

class TestRegisterTrendPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void init() { QSettings().remove(QStringLiteral("trends")); }
    void valueInAnswer_data();
    void valueInAnswer();
    void profileSeriesAreNamed();
    void trendOfAProfileRegister();
    void addedByAddressAndRefused();
    void tickedLaterShowsTheHistory();
    void choicesSurviveARestart();
};

namespace {

ReadAnswer holdingAnswer(int address, const QList<quint16> &registers)
{
    ReadAnswer answer;
    answer.table = ModbusTable::HoldingRegisters;
    answer.functionCode = 0x03;
    answer.address = address;
    answer.quantity = int(registers.size());
    answer.registers = registers;
    return answer;
}

int indexOfName(const RegisterTrendPanel &panel, const QString &name)
{
    for (int i = 0; i < panel.seriesCount(); ++i) {
        if (panel.series(i).name == name)
            return i;
    }
    return -1;
}

} // namespace

void TestRegisterTrendPanel::valueInAnswer_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("address");
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("offset");
    QTest::addColumn<bool>("has");
    QTest::addColumn<double>("value");
    // The answer: registers 200-205 hold FF83 2C3D 42F6 E979 E979 42F6.
    QTest::newRow("i16 scaled 0.1") << "i16" << 200 << 0.1 << 0.0 << true << -12.5;
    QTest::newRow("u16 scaled with offset") << "u16" << 201 << 0.01 << 900.0 << true << 1013.25;
    QTest::newRow("f32 abcd inside the answer") << "f32-abcd" << 202 << 1.0 << 0.0 << true << double(123.456f);
    QTest::newRow("f32 cdab at an odd offset") << "f32-cdab" << 204 << 1.0 << 0.0 << true << double(123.456f);
    QTest::newRow("f32 past the answer's end") << "f32" << 205 << 1.0 << 0.0 << false << 0.0;
    QTest::newRow("before the answer") << "u16" << 199 << 1.0 << 0.0 << false << 0.0;
}

void TestRegisterTrendPanel::valueInAnswer()
{
    QFETCH(QString, format);
    QFETCH(int, address);
    QFETCH(double, scale);
    QFETCH(double, offset);
    QFETCH(bool, has);
    QFETCH(double, value);
    TrendSeries series;
    series.address = address;
    series.format = RegisterFormat::parse(format).format;
    series.scale = scale;
    series.offset = offset;
    const std::optional<double> read =
        series.valueIn(holdingAnswer(200, {0xFF83, 11325, 0x42F6, 0xE979, 0xE979, 0x42F6}));
    QCOMPARE(read.has_value(), has);
    if (has)
        QVERIFY2(qAbs(*read - value) < 1e-9, qPrintable(QString::number(*read, 'g', 17)));
    // Another table's answer holds nothing of it.
    ReadAnswer input = holdingAnswer(200, {1, 2, 3, 4, 5, 6});
    input.table = ModbusTable::InputRegisters;
    QVERIFY(!series.valueIn(input));
}

void TestRegisterTrendPanel::profileSeriesAreNamed()
{
    const ProfileLoadResult loaded = ProfileLoader::load(QStringLiteral("conformance"));
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    const QList<TrendSeries> all = TrendSeries::fromProfile(*loaded.profile.unit(1), loaded.profile.name);
    const auto temperature = std::find_if(all.cbegin(), all.cend(),
                                          [](const TrendSeries &s) { return s.name == QLatin1String("temperature"); });
    QVERIFY(temperature != all.cend());
    QCOMPARE(temperature->address, 208);
    QCOMPARE(temperature->format.name(), QStringLiteral("i16"));
    QCOMPARE(temperature->scale, 0.1);
    QCOMPARE(temperature->label(), QStringLiteral("temperature, 40209 (degC)"));
    QVERIFY2(temperature->description().contains(QLatin1String("conformance")), qPrintable(temperature->description()));
    // A float takes two registers: the next series starts two addresses on.
    const auto cdab = std::find_if(all.cbegin(), all.cend(), [](const TrendSeries &s) { return s.address == 202; });
    QVERIFY(cdab != all.cend());
    QCOMPARE(cdab->name, QStringLiteral("float CDAB"));
    QCOMPARE(cdab->format.name(), QStringLiteral("f32-cdab"));
}

void TestRegisterTrendPanel::trendOfAProfileRegister()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("conformance"), QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    RegisterTrendPanel panel;
    panel.setFraming(started.url.framing());
    panel.setProfile(*sim.profile().unit(1), sim.profile().name);
    const int temperature = indexOfName(panel, QStringLiteral("temperature"));
    const int pressure = indexOfName(panel, QStringLiteral("pressure"));
    const int floatCdab = indexOfName(panel, QStringLiteral("float CDAB"));
    QVERIFY(temperature >= 0 && pressure >= 0 && floatCdab >= 0);
    panel.setSeriesShown(temperature, true);
    panel.setSeriesShown(pressure, true);
    panel.setSeriesShown(floatCdab, true);
    QVERIFY(panel.graphOf(temperature));

    LinkController controller;
    connect(&controller, &LinkController::transactionsFinished, &panel, &RegisterTrendPanel::addTransactions);
    QSignalSpy finished(&controller, &LinkController::pollFinished);
    controller.connectTo(started.url);
    // 03, 10 registers from 200 (0x00C8): the floats, u32, i32, temperature, pressure.
    const QByteArray read = AduBuilder::mbap(QByteArray::fromHex("0300C8000A"), 1, 1);
    QVERIFY(controller.startPoll(read, 20, 6));
    QVERIFY(finished.wait(15000));
    panel.redrawNow();

    for (const int index : {temperature, pressure, floatCdab})
        QCOMPARE(panel.graphOf(index)->dataCount(), 6);
    const auto first = [&](int index) { return panel.graphOf(index)->data()->constBegin()->value; };
    QVERIFY2(qAbs(first(temperature) - -12.5) < 1e-9, qPrintable(QString::number(first(temperature))));
    QVERIFY2(qAbs(first(pressure) - 1013.25) < 1e-9, qPrintable(QString::number(first(pressure))));
    QCOMPARE(first(floatCdab), double(123.456f));
    QCOMPARE(panel.graphOf(temperature)->name(), QStringLiteral("temperature, 40209 (degC)"));
    // Unchecked series are not plotted.
    const int u32 = indexOfName(panel, QStringLiteral("u32"));
    QVERIFY(u32 >= 0);
    QVERIFY(!panel.graphOf(u32));

    // The cursor reads the scaled value with its unit.
    panel.resize(900, 420);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.redrawNow();
    const double last = (panel.graphOf(temperature)->data()->constEnd() - 1)->key;
    panel.cursor()->setX(last);
    panel.plot()->replot();
    const QString readout = panel.cursor()->readout();
    QVERIFY2(readout.contains(QLatin1String("temperature, 40209 (degC): -12.5 degC")), qPrintable(readout));
    QVERIFY2(readout.contains(QLatin1String("pressure, 40210 (hPa): 1013.25 hPa")), qPrintable(readout));
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("register-trends.png")));
}

void TestRegisterTrendPanel::addedByAddressAndRefused()
{
    RegisterTrendPanel panel;
    TrendSeries series;
    series.address = 0x0086;
    const int index = panel.addSeries(series);
    QCOMPARE(panel.seriesCount(), 1);
    QVERIFY(panel.graphOf(index));
    QCOMPARE(panel.graphOf(index)->name(), QStringLiteral("40135 (u16)"));
    QCOMPARE(panel.addSeries(series), index); // the same register is not listed twice
    QCOMPARE(panel.seriesCount(), 1);
    // An answer from another unit than a profile series' is not its value.
    TrendSeries unit3 = series;
    unit3.address = 0x0079;
    unit3.unitId = 3;
    const int other = panel.addSeries(unit3);
    panel.setFraming(Framing::Rtu);
    Transaction t;
    t.status = TransactionStatus::Ok;
    t.sentNs = 1000;
    t.doneNs = 2000;
    t.request = AduBuilder::rtu(QByteArray::fromHex("030079000E"), 1);
    QByteArray pdu = QByteArray::fromHex("031C");
    for (int i = 0; i < 14; ++i)
        pdu += QByteArray::fromHex("0007");
    t.response = AduBuilder::rtu(pdu, 1);
    panel.addTransactions({t});
    panel.redrawNow();
    QCOMPARE(panel.graphOf(index)->dataCount(), 1);
    QCOMPARE(panel.graphOf(index)->data()->constBegin()->value, 7.0);
    QCOMPARE(panel.graphOf(other)->dataCount(), 0);
}


namespace {

// A read of quantity registers at address from unit 1 over RTU, answered with values, done at seconds.
Transaction readAt(double seconds, int address, const QList<quint16> &values)
{
    QByteArray pdu = QByteArray::fromHex("03");
    pdu.append(char(address >> 8)).append(char(address & 0xFF)).append(char(0)).append(char(values.size()));
    QByteArray answer = QByteArray::fromHex("03");
    answer.append(char(values.size() * 2));
    for (const quint16 v : values)
        answer.append(char(v >> 8)).append(char(v & 0xFF));
    Transaction t;
    t.status = TransactionStatus::Ok;
    t.request = AduBuilder::rtu(pdu, 1);
    t.response = AduBuilder::rtu(answer, 1);
    t.sentNs = qint64((1000 + seconds) * 1e9);
    t.firstByteNs = t.sentNs + 1000000;
    t.doneNs = t.sentNs + 2000000;
    return t;
}

} // namespace

// Issue 14, item 10: a register ticked during a poll shows what was already read; the time axis
// starts at its first point, not at the session's first answer; the legend lets the data through.
// Issue 14, item 3: the series plotted when the window closed are plotted again at the next start,
// a profile's as soon as its profile is listed, one added by address at once; unticked ones not.
void TestRegisterTrendPanel::choicesSurviveARestart()
{
    const ProfileLoadResult loaded = ProfileLoader::load(QStringLiteral("conformance"));
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    TrendSeries byAddress;
    byAddress.address = 0x0086;
    byAddress.format = RegisterFormat(RegisterType::Int16);
    {
        RegisterTrendPanel first;
        first.setProfile(*loaded.profile.unit(1), loaded.profile.name);
        const int temperature = indexOfName(first, QStringLiteral("temperature"));
        const int pressure = indexOfName(first, QStringLiteral("pressure"));
        QVERIFY(temperature >= 0 && pressure >= 0);
        first.setSeriesShown(temperature, true);
        first.setSeriesShown(pressure, true);
        first.setSeriesShown(pressure, false);
        first.addSeries(byAddress);
    }
    RegisterTrendPanel next;
    QCOMPARE(next.seriesCount(), 1);
    QVERIFY(next.series(0).sameRegister(byAddress));
    QVERIFY(next.graphOf(0) && next.graphOf(0)->visible());
    next.setProfile(*loaded.profile.unit(1), loaded.profile.name);
    const int temperature = indexOfName(next, QStringLiteral("temperature"));
    const int pressure = indexOfName(next, QStringLiteral("pressure"));
    QVERIFY(next.graphOf(temperature) && next.graphOf(temperature)->visible());
    QVERIFY(!next.graphOf(pressure) || !next.graphOf(pressure)->visible());
}

void TestRegisterTrendPanel::tickedLaterShowsTheHistory()
{
    RegisterTrendPanel panel;
    panel.setFraming(Framing::Rtu);
    QList<Transaction> early;
    for (int i = 0; i < 10; ++i)
        early.append(readAt(i, 200, {quint16(i)}));
    panel.addTransactions(early);
    QList<Transaction> late;
    for (int i = 20; i < 25; ++i)
        late.append(readAt(i, 300, {quint16(i)}));
    panel.addTransactions(late);

    TrendSeries first;
    first.table = ModbusTable::HoldingRegisters;
    first.address = 200;
    first.format = RegisterFormat::parse(QStringLiteral("u16")).format;
    const int index = panel.addSeries(first);
    QCOMPARE(panel.graphOf(index)->dataCount(), 10);

    TrendSeries second = first;
    second.address = 300;
    panel.setSeriesShown(index, false);
    const int other = panel.addSeries(second);
    QCOMPARE(panel.graphOf(other)->dataCount(), 5);
    panel.redrawNow();
    QVERIFY2(panel.plot()->xAxis->range().lower > 15, qPrintable(QString::number(panel.plot()->xAxis->range().lower)));
    QVERIFY(panel.plot()->xAxis->range().upper >= 24);
    QVERIFY(panel.plot()->legend->brush().color().alpha() < 255);
    QVERIFY(panel.plot()->axisRect()->insetLayout()->insetAlignment(0) & Qt::AlignLeft);
}

QTEST_MAIN(TestRegisterTrendPanel)
#include "tst_registertrendpanel.moc"
