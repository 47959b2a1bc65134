// docs/session.schema.json says what SessionReader reads: documents SessionWriter writes (every
// feature) and the shipped example validate against it, and the broken documents whose fault a
// schema can express are refused by it. Checked with python3-jsonschema (skipped without it).

#include "rosraosim.h"

#include "session/sessionreader.h"
#include "session/sessionwriter.h"

#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

struct Validation {
    bool available = false;
    QStringList lines;
    QString error;
};

Validation validate(const QStringList &files)
{
    const QString src = sessiontest::sourceDir();
    QProcess p;
    p.start(QStringLiteral("/usr/bin/python3"),
            QStringList{src + QStringLiteral("/tests/core/session/validate_session_schema.py"),
                        src + QStringLiteral("/docs/session.schema.json"), src + QStringLiteral("/docs/profile.schema.json")}
                + files);
    Validation v;
    if (!p.waitForStarted() || !p.waitForFinished(60000)) {
        v.error = QStringLiteral("/usr/bin/python3 could not run: %1").arg(p.errorString());
        return v;
    }
    if (p.exitCode() == 3)
        return v; // no jsonschema: the caller skips
    v.available = true;
    if (p.exitCode() != 0)
        v.error = QString::fromUtf8(p.readAllStandardError());
    v.lines = QString::fromUtf8(p.readAllStandardOutput()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    return v;
}

} // namespace

class TestSessionSchema : public QObject
{
    Q_OBJECT

private slots:
    void writtenDocumentsValidate();
    void brokenDocumentsRefused_data();
    void brokenDocumentsRefused();
};

void TestSessionSchema::writtenDocumentsValidate()
{
    QTemporaryDir dir;
    // Every feature of the format in one document (moc reads raw strings holding "//" as comments,
    // so it lives in a file).
    const SessionLoadResult rich = SessionReader::load(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/everything.mbscope.json"));
    QVERIFY2(rich.ok(), qPrintable(rich.errorText()));
    const SessionLoadResult example = SessionReader::load(sessiontest::sourceDir() + QStringLiteral("/docs/examples/rosrao-gamma.mbscope.json"));
    QVERIFY2(example.ok(), qPrintable(example.errorText()));
    const SessionLoadResult watches = SessionReader::load(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/watches.mbscope.json"));
    QVERIFY2(watches.ok(), qPrintable(watches.errorText()));
    QStringList files;
    QString error;
    for (const auto &[name, doc] : {std::pair{QStringLiteral("rich.mbscope.json"), *rich.document},
                                    std::pair{QStringLiteral("example.mbscope.json"), *example.document},
                                    std::pair{QStringLiteral("watches.mbscope.json"), *watches.document},
                                    std::pair{QStringLiteral("empty.mbscope.json"), SessionDocument{}}}) {
        files.append(dir.filePath(name));
        QVERIFY2(SessionWriter::save(doc, files.last(), &error), qPrintable(error));
    }
    files.append(sessiontest::sourceDir() + QStringLiteral("/docs/examples/rosrao-gamma.mbscope.json"));
    files.append(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/everything.mbscope.json"));
    files.append(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/watches.mbscope.json"));
    const Validation v = validate(files);
    if (!v.available && v.error.isEmpty())
        QSKIP("python3-jsonschema is not installed (scripts/install-deps.sh --tests installs it)");
    QVERIFY2(v.error.isEmpty(), qPrintable(v.error));
    QCOMPARE(v.lines.size(), files.size());
    for (int i = 0; i < files.size(); ++i)
        QCOMPARE(v.lines.at(i), files.at(i) + QStringLiteral(": valid"));
}

void TestSessionSchema::brokenDocumentsRefused_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("where"); // the first error's path, as the validator prints it
    // The others are beyond a schema (names that must exist, builder limits, hex text): the
    // reader is the reference for those.
    QTest::newRow("unknown-key") << "unknown-key" << "(top)";
    QTest::newRow("wrong-format") << "wrong-format" << "format";
    QTest::newRow("newer-version") << "newer-version" << "(top)";
    QTest::newRow("missing-format-and-version") << "missing-format-and-version" << "(top)";
    QTest::newRow("address-beyond") << "address-beyond" << "requests[3]";
    QTest::newRow("bad-target") << "bad-target" << "target";
    QTest::newRow("step-two-actions") << "step-two-actions" << "plan[0]";
    QTest::newRow("bad-wait-and-repeat") << "bad-wait-and-repeat" << "plan[0].wait";
    QTest::newRow("hex-and-function") << "hex-and-function" << "requests[0]";
    QTest::newRow("poll-without-end") << "poll-without-end" << "poll";
    QTest::newRow("bad-inline-profile") << "bad-inline-profile" << "profile";
    QTest::newRow("bad-watches") << "bad-watches" << "watchLinks[0].gapMs";
    QTest::newRow("bad-tap") << "bad-tap" << "tap";
}

void TestSessionSchema::brokenDocumentsRefused()
{
    QFETCH(QString, file);
    QFETCH(QString, where);
    const QString path = QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/broken/%1.mbscope.json").arg(file);
    const Validation v = validate({path});
    if (!v.available && v.error.isEmpty())
        QSKIP("python3-jsonschema is not installed (scripts/install-deps.sh --tests installs it)");
    QVERIFY2(v.error.isEmpty(), qPrintable(v.error));
    QCOMPARE(v.lines.size(), 1);
    QVERIFY2(v.lines.constFirst().startsWith(path + QStringLiteral(": invalid at ") + where + QStringLiteral(": ")),
             qPrintable(v.lines.constFirst()));
}

QTEST_GUILESS_MAIN(TestSessionSchema)
#include "tst_sessionschema.moc"
