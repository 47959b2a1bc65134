// mbscope conform (issue 29) as users run it, against `mbscope simulate`: the shipped conformance
// profile passes every mandatory check on tcp and rtu-tcp; each deviation the simulator can be
// made to commit (its fault rules, and a unit script that answers wrongly) is caught by the check
// named for it, and the set of checks that fail is exactly the expected one, so that no check
// fails falsely. Also: the scorecard's JSON and JUnit, usage errors, an unreachable target.

#include "clitest.h"
#include "pacedline.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QProcess>
#include <QtCore/QSet>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QXmlStreamReader>
#include <QtTest/QtTest>

#include <algorithm>

using namespace mbscope::testcli;

namespace {

// A small device for the script rows: unit 1, every table 0-99, device identification.
const char kProfile[] = R"({
  "name": "deviant",
  "units": [{
    "id": 1,
    "script": "deviant.js",
    "tables": {
      "coils": [{"address": 0, "count": 100, "values": [1, 0, 0, 1, 1]}],
      "discrete": [{"address": 0, "count": 100, "values": [0, 1, 1, 0, 1]}],
      "input": [{"address": 0, "count": 100}],
      "holding": [{"address": 0, "count": 100}]
    },
    "deviceIdentification": {"objects": {"VendorName": "mbscope", "ProductCode": "DV-1", "MajorMinorRevision": "1.0"}}
  }]
})";

// The ids of the checks whose verdict is "failed" in a scorecard.
QStringList failedIds(const QJsonObject &card)
{
    QStringList ids;
    for (const QJsonValue &v : card.value(QStringLiteral("checks")).toArray()) {
        const QJsonObject c = v.toObject();
        if (c.value(QStringLiteral("verdict")).toString() == QLatin1String("failed"))
            ids.append(c.value(QStringLiteral("id")).toString());
    }
    ids.sort();
    return ids;
}

QJsonObject checkOf(const QJsonObject &card, const QString &id)
{
    for (const QJsonValue &v : card.value(QStringLiteral("checks")).toArray()) {
        if (v.toObject().value(QStringLiteral("id")).toString() == id)
            return v.toObject();
    }
    return {};
}

const QStringList kTimeout{QStringLiteral("--timeout"), QStringLiteral("300ms"), QStringLiteral("--samples"), QStringLiteral("5")};

} // namespace

