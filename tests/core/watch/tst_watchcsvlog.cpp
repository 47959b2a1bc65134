// WatchCsvLog: a file per watch with a header of names and units, a row per poll or per change,
// failed polls with their error and empty values, quoting, rolling by size and by time.
#include "watch/watchcsvlog.h"

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

QTEST_GUILESS_MAIN(TestWatchCsvLog)
#include "tst_watchcsvlog.moc"
