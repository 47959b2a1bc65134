// The live frame log (--print frames, --frame-log FILE) on every command that talks to a device,
// end to end (issue 30): each command runs against the built-in simulator with --print frames and
// --record JOURNAL at once, and the frame log must hold exactly the frames the journal holds, with
// their directions, verdicts and bytes: both come from the one place the engines record frames
// (EngineRecorder), so a frame missing from one, or a second pairing of its own, shows here. The
// order is compared too where one engine talks; where several do (the timing scan's clients,
// watch's links), their batches interleave as they come, so only the lines are compared.
#include "clitest.h"

#include "exchange/trafficentry.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

const QString kSourceDir = QStringLiteral(MBSCOPE_SOURCE_DIR);

// A frame as the frame log writes it after its time stamp: "out sent        01 03 ...".
QString frameText(const TrafficEntry &e)
{
    const QString verdict = QString::fromLatin1(trafficVerdictName(e.verdict));
    QString text = QLatin1String(e.direction == TrafficDirection::Out ? "out " : "in  ") + verdict;
    if (!e.bytes.isEmpty())
        text += QString(qMax(1, 12 - int(verdict.size())), QLatin1Char(' ')) + QString::fromLatin1(e.bytes.toByteArray().toHex(' ').toUpper());
    return text;
}

// The frame lines of a log, without their time stamps; "-- link URL" lines go to links.
QStringList logFrames(const QString &log, QStringList *links = nullptr)
{
    static const QRegularExpression stamp(QStringLiteral(R"(^\d\d:\d\d:\d\d\.\d{6} )"));
    QStringList frames;
    for (const QString &line : log.split(QLatin1Char('\n'))) {
        if (stamp.match(line).hasMatch())
            frames.append(line.mid(16));
        else if (links && line.startsWith(QLatin1String("-- link ")))
            links->append(line.mid(8));
    }
    return frames;
}

QStringList journalFrames(const QString &path)
{
    QStringList frames;
    (void)TrafficJournalReader::read(path, [&](const TrafficEntry &e) { frames.append(frameText(e)); });
    return frames;
}

} // namespace

class TestCliFrameLog : public QObject
{
    Q_OBJECT

    Background m_sim;    // rosrao-gamma on tcp
    Background m_rtuSim; // rosrao-gamma on rtu-tcp: the example plan's framing
    QString m_url;
    QString m_rtuUrl;
    QTemporaryDir m_dir;
    int m_runs = 0;

private Q_SLOTS:
    void initTestCase();
    void sameFramesAsTheJournal_data();
    void sameFramesAsTheJournal();
    void toAFile();
    void refusedWhereNothingIsSent();
};

void TestCliFrameLog::initTestCase()
{
    QVERIFY2(QFileInfo::exists(mbscopePath()), qPrintable(mbscopePath()));
    QVERIFY(m_dir.isValid());
    QString error;
    QVERIFY2(m_sim.start(sl({"simulate", "--profile", "rosrao-gamma", "--listen", "tcp://127.0.0.1:0"}), &error), qPrintable(error));
    m_url = m_sim.url();
    QVERIFY2(m_rtuSim.start(sl({"simulate", "--profile", "rosrao-gamma", "--listen", "rtu-tcp://127.0.0.1:0"}), &error),
             qPrintable(error));
    m_rtuUrl = m_rtuSim.url();
    // Two watches on two links, polled twice each.
    const QByteArray session = QStringLiteral(R"({"format": "mbscope-session", "version": 2, "watches": [
        {"name": "tcp", "target": "%1", "address": "0x0079", "quantity": 4, "intervalMs": 50},
        {"name": "rtu", "target": "%2", "address": "0x0079", "quantity": 2, "intervalMs": 50}]})")
                                   .arg(m_url, m_rtuUrl)
                                   .toUtf8();
    QVERIFY(writeFile(m_dir.filePath(QStringLiteral("watches.mbscope.json")), session));
    // A journal to replay: two reads.
    const CliResult recorded = runMbscope({QStringLiteral("poll"), QStringLiteral("-r"), QStringLiteral("121"), QStringLiteral("--count"),
                                           QStringLiteral("2"), QStringLiteral("-l"), QStringLiteral("0"), QStringLiteral("--record"),
                                           m_dir.filePath(QStringLiteral("replayed.mbscope.journal")), m_url});
    QVERIFY2(recorded.exitCode == 0, recorded.describe());
}

