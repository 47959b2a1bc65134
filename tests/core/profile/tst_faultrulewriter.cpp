#include "profile/faultrulereader.h"
#include "profile/faultrulewriter.h"
#include "json/jsonreader.h"

#include <QtCore/QJsonDocument>
#include <QtTest/QtTest>

using namespace mbscope;

Q_DECLARE_METATYPE(mbscope::FaultRule)

// A rule written by FaultRuleWriter reads back as the same rule, for every kind and every
// parameter the reader knows; the window keeps its fault rules between runs this way.
class TestFaultRuleWriter : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip_data();
    void roundTrip();
    void setKeepsItsSeed();
};

void TestFaultRuleWriter::roundTrip_data()
{
    QTest::addColumn<FaultRule>("rule");
    using K = FaultRule::Kind;
    const auto rule = [](K kind) {
        FaultRule r;
        r.kind = kind;
        return r;
    };
    QTest::newRow("drop, defaults") << rule(K::Drop);
    FaultRule r = rule(K::WrongChecksum);
    r.name = QStringLiteral("bad crc");
    r.units = {1, 3};
    r.functions = {3, 4};
    r.firstAddress = 0x0170;
    r.lastAddress = 0x017F;
    r.probability = 0.25;
    QTest::newRow("checksum, matched and named") << r;
    r = rule(K::Exception);
    r.exceptionCode = 6;
    r.starts = {0x0170, 0x0171};
    r.quantities = {2};
    QTest::newRow("exact start and quantity") << r;
    r = rule(K::Drop);
    r.functions = {6};
    r.values = {0x1234};
    r.hasValues = true;
    QTest::newRow("exact values written") << r;
    r = rule(K::Drop);
    r.byIntervalMs = {{100, 0.5}, {400, 0.2}};
    QTest::newRow("chance by interval") << r;
    r = rule(K::Drop);
    r.hasTurnaround = true;
    r.turnaround.kind = DelaySpec::Kind::Exponential;
    r.turnaround.meanMs = 100;
    r.turnaround.maxMs = 330;
    QTest::newRow("turnaround") << r;
    r.turnaround.kind = DelaySpec::Kind::LogNormal;
    r.turnaround.meanMs = 112;
    r.turnaround.stddevMs = 132;
    QTest::newRow("turnaround lognormal") << r;
    r = rule(K::Noise);
    r.bitErrorRate = 0.0062;
    r.noiseOn = FaultRule::NoiseOn::Request;
    QTest::newRow("noise on requests") << r;
    r = rule(K::Delay);
    r.delay = DelaySpec::fixed(12.5);
    QTest::newRow("delay fixed") << r;
    r.delay = DelaySpec{};
    r.delay.kind = DelaySpec::Kind::Uniform;
    r.delay.minMs = 5;
    r.delay.maxMs = 50;
    QTest::newRow("delay uniform") << r;
    r.delay = DelaySpec{};
    r.delay.kind = DelaySpec::Kind::Normal;
    r.delay.meanMs = 20;
    r.delay.stddevMs = 4;
    r.delay.minMs = 1;
    r.delay.maxMs = 90;
    QTest::newRow("delay normal, clamped") << r;
    r.delay = DelaySpec{};
    r.delay.kind = DelaySpec::Kind::Exponential;
    r.delay.meanMs = 7;
    QTest::newRow("delay exponential") << r;
    r.delay = DelaySpec{};
    r.delay.kind = DelaySpec::Kind::LogNormal;
    r.delay.meanMs = 30;
    r.delay.stddevMs = 45;
    r.delay.minMs = 2;
    QTest::newRow("delay lognormal") << r;
    r = rule(K::WrongTransactionId);
    r.delta = 300;
    QTest::newRow("transaction id") << r;
    r = rule(K::WrongUnit);
    r.delta = 2;
    QTest::newRow("unit") << r;
    r = rule(K::Exception);
    r.exceptionCode = 6;
    QTest::newRow("exception 06") << r;
    r = rule(K::FewerRegisters);
    r.fewer = 3;
    QTest::newRow("fewer") << r;
    r = rule(K::Chunks);
    r.chunkBytes = 3;
    r.gapMs = 2.5;
    QTest::newRow("chunks") << r;
    r = rule(K::Trickle);
    r.gapMs = 5;
    QTest::newRow("trickle") << r;
    r = rule(K::Junk);
    r.junkBefore = QByteArray::fromHex("DEADBEEF");
    r.junkAfterCount = 7;
    QTest::newRow("junk bytes before, random after") << r;
    r = rule(K::Duplicate);
    r.copies = 2;
    r.gapMs = 1;
    QTest::newRow("duplicate") << r;
    for (const auto when : {FaultRule::CloseWhen::Before, FaultRule::CloseWhen::Midway, FaultRule::CloseWhen::After}) {
        r = rule(K::Close);
        r.closeWhen = when;
        QTest::addRow("close %d", int(when)) << r;
    }
}

void TestFaultRuleWriter::roundTrip()
{
    QFETCH(FaultRule, rule);
    const QJsonObject written = FaultRuleWriter::toJson(rule);
    QList<ProfileProblem> problems;
    JsonReader reader(&problems, QStringLiteral("test"));
    const std::optional<FaultRule> read = FaultRuleReader::readRule(reader, written, QStringLiteral("rules[0]"));
    QVERIFY2(problems.isEmpty(), qPrintable(ProfileProblem::join(problems)));
    QVERIFY(read.has_value());
    QVERIFY2(*read == rule, QJsonDocument(written).toJson(QJsonDocument::Compact).constData());
}

void TestFaultRuleWriter::setKeepsItsSeed()
{
    FaultRuleSet set;
    set.seed = 4242;
    FaultRule drop;
    drop.probability = 0.5;
    set.rules = {drop, drop};
    QList<ProfileProblem> problems;
    JsonReader reader(&problems, QStringLiteral("test"));
    const FaultRuleSet read = FaultRuleReader::readRuleSet(reader, FaultRuleWriter::toJson(set), QString(), 1);
    QVERIFY2(problems.isEmpty(), qPrintable(ProfileProblem::join(problems)));
    QCOMPARE(read, set);
}

QTEST_GUILESS_MAIN(TestFaultRuleWriter)
#include "tst_faultrulewriter.moc"
