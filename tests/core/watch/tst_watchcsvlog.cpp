// WatchCsvLog: a file per watch with a header of names and units, a row per poll or per change,
// failed polls with their error and empty values, quoting, rolling by size and by time; rule
// events in a file of their own; a FIFO's short answers padded to the header; a folder removed
// made again, one that cannot be made said and its rows counted as lost.
#include "watch/watchcsvlog.h"

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

WatchDefinition gamma()
{
    WatchDefinition w;
    w.name = QStringLiteral("gamma counts");
    w.address = 0x86;
    w.quantity = 2;
    WatchPoint p;
    p.address = 0x86;
    p.name = QStringLiteral("counts, gated");
    p.unit = QStringLiteral("cps");
    w.points.append(p);
    return w;
}

QList<WatchPointValue> values(const QString &a, const QString &b)
{
    WatchPointValue x;
    x.text = a;
    WatchPointValue y;
    y.text = b;
    return {x, y};
}

QStringList lines(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

constexpr qint64 kT0 = 1'795'000'000'000; // 2026-11-18T...Z

} // namespace

class TestWatchCsvLog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void rowsPerPoll();
    void rowsOnChange();
    void rollBySize();
    void rollByTime();
    void relativeDirectory();
    void ruleEvents();
    void fifoRowsHaveEveryColumn();
    void folderMadeAgain();
    void lostRowsCounted();
};

void TestWatchCsvLog::rowsPerPoll()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.filePath(QStringLiteral("logs"));
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("150"), QStringLiteral("0"))));
    QVERIFY(log.append(0, kT0 + 500, QStringLiteral("timeout"), {}, QStringLiteral("no answer within 1000 ms")));
    QVERIFY(log.append(0, kT0 + 1000, QStringLiteral("ok"), values(QStringLiteral("150"), QStringLiteral("0"))));
    log.close();
    QCOMPARE(log.files().size(), 1);
    QVERIFY(QFileInfo(log.files().first()).fileName().startsWith(QLatin1String("gamma_counts-")));
    const QStringList rows = lines(log.files().first());
    QCOMPARE(rows.size(), 4);
    QCOMPARE(rows.at(0), QStringLiteral("time,status,\"counts, gated [cps]\",0x0087,error"));
    QCOMPARE(rows.at(1), QDateTime::fromMSecsSinceEpoch(kT0, Qt::UTC).toString(Qt::ISODateWithMs) + QStringLiteral(",ok,150,0,"));
    QVERIFY(rows.at(2).endsWith(QLatin1String(",timeout,,,no answer within 1000 ms")));
}

void TestWatchCsvLog::rowsOnChange()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.path();
    settings.mode = WatchLogSettings::Mode::OnChange;
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    for (const auto &[a, b] : {std::pair{"1", "0"}, {"1", "0"}, {"2", "0"}, {"2", "0"}, {"2", "1"}})
        QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QLatin1String(a), QLatin1String(b))));
    QVERIFY(log.append(0, kT0, QStringLiteral("timeout"), {}, QStringLiteral("no answer")));
    QVERIFY(log.append(0, kT0, QStringLiteral("timeout"), {}, QStringLiteral("no answer")));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("2"), QStringLiteral("1"))));
    log.close();
    // header, 1/0, 2/0, 2/1, the first timeout, ok again
    QCOMPARE(lines(log.files().first()).size(), 6);
}

void TestWatchCsvLog::rollBySize()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.path();
    settings.rollBytes = 200;
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    int rows = 0;
    for (int i = 0; i < 20; ++i) {
        // A second apart, so that each file has a name of its own.
        QVERIFY(log.append(0, kT0 + i * 1000, QStringLiteral("ok"), values(QString::number(i), QStringLiteral("0"))));
        ++rows;
    }
    log.close();
    QVERIFY2(log.files().size() >= 4, qPrintable(log.files().join(QLatin1Char(' '))));
    int total = 0;
    for (const QString &f : log.files()) {
        const QStringList r = lines(f);
        QVERIFY(r.first().startsWith(QLatin1String("time,status,"))); // every file has its header
        QVERIFY(QFileInfo(f).size() < 200 + 60);                      // passes 200 by one row at most
        total += int(r.size()) - 1;
    }
    QCOMPARE(total, rows);
}

void TestWatchCsvLog::rollByTime()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.path();
    settings.rollSeconds = 60;
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    for (int i = 0; i < 5; ++i) // 0, 30, 60, 90, 120 s
        QVERIFY(log.append(0, kT0 + i * 30'000, QStringLiteral("ok"), values(QString::number(i), QStringLiteral("0"))));
    log.close();
    QCOMPARE(log.files().size(), 3);
    QCOMPARE(lines(log.files().at(0)).size(), 3);
    QCOMPARE(lines(log.files().at(2)).size(), 2);
}

void TestWatchCsvLog::relativeDirectory()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = QStringLiteral("logs/gamma");
    WatchCsvLog log(settings, dir.path());
    QCOMPARE(log.directory(), QDir::cleanPath(dir.path() + QStringLiteral("/logs/gamma")));
    QVERIFY(log.open({gamma()}));
    QVERIFY(QFileInfo(log.directory()).isDir());
}

