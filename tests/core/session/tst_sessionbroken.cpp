// A corpus of broken session documents (tests/data/sessions/broken/), one row per file: each is
// refused as a whole (no document, never half loaded) with exactly the problems its .expected
// file lists, one per line, each saying where (line:column for syntax, the JSON path for content)
// and what was expected. The file's directory is left out of the messages.
//
// To write the .expected files after a deliberate change of wording, run the test with
// MBSCOPE_UPDATE_EXPECTED=1 and read every diff before committing it.

#include "session/sessionreader.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

QString corpusDir()
{
    return QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/broken");
}

} // namespace

class TestSessionBroken : public QObject
{
    Q_OBJECT

private slots:
    void corpus_data();
    void corpus();
    void everyDocumentHasItsMessage();
};

void TestSessionBroken::corpus_data()
{
    QTest::addColumn<QString>("file");
    const QStringList files = QDir(corpusDir()).entryList({QStringLiteral("*.mbscope.json")}, QDir::Files, QDir::Name);
    QVERIFY2(files.size() >= 20, "the corpus is missing");
    for (const QString &f : files)
        QTest::newRow(qPrintable(f)) << f;
}

void TestSessionBroken::corpus()
{
    QFETCH(QString, file);
    const QDir dir(corpusDir());
    const SessionLoadResult r = SessionReader::load(dir.filePath(file));
    QVERIFY2(!r.ok(), "a broken document loaded");
    QVERIFY(!r.document.has_value());
    QVERIFY(!r.problems.isEmpty());
    QString actual = r.errorText();
    actual.replace(dir.filePath(file), file);

    const QString expectedPath = dir.filePath(QString(file).replace(QLatin1String(".mbscope.json"), QLatin1String(".expected")));
    if (qEnvironmentVariableIsSet("MBSCOPE_UPDATE_EXPECTED")) {
        QFile out(expectedPath);
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(actual.toUtf8() + '\n');
        return;
    }
    QFile in(expectedPath);
    QVERIFY2(in.open(QIODevice::ReadOnly), qPrintable(expectedPath + QStringLiteral(": missing")));
    QCOMPARE(actual, QString::fromUtf8(in.readAll()).trimmed());
    // Every problem names the file, and either a line and column or a path, or is about the
    // file as a whole.
    for (const ProfileProblem &p : r.problems)
        QVERIFY2(p.source == dir.filePath(file) && !p.message.isEmpty(), qPrintable(p.toString()));
}

void TestSessionBroken::everyDocumentHasItsMessage()
{
    const QDir dir(corpusDir());
    for (const QString &e : dir.entryList({QStringLiteral("*.expected")}, QDir::Files)) {
        const QString doc = QString(e).replace(QLatin1String(".expected"), QLatin1String(".mbscope.json"));
        QVERIFY2(dir.exists(doc), qPrintable(e + QStringLiteral(" has no document")));
    }
}

QTEST_GUILESS_MAIN(TestSessionBroken)
#include "tst_sessionbroken.moc"
