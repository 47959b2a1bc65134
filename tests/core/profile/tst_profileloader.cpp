#include "profile/deviceprofile.h"
#include "sim/profileapplier.h"
#include "profile/profileloader.h"
#include "sim/simunit.h"

#include "profilecases.h"

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <array>
#include <cmath>

using namespace mbscope;

namespace {

QString shippedPath(const char *name)
{
    return QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/%1.json").arg(QLatin1String(name));
}

// A one-unit profile around a holding table entry (or anything given as the unit's tables).
QByteArray unitWithTables(const char *tables)
{
    return QByteArray(R"({"name": "t", "units": [{"id": 1, "tables": )") + tables + "}]}";
}

QList<quint16> words(std::initializer_list<int> values)
{
    QList<quint16> out;
    for (int v : values)
        out.append(quint16(v));
    return out;
}

} // namespace

class TestProfileLoader : public QObject
{
    Q_OBJECT
private slots:
    void lineColumn_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("offset");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::newRow("start") << QByteArray("{}") << 0 << 1 << 1;
        QTest::newRow("first line") << QByteArray("{ \"a\" }") << 6 << 1 << 7;
        QTest::newRow("third line") << QByteArray("{\n  \"a\":\n   1x}") << 13 << 3 << 5;
        // "\xc3\xa9" is one character (e-acute): columns count characters, not bytes.
        QTest::newRow("utf-8") << QByteArray("{\"\xc3\xa9\": x}") << 7 << 1 << 7;
        QTest::newRow("past the end") << QByteArray("{\n") << 99 << 2 << 1;
    }
    void lineColumn()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, offset);
        QFETCH(int, line);
        QFETCH(int, column);
        const auto [l, c] = ProfileLoader::lineColumn(text, offset);
        QCOMPARE(l, line);
        QCOMPARE(c, column);
    }

    // Syntax errors carry line and column; Qt's parser reports the offset where it gave up.
    void syntaxErrors_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("message");
        QTest::newRow("missing comma") << QByteArray("{\n  \"name\": \"a\"\n  \"units\": []\n}") << 3 << 3
                                       << QStringLiteral("JSON syntax error: unterminated object");
        QTest::newRow("unterminated object") << QByteArray("{\n  \"name\": \"a\",\n") << 3 << 1
                                             << QStringLiteral("JSON syntax error: unterminated object");
        QTest::newRow("trailing comma") << QByteArray("{\"name\": \"a\", \"units\": [1, 2,]}") << 1 << 30
                                        << QStringLiteral("JSON syntax error: object is missing after a comma");
        QTest::newRow("comment") << QByteArray("{\n  // a comment\n}") << 2 << 3
                                 << QStringLiteral("JSON syntax error: unterminated object");
    }
    void syntaxErrors()
    {
        QFETCH(QByteArray, json);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, message);
        const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
        QVERIFY(!r.ok);
        QCOMPARE(r.problems.size(), 1);
        QCOMPARE(r.problems.at(0).line, line);
        QCOMPARE(r.problems.at(0).column, column);
        QCOMPARE(r.problems.at(0).message, message);
        QCOMPARE(r.problems.at(0).toString(),
                 QStringLiteral("p.json:%1:%2: %3").arg(line).arg(column).arg(message));
        QVERIFY(r.profile.units.isEmpty());
    }

    void contentErrors_data();
    void contentErrors()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, path);
        QFETCH(QString, message);
        const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
        QVERIFY(!r.ok);
        QVERIFY2(!r.problems.isEmpty(), "no problem reported");
        const ProfileProblem &p = r.problems.at(0);
        QCOMPARE(p.path, path);
        QCOMPARE(p.message, message);
        QCOMPARE(p.line, 0);
        QCOMPARE(p.toString(), QStringLiteral("p.json: %1%2").arg(path.isEmpty() ? QString() : path + QStringLiteral(": "), message));
        // Nothing half loaded.
        QVERIFY(r.profile.name.isEmpty());
        QVERIFY(r.profile.units.isEmpty());
    }

    void everyProblemReported()
    {
        const ProfileLoadResult r = ProfileLoader::parse(unitWithTables(R"({"holding": [
            {"address": 70000}, {"address": 0, "type": "u17"}, {"address": 5, "colour": "red"}]})"),
                                                         QStringLiteral("p.json"));
        QVERIFY(!r.ok);
        QCOMPARE(r.problems.size(), 3);
        QCOMPARE(r.problems.at(0).toString(), QStringLiteral("p.json: units[0].tables.holding[0].address: 70000 is beyond 65535"));
        QCOMPARE(r.problems.at(1).path, QStringLiteral("units[0].tables.holding[1].type"));
        QVERIFY(r.problems.at(1).message.startsWith(QStringLiteral("'u17' is not a register format")));
        QCOMPARE(r.problems.at(2).path, QStringLiteral("units[0].tables.holding[2]"));
        QVERIFY(r.problems.at(2).message.startsWith(QStringLiteral("unknown key 'colour'")));
        QVERIFY(r.errorText().count(QLatin1Char('\n')) == 2);
    }

    void missingFile()
    {
        const ProfileLoadResult r = ProfileLoader::loadFile(QStringLiteral("/nonexistent/p.json"));
        QVERIFY(!r.ok);
        QCOMPARE(r.problems.size(), 1);
        QCOMPARE(r.problems.at(0).toString(), QStringLiteral("/nonexistent/p.json: no such profile file"));
    }

    void resolve_data()
    {
        QTest::addColumn<QString>("given");
        QTest::addColumn<QString>("resolved");
        QTest::newRow("name") << QStringLiteral("rosrao-gamma") << QStringLiteral(":/profiles/rosrao-gamma.json");
        QTest::newRow("relative file") << QStringLiteral("my.json") << QStringLiteral("my.json");
        QTest::newRow("path") << QStringLiteral("dir/my-profile") << QStringLiteral("dir/my-profile");
        QTest::newRow("resource path") << QStringLiteral(":/profiles/x.json") << QStringLiteral(":/profiles/x.json");
    }
    void resolve()
    {
        QFETCH(QString, given);
        QFETCH(QString, resolved);
        QCOMPARE(ProfileLoader::resolve(given), resolved);
    }

    // By name from the resources when the executable links mbscope_resources; otherwise the
    // message says that none is built in.
    void loadByName()
    {
        const QList<ShippedProfile> shipped = ProfileLoader::shippedProfiles();
        const ProfileLoadResult r = ProfileLoader::load(QStringLiteral("rosrao-gamma"));
        if (shipped.isEmpty()) {
            QVERIFY(!r.ok);
            QCOMPARE(r.problems.at(0).toString(),
                     QStringLiteral("rosrao-gamma: no shipped profile of that name (none is built in); give a file "
                                    "path to load a user profile"));
            return;
        }
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        QCOMPARE(r.profile.source, QStringLiteral(":/profiles/rosrao-gamma.json"));
        QCOMPARE(shipped.size(), 4);
        const ProfileLoadResult missing = ProfileLoader::load(QStringLiteral("nope"));
        QCOMPARE(missing.problems.at(0).message,
                 QStringLiteral("no shipped profile of that name: expected one of arduino-rs485, conformance, "
                                "m221-plc, rosrao-gamma, or a file path"));
    }

    void userFileByPath()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("bench.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(unitWithTables(R"({"holding": [{"address": 10, "values": [1, 2, 3]}]})"));
        f.close();
        const ProfileLoadResult r = ProfileLoader::load(path);
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        QCOMPARE(r.profile.source, path);
        QCOMPARE(r.profile.units.at(0).entries.at(0).initial, words({1, 2, 3}));
    }

    void shippedProfilesLoad_data()
    {
        QTest::addColumn<QString>("name");
        for (const char *name : {"rosrao-gamma", "m221-plc", "arduino-rs485", "conformance", "libmodbus-unit-test", "scada-rs485",
                                  "scripted-meter", "sdm630-meter", "em340-meter", "sunspec-inverter", "heatpump-controller"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }
    void shippedProfilesLoad()
    {
        QFETCH(QString, name);
        const ProfileLoadResult r = ProfileLoader::loadFile(shippedPath(name.toLatin1().constData()));
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warningText()));
        QCOMPARE(r.profile.name, name);
        QVERIFY(!r.profile.description.isEmpty());
        QVERIFY(!r.profile.endpoints.isEmpty());
        // Every unit goes into a SimUnit without a refusal.
        QObject owner;
        QString error;
        const QList<SimUnit *> units = ProfileApplier::createUnits(r.profile, &owner, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(units.size(), r.profile.units.size());
    }

    void rosraoGamma();
    void m221Plc();
    void arduinoRs485();
    void conformance();
    void encodedValues_data();
    void encodedValues();
    void faultsInProfile();
    void faultsFile();
    void faultsFileErrors_data();
    void faultsFileErrors();
    void applier();
    void documentedExamples();
    void unreadableTableWarned();
    void mapMeanings();
    void scaleRegister_data();
    void scaleRegister();
    void sharedTablesAndGaps_data();
    void sharedTablesAndGaps();
};

