#include "watchcommand.h"

#include "cli.h"
#include "hangupwatcher.h"
#include "interruptwatcher.h"
#include "watchservice.h"

#include "fleet/watchrunner.h"
#include "session/sessionreader.h"
#include "watch/watchcsvlog.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QEventLoop>
#include <QtCore/QFileInfo>
#include <QtCore/QSet>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

#include <csignal>
#include <memory>

namespace mbscope::app {

namespace {

// The session's watches, or why not (said with where).
std::optional<SessionWatches> loadWatches(const QString &path, QString *error)
{
    const SessionLoadResult loaded = SessionReader::load(path);
    if (!loaded.ok()) {
        *error = loaded.errorText();
        return std::nullopt;
    }
    const SessionWatches &watches = loaded.document->watches;
    bool any = false;
    for (const WatchDefinition &w : watches.watches)
        any = any || w.enabled;
    if (!any) {
        *error = QStringLiteral("%1: no enabled watches (the session's \"watches\" section, docs/sessions.md)").arg(path);
        return std::nullopt;
    }
    return watches;
}

int linkCount(const SessionWatches &watches)
{
    QSet<QString> targets;
    for (const WatchDefinition &w : watches.watches) {
        if (w.enabled)
            targets.insert(w.target);
    }
    return int(targets.size());
}

// CSV logging: --csv DIR, else the session's watchLog when enabled (relative to the session).
class CsvLogging
{
public:
    CsvLogging(ServiceLog &log, QString directory, QString sessionDir)
        : m_log(log), m_directory(std::move(directory)), m_sessionDir(std::move(sessionDir))
    {
    }

    bool open(const SessionWatches &watches, QString *error)
    {
        close();
        m_watches = watches;
        WatchLogSettings settings;
        if (!m_directory.isEmpty()) {
            settings = watches.log.value_or(WatchLogSettings{});
            settings.directory = m_directory;
        } else if (watches.log && watches.log->enabled) {
            settings = *watches.log;
        } else {
            return true;
        }
        m_csv = std::make_unique<WatchCsvLog>(settings, m_sessionDir);
        if (!m_csv->open(watches.watches, error)) {
            m_csv.reset();
            return false;
        }
        m_log.notice(QStringLiteral("CSV: a file per watch in %1").arg(m_csv->directory()));
        return true;
    }

    void append(const QList<WatchSample> &samples)
    {
        if (!m_csv)
            return;
        for (const WatchSample &s : samples) {
            QString error;
            if (!m_csv->append(s.watch, s.timeMs, watchSampleStatusName(s.status), s.values, s.error, &error) &&
                error != m_lastError) {
                m_log.error(QStringLiteral("CSV: %1").arg(error));
                m_lastError = error;
            }
        }
    }

    void close()
    {
        if (m_csv)
            m_csv->close();
        m_csv.reset();
    }

private:
    ServiceLog &m_log;
    QString m_directory;
    QString m_sessionDir;
    SessionWatches m_watches;
    std::unique_ptr<WatchCsvLog> m_csv;
    QString m_lastError;
};

} // namespace

int runWatch(const QStringList &arguments)
{
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Runs a session's watches headless until stopped (SIGTERM or Ctrl-C), as a service: values logged to CSV, served to "
        "Prometheus, published to MQTT. SIGHUP reads the session again. One line per event on standard error, with its level.\n"
        "Example: mbscope watch lab.mbscope.json --metrics 127.0.0.1:9464 --mqtt mqtt://broker.lan/lab1\n"
        "Exit status: 0 after a clean stop, 2 for unusable options or a session that does not read."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("session"), QStringLiteral("The session document (*.mbscope.json) whose watches run."));
    parser.addOption({QStringLiteral("csv"),
                      QStringLiteral("Log every watch's values to CSV, a file per watch in DIR (default: the session's watchLog, when enabled)."),
                      QStringLiteral("DIR")});
    WatchService::addOptions(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope watch: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << subcommandHelp(parser.helpText(), "watch");
        return ExitOk;
    }
    if (parser.positionalArguments().size() != 1) {
        err << "mbscope watch: name one session document (mbscope watch SESSION.mbscope.json)\n";
        return ExitUsage;
    }
    const QString sessionPath = parser.positionalArguments().first();
    QString error;
    const std::optional<WatchService::Options> options = WatchService::readOptions(parser, sessionPath, &error);
    if (!options) {
        err << "mbscope watch: " << error << '\n';
        return ExitUsage;
    }
    std::optional<SessionWatches> watches = loadWatches(sessionPath, &error);
    if (!watches) {
        err << "mbscope watch: " << error << '\n';
        return ExitUsage;
    }

    WatchRunner runner(*watches);
    WatchService service(runner, *options);
    ServiceLog &log = service.log();
    if (!service.start(&error)) {
        err << "mbscope watch: " << error << '\n';
        return ExitUsage;
    }
    CsvLogging csv(log, parser.value(QStringLiteral("csv")), QFileInfo(sessionPath).absolutePath());
    if (!csv.open(*watches, &error)) {
        err << "mbscope watch: --csv: " << error << '\n';
        service.stop();
        return ExitUsage;
    }
    QObject::connect(&runner, &WatchRunner::sampled, &runner,
                     [&csv](const QList<WatchSample> &samples, const QList<WatchCounters> &) { csv.append(samples); });

    const auto begin = [&](const SessionWatches &w) {
        service.setWatches(w);
        log.notice(QStringLiteral("watching %1 watches on %2 links from %3").arg(w.watches.size()).arg(linkCount(w)).arg(sessionPath));
    };
    begin(*watches);
    runner.start();

    HangupWatcher hangup;
    QObject::connect(&hangup, &HangupWatcher::hangup, &runner, [&] {
        QString why;
        std::optional<SessionWatches> again = loadWatches(sessionPath, &why);
        if (!again) {
            log.error(QStringLiteral("SIGHUP: the session does not read, the running watches stay: %1").arg(why));
            return;
        }
        log.notice(QStringLiteral("SIGHUP: reading %1 again").arg(sessionPath));
        // The runner's counters start anew, and so do the metrics and CSV files of the new set.
        runner.setWatches(*again);
        begin(*again);
        if (!csv.open(*again, &why))
            log.error(QStringLiteral("CSV: %1").arg(why));
    });

    QEventLoop loop;
    InterruptWatcher interrupt;
    QObject::connect(&interrupt, &InterruptWatcher::interrupted, &loop, [&] {
        log.notice(QStringLiteral("stopping (%1)").arg(interrupt.signalNumber() == SIGINT ? QStringLiteral("SIGINT") : QStringLiteral("SIGTERM")));
        runner.stop();
        // The runner says stopped() once every link is closed; a link stuck in a system call
        // does not keep the service from stopping.
        QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    });
    QObject::connect(&runner, &WatchRunner::stopped, &loop, &QEventLoop::quit);
    loop.exec();
    csv.close();
    service.stop();
    log.notice(QStringLiteral("stopped"));
    return ExitOk;
}

} // namespace mbscope::app