void TestWatchCsvLog::ruleEvents()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.path();
    settings.mode = WatchLogSettings::Mode::OnChange; // events are written in either mode
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("150"), QStringLiteral("0"))));
    WatchRuleEvent e;
    e.watch = 0;
    e.rule = 1;
    e.severity = WatchSeverity::Alarm;
    e.point = QStringLiteral("counts, gated");
    e.value = 150.5;
    e.message = QStringLiteral("counts, gated above 100 cps for 2 polls");
    e.timeMs = kT0 + 500;
    e.firedCount = 1;
    QVERIFY(log.appendEvent(e));
    e.fired = false;
    e.value = 80;
    e.timeMs = kT0 + 1500;
    QVERIFY(log.appendEvent(e));
    e.watch = 5; // no such watch: nothing written
    QVERIFY(log.appendEvent(e));
    log.close();
    QCOMPARE(log.files().size(), 2);
    QVERIFY(QFileInfo(log.files().at(1)).fileName().startsWith(QLatin1String("gamma_counts-events-")));
    const QStringList rows = lines(log.files().at(1));
    QCOMPARE(rows.size(), 3);
    QCOMPARE(rows.at(0), WatchCsvLog::eventHeader());
    QCOMPARE(rows.at(1), QDateTime::fromMSecsSinceEpoch(kT0 + 500, Qt::UTC).toString(Qt::ISODateWithMs)
                             + QStringLiteral(",fired,alarm,1,\"counts, gated\",150.5,\"counts, gated above 100 cps for 2 polls\",1"));
    QVERIFY(rows.at(2).contains(QLatin1String(",cleared,alarm,1,\"counts, gated\",80,")));
    QCOMPARE(lines(log.files().at(0)).size(), 2); // the values' file: its header and one row
}

// A FIFO of at most 4 values that holds 2: the row has the header's columns (failed before: 2 short).
void TestWatchCsvLog::fifoRowsHaveEveryColumn()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.path();
    WatchCsvLog log(settings);
    WatchDefinition fifo;
    fifo.name = QStringLiteral("queue");
    fifo.function = 0x18;
    fifo.address = 0x04DE;
    fifo.quantity = 4;
    QVERIFY(log.open({fifo}));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("440"), QStringLiteral("4740"))));
    log.close();
    const QStringList rows = lines(log.files().first());
    QCOMPARE(rows.at(0).split(QLatin1Char(',')).size(), 7);
    QCOMPARE(rows.at(1).split(QLatin1Char(',')).size(), 7);
    QVERIFY(rows.at(1).endsWith(QLatin1String(",ok,440,4740,,,")));
}

void TestWatchCsvLog::folderMadeAgain()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.filePath(QStringLiteral("logs"));
    settings.rollBytes = 100;
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("1"), QStringLiteral("0"))));
    QVERIFY(log.append(0, kT0 + 1000, QStringLiteral("ok"), values(QStringLiteral("2"), QStringLiteral("0"))));
    QVERIFY(QDir(settings.directory).removeRecursively());
    QVERIFY(log.append(0, kT0 + 2000, QStringLiteral("ok"), values(QStringLiteral("3"), QStringLiteral("0"))));
    log.close();
    QCOMPARE(log.lostRows(), 0u);
    QVERIFY(QFileInfo::exists(log.files().constLast()));
    QCOMPARE(lines(log.files().constLast()).size(), 2);
}

void TestWatchCsvLog::lostRowsCounted()
{
    QTemporaryDir dir;
    WatchLogSettings settings;
    settings.directory = dir.filePath(QStringLiteral("logs"));
    settings.rollBytes = 100;
    WatchCsvLog log(settings);
    QVERIFY(log.open({gamma()}));
    QVERIFY(log.append(0, kT0, QStringLiteral("ok"), values(QStringLiteral("1"), QStringLiteral("0"))));
    QVERIFY(log.append(0, kT0 + 1000, QStringLiteral("ok"), values(QStringLiteral("2"), QStringLiteral("0"))));
    // A file where the folder was: the next file cannot be started.
    QVERIFY(QDir(settings.directory).removeRecursively());
    QFile blocker(settings.directory);
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    QString error;
    QVERIFY(!log.append(0, kT0 + 2000, QStringLiteral("ok"), values(QStringLiteral("3"), QStringLiteral("0")), {}, &error));
    QCOMPARE(error, settings.directory + QStringLiteral(": the log directory cannot be made"));
    QVERIFY(!log.append(0, kT0 + 3000, QStringLiteral("ok"), values(QStringLiteral("4"), QStringLiteral("0"))));
    QCOMPARE(log.lostRows(), 2u);
}

QTEST_GUILESS_MAIN(TestWatchCsvLog)
#include "tst_watchcsvlog.moc"