class TestCliConform : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void shippedProfilePasses_data()
    {
        QTest::addColumn<QString>("listen");
        QTest::newRow("tcp") << "tcp://127.0.0.1:0";
        QTest::newRow("rtu-tcp") << "rtu-tcp://127.0.0.1:0";
    }
    void shippedProfilePasses()
    {
        QFETCH(QString, listen);
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                            listen, QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const QString junit = m_dir.filePath(QStringLiteral("conform-%1.xml").arg(QString::fromLatin1(QTest::currentDataTag())));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--profile"),
                                                   QStringLiteral("conformance"), QStringLiteral("--writable"), QStringLiteral("holding:10-13"),
                                                   QStringLiteral("--writable"), QStringLiteral("coils:10-17"), QStringLiteral("--json"),
                                                   QStringLiteral("--junit"), junit}
                                       + kTimeout);
        QVERIFY2(r.finished, r.describe());
        const QJsonObject card = r.json();
        QVERIFY2(failedIds(card).isEmpty(), qPrintable(failedIds(card).join(QLatin1Char(' ')) + QLatin1Char('\n') + r.outText()));
        QVERIFY2(r.exitCode == 0, r.describe());
        QCOMPARE(card.value(QStringLiteral("passed")).toBool(), true);
        QCOMPARE(card.value(QStringLiteral("counts")).toObject().value(QStringLiteral("error")).toInt(), 0);
        // The writes ran (and were put back): 06's check passed, not skipped.
        QCOMPARE(checkOf(card, QStringLiteral("write.06.echo")).value(QStringLiteral("verdict")).toString(), QStringLiteral("passed"));
        QFile xml(junit);
        QVERIFY(xml.open(QIODevice::ReadOnly));
        QXmlStreamReader reader(&xml);
        int cases = 0;
        while (!reader.atEnd()) {
            reader.readNext();
            cases += reader.isStartElement() && reader.name() == QLatin1String("testcase") ? 1 : 0;
        }
        QVERIFY2(!reader.hasError(), qPrintable(reader.errorString()));
        QCOMPARE(cases, card.value(QStringLiteral("checks")).toArray().size());
        // The values written were put back: holding 10 is 1000 + 3 x 10 again.
        const CliResult read = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), sim.url(), QStringLiteral("--function"),
                                           QStringLiteral("3"), QStringLiteral("--address"), QStringLiteral("10"), QStringLiteral("--quantity"),
                                           QStringLiteral("4"), QStringLiteral("--json")});
        QVERIFY2(read.exitCode == 0, read.describe());
        QVERIFY2(read.outText().contains(QStringLiteral("1030")) && read.outText().contains(QStringLiteral("1039")), read.describe());
    }

    // Each row makes the simulator commit one deviation; caught names the check meant to catch it,
    // failing is every check that fails (the caught one among them): any other failure is false.
    void deviationsCaught_data()
    {
        QTest::addColumn<QString>("listen");
        QTest::addColumn<QString>("faults"); // a faults file's rules, for the conformance profile
        QTest::addColumn<QString>("script"); // or the deviant profile's onRequest body
        QTest::addColumn<QString>("caught");
        QTest::addColumn<QStringList>("failing");
        const QString tcp = QStringLiteral("tcp://127.0.0.1:0");
        const QString rtu = QStringLiteral("rtu-tcp://127.0.0.1:0");
        QTest::newRow("wrong exception code") << tcp << R"({"kind": "exception", "code": 2, "functions": ["0x03"], "quantity": 0})" << ""
                                              << "read.03.quantity-zero" << QStringList{"read.03.quantity-zero"};
        QTest::newRow("silence for an unassigned function") << tcp << R"({"kind": "drop", "functions": ["0x12"]})" << ""
                                                            << "exception.illegal-function" << QStringList{"exception.illegal-function"};
        QTest::newRow("transaction id not echoed") << tcp << R"({"kind": "wrongTransactionId", "delta": 1, "functions": ["0x03"], "quantity": 3})" << ""
                                                   << "mbap.transaction-id" << QStringList{"mbap.transaction-id"};
        QTest::newRow("unit id not echoed") << tcp << R"({"kind": "wrongUnit", "delta": 1, "functions": ["0x03"], "quantity": 3})" << "" << "mbap.unit-id"
                                            << QStringList{"mbap.unit-id"};
        QTest::newRow("closes after each answer") << tcp << R"({"kind": "close", "when": "after"})" << "" << "tcp.keeps-connection"
                                                  << QStringList{"mbap.pipelined", "tcp.keeps-connection"};
        QTest::newRow("answers twice") << tcp << R"({"kind": "duplicate", "copies": 1, "gapMs": 5})" << "" << "answer.single" << QStringList{"answer.single", "answer.unsolicited"};
        QTest::newRow("slow answers") << tcp << R"({"kind": "delay", "delay": 450, "functions": ["0x04"]})" << "" << "answer.late"
                                      << QStringList{"answer.late", "read.04.answer", "read.04.block-past-map", "read.04.missing-address",
                                                     "read.04.past-end", "read.04.quantity-max", "read.04.quantity-over", "read.04.quantity-zero"};
        QTest::newRow("wrong byte count") << tcp << R"({"kind": "fewerRegisters", "functions": ["0x04"]})" << "" << "read.04.answer" << QStringList{"read.04.answer"};
        QTest::newRow("wrong CRC on 08") << rtu << R"({"kind": "wrongChecksum", "functions": ["0x08"]})" << "" << "diag.echo" << QStringList{"diag.echo"};
        // Line noise on 08's answers (every bit flipped with probability 0.5, seeded): the garbled
        // answers are no echo, and answer nothing the battery asked.
        QTest::newRow("line noise on 08's answers") << rtu << R"({"kind": "noise", "bitErrorRate": 0.5, "on": "answer", "functions": ["0x08"]})" << ""
                                                    << "diag.echo" << QStringList{"answer.unsolicited", "diag.echo"};
        QTest::newRow("closes instead of answering 2B") << tcp << R"({"kind": "close", "when": "before", "functions": ["0x2B"]})" << ""
                                                        << "exception.unsupported-function"
                                                        << QStringList{"exception.unsupported-function", "promise.functions"};
        QTest::newRow("junk before 2B") << tcp << R"({"kind": "junk", "before": "DE AD", "functions": ["0x2B"]})" << "" << "answer.unsolicited"
                                        << QStringList{"answer.unsolicited"};
        QTest::newRow("chunked answers are legal") << tcp << R"({"kind": "chunks", "chunkBytes": 3, "gapMs": 2})" << "" << "" << QStringList{};
        QTest::newRow("trickled answers are legal") << rtu << R"({"kind": "trickle", "gapMs": 2})" << "" << "" << QStringList{};

        QTest::newRow("a script that changes nothing") << tcp << "" << "" << "" << QStringList{};
        QTest::newRow("quantity 0 accepted") << tcp << ""
                                             << "if (r.function === 3 && r.quantity === 0) return {pdu: [3, 0]};"
                                             << "read.03.quantity-zero" << QStringList{"read.03.quantity-zero"};
        QTest::newRow("zeros for an illegal address") << tcp << ""
                                                      << "if (r.function === 3 && r.address >= 100 && r.quantity <= 125) { var z = []; for (var i = 0; i < r.quantity; i++) z.push(0); return z; }"
                                                      << "read.03.missing-address" << QStringList{"read.03.missing-address", "read.03.past-end"};
        QTest::newRow("MBAP length wrong") << tcp << ""
                                           << "if (r.transactionId === 0xA5C3) return {adu: 'A5 C3 00 00 00 09 01 03 02 00 00'};"
                                           << "mbap.length" << QStringList{"answer.unsolicited", "mbap.length"};
        QTest::newRow("08 does not echo") << tcp << "" << "if (r.function === 8) return {pdu: '08 00 00 00 00'};" << "diag.echo"
                                          << QStringList{"diag.echo"};
        QTest::newRow("bits in the wrong order") << tcp << ""
                                                 << "if (r.function === 1 && r.quantity === 5) { var v = unit.read('coils', r.address, 5), b = 0; for (var i = 0; i < 5; i++) if (v[i]) b |= 0x80 >> i; return {pdu: [1, 1, b]}; }"
                                                 << "read.01.bit-order" << QStringList{"read.01.bit-order"};
        QTest::newRow("basic identification incomplete") << tcp << ""
                                                         << "if (r.function === 0x2B && r.pdu[2] === 1) return {pdu: '2B 0E 01 01 00 00 01 00 03 41 42 43'};"
                                                         << "ident.basic" << QStringList{"ident.basic"};
        QTest::newRow("06 echoes another value") << tcp << ""
                                                 << "if (r.function === 6) { var p = r.pdu.slice(0); p[4] ^= 1; return {pdu: p}; }"
                                                 << "write.06.echo" << QStringList{"write.06.echo"};
        QTest::newRow("05 takes any value") << tcp << ""
                                            << "if (r.function === 5 && r.pdu[3] === 0x12) return {pdu: r.pdu};"
                                            << "write.05.bad-value" << QStringList{"write.05.bad-value"};
        QTest::newRow("10 byte count not checked") << tcp << ""
                                                   << "if (r.function === 16 && r.pdu.length > 6 && r.pdu[5] !== 2 * r.quantity) return {pdu: r.pdu.slice(0, 5)};"
                                                   << "write.10.byte-count" << QStringList{"write.10.byte-count"};
        QTest::newRow("17 reads before it writes") << tcp << ""
                                                   << "if (r.function === 0x17) { var old = unit.read('holding', r.address, r.quantity); unit.write('holding', r.writeAddress, r.values); return old; }"
                                                   << "write.17.order" << QStringList{"write.17.order"};
    }
    void deviationsCaught()
    {
        QFETCH(QString, listen);
        QFETCH(QString, faults);
        QFETCH(QString, script);
        QFETCH(QString, caught);
        QFETCH(QStringList, failing);
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'));
        QStringList simArgs{QStringLiteral("simulate"), QStringLiteral("--listen"), listen, QStringLiteral("--quiet")};
        QStringList conformArgs;
        if (!faults.isEmpty()) {
            const QString path = m_dir.filePath(tag + QStringLiteral("-faults.json"));
            QVERIFY(writeFile(path, QStringLiteral(R"({"seed": 1, "rules": [%1]})").arg(faults).toUtf8()));
            simArgs += {QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--faults"), path};
            conformArgs += {QStringLiteral("--profile"), QStringLiteral("conformance")};
        } else {
            const QString folder = m_dir.filePath(tag);
            QVERIFY(QDir().mkpath(folder));
            QVERIFY(writeFile(folder + QStringLiteral("/deviant.json"), kProfile));
            QVERIFY(writeFile(folder + QStringLiteral("/deviant.js"),
                              QStringLiteral("function onRequest(r) {\n%1\nreturn undefined;\n}\n").arg(script).toUtf8()));
            simArgs += {QStringLiteral("--profile"), folder + QStringLiteral("/deviant.json")};
            conformArgs += {QStringLiteral("--profile"), folder + QStringLiteral("/deviant.json")};
        }
        Background sim;
        QString error;
        QVERIFY2(sim.start(simArgs, &error), qPrintable(error));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--json"),
                                                   QStringLiteral("--writable"), QStringLiteral("holding:10-13"), QStringLiteral("--writable"),
                                                   QStringLiteral("coils:10-17")}
                                       + conformArgs + kTimeout);
        QVERIFY2(r.finished, r.describe());
        const QJsonObject card = r.json();
        const QStringList failed = failedIds(card);
        if (!caught.isEmpty()) {
            QVERIFY2(failed.contains(caught), qPrintable(QStringLiteral("%1 not among the failures: %2\n%3").arg(caught, failed.join(QLatin1Char(' ')), r.outText())));
            QVERIFY2(!checkOf(card, caught).value(QStringLiteral("sentence")).toString().isEmpty(), r.describe());
        }
        failing.sort();
        QCOMPARE(failed, failing);
        QCOMPARE(r.exitCode, card.value(QStringLiteral("counts")).toObject().value(QStringLiteral("failed_mandatory")).toInt() > 0 ? 1 : 0);
    }

    // 0F one coil over the most: refused with 03 by the simulator; a device that echoes it fails,
    // and what it changed is put back; with fewer writable coils than the request would write, the
    // check is skipped, saying why (it never writes a coil the user did not name).
    void writeQuantityOver_data()
    {
        QTest::addColumn<QString>("script");
        QTest::addColumn<QString>("writable");
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<QString>("says");
        QTest::newRow("refused") << "" << "coils:0-1999" << "passed" << "";
        QTest::newRow("taken") << "if (r.function === 15 && r.quantity > 1968) { unit.write('coils', r.address, [0]); return {pdu: r.pdu.slice(0, 5)}; }"
                               << "coils:0-1999" << "failed" << "exception 03";
        QTest::newRow("too few writable") << "" << "coils:10-17" << "skipped" << "needs 1969 writable coils";
    }
    void writeQuantityOver()
    {
        QFETCH(QString, script);
        QFETCH(QString, writable);
        QFETCH(QString, verdict);
        QFETCH(QString, says);
        const QString folder = m_dir.filePath(QStringLiteral("over-%1").arg(QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'))));
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(writeFile(folder + QStringLiteral("/many.json"),
                          R"({"name": "many-coils", "units": [{"id": 1, "script": "many.js", "tables": {"coils": [{"address": 0, "count": 2000, "values": [1, 1, 0, 1]}]}}]})"));
        QVERIFY(writeFile(folder + QStringLiteral("/many.js"),
                          QStringLiteral("function onRequest(r) {\n%1\nreturn undefined;\n}\n").arg(script).toUtf8()));
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), folder + QStringLiteral("/many.json"), QStringLiteral("--listen"),
                            QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--json"),
                                                   QStringLiteral("--writable"), writable, QStringLiteral("--only"), QStringLiteral("write.0F.quantity-over")}
                                       + kTimeout);
        QVERIFY2(r.finished, r.describe());
        const QJsonObject c = checkOf(r.json(), QStringLiteral("write.0F.quantity-over"));
        QVERIFY2(c.value(QStringLiteral("verdict")).toString() == verdict, r.describe());
        QVERIFY2(c.value(QStringLiteral("sentence")).toString().contains(says), r.describe());
        if (verdict == QLatin1String("failed")) {
            // Coil 0 was ON; the device cleared it while taking the write: put back.
            const CliResult read = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), sim.url(), QStringLiteral("--function"),
                                               QStringLiteral("1"), QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--quantity"),
                                               QStringLiteral("4"), QStringLiteral("--json")});
            QVERIFY2(read.exitCode == 0, read.describe());
            const QJsonArray values = read.json().value(QStringLiteral("values")).toArray();
            QVERIFY2(values.size() == 4 && values.at(0).toObject().value(QStringLiteral("value")).toVariant().toInt() == 1, read.describe());
        }
    }

    // --html: one self-contained page, read back as XML: the summary before the first check, a
    // section per check of the JSON scorecard with its clause, verdict, request and answer, the
    // failures listed and linked, and nothing loaded from outside (no src, no href but #anchors).
    void htmlReport_data()
    {
        QTest::addColumn<QString>("listen");
        QTest::addColumn<QString>("faults");
        QTest::addColumn<QString>("only");
        QTest::addColumn<bool>("passes");
        QTest::newRow("tcp passes") << "tcp://127.0.0.1:0" << "" << "" << true;
        QTest::newRow("rtu-tcp passes") << "rtu-tcp://127.0.0.1:0" << "" << "read.03,serial,diag" << true;
        QTest::newRow("wrong exception code fails") << "tcp://127.0.0.1:0" << R"({"kind": "exception", "code": 2, "functions": ["0x03"], "quantity": 0})"
                                                    << "read.03,mbap" << false;
    }
    void htmlReport()
    {
        QFETCH(QString, listen);
        QFETCH(QString, faults);
        QFETCH(QString, only);
        QFETCH(bool, passes);
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'));
        QStringList simArgs{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"), listen,
                            QStringLiteral("--quiet")};
        if (!faults.isEmpty()) {
            const QString path = m_dir.filePath(tag + QStringLiteral("-html-faults.json"));
            QVERIFY(writeFile(path, QStringLiteral(R"({"seed": 1, "rules": [%1]})").arg(faults).toUtf8()));
            simArgs += {QStringLiteral("--faults"), path};
        }
        Background sim;
        QString error;
        QVERIFY2(sim.start(simArgs, &error), qPrintable(error));
        const QString html = m_dir.filePath(tag + QStringLiteral(".html"));
        QStringList args{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--profile"), QStringLiteral("conformance"),
                         QStringLiteral("--json"), QStringLiteral("--html"), html};
        if (!only.isEmpty())
            args += {QStringLiteral("--only"), only};
        const CliResult r = runMbscope(args + kTimeout);
        QVERIFY2(r.finished, r.describe());
        QCOMPARE(r.exitCode, passes ? 0 : 1);
        const QJsonObject card = r.json();
        const QJsonArray checks = card.value(QStringLiteral("checks")).toArray();
        QVERIFY(!checks.isEmpty());

        QFile file(html);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(html));
        QXmlStreamReader reader(&file);
        int section = -1;           // index of the check section being read
        bool summarySeen = false;
        QString verdictClass;
        QString cell;               // the class of the <td> being read
        QStringList failuresListed;
        QString inLi;
        QList<QJsonObject> seen;    // per check section: what the page says
        while (!reader.atEnd()) {
            reader.readNext();
            if (reader.isStartElement()) {
                const QXmlStreamAttributes a = reader.attributes();
                const QString name = reader.name().toString();
                QVERIFY2(!a.hasAttribute(QStringLiteral("src")), "an element loads something");
                if (a.hasAttribute(QStringLiteral("href")))
                    QVERIFY2(a.value(QStringLiteral("href")).startsWith(QLatin1Char('#')), qPrintable(a.value(QStringLiteral("href")).toString()));
                QVERIFY2(name != QLatin1String("script") && name != QLatin1String("link") && name != QLatin1String("img"), qPrintable(name));
                const QString cls = a.value(QStringLiteral("class")).toString();
                if (name == QLatin1String("section") && a.value(QStringLiteral("id")) == QLatin1String("summary")) {
                    QCOMPARE(section, -1); // the summary comes first
                    summarySeen = true;
                } else if (name == QLatin1String("section") && cls == QLatin1String("check")) {
                    ++section;
                    QJsonObject o;
                    o.insert(QStringLiteral("id"), a.value(QStringLiteral("id")).toString());
                    o.insert(QStringLiteral("verdict"), a.value(QStringLiteral("data-verdict")).toString());
                    seen.append(o);
                } else if (name == QLatin1String("p") && cls.startsWith(QLatin1String("verdict "))) {
                    verdictClass = cls.mid(8);
                } else if (name == QLatin1String("td")) {
                    cell = cls;
                } else if (name == QLatin1String("li")) {
                    inLi = QStringLiteral("?");
                } else if (name == QLatin1String("a") && !inLi.isEmpty()) {
                    failuresListed.append(a.value(QStringLiteral("href")).mid(1).toString());
                }
            } else if (reader.isEndElement() && reader.name() == QLatin1String("td")) {
                cell.clear();
            } else if (reader.isEndElement() && reader.name() == QLatin1String("li")) {
                inLi.clear();
            } else if (reader.isCharacters() && !reader.isWhitespace() && section >= 0 && !cell.isEmpty()) {
                QJsonObject &o = seen[section];
                o.insert(cell, o.value(cell).toString() + reader.text().toString());
            }
        }
        QVERIFY2(!reader.hasError(), qPrintable(QStringLiteral("%1 at line %2").arg(reader.errorString()).arg(reader.lineNumber())));
        QVERIFY(summarySeen);
        QCOMPARE(verdictClass, passes ? QStringLiteral("passed") : QStringLiteral("failed"));
        QCOMPARE(seen.size(), checks.size());
        QStringList failed;
        for (qsizetype i = 0; i < checks.size(); ++i) {
            const QJsonObject want = checks.at(i).toObject();
            const QJsonObject got = seen.at(i);
            const QString id = want.value(QStringLiteral("id")).toString();
            QCOMPARE(got.value(QStringLiteral("id")).toString(), id);
            QCOMPARE(got.value(QStringLiteral("verdict")).toString(), want.value(QStringLiteral("verdict")).toString());
            QCOMPARE(got.value(QStringLiteral("clause")).toString(), want.value(QStringLiteral("clause")).toString());
            QCOMPARE(got.value(QStringLiteral("level")).toString(), want.value(QStringLiteral("level")).toString());
            const QString request = want.value(QStringLiteral("request")).toString();
            const QString answer = want.value(QStringLiteral("answer")).toString();
            QCOMPARE(got.value(QStringLiteral("request")).toString(), request.isEmpty() ? QStringLiteral("(none sent)") : request);
            QCOMPARE(got.value(QStringLiteral("answer")).toString(), answer.isEmpty() ? QStringLiteral("(none)") : answer);
            if (want.value(QStringLiteral("verdict")).toString() == QLatin1String("failed"))
                failed.append(id);
        }
        QCOMPARE(failuresListed, failed);
        QCOMPARE(failed.isEmpty(), passes);
    }

    // --pdf: the --html report printed to a PDF (ConformancePdf); pdftotext (poppler-utils) reads
    // it back: the summary's verdict and counts, and each check's id with its clause.
    void pdfReport_data()
    {
        QTest::addColumn<QString>("faults");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("verdict"); // in the summary
        QTest::newRow("passes") << "" << 0 << "every mandatory check passed";
        QTest::newRow("wrong exception code fails") << R"({"kind": "exception", "code": 2, "functions": ["0x03"], "quantity": 0})" << 1
                                                    << "mandatory check(s) failed";
    }
    void pdfReport()
    {
        QFETCH(QString, faults);
        QFETCH(int, exitCode);
        QFETCH(QString, verdict);
        const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
        if (pdftotext.isEmpty())
            QSKIP("pdftotext (poppler-utils, scripts/install-deps.sh --tests) is not installed");
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'));
        QStringList simArgs{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                            QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")};
        if (!faults.isEmpty()) {
            const QString path = m_dir.filePath(tag + QStringLiteral("-pdf-faults.json"));
            QVERIFY(writeFile(path, QStringLiteral(R"({"seed": 1, "rules": [%1]})").arg(faults).toUtf8()));
            simArgs += {QStringLiteral("--faults"), path};
        }
        Background sim;
        QString error;
        QVERIFY2(sim.start(simArgs, &error), qPrintable(error));
        const QString pdf = m_dir.filePath(tag + QStringLiteral(".pdf"));
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--profile"),
                                                   QStringLiteral("conformance"), QStringLiteral("--only"), QStringLiteral("read.03,mbap"),
                                                   QStringLiteral("--json"), QStringLiteral("--pdf"), pdf}
                                       + kTimeout);
        QVERIFY2(r.finished, r.describe());
        QVERIFY2(r.exitCode == exitCode, r.describe());
        QFile file(pdf);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(pdf));
        QCOMPARE(file.read(5), QByteArray("%PDF-"));
        QProcess text;
        text.start(pdftotext, {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
        QVERIFY(text.waitForFinished(60000));
        QCOMPARE(text.exitCode(), 0);
        // Words as laid out: lines joined, runs of blanks made one.
        const QString words = QString::fromUtf8(text.readAllStandardOutput()).simplified();
        QVERIFY2(words.contains(QStringLiteral("Modbus conformance scorecard")), qPrintable(words.left(400)));
        QVERIFY2(words.contains(verdict), qPrintable(words.left(400)));
        const QJsonObject card = r.json();
        const QString counts = QStringLiteral("%1 checks").arg(card.value(QStringLiteral("checks")).toArray().size());
        QVERIFY2(words.contains(counts), qPrintable(counts + QLatin1Char('\n') + words.left(400)));
        for (const QString &id : {QStringLiteral("read.03.quantity-zero"), QStringLiteral("mbap.transaction-id")}) {
            const QJsonObject c = checkOf(card, id);
            QVERIFY2(words.contains(id), qPrintable(id));
            const QString clause = c.value(QStringLiteral("clause")).toString();
            QVERIFY(!clause.isEmpty());
            QVERIFY2(words.contains(QStringLiteral("clause ") + clause), qPrintable(id + QStringLiteral(": ") + clause));
        }
    }

    // The line timing on an RTU serial port, at 600 baud 8N1 (a character 16.7 ms, t1.5 27.5 ms,
    // t3.5 64.2 ms): the simulator behind a line relay that takes each character's time
    // (PacedLine) keeps t3.5 before it answers (it did not, and failed serial.t35-before-answer,
    // before session 14); a delay fault makes it wait longer; a trickle fault puts 55 ms of
    // silence between its characters (over t1.5, under t3.5: still one frame). A bare pty pair
    // carries bytes at once: its times are not the line's.
    void serialTiming_data()
    {
        QTest::addColumn<bool>("paced");
        QTest::addColumn<QString>("faults");
        QTest::addColumn<QString>("t35");  // serial.t35-before-answer's verdict
        QTest::addColumn<QString>("t15");  // serial.t15-within-answer's
        QTest::addColumn<QString>("says"); // in t15's sentence, or t35's when t15 says nothing new
        QTest::newRow("bare pty pair") << false << "" << "skipped" << "skipped" << "not measurable on this link";
        QTest::newRow("paced, the default profile") << true << "" << "passed" << "skipped" << "came in one read";
        QTest::newRow("paced, waits 100 ms") << true << R"({"kind": "delay", "delay": 100})" << "passed" << "skipped" << "came in one read";
        QTest::newRow("paced, silences inside the answer") << true << R"({"kind": "trickle", "gapMs": 55})" << "passed" << "failed"
                                                           << "at least one silence between its characters";
    }
    void serialTiming()
    {
        QFETCH(bool, paced);
        QFETCH(QString, faults);
        QFETCH(QString, t35);
        QFETCH(QString, t15);
        QFETCH(QString, says);
        constexpr int kBaud = 600;
        const qint64 characterNs = 10LL * 1000000000LL / kBaud; // 8N1: start, 8 data, stop
        mbscope::testpeers::PacedLine line;
        QString error;
        QVERIFY2(line.start(paced ? characterNs : 0, &error), qPrintable(error));
        const QString options = QStringLiteral("?baud=%1&parity=N").arg(kBaud);
        QStringList simArgs{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                            QStringLiteral("rtu://") + line.deviceEnd() + options, QStringLiteral("--quiet")};
        if (!faults.isEmpty()) {
            const QString path = m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-')) + QStringLiteral("-line.json"));
            QVERIFY(writeFile(path, QStringLiteral(R"({"seed": 1, "rules": [%1]})").arg(faults).toUtf8()));
            simArgs += {QStringLiteral("--faults"), path};
        }
        Background sim;
        QVERIFY2(sim.start(simArgs, &error), qPrintable(error));
        const CliResult r = runMbscope({QStringLiteral("conform"), QStringLiteral("--target"), QStringLiteral("rtu://") + line.masterEnd() + options,
                                        QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--only"),
                                        QStringLiteral("serial.t"), QStringLiteral("--timeout"), QStringLiteral("2s"), QStringLiteral("--json")});
        QVERIFY2(r.finished, r.describe());
        const QJsonObject card = r.json();
        const QJsonObject c35 = checkOf(card, QStringLiteral("serial.t35-before-answer"));
        const QJsonObject c15 = checkOf(card, QStringLiteral("serial.t15-within-answer"));
        QVERIFY2(c35.value(QStringLiteral("verdict")).toString() == t35, r.describe());
        QVERIFY2(c15.value(QStringLiteral("verdict")).toString() == t15, r.describe());
        const QString sentence = c15.value(QStringLiteral("sentence")).toString();
        QVERIFY2(sentence.contains(says), qPrintable(sentence));
        // Never a pass without evidence: what is not judged says so.
        for (const QJsonObject &c : {c35, c15}) {
            if (c.value(QStringLiteral("verdict")).toString() == QLatin1String("skipped"))
                QVERIFY2(c.value(QStringLiteral("sentence")).toString().startsWith(QLatin1String("not judged")), r.describe());
        }
        QCOMPARE(r.exitCode, t35 == QLatin1String("failed") || t15 == QLatin1String("failed") ? 1 : 0);
    }

    // The simulator's RTU serial endpoint keeps t3.5 of silence between a request's last byte and
    // its answer's first (Serial Line V1.02, 2.5.1.1), at the baud rate's t3.5 up to 19200 baud and
    // the fixed 1.75 ms above. The relay measures each turnaround from just before it handed the
    // request over to just after it read the answer, never shorter than the simulator kept it.
    // Before session 14 the answer left as soon as the request's length was in.
    void simulatorKeepsT35BeforeAnswer_data()
    {
        QTest::addColumn<int>("baud");
        QTest::newRow("9600 baud") << 9600;
        QTest::newRow("19200 baud") << 19200;
        QTest::newRow("115200 baud") << 115200;
    }
    void simulatorKeepsT35BeforeAnswer()
    {
        QFETCH(int, baud);
        const qint64 characterNs = 10LL * 1000000000LL / baud; // 8N1
        mbscope::testpeers::PacedLine line;
        QString error;
        QVERIFY2(line.start(characterNs, &error), qPrintable(error));
        const QString options = QStringLiteral("?baud=%1&parity=N").arg(baud);
        Background sim;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                            QStringLiteral("rtu://") + line.deviceEnd() + options, QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), QStringLiteral("rtu://") + line.masterEnd() + options,
                                           QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--quantity"), QStringLiteral("4"),
                                           QStringLiteral("--count"), QStringLiteral("10"), QStringLiteral("--interval"), QStringLiteral("0")});
        QVERIFY2(poll.exitCode == 0, poll.describe());
        const mbscope::testpeers::PacedLine::Timing timing = line.take();
        QCOMPARE(timing.turnaroundsNs.size(), size_t(10));
        const qint64 t35 = baud > 19200 ? 1750000 : 77LL * 1000000000LL / (2LL * baud); // 3.5 11-bit characters (Serial Line V1.02, 2.5.1.1)
        const qint64 shortest = *std::min_element(timing.turnaroundsNs.begin(), timing.turnaroundsNs.end());
        QVERIFY2(shortest >= t35, qPrintable(QStringLiteral("%1 us of silence before an answer; t3.5 at %2 baud is %3 us")
                                                 .arg(double(shortest) / 1000, 0, 'f', 1)
                                                 .arg(baud)
                                                 .arg(double(t35) / 1000, 0, 'f', 1)));
    }

    // Connections at once: the simulator takes 64 by default (the check's 8 beside its own pass);
    // with maxClients 3 it refuses the fourth (a deviation: TCP/IP Guide 4.2.1 has the oldest idle
    // one closed instead), or closes the oldest (what the guide asks).
    void tcpClients_data()
    {
        QTest::addColumn<QString>("limits");
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<QString>("measured");
        QTest::addColumn<QString>("says");
        QTest::newRow("no limit") << "" << "passed" << "9 connections at once or more" << "each answered again";
        QTest::newRow("refuses the fourth") << R"({"maxClients": 3})" << "failed" << "3 connections at once" << "connection 4 got";
        QTest::newRow("drops the oldest") << R"({"maxClients": 3, "extraClients": "dropOldest"})" << "passed" << "3 connections at once"
                                          << "by closing the oldest idle one";
    }
    void tcpClients()
    {
        QFETCH(QString, limits);
        QFETCH(QString, verdict);
        QFETCH(QString, measured);
        QFETCH(QString, says);
        const QString path = m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-')) + QStringLiteral("-clients.json"));
        QVERIFY(writeFile(path, QStringLiteral(R"({"name": "clients", %1 "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})")
                                    .arg(limits.isEmpty() ? QString() : QStringLiteral("\"limits\": %1,").arg(limits))
                                    .toUtf8()));
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), path, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"),
                            QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const CliResult r = runMbscope({QStringLiteral("conform"), QStringLiteral("--target"), sim.url(), QStringLiteral("--only"),
                                        QStringLiteral("tcp.clients"), QStringLiteral("--timeout"), QStringLiteral("500ms"), QStringLiteral("--json")});
        QVERIFY2(r.finished, r.describe());
        const QJsonObject c = checkOf(r.json(), QStringLiteral("tcp.clients"));
        QVERIFY2(c.value(QStringLiteral("verdict")).toString() == verdict, r.describe());
        QVERIFY2(c.value(QStringLiteral("measured")).toString() == measured, r.describe());
        QVERIFY2(c.value(QStringLiteral("sentence")).toString().contains(says), r.describe());
        QCOMPARE(r.exitCode, 0); // a recommended check: a deviation, not a failed device
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("no target") << QStringList{} << "--target is required";
        QTest::newRow("bad writable") << QStringList{"--target", "tcp://127.0.0.1:1", "--writable", "holdings:1"}
                                      << "--writable 'holdings:1': 'holdings' is not a table";
        QTest::newRow("unit 0") << QStringList{"--target", "tcp://127.0.0.1:1", "--unit", "0"} << "--unit 0 is out of range: expected 1 to 247";
        QTest::newRow("only selects nothing") << QStringList{"--target", "tcp://127.0.0.1:1", "--only", "nosuch"} << "--only nosuch selects no check";
        QTest::newRow("unknown profile") << QStringList{"--target", "tcp://127.0.0.1:1", "--profile", "nosuch"} << "--profile nosuch";
        QTest::newRow("html folder missing") << QStringList{"--target", "tcp://127.0.0.1:1", "--html", "/nonexistent/conform.html"}
                                             << "--html: cannot write /nonexistent/conform.html";
        QTest::newRow("positional") << QStringList{"tcp://127.0.0.1:1"} << "the device is given with --target URL";
    }
    void usageErrors()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const CliResult r = runMbscope(QStringList{QStringLiteral("conform")} + args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.errText().contains(says), r.describe());
    }

    void unreachableTarget()
    {
        const QString url = QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort());
        const CliResult r = runMbscope({QStringLiteral("conform"), QStringLiteral("--target"), url});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.errText().startsWith(QStringLiteral("mbscope conform: ")), r.describe());
        const CliResult j = runMbscope({QStringLiteral("conform"), QStringLiteral("--target"), url, QStringLiteral("--json")});
        QCOMPARE(j.exitCode, 2);
        QVERIFY2(j.json().contains(QStringLiteral("link_error")), j.describe());
    }

    void listsChecks()
    {
        const CliResult r = runMbscope({QStringLiteral("conform"), QStringLiteral("--list")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.outText().contains(QStringLiteral("read.03.quantity-zero")));
        QVERIFY(r.outText().contains(QStringLiteral("Application Protocol V1.1b3, 6.3")));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliConform)
#include "tst_cli_conform.moc"