void TestCliFrameLog::sameFramesAsTheJournal_data()
{
    QTest::addColumn<QStringList>("arguments"); // TARGET: the tcp simulator; RTU: the rtu-tcp one; DIR: the scratch folder
    QTest::addColumn<bool>("ordered");
    QTest::addColumn<int>("minFrames");
    QTest::newRow("read") << sl({"read", "-r", "121", "-c", "4", "TARGET"}) << true << 2;
    QTest::newRow("read, exception") << sl({"read", "-r", "0", "TARGET"}) << true << 2;
    QTest::newRow("write") << sl({"write", "-r", "127", "--registers", "1000", "--single", "TARGET"}) << true << 2;
    QTest::newRow("poll") << sl({"poll", "-r", "121", "--count", "5", "-l", "0", "TARGET"}) << true << 10;
    QTest::newRow("sweep") << sl({"sweep", "-r", "121", "--intervals", "0,1", "--count", "2", "TARGET"}) << true << 8;
    QTest::newRow("scan units") << sl({"scan", "--target", "TARGET", "--units", "1-5"}) << true << 6;
    QTest::newRow("scan map") << sl({"scan", "--target", "TARGET", "--map", "1", "--addresses", "100-160", "--tables", "3",
                                     "--no-optional"})
                              << true << 4;
    QTest::newRow("scan timing") << sl({"scan", "--target", "TARGET", "--timing", "1", "--clients", "3", "--max-time", "20s"})
                                 << false << 10;
    QTest::newRow("run") << sl({"run", "SOURCE/docs/examples/rosrao-gamma.mbscope.json", "--target", "RTU"}) << true << 10;
    QTest::newRow("watch") << sl({"watch", "DIR/watches.mbscope.json", "--count", "2", "--quiet"}) << false << 8;
    QTest::newRow("conform") << sl({"conform", "--target", "TARGET", "--only", "exception,read.03,mbap", "--timeout", "300ms", "--samples", "3"})
                             << true << 20;
    QTest::newRow("infer, map scan then samples") << sl({"infer", "TARGET", "--addresses", "115-130", "--tables", "3", "--samples",
                                                        "3", "--interval", "10ms"})
                                                  << true << 8;
    QTest::newRow("replay") << sl({"replay", "DIR/replayed.mbscope.journal", "--target", "TARGET", "--speed", "max"}) << true << 4;
}

// Each command with the frame log on standard error and a journal: the same frames in both.
void TestCliFrameLog::sameFramesAsTheJournal()
{
    QFETCH(QStringList, arguments);
    QFETCH(bool, ordered);
    QFETCH(int, minFrames);
    for (QString &a : arguments) {
        a.replace(QStringLiteral("TARGET"), m_url);
        a.replace(QStringLiteral("RTU"), m_rtuUrl);
        a.replace(QStringLiteral("SOURCE"), kSourceDir);
        a.replace(QStringLiteral("DIR"), m_dir.path());
    }
    const QString journal = m_dir.filePath(QStringLiteral("run%1.mbscope.journal").arg(++m_runs));
    const CliResult r = runMbscope(QStringList(arguments) << QStringLiteral("--print") << QStringLiteral("frames")
                                                          << QStringLiteral("--record") << journal);
    QVERIFY2(r.finished && (r.exitCode == 0 || r.exitCode == 1), r.describe());
    QStringList links;
    QStringList logged = logFrames(r.errText(), &links);
    QStringList recorded = journalFrames(journal);
    QVERIFY2(recorded.size() >= minFrames, r.describe());
    QVERIFY2(recorded.filter(QRegularExpression(QStringLiteral("^out sent "))).size() * 2 >= minFrames, r.describe());
    if (!ordered) {
        std::sort(logged.begin(), logged.end());
        std::sort(recorded.begin(), recorded.end());
    }
    if (logged != recorded) {
        const qsizetype n = std::min(logged.size(), recorded.size());
        qsizetype i = 0;
        while (i < n && logged.at(i) == recorded.at(i))
            ++i;
        QFAIL(qPrintable(QStringLiteral("%1 frames logged, %2 journaled; first difference at %3: '%4' against '%5'\n%6")
                             .arg(logged.size())
                             .arg(recorded.size())
                             .arg(i + 1)
                             .arg(logged.value(i), recorded.value(i), QString::fromUtf8(r.describe()))));
    }
    // Several links: each batch says which.
    if (arguments.constFirst() == QLatin1String("watch")) {
        QVERIFY2(links.contains(m_url) && links.contains(m_rtuUrl), r.describe());
    }
}

void TestCliFrameLog::toAFile()
{
    const QString path = m_dir.filePath(QStringLiteral("scan.frames"));
    const QStringList arguments{QStringLiteral("scan"), QStringLiteral("--target"), m_url, QStringLiteral("--units"),
                                QStringLiteral("1-3"), QStringLiteral("--frame-log"), path};
    const CliResult r = runMbscope(arguments);
    QVERIFY2(r.exitCode == 0, r.describe());
    QVERIFY2(logFrames(r.errText()).isEmpty(), r.describe());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList frames = logFrames(QString::fromUtf8(file.readAll()));
    QCOMPARE(frames.filter(QRegularExpression(QStringLiteral("^out sent "))).size(), 3);
    // Refused once it exists, without --force.
    const CliResult again = runMbscope(arguments);
    QVERIFY2(again.exitCode == 2 && again.errText().contains(QLatin1String("--frame-log")), again.describe());
}

// replay --serve answers, it sends nothing of its own: said, not ignored.
void TestCliFrameLog::refusedWhereNothingIsSent()
{
    const CliResult r = runMbscope({QStringLiteral("replay"), m_dir.filePath(QStringLiteral("replayed.mbscope.journal")),
                                    QStringLiteral("--serve"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--print"),
                                    QStringLiteral("frames")});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.errText().contains(QLatin1String("--print frames")) && r.errText().contains(QLatin1String("--serve")), r.describe());
}

QTEST_GUILESS_MAIN(TestCliFrameLog)
#include "tst_cli_framelog.moc"
