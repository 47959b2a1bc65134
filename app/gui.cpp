// The window: what `mbscope` runs without a subcommand.
#include "commands.h"
#include "instancehandover.h"
#include "common/interruptwatcher.h"

#include "link/linkcontroller.h"
#include "compose/requestcomposer.h"
#include "shell/mainwindow.h"
#include "shell/responsivenessprobe.h"
#include "traffic/trafficmonitor.h"
#include "session/sessioncontroller.h"
#include "decode/transactionview.h"
#include "watch/watchworkspace.h"
#include "shell/translationloader.h"
#include "common/theme.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonObject>
#include <QtCore/QRegularExpression>
#include <QtCore/QTimer>
#include <QtGui/QPixmap>
#include <QtWidgets/QApplication>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

namespace mbscope::app {

namespace {

// The --session argument, taken out of argv before QApplication could claim it.
QString g_sessionArgument;
bool g_sessionArgumentMissing = false;

// How long a screenshot waits for the first answer before it renders what is there.
constexpr int kScreenshotAnswerWaitMs = 3000;

bool saveScreenshot(QWidget &window, const QString &path)
{
    // Layout requests are posted events; deliver them so the grab shows final geometry.
    QCoreApplication::sendPostedEvents();
    const QPixmap shot = window.grab();
    return !shot.isNull() && shot.save(path, "PNG");
}

// --dock NAME: the dock whose object name is NAME or NAMEDock, or whose title is NAME (case and
// the mnemonic & ignored), shown and raised, so a screenshot can show any dock of the window.
bool raiseDock(MainWindow &window, const QString &name)
{
    const QList<QDockWidget *> docks = window.findChildren<QDockWidget *>();
    for (QDockWidget *dock : docks) {
        const QString title = dock->windowTitle().remove(QLatin1Char('&'));
        if (dock->objectName().compare(name, Qt::CaseInsensitive) == 0
            || dock->objectName().compare(name + QStringLiteral("Dock"), Qt::CaseInsensitive) == 0
            || title.compare(name, Qt::CaseInsensitive) == 0) {
            dock->show();
            dock->raise();
            return true;
        }
    }
    QStringList names;
    for (const QDockWidget *dock : docks)
        names += dock->windowTitle().remove(QLatin1Char('&')).toLower();
    std::fprintf(stderr, "mbscope: --dock '%s' names no dock of the window (it has: %s)\n", qPrintable(name),
                 qPrintable(names.join(QStringLiteral(", "))));
    return false;
}

// Renders the window once it is laid out and, on a first run, once the simulator's answer to
// the ready request is shown (or a few seconds passed), then quits: docs and GUI smoke tests use
// it with QT_QPA_PLATFORM=offscreen, so no display is needed.
// With pollCount > 0 the ready request is polled that many times, intervalMs apart (0: back to
// back), instead of sent once, the status bar's summary of the poll printed, and the window is
// rendered when the poll ends: the traffic list,
// the register table and the analysis dock then have something to show.
void scheduleScreenshot(QApplication &app, MainWindow &window, const QString &path, bool waitForAnswer, int pollCount,
                        int intervalMs)
{
    auto shoot = [&app, &window, path] {
        if (!saveScreenshot(window, path)) {
            std::fprintf(stderr, "mbscope: cannot write the screenshot to %s\n", qPrintable(path));
            app.exit(ExitFailure);
            return;
        }
        app.exit(ExitOk);
    };
    if (!waitForAnswer) {
        QTimer::singleShot(0, &window, shoot);
        return;
    }
    if (pollCount > 0) {
        // The analysis plots redraw in batches: a short wait after the poll lets the last one in.
        // The status bar's summary is printed too: an offscreen poll is a measurement to read.
        QObject::connect(window.controller(), &LinkController::pollFinished, &window,
                         [shoot](const PollReport &report) {
                             std::printf("%s\n", qPrintable(LinkController::describe(report)));
                             std::fflush(stdout);
                             QTimer::singleShot(400, shoot);
                         },
                         Qt::SingleShotConnection);
        // Rendered anyway when the poll has not ended by then (a device that stopped answering):
        // every request allowed its interval and 100 ms more.
        const qint64 fallbackMs = kScreenshotAnswerWaitMs + qint64(pollCount) * (intervalMs + 100);
        QTimer::singleShot(int(std::min<qint64>(fallbackMs, std::numeric_limits<int>::max())), &window, shoot);
        window.composer()->intervalSpin()->setValue(intervalMs);
        window.composer()->countSpin()->setValue(pollCount);
        QTimer::singleShot(0, &window, [&window] { window.composer()->togglePoll(); });
        return;
    }
    QObject::connect(window.answerView(), &TransactionView::transactionShown, &window,
                     [shoot] { QTimer::singleShot(50, shoot); }, Qt::SingleShotConnection);
    QTimer::singleShot(kScreenshotAnswerWaitMs, &window, shoot);
    QTimer::singleShot(0, &window, [&window] { window.composer()->send(); });
}

// What a second start handed over (InstanceHandover): its session opened (asking about unsaved
// changes first), its tab and dock shown, the window brought forward; the line the start prints.
QString takeRequest(MainWindow &window, const QJsonObject &request)
{
    if (window.isMinimized())
        window.showNormal();
    window.raise();
    window.activateWindow();
    QStringList done;
    const QString session = request.value(QStringLiteral("session")).toString();
    if (!session.isEmpty()) {
        if (!window.session()->openWithPrompt(session))
            return QStringLiteral("error: the running window did not open %1: %2")
                .arg(session, window.session()->lastProblems().isEmpty() ? QStringLiteral("kept the session it has")
                                                                         : window.session()->lastProblems().join(QStringLiteral("; ")));
        done << QStringLiteral("opened %1").arg(session);
    }
    const QString tab = request.value(QStringLiteral("tab")).toString();
    if (!tab.isEmpty() && !window.showTab(tab))
        return QStringLiteral("error: --tab '%1' names no tab of the main area (it has: answer, decode, watches)").arg(tab);
    const QString dock = request.value(QStringLiteral("dock")).toString();
    if (!dock.isEmpty() && !raiseDock(window, dock))
        return QStringLiteral("error: --dock '%1' names no dock of the window").arg(dock);
    if (done.isEmpty())
        done << QStringLiteral("came forward");
    return QStringLiteral("ok: the running window (pid %1) %2; --new-instance opens another")
        .arg(QCoreApplication::applicationPid())
        .arg(done.join(QStringLiteral(", ")));
}

} // namespace

bool guiWantsOffscreen(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--screenshot") == 0 || std::strncmp(argv[i], "--screenshot=", 13) == 0)
            return true;
    }
    return false;
}

