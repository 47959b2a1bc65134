// The conformance battery's settings and scorecard without a device: TableRange (--readable,
// --missing, --writable) read and refused with what is wrong and where; a profile's unit giving
// readable and missing addresses and the functions it promises; the check ids unique and each
// citing a clause; a scorecard's verdict and its JUnit cases.

#include "conformance/conformanceresult.h"
#include "conformance/conformancerunner.h"
#include "conformance/conformancesettings.h"
#include "profile/profileloader.h"
#include "session/junitreport.h"

#include <QtCore/QSet>
#include <QtTest/QtTest>

using namespace mbscope;

class TestConformanceSettings : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void rangeParses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("table");
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::newRow("one register") << "holding:121" << int(SimTable::HoldingRegisters) << 121 << 121;
        QTest::newRow("hex") << "holding:0x79" << int(SimTable::HoldingRegisters) << 121 << 121;
        QTest::newRow("coils range") << "coils:0-7" << int(SimTable::Coils) << 0 << 7;
        QTest::newRow("discrete") << "discrete:65535" << int(SimTable::DiscreteInputs) << 65535 << 65535;
        QTest::newRow("input") << "input:10-0x0B" << int(SimTable::InputRegisters) << 10 << 11;
    }
    void rangeParses()
    {
        QFETCH(QString, text);
        QFETCH(int, table);
        QFETCH(int, first);
        QFETCH(int, last);
        QString error;
        const std::optional<TableRange> r = TableRange::parse(text, &error);
        QVERIFY2(r, qPrintable(error));
        QCOMPARE(int(r->table), table);
        QCOMPARE(r->first, first);
        QCOMPARE(r->last, last);
    }

    void rangeRefused_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("says");
        QTest::newRow("no colon") << "holding" << "no ':' between the table and the address";
        QTest::newRow("unknown table") << "registers:1" << "'registers' is not a table";
        QTest::newRow("address too big") << "holding:65536" << "'65536' is not an address 0-65535";
        QTest::newRow("not a number") << "coils:x" << "'x' is not an address 0-65535";
        QTest::newRow("backwards") << "holding:9-3" << "the last address 3 is before the first 9";
        QTest::newRow("bad last") << "holding:3-" << "'' is not an address 0-65535";
    }
    void rangeRefused()
    {
        QFETCH(QString, text);
        QFETCH(QString, says);
        QString error;
        QVERIFY(!TableRange::parse(text, &error));
        QVERIFY2(error.contains(says), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("'%1'").arg(text)), qPrintable(error));
    }

    // The shipped conformance profile: holding, coils, discrete and input 0-99 then gaps.
    void profileGivesAddresses()
    {
        const ProfileLoadResult loaded = ProfileLoader::loadFile(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/conformance.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
        ConformanceSettings s;
        QString error;
        QVERIFY2(s.applyProfile(loaded.profile, &error), qPrintable(error));
        QCOMPARE(s.readable[int(SimTable::HoldingRegisters)], 0);
        QCOMPARE(s.missing[int(SimTable::Coils)], 100);
        QCOMPARE(s.missing[int(SimTable::InputRegisters)], 100);
        QVERIFY(s.promised);
        QVERIFY(s.promisedFunctions.contains(0x2B));
        s.unit = 9;
        QVERIFY(!s.applyProfile(loaded.profile, &error));
        QCOMPARE(error, QStringLiteral("profile conformance has no unit 9"));
    }

    void checksAreNamedAndCited()
    {
        QSet<QString> ids;
        for (const ConformanceCheck &c : ConformanceRunner::battery()) {
            QVERIFY2(!ids.contains(c.id), qPrintable(c.id));
            ids.insert(c.id);
            QVERIFY2(!c.clause.isEmpty() && !c.title.isEmpty() && c.run, qPrintable(c.id));
        }
        QVERIFY(ids.size() >= 40);
    }

    // Exit status 0 only when every mandatory check passed; a recommended failure is a
    // deviation, JUnit's failures are the mandatory ones.
    void verdictAndJUnit_data()
    {
        QTest::addColumn<int>("level");
        QTest::addColumn<int>("verdict");
        QTest::addColumn<bool>("passed");
        QTest::addColumn<QString>("element");
        QTest::newRow("mandatory passed") << int(CheckLevel::Mandatory) << int(CheckVerdict::Passed) << true << "";
        QTest::newRow("mandatory failed") << int(CheckLevel::Mandatory) << int(CheckVerdict::Failed) << false << "<failure";
        QTest::newRow("recommended failed") << int(CheckLevel::Recommended) << int(CheckVerdict::Failed) << true << "deviation";
        QTest::newRow("skipped") << int(CheckLevel::Mandatory) << int(CheckVerdict::Skipped) << true << "<skipped";
        QTest::newRow("error") << int(CheckLevel::Mandatory) << int(CheckVerdict::Error) << false << "<error";
    }
    void verdictAndJUnit()
    {
        QFETCH(int, level);
        QFETCH(int, verdict);
        QFETCH(bool, passed);
        QFETCH(QString, element);
        ConformanceResult result;
        result.target = QStringLiteral("tcp://127.0.0.1:502");
        CheckResult c;
        c.id = QStringLiteral("read.03.quantity-zero");
        c.title = QStringLiteral("quantity 0 gets exception 03");
        c.clause = QStringLiteral("Application Protocol V1.1b3, 6.3");
        c.level = CheckLevel(level);
        c.verdict = CheckVerdict(verdict);
        c.sentence = QStringLiteral("what happened");
        result.checks.append(c);
        QCOMPARE(result.passed(), passed);
        const QByteArray xml = JUnitReport::toXml(result.toJUnit());
        QVERIFY(xml.contains("name=\"read.03.quantity-zero\""));
        if (element.isEmpty())
            QVERIFY(!xml.contains("<failure") && !xml.contains("<skipped") && !xml.contains("<error"));
        else
            QVERIFY2(xml.contains(element.toUtf8()), xml.constData());
        QCOMPARE(result.toJson().value(QStringLiteral("passed")).toBool(), result.passed());
    }
};

QTEST_GUILESS_MAIN(TestConformanceSettings)
#include "tst_conformancesettings.moc"
