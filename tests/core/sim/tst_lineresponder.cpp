// Delimited protocols served from a table of request patterns (LineResponder, LineTemplate):
// the SCADA lab's '$' ... '#' protocol as its paper publishes it, LG Master-K's binary ENQ/EOT
// frames with a BCC, writes, unknown units and frames no rule matches.

#include "profile/linetemplate.h"
#include "profile/profileloader.h"
#include "protocol/delimitedframer.h"
#include "sim/lineresponder.h"
#include "sim/profileapplier.h"
#include "sim/simunit.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestLineResponder : public QObject
{
    Q_OBJECT
private:
    DeviceProfile m_profile;
    QObject m_owner;
    QList<SimUnit *> m_units;

    LineAnswer ask(const QByteArray &frame)
    {
        return LineResponder::respond(m_profile.delimited, frame, [this](int id) -> SimUnit * {
            for (SimUnit *u : std::as_const(m_units)) {
                if (id < 0 || u->id() == id)
                    return u;
            }
            return nullptr;
        });
    }

private Q_SLOTS:
    void init()
    {
        const ProfileLoadResult r = ProfileLoader::load(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/scada-rs485.json"));
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        m_profile = r.profile;
        qDeleteAll(m_units);
        QString error;
        m_units = ProfileApplier::createUnits(m_profile, &m_owner, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    // The published exchange: '$01R#' answered with eight temperatures and eight lamp states.
    void publishedRead()
    {
        const LineAnswer a = ask("$01R#");
        QVERIFY(a.answers);
        QCOMPARE(a.unitId, 1);
        QCOMPARE(a.bytes, QByteArray("$01 293 295 363 353 342 335 329 347 0 1 0 0 0 1 0 0 #"));
        QCOMPARE(ask("$03R#").bytes, QByteArray("$03 0 0 0 0 0 0 0 0 #"));
    }

    // '$01WB00#' switches port B bit 0 of slave 01 off; bit 1 on, then read back.
    void writeThenRead()
    {
        LineAnswer a = ask("$01WB11#");
        QVERIFY(a.answers);
        QCOMPARE(a.bytes, QByteArray("$01WB11#"));
        QCOMPARE(a.note, QStringLiteral("coils 1 = 1"));
        QCOMPARE(ask("$01WB50#").note, QStringLiteral("coils 5 = 0"));
        QCOMPARE(ask("$01R#").bytes, QByteArray("$01 293 295 363 353 342 335 329 347 0 1 0 0 0 0 0 0 #"));
        QCOMPARE(ask("$02R#").bytes, QByteArray("$02 293 295 363 353 342 335 329 347 0 1 0 0 0 1 0 0 #"));
    }

    void noMatchNoAnswer_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QString>("note");
        QTest::newRow("unknown command") << QByteArray("$01X#") << QStringLiteral("no rule's request pattern matches: ignored");
        QTest::newRow("slave 04") << QByteArray("$04R#") << QStringLiteral("no rule's request pattern matches: ignored");
        QTest::newRow("part of a frame") << QByteArray("$01R#$02R#") << QStringLiteral("no rule's request pattern matches: ignored");
        QTest::newRow("write bit 8") << QByteArray("$01WB81#") << QStringLiteral("no rule's request pattern matches: ignored");
    }
    void noMatchNoAnswer()
    {
        QFETCH(QByteArray, frame);
        QFETCH(QString, note);
        const LineAnswer a = ask(frame);
        QVERIFY(!a.answers);
        QCOMPARE(a.note, note);
    }

    // A pattern naming a unit the profile lacks: matched, no answer, said so.
    void unitMissing()
    {
        const QByteArray json = "{\"name\": \"t\", \"units\": [{\"id\": 1}], \"delimited\": {\"rules\": "
                                "[{\"request\": \"\\\\$(?<unit>\\\\d\\\\d)R#\", \"answer\": \"ok\"}]}}";
        const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("t"));
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        m_profile = r.profile;
        const LineAnswer a = ask("$07R#");
        QVERIFY(a.matched && a.unitMissing && !a.answers);
        QCOMPARE(a.note, QStringLiteral("rule 0: no unit 7 here: ignored"));
    }

    // LG Master-K style binary frames: ENQ ... EOT with a BCC; the answer ACK ... ETX.
    void binaryFrames()
    {
        // ENQ is \u0005 and EOT \u0004 in JSON; ACK \u0006, ETX \u0003.
        const QByteArray json = "{\"name\": \"masterk\", \"units\": [{\"id\": 1, "
                                "\"tables\": {\"holding\": [{\"address\": 0, \"values\": [4660]}]}}], "
                                "\"delimited\": {\"rules\": [{\"request\": \"\\u0005(?<station>\\\\d\\\\d)RSS.*\\u0004\", "
                                "\"answer\": \"\\u0006{station}RSS{holding:0}\\u0003\"}]}}";
        const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("t"));
        QVERIFY2(r.ok, qPrintable(r.errorText()));
        m_profile = r.profile;
        qDeleteAll(m_units);
        m_units = ProfileApplier::createUnits(m_profile, &m_owner);
        const LineAnswer a = ask(QByteArray("\x05" "00RSS0106%MW000\x04"));
        QVERIFY2(a.answers, qPrintable(a.note));
        QCOMPARE(a.bytes, QByteArray("\x06" "00RSS4660\x03"));
        DelimitedFraming framing;
        framing.enabled = true;
        framing.checksum = DelimitedChecksum::Sum;
        const QByteArray sent = DelimitedFramer::complete(framing, a.bytes);
        QCOMPARE(sent.size(), a.bytes.size() + 1);
        QCOMPARE(quint8(sent.back()), DelimitedFramer::checksum(DelimitedChecksum::Sum, a.bytes));
    }

    void templates_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expanded"); // or the error
        QTest::newRow("literal braces") << QStringLiteral("{{x}}") << QStringLiteral("{x}");
        QTest::newRow("range") << QStringLiteral("[{holding:1-2}]") << QStringLiteral("[295 363]");
        QTest::newRow("hex address") << QStringLiteral("{holding:0x7}") << QStringLiteral("347");
        QTest::newRow("missing address") << QStringLiteral("{holding:8}") << QStringLiteral("{holding:8}: an address the unit does not have");
        QTest::newRow("stray brace") << QStringLiteral("a}") << QStringLiteral("character 2: '}' without '{' (write }} for a brace)");
    }
    void templates()
    {
        QFETCH(QString, text);
        QFETCH(QString, expanded);
        SimUnit *unit = m_units.first();
        QString error;
        const auto out = LineTemplate::expand(text, [](const QString &) { return QString(); },
                                              [unit](SimTable t, int first, int count) -> std::optional<QList<quint16>> {
                                                  const QList<quint16> v = unit->values(t, first, count);
                                                  if (v.isEmpty())
                                                      return std::nullopt;
                                                  return v;
                                              },
                                              &error);
        QCOMPARE(out.value_or(error), expanded);
    }
};

QTEST_GUILESS_MAIN(TestLineResponder)
#include "tst_lineresponder.moc"
