// A corpus of broken session documents (tests/data/sessions/broken/), one row per file: each is
// refused as a whole (no document, never half loaded) with exactly the problems its .expected
// file lists, one per line, each saying where (line:column for syntax, the JSON path for content)
// and what was expected. The file's directory is left out of the messages. Also: a document cut
// at every byte, and documents with bytes changed at random (seeded), are never half loaded.
//
// To write the .expected files after a deliberate change of wording, run the test with
// MBSCOPE_UPDATE_EXPECTED=1 and read every diff before committing it.

#include "session/sessionreader.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QRandomGenerator>
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
    void truncatedAnywhere();
    void mutatedNeverHalfLoaded();
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

void TestSessionBroken::truncatedAnywhere()
{
    // A document cut anywhere (a copy interrupted, a disk full) is refused with a syntax error
    // that has a line and a column inside the text, never loaded in part.
    QFile file(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/everything.mbscope.json"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray whole = file.readAll().trimmed();
    QVERIFY(SessionReader::parse(whole, QStringLiteral("whole")).ok());
    const int lines = int(whole.count('\n')) + 1;
    for (qsizetype cut = 0; cut < whole.size(); ++cut) {
        const SessionLoadResult r = SessionReader::parse(whole.left(cut), QStringLiteral("cut"));
        QVERIFY2(!r.ok(), qPrintable(QStringLiteral("loaded when cut at byte %1").arg(cut)));
        QCOMPARE(r.problems.size(), 1);
        const ProfileProblem &p = r.problems.constFirst();
        QVERIFY2(p.message.startsWith(QLatin1String("JSON syntax error: ")) || cut == 0, qPrintable(p.toString()));
        if (cut > 0)
            QVERIFY2(p.line >= 1 && p.line <= lines && p.column >= 1, qPrintable(p.toString()));
    }
}

void TestSessionBroken::mutatedNeverHalfLoaded()
{
    // Bytes changed at random (seeded: the same every run): the reader either loads a whole
    // document or lists problems, each with a message; it never crashes or returns both.
    QFile file(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/sessions/everything.mbscope.json"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray whole = file.readAll();
    QRandomGenerator random(20261121);
    const char replacements[] = "{}[]\",:0123456789-.aexnt \\";
    int loaded = 0;
    for (int round = 0; round < 3000; ++round) {
        QByteArray text = whole;
        const int changes = 1 + int(random.bounded(3));
        for (int c = 0; c < changes; ++c)
            text[qsizetype(random.bounded(int(text.size())))] = replacements[random.bounded(int(sizeof replacements - 1))];
        const SessionLoadResult r = SessionReader::parse(text, QStringLiteral("mutated"));
        QCOMPARE(r.ok(), r.problems.isEmpty());
        for (const ProfileProblem &p : r.problems)
            QVERIFY2(!p.message.isEmpty(), qPrintable(p.toString()));
        loaded += r.ok() ? 1 : 0;
    }
    QVERIFY2(loaded < 3000, "no mutation was refused: the test changes nothing");
}

QTEST_GUILESS_MAIN(TestSessionBroken)
#include "tst_sessionbroken.moc"
