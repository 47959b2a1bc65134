// WatchFactory: watches from the composer's read request and from a device profile's unit.
#include "watch/watchfactory.h"

#include "profile/profileloader.h"
#include "protocol/adubuilder.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestWatchFactory : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void fromTheRosRaoRead();
    void fromAnMbapRead();
    void refusesWritesAndShortRequests_data();
    void refusesWritesAndShortRequests();
    void namesAreUnique();
    void fromProfiles_data();
    void fromProfiles();
    void fromProfileHonoursMaxQuantity();
};

void TestWatchFactory::fromTheRosRaoRead()
{
    // The RosRao detector's read as the lab types it: unit 1, 03, 0x0079, 22 registers, CRC.
    const QByteArray adu = QByteArray::fromHex("01030079001615DD");
    const WatchFromRequest made = WatchFactory::fromRequest(adu, Framing::Rtu, QStringLiteral("rtu-tcp://127.0.0.1:4001"), 500, {});
    QVERIFY2(made.error.isEmpty(), qPrintable(made.error));
    QCOMPARE(made.watch.unit, quint8(1));
    QCOMPARE(made.watch.function, quint8(3));
    QCOMPARE(made.watch.address, quint16(0x79));
    QCOMPARE(made.watch.quantity, quint16(22));
    QCOMPARE(made.watch.intervalMs, qint64(500));
    QCOMPARE(made.watch.target, QStringLiteral("rtu-tcp://127.0.0.1:4001"));
    QCOMPARE(made.watch.name, QStringLiteral("unit 1 holding 0x0079 x22"));
}

void TestWatchFactory::fromAnMbapRead()
{
    const QByteArray adu = QByteArray::fromHex("000100000006110100000010");
    const WatchFromRequest made = WatchFactory::fromRequest(adu, Framing::Tcp, QStringLiteral("tcp://127.0.0.1:5020"), 1000, {});
    QVERIFY2(made.error.isEmpty(), qPrintable(made.error));
    QCOMPARE(made.watch.unit, quint8(0x11));
    QCOMPARE(made.watch.function, quint8(1));
    QCOMPARE(made.watch.quantity, quint16(16));
}

void TestWatchFactory::refusesWritesAndShortRequests_data()
{
    QTest::addColumn<QByteArray>("adu");
    QTest::addColumn<QString>("expected");
    QTest::newRow("write 06") << QByteArray::fromHex("010600010003") << QStringLiteral("function 0x06");
    QTest::newRow("empty") << QByteArray() << QStringLiteral("no request");
    QTest::newRow("126 registers") << QByteArray::fromHex("01030000007E") << QStringLiteral("1 to 125");
}

void TestWatchFactory::refusesWritesAndShortRequests()
{
    QFETCH(QByteArray, adu);
    QFETCH(QString, expected);
    const WatchFromRequest made = WatchFactory::fromRequest(AduBuilder::complete(adu.mid(1), AduOptions{Framing::Rtu, quint8(1), 1, 0}),
                                                            Framing::Rtu, QStringLiteral("tcp://h:1"), 1000, {});
    if (adu.isEmpty()) {
        const WatchFromRequest none = WatchFactory::fromRequest(adu, Framing::Rtu, QStringLiteral("tcp://h:1"), 1000, {});
        QVERIFY2(none.error.contains(expected), qPrintable(none.error));
        return;
    }
    QVERIFY2(made.error.contains(expected), qPrintable(made.error));
}

void TestWatchFactory::namesAreUnique()
{
    QCOMPARE(WatchFactory::uniqueName(QStringLiteral("a"), {}), QStringLiteral("a"));
    QCOMPARE(WatchFactory::uniqueName(QStringLiteral("a"), {QStringLiteral("a"), QStringLiteral("a 2")}), QStringLiteral("a 3"));
    QCOMPARE(WatchFactory::uniqueName(QString(), {}), QStringLiteral("watch"));
}

void TestWatchFactory::fromProfiles_data()
{
    QTest::addColumn<QString>("profile");
    QTest::newRow("rosrao-gamma") << QStringLiteral("rosrao-gamma");
    QTest::newRow("m221-plc") << QStringLiteral("m221-plc");
    QTest::newRow("arduino-rs485") << QStringLiteral("arduino-rs485");
}

// Every value of every entry of the unit lands in exactly one watch, each watch one legal read.
void TestWatchFactory::fromProfiles()
{
    QFETCH(QString, profile);
    const ProfileLoadResult loaded = ProfileLoader::load(profile);
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    const UnitProfile &unit = loaded.profile.units.constFirst();
    const QList<WatchDefinition> watches = WatchFactory::fromProfile(loaded.profile, unit.id, QStringLiteral("tcp://127.0.0.1:502"), 250, {});
    QVERIFY(!watches.isEmpty());
    QStringList names;
    int points = 0;
    for (const WatchDefinition &watch : watches) {
        QVERIFY(!names.contains(watch.name));
        names << watch.name;
        QVERIFY(watch.quantity >= 1);
        QVERIFY(watch.quantity <= (watch.function <= 2 ? WatchFactory::kMaxBits : WatchFactory::kMaxRegisters));
        QCOMPARE(watch.intervalMs, qint64(250));
        QVERIFY(watch.profileBlock.startsWith(profile));
        for (const WatchPoint &point : watch.points) {
            QVERIFY(point.address >= watch.address);
            QVERIFY(point.address + point.format.registerCount() <= watch.address + watch.quantity
                    || watch.function <= 2);
        }
        points += int(watch.points.size());
    }
    // Every value of every entry, those longer than one read included (issue 26 item 5: the
    // M221's 8000 holding registers were left out).
    int expected = 0;
    for (const TableEntry &entry : unit.entries)
        expected += entry.valueCount();
    QCOMPARE(points, expected);
}

// A device that takes 16 registers a read (limits.maxQuantity, as the scans record it): its 40
// holding registers become reads of 16, 16 and 8 (before, one read of 40, refused with 03), its
// coils (no limit of theirs) stay one read.
void TestWatchFactory::fromProfileHonoursMaxQuantity()
{
    const ProfileLoadResult loaded = ProfileLoader::parse(R"({"name": "narrow", "limits": {"maxQuantity": {"0x03": 16}},
        "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 40}], "coils": [{"address": 0, "count": 40}]}}]})",
                                                          QStringLiteral("narrow.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    const QList<WatchDefinition> watches = WatchFactory::fromProfile(loaded.profile, 1, QStringLiteral("tcp://127.0.0.1:502"), 250, {});
    QList<std::pair<int, int>> holding;
    int coilReads = 0;
    int holdingPoints = 0;
    for (const WatchDefinition &watch : watches) {
        if (watch.function == 3) {
            holding.append({watch.address, watch.quantity});
            holdingPoints += int(watch.points.size());
        } else if (watch.function == 1) {
            ++coilReads;
        }
    }
    QCOMPARE(holding, (QList<std::pair<int, int>>{{0, 16}, {16, 16}, {32, 8}}));
    QCOMPARE(holdingPoints, 40);
    QCOMPARE(coilReads, 1);
}

QTEST_MAIN(TestWatchFactory)
#include "tst_watchfactory.moc"