void TestProfileLoader::contentErrors_data()
{
    profilecases::addErrorRows();
}

// The published RosRao response: 22 holding registers from 0x0079 starting with these values
// (tests/data/published-frames.json, rosrao-read-response-as-printed).
void TestProfileLoader::rosraoGamma()
{
    const ProfileLoadResult r = ProfileLoader::loadFile(shippedPath("rosrao-gamma"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QCOMPARE(r.profile.endpoints, QStringList{QStringLiteral("rtu-tcp://127.0.0.1:4001")});
    QCOMPARE(r.profile.units.size(), 2);
    QObject owner;
    const QList<SimUnit *> units = ProfileApplier::createUnits(r.profile, &owner);
    QCOMPARE(units.size(), 2);
    const QList<quint16> published = words({1050, 0, 0, 0, 250, 1, 1000, 10000, 4, 4, 80, 800, 8000,
                                            0, 0, 0, 0, 0, 0, 0, 0, 0});
    for (int i = 0; i < 2; ++i) {
        const UnitProfile &u = r.profile.units.at(i);
        QCOMPARE(u.id, quint8(i == 0 ? 1 : 3));
        QCOMPARE(u.functions, (QList<quint8>{0x03, 0x06, 0x10}));
        QCOMPARE(u.responseDelay.kind, DelaySpec::Kind::Normal);
        QVERIFY(u.responseDelay.meanMs >= 1 && u.responseDelay.meanMs <= 10);
        QVERIFY(u.responseDelay.stddevMs > 0);
        SimUnit *unit = units.at(i);
        QCOMPARE(unit->id(), u.id);
        QCOMPARE(unit->values(SimTable::HoldingRegisters, 0x0079, 22), published);
        QVERIFY(unit->contains(SimTable::HoldingRegisters, 0x0079, 22));
        QVERIFY(!unit->contains(SimTable::HoldingRegisters, 0x0078));
        QVERIFY(!unit->contains(SimTable::HoldingRegisters, 0x0079 + 22));
        QVERIFY(unit->isWritable(SimTable::HoldingRegisters, 0x0079, 22));
        QVERIFY(unit->supportsFunction(0x03) && unit->supportsFunction(0x06) && unit->supportsFunction(0x10));
        QVERIFY(!unit->supportsFunction(0x04));
        // The live register: Poisson counts in a 1000 ms gate.
        const TableEntry *live = u.entryAt(SimTable::HoldingRegisters, 0x0086);
        QVERIFY(live && live->generator);
        QCOMPARE(live->generator->kind, GeneratorSpec::Kind::Poisson);
        QCOMPARE(live->generator->gateMs, 1000.0);
        QVERIFY(live->generator->rate > 0);
    }
    // The scintillator counts far more than the GM tube.
    QVERIFY(r.profile.units.at(0).entryAt(SimTable::HoldingRegisters, 0x0086)->generator->rate
            > 10 * r.profile.units.at(1).entryAt(SimTable::HoldingRegisters, 0x0086)->generator->rate);
}

// The M221 exchange as published: 10 writes %MW0 = 205, 0F writes %M0 = 1, unit 0 over TCP.
void TestProfileLoader::m221Plc()
{
    const ProfileLoadResult r = ProfileLoader::loadFile(shippedPath("m221-plc"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QVERIFY(r.profile.endpoints.at(0).startsWith(QLatin1String("tcp://127.0.0.1:")));
    QCOMPARE(r.profile.units.size(), 1);
    QObject owner;
    SimUnit *unit = ProfileApplier::createUnits(r.profile, &owner).value(0);
    QVERIFY(unit);
    QCOMPARE(unit->id(), quint8(1)); // TCP requests to unit 0 reach it (the simulator routes 0 and 255)
    QVERIFY(unit->supportsFunction(0x0F));
    QVERIFY(unit->supportsFunction(0x10));
    QVERIFY(unit->contains(SimTable::Coils, 0, 1024));
    QVERIFY(!unit->contains(SimTable::Coils, 1024));
    QVERIFY(unit->contains(SimTable::HoldingRegisters, 0, 8000));
    QVERIFY(!unit->contains(SimTable::HoldingRegisters, 8000));
    QVERIFY(unit->clientWrite(SimTable::HoldingRegisters, 0, words({205})));
    QVERIFY(unit->clientWrite(SimTable::Coils, 0, words({1})));
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(205));
    QCOMPARE(unit->value(SimTable::Coils, 0), std::optional<quint16>(1));
    // Published round trips: 5.7-13.8 ms (write bits), 8.2-14.7 ms (write words).
    const DelaySpec &d = r.profile.units.at(0).responseDelay;
    QVERIFY(d.minMs >= 5 && d.maxMs <= 15 && d.meanMs >= 5 && d.meanMs <= 10);
}

// The published Arduino response: 69, 78, 1, 1 in holding registers 0-3 of unit 1.
void TestProfileLoader::arduinoRs485()
{
    const ProfileLoadResult r = ProfileLoader::loadFile(shippedPath("arduino-rs485"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QVERIFY(r.profile.endpoints.at(0).startsWith(QLatin1String("rtu://")));
    QObject owner;
    SimUnit *unit = ProfileApplier::createUnits(r.profile, &owner).value(0);
    QVERIFY(unit);
    QCOMPARE(unit->id(), quint8(1));
    QCOMPARE(unit->values(SimTable::HoldingRegisters, 0, 4), words({69, 78, 1, 1}));
    QVERIFY(!unit->contains(SimTable::HoldingRegisters, 4));
    const UnitProfile &u = r.profile.units.at(0);
    for (int address : {0, 1}) {
        const TableEntry *e = u.entryAt(SimTable::HoldingRegisters, address);
        QVERIFY(e && e->generator);
        QCOMPARE(e->generator->kind, GeneratorSpec::Kind::RandomWalk);
        const double published = address == 0 ? 69 : 78;
        QVERIFY(e->generator->min < published && published < e->generator->max);
        QVERIFY(!e->writable);
    }
    QVERIFY(unit->isWritable(SimTable::HoldingRegisters, 3));
}

void TestProfileLoader::conformance()
{
    const ProfileLoadResult r = ProfileLoader::loadFile(shippedPath("conformance"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QObject owner;
    const QList<SimUnit *> units = ProfileApplier::createUnits(r.profile, &owner);
    QCOMPARE(units.size(), 2);
    SimUnit *unit = units.at(0);
    // Every function code the simulator implements.
    QCOMPARE(unit->supportedFunctions(), SimUnit::implementedFunctions());
    // The test peers' data map (tests/peers/peer_datamap.h) over 0-99.
    for (int a = 0; a < 100; ++a) {
        QCOMPARE(unit->value(SimTable::Coils, a), std::optional<quint16>(a % 3 == 0 ? 1 : 0));
        QCOMPARE(unit->value(SimTable::DiscreteInputs, a), std::optional<quint16>(a % 2 == 1 ? 1 : 0));
        QCOMPARE(unit->value(SimTable::HoldingRegisters, a), std::optional<quint16>(1000 + 3 * a));
        QCOMPARE(unit->value(SimTable::InputRegisters, a), std::optional<quint16>(40000 + 2 * a));
    }
    QVERIFY(!unit->isWritable(SimTable::HoldingRegisters, 300));
    // FIFO and file records as in the spec's examples (V1.1b3 6.18, 6.14).
    QCOMPARE(unit->fifo(0x04DE), words({0x01B8, 0x1284}));
    QCOMPARE(unit->fileRecords(4).mid(1, 2), words({0x0DFE, 0x0020}));
    QCOMPARE(unit->fileRecords(3).mid(9, 2), words({0x33CD, 0x0040}));
    QCOMPARE(unit->fileRecords(4).size(), 10);
    // Identification: basic, regular and extended objects.
    const QMap<quint8, QByteArray> objects = unit->deviceIdObjects();
    for (quint8 id = 0; id <= 6; ++id)
        QVERIFY2(objects.contains(id), qPrintable(QString::number(id)));
    QVERIFY(objects.contains(0x80) && objects.contains(0x81) && objects.contains(0x82));
    QVERIFY(objects.value(0x80).size() + objects.value(0x81).size() > 253); // more than one answer
    QCOMPARE(unit->conformityLevel(), quint8(0x83));
    QCOMPARE(unit->serverId(), QByteArray("\x4D\x42"));
    QVERIFY(unit->runIndicator());
    QCOMPARE(unit->additionalData(), QByteArray("mbscope conformance"));
    QCOMPARE(unit->exceptionStatus(), quint8(0x6D));
    // The second unit: 03 only.
    QCOMPARE(units.at(1)->supportedFunctions(), QList<quint8>{0x03});
}

// Engineering values encoded with RegisterFormat/RegisterValue and the entry's scaling.
void TestProfileLoader::encodedValues_data()
{
    profilecases::addEncodingRows();
}

void TestProfileLoader::encodedValues()
{
    QFETCH(QByteArray, entry);
    QFETCH(QList<quint16>, registers);
    const ProfileLoadResult r = ProfileLoader::parse(unitWithTables(("{\"holding\": [" + entry + "]}").constData()),
                                                     QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    const TableEntry &e = r.profile.units.at(0).entries.at(0);
    QCOMPARE(e.initial, registers);
    QCOMPARE(e.count, int(registers.size()));
}

void TestProfileLoader::faultsInProfile()
{
    const QByteArray json = R"({"name": "t", "seed": 9, "units": [{"id": 1}, {"id": 2}], "faults": {"rules": [
        {"kind": "delay", "units": [2], "functions": ["0x03"], "addresses": [100, 199], "probability": 0.25,
         "delay": {"distribution": "exponential", "meanMs": 30, "maxMs": 500}},
        {"kind": "junk", "before": "DE AD", "after": 3},
        {"kind": "close", "when": "midway", "name": "cable pulled", "addresses": 7},
        {"kind": "wrongUnit", "delta": 255}]}})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    const FaultRuleSet &set = r.profile.faults;
    QCOMPARE(set.seed, quint64(9)); // the profile's seed when the faults give none
    QCOMPARE(set.rules.size(), 4);
    const FaultRule &delay = set.rules.at(0);
    QCOMPARE(delay.kind, FaultRule::Kind::Delay);
    QCOMPARE(delay.units, QList<quint8>{2});
    QCOMPARE(delay.functions, QList<quint8>{3});
    QCOMPARE(delay.firstAddress, 100);
    QCOMPARE(delay.lastAddress, 199);
    QCOMPARE(delay.probability, 0.25);
    QCOMPARE(delay.delay.kind, DelaySpec::Kind::Exponential);
    QCOMPARE(delay.delay.meanMs, 30.0);
    QCOMPARE(delay.delay.maxMs, 500.0);
    QCOMPARE(set.rules.at(1).junkBefore, QByteArray("\xDE\xAD"));
    QCOMPARE(set.rules.at(1).junkAfterCount, 3);
    QCOMPARE(set.rules.at(2).closeWhen, FaultRule::CloseWhen::Midway);
    QCOMPARE(set.rules.at(2).name, QStringLiteral("cable pulled"));
    QCOMPARE(set.rules.at(2).firstAddress, 7);
    QCOMPARE(set.rules.at(2).lastAddress, 7);
    QCOMPARE(set.rules.at(3).delta, 255);
}

void TestProfileLoader::faultsFile()
{
    const QByteArray json = R"({"seed": 42, "rules": [{"kind": "drop", "probability": 0.1},
        {"kind": "exception", "code": "0x06", "functions": [16]}, {"kind": "trickle", "gapMs": 5},
        {"kind": "chunks", "chunkBytes": 3, "gapMs": 2.5}, {"kind": "duplicate", "copies": 2},
        {"kind": "fewerRegisters", "fewer": 2}, {"kind": "wrongChecksum"}, {"kind": "wrongTransactionId"}]})";
    const FaultRulesLoadResult r = ProfileLoader::parseFaults(json, QStringLiteral("f.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QCOMPARE(r.rules.seed, quint64(42));
    QCOMPARE(r.rules.rules.size(), 8);
    QCOMPARE(r.rules.rules.at(0).probability, 0.1);
    QCOMPARE(r.rules.rules.at(1).exceptionCode, quint8(6));
    QCOMPARE(r.rules.rules.at(1).functions, QList<quint8>{0x10});
    QCOMPARE(r.rules.rules.at(2).gapMs, 5.0);
    QCOMPARE(r.rules.rules.at(3).chunkBytes, 3);
    QCOMPARE(r.rules.rules.at(3).gapMs, 2.5);
    QCOMPARE(r.rules.rules.at(4).copies, 2);
    QCOMPARE(r.rules.rules.at(5).fewer, 2);
    QCOMPARE(r.rules.rules.at(7).delta, 1);
}

void TestProfileLoader::faultsFileErrors_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown key") << QByteArray(R"({"rule": []})")
                                 << QStringLiteral("f.json: unknown key 'rule': expected one of $schema, description, seed, rules");
    QTest::newRow("rule path") << QByteArray(R"({"rules": [{"kind": "drop"}, {"kind": "delay", "delay": {"distribution": "normal", "meanMs": 1, "stddevMs": -1}}]})")
                               << QStringLiteral("f.json: rules[1].delay.stddevMs: -1 is below 0");
    QTest::newRow("junk not hex") << QByteArray(R"({"rules": [{"kind": "junk", "before": "ZZ"}]})")
                                  << QStringLiteral("f.json: rules[0].before: expected hex bytes such as \"DE AD BE EF\": "
                                                    "line 1, column 1: 'Z' is not a hex digit or a separator "
                                                    "(separators are space, tab, newline, ',', '-', ':' and ';')");
    QTest::newRow("syntax") << QByteArray("{\"rules\": [}") << QStringLiteral("f.json:1:12: JSON syntax error: object is missing after a comma");
}

void TestProfileLoader::faultsFileErrors()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const FaultRulesLoadResult r = ProfileLoader::parseFaults(json, QStringLiteral("f.json"));
    QVERIFY(!r.ok);
    QVERIFY(r.rules.rules.isEmpty());
    QCOMPARE(r.problems.at(0).toString(), expected);
}

// What a profile puts into a SimUnit besides the tables.
void TestProfileLoader::applier()
{
    const QByteArray json = R"({"name": "t", "units": [{"id": 7, "name": "seven", "functions": [3, 16],
        "responseDelay": {"distribution": "uniform", "minMs": 2, "maxMs": 4}, "exceptionStatus": 5,
        "tables": {"holding": [{"address": 10, "count": 2, "writable": false}], "coils": [{"address": 0, "values": [true]}],
                   "input": [{"address": 3, "value": 9}], "discrete": [{"address": 1, "count": 8, "value": 1}]},
        "serverId": {"id": "01 02", "running": false, "additionalDataHex": "AA BB"},
        "files": [{"file": 2, "length": 3, "writable": false}]}]})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    SimUnit unit(7);
    unit.setFifo(99, words({1}));
    QString error;
    QVERIFY2(ProfileApplier::apply(r.profile.units.at(0), &unit, &error), qPrintable(error));
    QCOMPARE(unit.name(), QStringLiteral("seven"));
    QCOMPARE(unit.supportedFunctions(), (QList<quint8>{0x03, 0x10}));
    QCOMPARE(unit.responseDelayNs(), qint64(3000000)); // the nominal (mean) response time
    QCOMPARE(unit.exceptionStatus(), quint8(5));
    QVERIFY(!unit.isWritable(SimTable::HoldingRegisters, 10, 2));
    QCOMPARE(unit.value(SimTable::Coils, 0), std::optional<quint16>(1));
    QCOMPARE(unit.value(SimTable::InputRegisters, 3), std::optional<quint16>(9));
    QCOMPARE(unit.values(SimTable::DiscreteInputs, 1, 8), words({1, 1, 1, 1, 1, 1, 1, 1}));
    QCOMPARE(unit.serverId(), QByteArray("\x01\x02"));
    QVERIFY(!unit.runIndicator());
    QCOMPARE(unit.additionalData(), QByteArray("\xAA\xBB"));
    QCOMPARE(unit.fileRecords(2), words({0, 0, 0}));
    QVERIFY(!unit.isFileWritable(2));
    QVERIFY(unit.deviceIdObjects().isEmpty());
    // Applying again replaces the ranges rather than refusing them as overlaps.
    QVERIFY2(ProfileApplier::apply(r.profile.units.at(0), &unit, &error), qPrintable(error));
    QCOMPARE(unit.ranges(SimTable::HoldingRegisters).size(), 1);
}

