// Surviving kill -9. A child process (this executable, started again in a child mode) polls an
// in-process simulator as fast as it can with the traffic journaled, and is killed with SIGKILL in
// the middle: reopening the session that names the journal recovers every batch that had reached
// the disk before the kill (checked against a copy taken just before it), with frames that make
// sense (requests and their answers, in order), and says how much was recovered. Another child
// saves a large session over and over and is killed: the file is always one whole document.

#include "session/capturerecovery.h"
#include "session/sessionreader.h"
#include "session/sessionwriter.h"

#include "exchange/requestitem.h"
#include "traffic/trafficlog.h"
#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "protocol/dissector.h"
#include "protocol/requestbuilder.h"
#include "sim/simendpoint.h"
#include "sim/simrange.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <functional>

using namespace mbscope;

namespace {

constexpr const char *kChildMode = "MBSCOPE_RECOVERY_CHILD";
constexpr const char *kChildPath = "MBSCOPE_RECOVERY_PATH";

// Child: poll forever, journaling every frame in small batches, until killed.
int journalChild(const QString &journalPath)
{
    Simulator sim;
    SimRange range;
    range.count = 10;
    for (int i = 0; i < 10; ++i)
        range.values.append(quint16(100 + i));
    QString error;
    if (!sim.addUnit(1)->addRange(range, &error))
        qFatal("%s", qPrintable(error));
    SimEndpoint *endpoint = sim.listen(QStringLiteral("tcp://127.0.0.1:0"), {}, &error);
    if (!endpoint)
        qFatal("%s", qPrintable(error));
    const LinkUrl url = endpoint->boundUrl();

    TrafficLog log;
    TrafficJournalWriter::Options options;
    options.batchEntries = 40;
    options.batchNs = 5'000'000;
    if (!log.openJournal(journalPath, options, false, &error))
        qFatal("%s", qPrintable(error));
    TransactionEngine engine;
    engine.setTarget(url);
    engine.setTrafficLog(&log);
    PollSettings poll;
    poll.items.append(RequestItem::forLink(AduBuilder::mbap(RequestBuilder::readHoldingRegisters(0, 10).pdu, 1, 1), url,
                                           QStringLiteral("read 10")));
    poll.intervalNs = 0; // back to back, with neither count nor duration: until killed
    engine.startPoll(poll);
    return QCoreApplication::exec();
}

SessionDocument bigDocument(const QString &name)
{
    SessionDocument d;
    d.name = name;
    d.notes = QString(4 * 1024 * 1024, name.at(0)); // a save takes a while: the kill lands in one
    return d;
}

// Child: save documents A and B in turn, saying "saved" after each, until killed.
int saveChild(const QString &path)
{
    const SessionDocument a = bigDocument(QStringLiteral("A"));
    const SessionDocument b = bigDocument(QStringLiteral("B"));
    QTextStream out(stdout);
    for (quint64 n = 0;; ++n) {
        QString error;
        if (!SessionWriter::save(n % 2 ? b : a, path, &error))
            qFatal("%s", qPrintable(error));
        out << "saved\n";
        out.flush();
    }
}

bool waitFor(const std::function<bool()> &condition, int ms)
{
    QDeadlineTimer deadline(ms);
    while (!condition()) {
        if (deadline.hasExpired())
            return false;
        QTest::qWait(10);
    }
    return true;
}

} // namespace

class TestSessionRecovery : public QObject
{
    Q_OBJECT

private slots:
    void killedPollRecovered();
    void killedSaveLeavesWholeFile();
};

