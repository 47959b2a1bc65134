// packaging/mbscope-watch@.service, the watch service's template unit: systemd's own checker
// (systemd-analyze verify) accepts an instance of it with the build's mbscope in place of
// /usr/bin/mbscope, its sandbox is what the man page promises (DynamicUser, ProtectSystem=strict,
// the dialout group only, reload by SIGHUP, stop by SIGTERM), and systemd-analyze security rates
// its exposure (printed, and kept in the "OK" band or better).
#include "processrun.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope::testpackaging;

namespace {

QString readUnit()
{
    QFile f(QStringLiteral(MBSCOPE_WATCH_UNIT));
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

} // namespace

class TestSystemdUnit : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void sandbox_data();
    void sandbox();
    void manPageDocumentsIt();
    void systemdAcceptsIt();
    void exposure();

private:
    QString m_unit;
    QTemporaryDir m_dir;
    QString m_instance;
};

void TestSystemdUnit::initTestCase()
{
    m_unit = readUnit();
    QVERIFY2(!m_unit.isEmpty(), MBSCOPE_WATCH_UNIT);
    QVERIFY(m_dir.isValid());
    // An instance with the build's executable, since systemd checks the command exists.
    m_instance = m_dir.filePath(QStringLiteral("mbscope-watch@lab1.service"));
    QFile out(m_instance);
    QVERIFY(out.open(QIODevice::WriteOnly));
    QString text = m_unit;
    QVERIFY2(text.contains(QLatin1String("ExecStart=/usr/bin/mbscope watch ")), "ExecStart runs /usr/bin/mbscope watch");
    text.replace(QLatin1String("ExecStart=/usr/bin/mbscope"), QStringLiteral("ExecStart=") + QStringLiteral(MBSCOPE_EXECUTABLE));
    out.write(text.toUtf8());
}

void TestSystemdUnit::sandbox_data()
{
    QTest::addColumn<QString>("line");
    for (const char *line : {"DynamicUser=yes", "ProtectSystem=strict", "SupplementaryGroups=dialout", "ProtectHome=yes",
                             "ExecReload=/bin/kill -HUP $MAINPID", "KillSignal=SIGTERM", "Restart=on-failure",
                             "StateDirectory=mbscope-watch/%i", "EnvironmentFile=-/etc/mbscope/%i.env",
                             "ExecStart=/usr/bin/mbscope watch /etc/mbscope/%i.mbscope.json --quiet $MBSCOPE_WATCH_OPTIONS", "SuccessExitStatus=1"})
        QTest::newRow(line) << QString::fromLatin1(line);
}

void TestSystemdUnit::sandbox()
{
    QFETCH(QString, line);
    QVERIFY2(m_unit.split(QLatin1Char('\n')).contains(line), qPrintable(line + QStringLiteral(" is not in the unit")));
}

void TestSystemdUnit::manPageDocumentsIt()
{
    QFile man(QStringLiteral(MBSCOPE_MAN_PAGE));
    QVERIFY(man.open(QIODevice::ReadOnly));
    const QString page = QString::fromUtf8(man.readAll());
    for (const char *word : {"mbscope\\-watch@.service", "DynamicUser=", "ProtectSystem=strict", "dialout", "SIGHUP", "SIGTERM",
                             "/etc/mbscope/NAME.env", "MBSCOPE_WATCH_OPTIONS"})
        QVERIFY2(page.contains(QLatin1String(word)), word);
}

void TestSystemdUnit::systemdAcceptsIt()
{
    const QString analyze = QStandardPaths::findExecutable(QStringLiteral("systemd-analyze"));
    if (analyze.isEmpty())
        QSKIP("systemd-analyze is not installed (Debian: systemd)");
    const ProcessRun run = runProcess(analyze, {QStringLiteral("--man=no"), QStringLiteral("verify"), m_instance}, {}, 60000);
    QVERIFY2(run.finished && run.exitCode == 0 && run.err.trimmed().isEmpty() && run.out.trimmed().isEmpty(), run.describe().constData());
}

void TestSystemdUnit::exposure()
{
    const QString analyze = QStandardPaths::findExecutable(QStringLiteral("systemd-analyze"));
    if (analyze.isEmpty())
        QSKIP("systemd-analyze is not installed (Debian: systemd)");
    const ProcessRun run =
        runProcess(analyze, {QStringLiteral("security"), QStringLiteral("--offline=yes"), QStringLiteral("--man=no"), m_instance}, {}, 60000);
    static const QRegularExpression overall(QStringLiteral(R"(Overall exposure level for \S+: ([0-9.]+) (\w+))"));
    const QRegularExpressionMatch m = overall.match(run.outText() + run.errText());
    if (!m.hasMatch())
        QSKIP(qPrintable(QStringLiteral("systemd-analyze security --offline is not available: ") + run.errText()));
    qInfo("systemd-analyze security: exposure %s (%s); 10 is unprotected, below 4 is 'OK'", qPrintable(m.captured(1)),
          qPrintable(m.captured(2)));
    QVERIFY2(m.captured(1).toDouble() < 4.0, qPrintable(m.captured(0)));
}

QTEST_GUILESS_MAIN(TestSystemdUnit)
#include "tst_systemdunit.moc"