// The examples in docs/profiles.md load as they are shown.
void TestProfileLoader::documentedExamples()
{
    QFile doc(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../docs/profiles.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QByteArray text = doc.readAll();
    QList<QByteArray> blocks;
    for (qsizetype at = text.indexOf("```json\n"); at >= 0; at = text.indexOf("```json\n", at)) {
        const qsizetype start = at + 8;
        const qsizetype end = text.indexOf("```", start);
        QVERIFY(end > start);
        blocks.append(text.mid(start, end - start));
        at = end + 3;
    }
    QVERIFY(blocks.size() >= 3);
    const ProfileLoadResult profile = ProfileLoader::parse(blocks.at(0), QStringLiteral("profiles.md"));
    QVERIFY2(profile.ok, qPrintable(profile.errorText()));
    // Tryout 8, item 14: the example had coils and no 01 in functions, so Read Coils got exception 01.
    QVERIFY2(profile.warnings.isEmpty(), qPrintable(profile.warningText()));
    QCOMPARE(profile.profile.units.at(0).entries.size(), 5);
    QCOMPARE(profile.profile.faults.rules.size(), 2);
    // A profile has units at the top; a faults file has rules.
    const auto isProfile = [](const QByteArray &b) { return QJsonDocument::fromJson(b).object().contains(QLatin1String("units")); };
    // The first faults file.
    const auto firstFaults = std::find_if(blocks.cbegin(), blocks.cend(), [&](const QByteArray &b) { return !isProfile(b); });
    QVERIFY(firstFaults != blocks.cend());
    const FaultRulesLoadResult faults = ProfileLoader::parseFaults(*firstFaults, QStringLiteral("profiles.md"));
    QVERIFY2(faults.ok, qPrintable(faults.errorText()));
    QCOMPARE(faults.rules.rules.size(), 4);
    // Every further example: a profile when it has units, else a faults file.
    for (qsizetype i = 1; i < blocks.size(); ++i) {
        if (isProfile(blocks.at(i))) {
            const ProfileLoadResult r = ProfileLoader::parse(blocks.at(i), QStringLiteral("profiles.md block %1").arg(i));
            QVERIFY2(r.ok, qPrintable(r.errorText()));
            QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warningText()));
        } else {
            const FaultRulesLoadResult r = ProfileLoader::parseFaults(blocks.at(i), QStringLiteral("profiles.md block %1").arg(i));
            QVERIFY2(r.ok, qPrintable(r.errorText()));
        }
    }
}