void TestSessionRecovery::killedPollRecovered()
{
    QTemporaryDir dir;
    const QString journal = dir.filePath(QStringLiteral("poll.mbscope.journal"));
    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QLatin1String(kChildMode), QStringLiteral("journal"));
    env.insert(QLatin1String(kChildPath), journal);
    child.setProcessEnvironment(env);
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child.start(QCoreApplication::applicationFilePath(), {});
    QVERIFY2(child.waitForStarted(), qPrintable(child.errorString()));

    // Let it journal a good number of batches, copy what is on disk, let it run on, then kill it.
    QVERIFY2(waitFor([&] { return QFileInfo(journal).size() > 200'000; }, 60'000), "the child journals nothing");
    const QString snapshot = dir.filePath(QStringLiteral("snapshot.journal"));
    QVERIFY(QFile::copy(journal, snapshot));
    const qint64 snapshotSize = QFileInfo(snapshot).size();
    QVERIFY(waitFor([&] { return QFileInfo(journal).size() > snapshotSize + 50'000; }, 60'000));
    QCOMPARE(child.state(), QProcess::Running);
    child.kill(); // SIGKILL: no destructor runs, the pending batch is lost
    QVERIFY(child.waitForFinished());
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);

    // The session that names the journal, reopened.
    SessionDocument doc;
    doc.name = QStringLiteral("killed poll");
    doc.capture = SessionCapture{QStringLiteral("poll.mbscope.journal"), {}, {}};
    const QString docPath = dir.filePath(QStringLiteral("poll.mbscope.json"));
    QString error;
    QVERIFY2(SessionWriter::save(doc, docPath, &error), qPrintable(error));
    const SessionLoadResult loaded = SessionReader::load(docPath);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const RecoveredCapture capture = CaptureRecovery::open(*loaded.document, docPath);
    QVERIFY2(capture.ok(), qPrintable(capture.summary()));
    QCOMPARE(capture.journalPath, QFileInfo(journal).absoluteFilePath());

    // Everything that was on disk before the kill is there.
    QList<TrafficFrame> before;
    const TrafficJournalRecovery early = TrafficJournalReader::readAll(snapshot, &before);
    QVERIFY(early.frames > 0);
    QVERIFY2(capture.recovery.frames >= early.frames + 1, qPrintable(capture.summary()));
    QCOMPARE(quint64(capture.frames.size()), capture.recovery.frames);
    for (qsizetype i = 0; i < before.size(); ++i) {
        QCOMPARE(capture.frames.at(i).bytes, before.at(i).bytes);
        QCOMPARE(capture.frames.at(i).tNs, before.at(i).tNs);
    }
    // What the kill cut is at most the batch being written.
    QVERIFY(capture.recovery.fileBytes - capture.recovery.goodBytes < 40 * 64 + 64);

    // The frames are the poll: requests out, their answers in, every answer after its request.
    QHash<quint64, qint64> sentAt;
    quint64 answers = 0;
    for (const TrafficFrame &f : capture.frames) {
        const Dissection d = Dissector::dissect(f.bytes, {Framing::Tcp, f.direction == TrafficDirection::Out ? Direction::Request : Direction::Response, {}});
        QVERIFY2(d.isValid(), qPrintable(QStringLiteral("frame %1 does not dissect cleanly").arg(f.sequence)));
        if (f.direction == TrafficDirection::Out) {
            sentAt.insert(f.transactionId, f.tNs);
        } else {
            QVERIFY2(sentAt.contains(f.transactionId), "an answer without its request");
            QVERIFY(f.tNs >= sentAt.value(f.transactionId));
            ++answers;
        }
    }
    QVERIFY(answers > 100);

    // And the user is told how much.
    const QString summary = capture.summary();
    QVERIFY2(summary.startsWith(QStringLiteral("capture poll.mbscope.journal: recovered ")), qPrintable(summary));
    QVERIFY2(summary.contains(QLocale(QLocale::English).toString(qint64(capture.recovery.frames)) + QStringLiteral(" frames")), qPrintable(summary));
    qInfo("%s", qPrintable(summary));

    // A journal cut inside a batch (the kill's worst case, made certain): the batches before it
    // come back and the message says the last one was cut short.
    QFile file(journal);
    QVERIFY(file.resize(capture.recovery.goodBytes - 7));
    const RecoveredCapture cut = CaptureRecovery::open(*loaded.document, docPath, false);
    QCOMPARE(cut.recovery.ending, TrafficJournalRecovery::Ending::CutShort);
    QVERIFY(cut.recovery.frames < capture.recovery.frames);
    QCOMPARE(cut.recovery.batches, capture.recovery.batches - 1);
    QVERIFY2(cut.summary().contains(QStringLiteral("the last batch was cut short")), qPrintable(cut.summary()));
    QVERIFY2(cut.summary().endsWith(QStringLiteral("everything up to the last complete batch is kept)")), qPrintable(cut.summary()));
}

void TestSessionRecovery::killedSaveLeavesWholeFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.mbscope.json"));
    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QLatin1String(kChildMode), QStringLiteral("save"));
    env.insert(QLatin1String(kChildPath), path);
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(), {});
    QVERIFY2(child.waitForStarted(), qPrintable(child.errorString()));
    int saves = 0;
    QVERIFY2(waitFor([&] {
        saves += int(child.readAllStandardOutput().count("saved\n"));
        return saves >= 3;
    }, 120'000), "the child does not save");
    QTest::qWait(7); // land somewhere inside a later save
    child.kill();
    QVERIFY(child.waitForFinished());

    const SessionLoadResult loaded = SessionReader::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText().left(500)));
    QVERIFY(loaded.document->name == QLatin1String("A") || loaded.document->name == QLatin1String("B"));
    QVERIFY(*loaded.document == bigDocument(loaded.document->name));
}

int main(int argc, char *argv[])
{
    const QByteArray mode = qgetenv(kChildMode);
    if (!mode.isEmpty()) {
        QCoreApplication app(argc, argv);
        const QString path = qEnvironmentVariable(kChildPath);
        return mode == "journal" ? journalChild(path) : saveChild(path);
    }
    QCoreApplication app(argc, argv);
    TestSessionRecovery test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_sessionrecovery.moc"
