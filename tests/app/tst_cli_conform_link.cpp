// mbscope conform (issue 29) when the link drops or the device dies under the run, against
// tests/peers/fault_server.py (--drop-at: a connection closed instead of an answer, the device
// serving on, as a server restarted in a loop; --die-at: the port closed for good). The scorecard
// never judges what it could not ask: a function the survey could not reach is surveyed again
// after reconnecting, or marked "not surveyed" and its checks skipped; a device gone mid-run is
// said once (the check that met it), the rest "not judged", and the run is called cut short.
// Also the deviation "answering broadcasts" (a profile's "answersBroadcasts") caught by
// serial.broadcast, with nothing else failing (tst_cli_conform.cpp is at its size limit).

#include "clitest.h"
#include "peerprocess.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope::testcli;
using mbscope::testpeers::PeerProcess;

namespace {

const QStringList kTimeout{QStringLiteral("--timeout"), QStringLiteral("300ms"), QStringLiteral("--samples"), QStringLiteral("5")};

// id -> verdict, in the battery's order.
QList<QPair<QString, QJsonObject>> checksOf(const QJsonObject &card)
{
    QList<QPair<QString, QJsonObject>> out;
    for (const QJsonValue &v : card.value(QStringLiteral("checks")).toArray())
        out.append({v.toObject().value(QStringLiteral("id")).toString(), v.toObject()});
    return out;
}

QStringList withVerdict(const QJsonObject &card, const QString &verdict)
{
    QStringList ids;
    for (const auto &c : checksOf(card)) {
        if (c.second.value(QStringLiteral("verdict")).toString() == verdict)
            ids.append(c.first);
    }
    ids.sort();
    return ids;
}

// unit 1, every table 0-99, device identification; %1: whether it answers broadcasts.
const char kProfile[] = R"({
  "name": "broadcaster",
  "answersBroadcasts": %1,
  "units": [{
    "id": 1,
    "tables": {
      "coils": [{"address": 0, "count": 100, "values": [1, 0, 0, 1, 1]}],
      "discrete": [{"address": 0, "count": 100, "values": [0, 1, 1, 0, 1]}],
      "input": [{"address": 0, "count": 100}],
      "holding": [{"address": 0, "count": 100}]
    },
    "deviceIdentification": {"objects": {"VendorName": "mbscope", "ProductCode": "BC-1", "MajorMinorRevision": "1.0"}}
  }]
})";

} // namespace

class TestCliConformLink : public QObject
{
    Q_OBJECT

    CliResult conform(const QStringList &peerExtra, PeerProcess &peer, QString *error)
    {
        if (!peer.start(mbscope::testpeers::systemPython(),
                        QStringList{mbscope::testpeers::peersDir() + QStringLiteral("/fault_server.py"), QStringLiteral("tcp")} + peerExtra)) {
            *error = peer.error();
            return {};
        }
        return runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), QStringLiteral("tcp://") + peer.where(),
                                      QStringLiteral("--json")}
                          + kTimeout);
    }