// A table whose read function the unit's functions leave out loads, with a warning that says
// where and what every read of it gets (tryout 8, item 14).
void TestProfileLoader::unreadableTableWarned()
{
    const QByteArray json = R"({"name": "x", "units": [
        {"id": 1, "functions": ["0x03"], "tables": {"holding": [{"address": 0}]}},
        {"id": 2, "functions": ["0x03", "0x05", "0x17"], "tables": {"coils": [{"address": 0}], "input": [{"address": 0}],
                                                            "holding": [{"address": 0}]}},
        {"id": 3, "tables": {"coils": [{"address": 0}]}}]})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("x.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    QCOMPARE(r.warningText(),
             QStringLiteral("x.json: units[1].tables.coils: the table has entries but its read function 01 (Read Coils) is not in "
                            "functions: every read of it gets exception 01 (add \"0x01\" to functions)\n"
                            "x.json: units[1].tables.input: the table has entries but its read function 04 (Read Input Registers) "
                            "is not in functions: every read of it gets exception 01 (add \"0x04\" to functions)"));
}

// What a register map says besides the numbers reaches the entry.
void TestProfileLoader::mapMeanings()
{
    const ProfileLoadResult r = ProfileLoader::parse(unitWithTables(R"({"holding": [
        {"address": 0, "type": "u32", "kind": "status", "bits": {"0": "run", "31": "fault"}},
        {"address": 2, "kind": "enumeration", "enum": {"0": "off", "0x1": "on", "2": "fault"}},
        {"address": 3, "type": "i16", "kind": "measurement", "min": -40, "max": 125, "notImplemented": "0x8000"},
        {"address": 4, "type": "f32-cdab", "notImplemented": "NaN"},
        {"address": 6, "type": "ascii", "length": 8, "padding": "space", "value": "SN42", "kind": "constant"},
        {"address": 10, "count": 2, "kind": "reserved"}],
        "coils": [{"address": 0, "kind": "setting"}]})"),
                                                     QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    const UnitProfile &u = r.profile.units.at(0);
    const TableEntry *bits = u.entryAt(SimTable::HoldingRegisters, 0);
    QCOMPARE(bits->kind, ValueKind::Status);
    QCOMPARE(bits->bitNames, (QMap<int, QString>{{0, QStringLiteral("run")}, {31, QStringLiteral("fault")}}));
    const TableEntry *state = u.entryAt(SimTable::HoldingRegisters, 2);
    QCOMPARE(state->enumNames.value(1), QStringLiteral("on"));
    QCOMPARE(state->enumNames.size(), 3);
    const TableEntry *temperature = u.entryAt(SimTable::HoldingRegisters, 3);
    QCOMPARE(temperature->min, std::optional<double>(-40));
    QCOMPARE(temperature->max, std::optional<double>(125));
    QCOMPARE(temperature->notImplemented, std::optional<quint64>(0x8000));
    QVERIFY(temperature->isNotImplemented(std::array<quint16, 1>{0x8000}));
    QVERIFY(!temperature->isNotImplemented(std::array<quint16, 1>{0x7FFF}));
    const TableEntry *flow = u.entryAt(SimTable::HoldingRegisters, 4);
    QVERIFY(flow->notImplementedNaN);
    QVERIFY(flow->isNotImplemented(std::array<quint16, 2>{0x0000, 0x7FC0})); // CDAB NaN
    QVERIFY(!flow->isNotImplemented(std::array<quint16, 2>{0x0000, 0x3F80}));
    const TableEntry *serial = u.entryAt(SimTable::HoldingRegisters, 6);
    QCOMPARE(serial->stringLength, 8);
    QCOMPARE(serial->count, 4);
    QCOMPARE(serial->valueCount(), 4); // four registers; one string for the exports
    QCOMPARE(serial->initial, words({0x534E, 0x3432, 0x2020, 0x2020}));
    QCOMPARE(u.entryAt(SimTable::HoldingRegisters, 10)->kind, ValueKind::Reserved);
    QCOMPARE(u.entryAt(SimTable::Coils, 0)->kind, ValueKind::Setting);
    // Without the new keys nothing changes.
    QCOMPARE(u.entryAt(SimTable::HoldingRegisters, 2)->format, RegisterFormat());
    QVERIFY(!u.gapReadsZeros);
    QVERIFY(u.sharedTables.isEmpty());
}