void takeSessionArgument(int &argc, char *argv[])
{
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--session") == 0 || std::strcmp(argv[i], "-session") == 0) {
            if (i + 1 < argc)
                g_sessionArgument = QString::fromLocal8Bit(argv[++i]);
            else
                g_sessionArgumentMissing = true;
            continue;
        }
        if (std::strncmp(argv[i], "--session=", 10) == 0) {
            g_sessionArgument = QString::fromLocal8Bit(argv[i] + 10);
            continue;
        }
        argv[kept++] = argv[i];
    }
    argc = kept;
    argv[argc] = nullptr;
}

int runGui(QApplication &app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("mbscope: the Modbus test and analysis workbench. Without a "
                                                    "subcommand it opens the window; `mbscope help` lists the subcommands."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshotOption(QStringLiteral("screenshot"),
                                              QStringLiteral("Render the window offscreen to FILE (PNG) and exit."),
                                              QStringLiteral("FILE"));
    const QCommandLineOption sizeOption(QStringLiteral("size"),
                                        QStringLiteral("Window size WIDTHxHEIGHT (default 1400x900)."),
                                        QStringLiteral("WxH"));
    const QCommandLineOption noSimulatorOption(QStringLiteral("no-simulator"),
                                               QStringLiteral("Start disconnected instead of with the built-in simulator."));
    const QCommandLineOption sessionOption(QStringLiteral("session"),
                                           QStringLiteral("Open the session FILE (*.mbscope.json) at start: its target, requests "
                                                          "and poll settings; the built-in simulator is not started."),
                                           QStringLiteral("FILE"));
    const QCommandLineOption beforeSendOption(QStringLiteral("screenshot-before-send"),
                                              QStringLiteral("With --screenshot: render the first run as it opens, before "
                                                             "the ready request is sent."));
    const QCommandLineOption dockOption(QStringLiteral("dock"),
                                        QStringLiteral("Show and raise the dock NAME (traffic, registers, ...) at start."),
                                        QStringLiteral("NAME"));
    const QCommandLineOption pollOption(QStringLiteral("screenshot-poll"),
                                        QStringLiteral("With --screenshot: poll the first run's request COUNT times "
                                                       "(1 to 100000000), --poll-interval apart, and render when the poll ends."),
                                        QStringLiteral("COUNT"));
    const QCommandLineOption pollIntervalOption(QStringLiteral("poll-interval"),
                                                QStringLiteral("With --screenshot-poll: milliseconds from the start of one request "
                                                               "to the start of the next (default 20; 0: back to back, as fast as "
                                                               "the simulator answers)."),
                                                QStringLiteral("MS"));
    const QCommandLineOption langOption(QStringLiteral("lang"),
                                        QStringLiteral("Language of the window for this run: id (Bahasa Indonesia), en "
                                                       "(English) or system; without it, the choice in Preferences."),
                                        QStringLiteral("CODE"));
    const QCommandLineOption themeOption(QStringLiteral("theme"),
                                         QStringLiteral("Colours of the window for this run: light, dark or system (the "
                                                        "desktop's); without it, the choice in Preferences."),
                                         QStringLiteral("NAME"));
    const QCommandLineOption tabOption(QStringLiteral("tab"),
                                       QStringLiteral("Show the tab NAME of the main area (answer, decode, watches) at start."),
                                       QStringLiteral("NAME"));
    const QCommandLineOption startWatchesOption(QStringLiteral("start-watches"),
                                                QStringLiteral("Start the session's watches at start (Workspace > Start all); "
                                                               "with --screenshot, render a few seconds later."));
    const QCommandLineOption newInstanceOption(QStringLiteral("new-instance"),
                                               QStringLiteral("Open a window of its own even when one is running (without it, "
                                                              "--session, --tab and --dock go to the running window)."));
    parser.addOptions({screenshotOption, sizeOption, noSimulatorOption, sessionOption, beforeSendOption, dockOption, pollOption,
                       pollIntervalOption, langOption, themeOption, tabOption, startWatchesOption, newInstanceOption});
    if (!parser.parse(QCoreApplication::arguments())) {
        std::fprintf(stderr, "mbscope: %s\nUsage: mbscope [--screenshot FILE] [--size WxH] [--no-simulator] [--session FILE] [--screenshot-before-send] [--screenshot-poll COUNT [--poll-interval MS]] [--dock NAME] [--lang CODE] [--theme NAME] [--tab NAME] [--start-watches] [--new-instance]\n",
                     qPrintable(parser.errorText()));
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        std::printf("%s", qPrintable(parser.helpText()));
        return ExitOk;
    }
    if (parser.isSet(QStringLiteral("version"))) {
        std::printf("mbscope %s\n", qPrintable(QCoreApplication::applicationVersion()));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        std::fprintf(stderr, "mbscope: unexpected argument '%s'\n", qPrintable(parser.positionalArguments().constFirst()));
        return ExitUsage;
    }

    QSize size(1400, 900);
    if (parser.isSet(sizeOption)) {
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("^(\\d{3,5})[xX](\\d{3,5})$")).match(parser.value(sizeOption));
        if (!m.hasMatch()) {
            std::fprintf(stderr, "mbscope: --size '%s' is not WIDTHxHEIGHT (e.g. 1400x900, each 100-99999)\n",
                         qPrintable(parser.value(sizeOption)));
            return ExitUsage;
        }
        size = QSize(m.captured(1).toInt(), m.captured(2).toInt());
    }
    // MBSCOPE_SCREENSHOT is kept for scripts (run-mbscope.sh, the CTest smoke test).
    QString screenshot = parser.value(screenshotOption);
    if (screenshot.isEmpty())
        screenshot = qEnvironmentVariable("MBSCOPE_SCREENSHOT");

    // QSettings (recent targets, saved requests) under ~/.config/mbscope/.
    if (QCoreApplication::organizationName().isEmpty())
        QCoreApplication::setOrganizationName(QStringLiteral("mbscope"));
    // The language: --lang, else Preferences, else the system's (LANG=id_ID.UTF-8 gives Indonesian).
    TranslationLoader::Choice language = TranslationLoader::storedChoice();
    if (parser.isSet(langOption)) {
        const std::optional<TranslationLoader::Choice> asked = TranslationLoader::parse(parser.value(langOption));
        if (!asked) {
            std::fprintf(stderr, "mbscope: --lang '%s' is not a language mbscope speaks: use id, en or system\n",
                         qPrintable(parser.value(langOption)));
            return ExitUsage;
        }
        language = *asked;
    }
    TranslationLoader::install(app, TranslationLoader::localeFor(language));
    // The colours: --theme, else Preferences, else the desktop's.
    Theme::Choice theme = Theme::storedChoice();
    if (parser.isSet(themeOption)) {
        const std::optional<Theme::Choice> asked = Theme::parse(parser.value(themeOption));
        if (!asked) {
            std::fprintf(stderr, "mbscope: --theme '%s' is not a theme: use light, dark or system\n",
                         qPrintable(parser.value(themeOption)));
            return ExitUsage;
        }
        theme = *asked;
    }
    Theme::apply(theme);
    // SIGTERM (a logout, systemctl, kill) and Ctrl-C in the terminal that started it end the window
    // without asking (nobody may be there to answer), but as a quit does: the event loop returns,
    // the connection's journal is closed and marked closed, so the next start offers no recovery.
    InterruptWatcher interrupts;
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &app, [&app, &interrupts] {
        std::fprintf(stderr, "mbscope: %s: closing the window and its recording\n",
                     interrupts.signalNumber() == SIGTERM ? "SIGTERM" : "interrupted");
        app.exit(ExitOk);
    });

    const QString sessionPath = parser.isSet(sessionOption) ? parser.value(sessionOption) : g_sessionArgument;
    if (g_sessionArgumentMissing || (parser.isSet(sessionOption) && sessionPath.isEmpty())) {
        std::fprintf(stderr, "mbscope: --session needs a FILE (a *.mbscope.json session)\n");
        return ExitUsage;
    }
    // A window already running on the same data (journal, layout, ports) takes this start's
    // session, tab and dock; a screenshot is a run of its own.
    InstanceHandover handover;
    const bool ownWindow = parser.isSet(newInstanceOption) || !screenshot.isEmpty();
    if (!ownWindow) {
        QJsonObject request;
        if (!sessionPath.isEmpty())
            request.insert(QStringLiteral("session"), QFileInfo(sessionPath).absoluteFilePath());
        if (parser.isSet(tabOption))
            request.insert(QStringLiteral("tab"), parser.value(tabOption));
        if (parser.isSet(dockOption))
            request.insert(QStringLiteral("dock"), parser.value(dockOption));
        QString answer;
        if (InstanceHandover::handOver(request, &answer)) {
            std::fprintf(stderr, "mbscope: %s\n", qPrintable(answer));
            return answer.startsWith(QLatin1String("ok")) ? ExitOk : ExitFailure;
        }
    }

    MainWindow window;
    if (!ownWindow && !handover.listen([&window](const QJsonObject &request) { return takeRequest(window, request); }))
        std::fprintf(stderr, "mbscope: later starts open windows of their own (%s)\n", qPrintable(handover.errorString()));
    // A screenshot or an asked size is reproducible: the layout the last close saved is not used.
    if (!screenshot.isEmpty() || parser.isSet(sizeOption) || !window.restoreLayout())
        window.resize(size);
    bool simulated = false;
    if (!sessionPath.isEmpty()) {
        // Said on standard error too: a screenshot run has nobody to read a dialog.
        window.session()->setProblemReport([&screenshot, &window](const QString &path, const QStringList &problems) {
            std::fprintf(stderr, "mbscope: the session %s was not opened:\n", qPrintable(path));
            for (const QString &problem : problems)
                std::fprintf(stderr, "  %s\n", qPrintable(problem));
            if (screenshot.isEmpty())
                QMessageBox::warning(&window, QObject::tr("Session not opened"),
                                     QObject::tr("%1 was not opened:\n%2").arg(path, problems.join(QLatin1Char('\n'))));
        });
        if (!window.session()->open(sessionPath) && !screenshot.isEmpty())
            return ExitFailure;
    } else if (!parser.isSet(noSimulatorOption)) {
        // A screenshot is the first run as documented; a user's start is as Preferences says.
        simulated = screenshot.isEmpty() ? window.startAsConfigured() : window.startWithSimulator();
    }
    window.show();

    if (parser.isSet(dockOption) && !raiseDock(window, parser.value(dockOption)))
        return ExitUsage;
    if (parser.isSet(tabOption) && !window.showTab(parser.value(tabOption))) {
        std::fprintf(stderr, "mbscope: --tab '%s' names no tab of the main area (it has: answer, decode, watches)\n",
                     qPrintable(parser.value(tabOption)));
        return ExitUsage;
    }
    const bool startWatches = parser.isSet(startWatchesOption);
    if (startWatches)
        window.watchWorkspace()->startAll();
    int pollCount = 0;
    if (parser.isSet(pollOption)) {
        bool countOk = false;
        pollCount = parser.value(pollOption).toInt(&countOk);
        if (!countOk || pollCount < 1 || pollCount > 100000000) {
            std::fprintf(stderr, "mbscope: --screenshot-poll '%s' is not a count from 1 to 100000000\n",
                         qPrintable(parser.value(pollOption)));
            return ExitUsage;
        }
    }
    int pollIntervalMs = 20;
    if (parser.isSet(pollIntervalOption)) {
        bool intervalOk = false;
        pollIntervalMs = parser.value(pollIntervalOption).toInt(&intervalOk);
        if (!intervalOk || pollIntervalMs < 0 || pollIntervalMs > 3600000) {
            std::fprintf(stderr, "mbscope: --poll-interval '%s' is not a number of milliseconds from 0 to 3600000\n",
                         qPrintable(parser.value(pollIntervalOption)));
            return ExitUsage;
        }
        if (!parser.isSet(pollOption)) {
            std::fprintf(stderr, "mbscope: --poll-interval goes with --screenshot-poll COUNT (the window's own polls "
                                 "take the interval in the composer)\n");
            return ExitUsage;
        }
    }
    if (!screenshot.isEmpty() && startWatches) {
        // The watches' first answers, and a few more polls for the counters.
        QTimer::singleShot(kScreenshotAnswerWaitMs, &window, [&app, &window, screenshot] {
            const bool saved = saveScreenshot(window, screenshot);
            if (!saved)
                std::fprintf(stderr, "mbscope: cannot write the screenshot to %s\n", qPrintable(screenshot));
            app.exit(saved ? ExitOk : ExitFailure);
        });
    } else if (!screenshot.isEmpty()) {
        scheduleScreenshot(app, window, screenshot, simulated && !parser.isSet(beforeSendOption), simulated ? pollCount : 0,
                           pollIntervalMs);
    }

    bool ok = false;
    const int quitAfterMs = qEnvironmentVariableIntValue("MBSCOPE_QUIT_AFTER_MS", &ok);
    if (ok && quitAfterMs >= 0)
        QTimer::singleShot(quitAfterMs, &app, &QCoreApplication::quit);
    // How fast the window answers while it works (bench_windowsoak): menus opened and the traffic
    // list moved every N ms, the figures on standard error at the end.
    std::unique_ptr<ResponsivenessProbe> probe;
    const int probeMs = qEnvironmentVariableIntValue("MBSCOPE_RESPONSIVENESS_MS", &ok);
    if (ok && probeMs > 0) {
        auto *traffic = window.findChild<TrafficMonitor *>();
        probe = std::make_unique<ResponsivenessProbe>(&window, traffic ? traffic->view() : nullptr, probeMs);
        QObject::connect(&app, &QCoreApplication::aboutToQuit, &app, [&probe] {
            std::fprintf(stderr, "responsiveness: %s\n", qPrintable(probe->summary()));
        });
    }

    return app.exec();
}

} // namespace mbscope::app