private Q_SLOTS:
    // A slave that answers unit 0 on a serial line (rtu-tcp: RTU frames, the serial rules): caught
    // by serial.broadcast, and no other check fails; the same device without the deviation passes.
    void answeringBroadcastsCaught_data()
    {
        QTest::addColumn<bool>("answers");
        QTest::addColumn<QStringList>("failing");
        QTest::newRow("answers broadcasts") << true << QStringList{"serial.broadcast"};
        QTest::newRow("does not") << false << QStringList{};
    }
    void answeringBroadcastsCaught()
    {
        QFETCH(bool, answers);
        QFETCH(QStringList, failing);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("broadcaster.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QString::fromLatin1(kProfile).arg(answers ? QStringLiteral("true") : QStringLiteral("false")).toUtf8());
        f.close();
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet"),
                            QStringLiteral("--profile"), path},
                           &error),
                 qPrintable(error));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--json"),
                                                   QStringLiteral("--profile"), path, QStringLiteral("--writable"), QStringLiteral("holding:10-13"),
                                                   QStringLiteral("--writable"), QStringLiteral("coils:10-17")}
                                       + kTimeout);
        QVERIFY2(r.finished, r.describe());
        const QJsonObject card = r.json();
        QCOMPARE(withVerdict(card, QStringLiteral("failed")), failing);
        QCOMPARE(withVerdict(card, QStringLiteral("error")), QStringList{});
        QCOMPARE(r.exitCode, failing.isEmpty() ? 0 : 1);
        if (answers) {
            for (const auto &c : checksOf(card)) {
                if (c.first == QLatin1String("serial.broadcast")) {
                    const QString sentence = c.second.value(QStringLiteral("sentence")).toString();
                    QVERIFY2(sentence.contains(QLatin1String("requires that no slave answer a broadcast")), qPrintable(sentence));
                    QVERIFY2(!c.second.value(QStringLiteral("answer")).toString().isEmpty(), qPrintable(sentence));
                }
            }
        }
    }

    void initTestCase()
    {
        if (mbscope::testpeers::systemPython().isEmpty())
            QSKIP("no python3 for tests/peers/fault_server.py");
    }

    // The connection closes under the survey's 6th request (08) and the server serves on: the
    // survey asks 08 again on a new connection, and the scorecard is the one of a run without the
    // drop (before: 08 stayed unknown and its checks ran and failed on exception 01).
    void surveyAsksAgainAfterADrop()
    {
        PeerProcess steady;
        QString error;
        const CliResult base = conform({}, steady, &error);
        QVERIFY2(base.finished, qPrintable(error + base.describe()));
        PeerProcess dropping;
        const CliResult r = conform({QStringLiteral("--drop-at"), QStringLiteral("6")}, dropping, &error);
        QVERIFY2(r.finished, qPrintable(error + r.describe()));
        QVERIFY(dropping.waitForLine("SERVED 6 drop", 5000));
        const QJsonObject card = r.json();
        const QJsonObject baseCard = base.json();
        QCOMPARE(card.value(QStringLiteral("functions")).toObject().value(QStringLiteral("08")).toString(), QStringLiteral("unsupported"));
        QCOMPARE(card.value(QStringLiteral("functions")), baseCard.value(QStringLiteral("functions")));
        QCOMPARE(withVerdict(card, QStringLiteral("failed")), withVerdict(baseCard, QStringLiteral("failed")));
        QCOMPARE(withVerdict(card, QStringLiteral("skipped")), withVerdict(baseCard, QStringLiteral("skipped")));
        QCOMPARE(r.exitCode, base.exitCode);
        QVERIFY(!card.contains(QStringLiteral("link_lost")));
    }

    // The connection closes under every ask of the survey's 07 (requests 5, 6 and 7: the first and
    // both asks again), the server serving on, as libmodbus 3.1.6's unit-test server restarted in a
    // loop does: the device's reply to 07 is no answer at all, so 07 is "silent" and
    // exception.unsupported-function fails naming it (before: 07 was left out of the functions and
    // the check passed, "the device supports every function surveyed"); nothing else changes.
    void surveyFunctionClosedEveryTime()
    {
        PeerProcess steady;
        QString error;
        const CliResult base = conform({}, steady, &error);
        QVERIFY2(base.finished, qPrintable(error + base.describe()));
        PeerProcess dropping;
        const CliResult r = conform({QStringLiteral("--drop-at"), QStringLiteral("5,6,7")}, dropping, &error);
        QVERIFY2(r.finished, qPrintable(error + r.describe()));
        QVERIFY(dropping.waitForLine("SERVED 7 drop", 5000));
        const QJsonObject card = r.json();
        const QJsonObject baseCard = base.json();
        QCOMPARE(card.value(QStringLiteral("functions")).toObject().value(QStringLiteral("07")).toString(), QStringLiteral("silent"));
        QStringList failed = withVerdict(baseCard, QStringLiteral("failed"));
        failed.append(QStringLiteral("exception.unsupported-function"));
        failed.sort();
        failed.removeDuplicates();
        QCOMPARE(withVerdict(card, QStringLiteral("failed")), failed);
        QCOMPARE(withVerdict(card, QStringLiteral("error")), QStringList{});
        for (const auto &c : checksOf(card)) {
            if (c.first == QLatin1String("exception.unsupported-function")) {
                const QString sentence = c.second.value(QStringLiteral("sentence")).toString();
                QVERIFY2(sentence.contains(QLatin1String("no answer at all to function 07")), qPrintable(sentence));
                QVERIFY2(sentence.contains(QLatin1String("closed the connection")), qPrintable(sentence));
            }
        }
        QCOMPARE(r.exitCode, 1);
        QVERIFY(!card.contains(QStringLiteral("link_lost")));
    }

    // Every answer carries a wrong transaction id (the simulator's wrongTransactionId fault): no
    // answer can be matched to its request, so diag.subfunctions is not judged, saying why
    // (before: it passed "offered: none; not offered: 02 ...", what nothing it read supports);
    // nor are exception.unsupported-function and promise.functions, whose passes would claim
    // every function answers (before: "the device supports every function surveyed").
    void subfunctionsUnmatchedNotJudged()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("faults.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"seed": 1, "rules": [{"kind": "wrongTransactionId", "delta": 1}]})");
        f.close();
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet"),
                            QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--faults"), path},
                           &error),
                 qPrintable(error));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--json"),
                                                   QStringLiteral("--profile"), QStringLiteral("conformance")}
                                       + kTimeout);
        QVERIFY2(r.finished, r.describe());
        int seen = 0;
        for (const auto &c : checksOf(r.json())) {
            const QString sentence = c.second.value(QStringLiteral("sentence")).toString();
            // Nothing the survey asked was matched: no pass claims every function answers.
            if (c.first == QLatin1String("exception.unsupported-function") || c.first == QLatin1String("promise.functions")) {
                ++seen;
                QCOMPARE(c.second.value(QStringLiteral("verdict")).toString(), QStringLiteral("skipped"));
                QVERIFY2(sentence.startsWith(QLatin1String("not judged: no answer could be matched to the survey's request: 03, 04")), qPrintable(sentence));
            }
            if (c.first != QLatin1String("diag.subfunctions"))
                continue;
            ++seen;
            QCOMPARE(c.second.value(QStringLiteral("verdict")).toString(), QStringLiteral("skipped"));
            QVERIFY2(sentence.startsWith(QLatin1String("not judged: no answer could be matched")), qPrintable(sentence));
            QVERIFY2(!sentence.contains(QLatin1String("not offered")), qPrintable(sentence));
        }
        QVERIFY2(seen == 3, r.describe());
    }

    // The device dies at request dieAt (its port closed): one check is an error saying the link
    // was lost; every check after it is skipped as not judged; no check fails on a link error; the
    // functions the survey could not reach are "not surveyed"; the run is cut short (exit 1), and
    // the text report says so.
    void deviceDiesMidRun_data()
    {
        QTest::addColumn<int>("dieAt");
        QTest::addColumn<QStringList>("notSurveyed");
        QTest::newRow("during the survey") << 6 << QStringList{"08", "0B", "0C", "11", "2B"};
        QTest::newRow("at the survey's 07") << 5 << QStringList{"07", "08", "0B", "0C", "11", "2B"};
        QTest::newRow("during the checks") << 20 << QStringList{};
    }
    void deviceDiesMidRun()
    {
        QFETCH(int, dieAt);
        QFETCH(QStringList, notSurveyed);
        PeerProcess peer;
        QString error;
        const CliResult r = conform({QStringLiteral("--die-at"), QString::number(dieAt)}, peer, &error);
        QVERIFY2(r.finished, qPrintable(error + r.describe()));
        QCOMPARE(r.exitCode, 1);
        const QJsonObject card = r.json();
        QCOMPARE(card.value(QStringLiteral("passed")).toBool(true), false);
        const QJsonObject functions = card.value(QStringLiteral("functions")).toObject();
        QStringList unsurveyed;
        for (auto it = functions.begin(); it != functions.end(); ++it) {
            if (it.value().toString() == QLatin1String("not surveyed"))
                unsurveyed.append(it.key());
        }
        QCOMPARE(unsurveyed, notSurveyed);
        const QStringList errors = withVerdict(card, QStringLiteral("error"));
        QCOMPARE(errors.size(), 1);
        const QString lostAt = errors.constFirst();
        const QJsonObject lost = card.value(QStringLiteral("link_lost")).toObject();
        QCOMPARE(lost.value(QStringLiteral("check")).toString(), lostAt);
        bool after = false;
        int notJudged = 0;
        for (const auto &c : checksOf(card)) {
            const QString sentence = c.second.value(QStringLiteral("sentence")).toString();
            QVERIFY2(!sentence.contains(QLatin1String("link error")) && !sentence.contains(QLatin1String("the link failed")),
                     qPrintable(c.first + QStringLiteral(": ") + sentence));
            // A function the survey could not ask leaves exception.unsupported-function unjudged:
            // its pass would claim every function answers (before: passed, "...; not surveyed: 07...").
            if (c.first == QLatin1String("exception.unsupported-function") && !notSurveyed.isEmpty()) {
                QCOMPARE(c.second.value(QStringLiteral("verdict")).toString(), QStringLiteral("skipped"));
                QVERIFY2(sentence.startsWith(QLatin1String("not judged: ")), qPrintable(sentence));
                QVERIFY2(sentence.contains(notSurveyed.join(QLatin1String(", "))), qPrintable(sentence));
            }
            if (c.first == lostAt) {
                QVERIFY2(sentence.startsWith(QLatin1String("not judged: the link was lost during this check")), qPrintable(sentence));
                after = true;
            } else if (after) {
                ++notJudged;
                QCOMPARE(c.second.value(QStringLiteral("verdict")).toString(), QStringLiteral("skipped"));
                QCOMPARE(sentence, QStringLiteral("not judged: the link was lost at check %1").arg(lostAt));
            }
        }
        QVERIFY(notJudged > 10);
        QCOMPARE(lost.value(QStringLiteral("not_judged")).toInt(), notJudged);
        // Before the loss, nothing failed that the steady server passes: its own failures at most.
        PeerProcess steady;
        const CliResult base = conform({}, steady, &error);
        QVERIFY2(base.finished, qPrintable(error + base.describe()));
        for (const QString &id : withVerdict(card, QStringLiteral("failed")))
            QVERIFY2(withVerdict(base.json(), QStringLiteral("failed")).contains(id), qPrintable(id));

        // The text report: the summary says the run was cut short.
        PeerProcess again;
        QVERIFY2(again.start(mbscope::testpeers::systemPython(),
                             {mbscope::testpeers::peersDir() + QStringLiteral("/fault_server.py"), QStringLiteral("tcp"), QStringLiteral("--die-at"),
                              QString::number(dieAt)}),
                 qPrintable(again.error()));
        const CliResult text = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), QStringLiteral("tcp://") + again.where()} + kTimeout);
        QCOMPARE(text.exitCode, 1);
        QVERIFY2(text.outText().contains(QStringLiteral("verdict    cut short: the link was lost at check %1").arg(lostAt)), text.describe());
    }
};

QTEST_GUILESS_MAIN(TestCliConformLink)
#include "tst_cli_conform_link.moc"