void TestProfileLoader::scaleRegister_data()
{
    QTest::addColumn<int>("exponent");
    QTest::addColumn<double>("value");
    QTest::addColumn<QList<quint16>>("raw");
    QTest::newRow("10^-1: 230.4 is raw 2304") << -1 << 230.4 << words({2304});
    QTest::newRow("10^-3: 1.234 is raw 1234") << -3 << 1.234 << words({1234});
    QTest::newRow("10^0: 17 is raw 17") << 0 << 17.0 << words({17});
    QTest::newRow("10^2: 4500 is raw 45") << 2 << 4500.0 << words({45});
}

// A SunSpec scale factor: the entry's scale is 10 to the power of another register, whichever
// comes first in the file.
void TestProfileLoader::scaleRegister()
{
    QFETCH(int, exponent);
    QFETCH(double, value);
    QFETCH(QList<quint16>, raw);
    const QByteArray json = unitWithTables(QStringLiteral(R"({"holding": [
        {"address": 0, "name": "V", "scaleRegister": 5, "value": %1},
        {"address": 5, "name": "V_SF", "type": "i16", "value": %2, "kind": "constant"}]})")
                                               .arg(value, 0, 'g', 17).arg(exponent).toUtf8().constData());
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    const TableEntry *v = r.profile.units.at(0).entryAt(SimTable::HoldingRegisters, 0);
    QCOMPARE(v->scaleRegister, std::optional<quint16>(5));
    QCOMPARE(v->scale, std::pow(10.0, exponent));
    QCOMPARE(v->initial, raw);
    QCOMPARE(r.profile.units.at(0).entries.at(0).address, quint16(0)); // still in address order
}

void TestProfileLoader::sharedTablesAndGaps_data()
{
    QTest::addColumn<QByteArray>("unitKeys");
    QTest::addColumn<int>("table");
    QTest::addColumn<int>("start");
    QTest::addColumn<int>("count");
    QTest::addColumn<QList<quint16>>("expected"); // empty: the read fails (exception 02)
    const QByteArray shared = R"("sharedTables": {"input": "holding", "discrete": "coils"})";
    const int holding = int(SimTable::HoldingRegisters), input = int(SimTable::InputRegisters);
    const int coils = int(SimTable::Coils), discrete = int(SimTable::DiscreteInputs);
    QTest::newRow("03 reads holding") << shared << holding << 0 << 2 << words({11, 12});
    QTest::newRow("04 reads the same registers") << shared << input << 0 << 2 << words({11, 12});
    QTest::newRow("02 reads the coils") << shared << discrete << 0 << 2 << words({1, 0});
    QTest::newRow("01 reads the coils") << shared << coils << 0 << 2 << words({1, 0});
    QTest::newRow("not shared: 04 has nothing") << QByteArray(R"("gapReads": "exception")") << input << 0 << 1 << words({});
    QTest::newRow("gap: exception 02") << QByteArray(R"("gapReads": "exception")") << holding << 0 << 6 << words({});
    QTest::newRow("gap: zeros") << QByteArray(R"("gapReads": "zeros")") << holding << 0 << 6 << words({11, 12, 0, 0, 0, 15});
    QTest::newRow("gap: zeros, but 02 past the end") << QByteArray(R"("gapReads": "zeros")") << holding << 5 << 2 << words({});
    QTest::newRow("gap: zeros, but 02 past the last coil") << QByteArray(R"("gapReads": "zeros")") << coils << 0 << 3 << words({});
    QTest::newRow("gap: zeros through a shared table") << QByteArray(R"("gapReads": "zeros", )" + shared) << input << 1 << 4
                                                       << words({12, 0, 0, 0});
}

// The simulator's unit answers as the profile says: a table read through another function, and
// zeros (or exception 02) over the gaps of a map.
void TestProfileLoader::sharedTablesAndGaps()
{
    QFETCH(QByteArray, unitKeys);
    QFETCH(int, table);
    QFETCH(int, start);
    QFETCH(int, count);
    QFETCH(QList<quint16>, expected);
    const QByteArray json = R"({"name": "t", "units": [{"id": 1, )" + unitKeys + R"(, "tables": {
        "holding": [{"address": 0, "values": [11, 12]}, {"address": 5, "value": 15}],
        "coils": [{"address": 0, "values": [true, false]}]}}]})";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("p.json"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    SimUnit unit(1);
    QString error;
    QVERIFY2(ProfileApplier::apply(r.profile.units.at(0), &unit, &error), qPrintable(error));
    QCOMPARE(unit.values(SimTable(table), start, count), expected);
}

QTEST_GUILESS_MAIN(TestProfileLoader)
#include "tst_profileloader.moc"
