#include "commands.h"

#include "capture/analyzecommand.h"
#include "common/completioncommand.h"
#include "conform/conformcommand.h"
#include "capture/decodecommand.h"
#include "capture/exportcommand.h"
#include "map/exportmapcommand.h"
#include "map/infercommand.h"
#include "common/jsonfailure.h"
#include "monitor/monitorcommand.h"
#include "sim/simulatecommand.h"
#include "poll/pollcommand.h"
#include "exchange/readcommand.h"
#include "sim/replaycommand.h"
#include "exchange/runcommand.h"
#include "scan/scancommand.h"
#include "exchange/sendcommand.h"
#include "poll/sweepcommand.h"
#include "tap/tapcommand.h"
#include "service/watchcommand.h"
#include "exchange/writecommand.h"

#include <QtCore/QTextStream>

#include <cstring>

namespace mbscope::app {

namespace {

struct Subcommand {
    const char *name;
    const char *summary;
    int (*run)(const QStringList &arguments); // nullptr: runs in mbscope-full (see runsHere)
};

// The commands that need what the light executable leaves out (the simulator and its device
// scripts, Qt SerialBus, the watch service's HTTP server and MQTT, every subcommand's help at
// once) run in mbscope-full: `mbscope` execs it before it starts Qt (launcher.h). This file is
// compiled into both executables; MBSCOPE_LIGHT is defined for `mbscope`.
#ifdef MBSCOPE_LIGHT
#define MBSCOPE_FULL_ONLY(run) nullptr
#else
#define MBSCOPE_FULL_ONLY(run) run
#endif

#ifndef MBSCOPE_LIGHT
int runCompletionOfThese(const QStringList &arguments)
{
    return runCompletion(arguments, CommandLineIndex{&subcommandHelps, topLevelOptions()});
}
#endif

const Subcommand kSubcommands[] = {
    {"decode", "explain a Modbus frame field by field (hex argument or standard input)", runDecode},
    {"send", "send bytes exactly (or a PDU completed) and show the answer decoded and the latency", runSend},
    {"read", "read coils, inputs or registers and show the values in chosen formats", runRead},
    {"write", "write coils or holding registers", runWrite},
    {"poll", "send requests in cycles and print statistics: counts, latency percentiles, histogram", runPoll},
    {"monitor", "listen to a bus another master drives, never sending: every exchange paired and measured", runMonitor},
    {"watch", "run a session's watches headless: many devices at once, CSV, Prometheus metrics, MQTT", MBSCOPE_FULL_ONLY(runWatch)},
    {"sweep", "poll at several intervals and print error rate and latency per interval", runSweep},
    {"scan", "find what is on a link: unit ids that answer, a unit's register map (as a profile draft), limits", runScan},
    {"infer", "sample a unit's registers and propose types, orders, scales, units and kinds (a profile draft)", MBSCOPE_FULL_ONLY(runInfer)},
    {"conform", "judge a slave against the Modbus specifications: a scorecard of checks, each citing its clause", MBSCOPE_FULL_ONLY(runConform)},
    {"run", "run a session's test plan against a device; pass/fail per step, JUnit XML for CI", MBSCOPE_FULL_ONLY(runRun)},
    {"simulate", "serve a device profile as a Modbus server (the built-in simulator) until Ctrl-C", MBSCOPE_FULL_ONLY(runSimulate)},
    {"tap", "sit between masters and devices: forward every request (TCP to RTU and back, any link), record both legs, inject faults", MBSCOPE_FULL_ONLY(runTap)},
    {"analyze", "read a pcap, pcapng or traffic journal offline: pairs, decoded frames, statistics, histogram", MBSCOPE_FULL_ONLY(runAnalyze)},
    {"export", "write a capture or journal as CSV, JSON lines, pcapng for Wireshark, or latency plots", MBSCOPE_FULL_ONLY(runExport)},
    {"export-map", "write a device profile's register map for Node-RED, Telegraf, Home Assistant, modbus_exporter or CSV, verified first if asked", MBSCOPE_FULL_ONLY(runExportMap)},
    {"replay", "re-send a recording to a device and compare the answers, or serve it as a stand-in device", MBSCOPE_FULL_ONLY(runReplay)},
    {"completion", "print a bash or zsh completion script for these subcommands and their options", MBSCOPE_FULL_ONLY(runCompletionOfThese)},
};

void printUsage(QTextStream &out)
{
    out << "Usage: mbscope [SUBCOMMAND] [OPTIONS]\n\n"
        << "Without a subcommand mbscope opens its window.\n\nSubcommands:\n";
    for (const Subcommand &s : kSubcommands)
        out << "  " << QString::fromLatin1(s.name).leftJustified(12) << s.summary << '\n';
    out << "\nWindow options (without a subcommand; the man page says more):\n"
        << "  --session FILE   open a session document       --lang CODE    id, en or system\n"
        << "  --theme NAME     light, dark or system          --tab NAME     answer, decode or watches\n"
        << "  --dock NAME      show a dock at start           --start-watches  start the session's watches\n"
        << "  --no-simulator   start without the built-in simulator\n"
        << "  --new-instance   a window of its own (otherwise --session, --tab and --dock go to the running one)\n"
        << "  --screenshot FILE [--size WxH] [--screenshot-before-send] [--screenshot-poll COUNT [--poll-interval MS]]\n"
        << "                   render the window to a PNG and quit (after COUNT polls, MS apart; 0: back to back)\n"
        << "\nRun 'mbscope SUBCOMMAND --help' for a subcommand's options, 'mbscope --help-all' for every one's.\n";
}

} // namespace

QList<SubcommandHelp> subcommandHelps()
{
    // As --help-all does, each subcommand runs with --help; the text is captured, not printed.
    QList<SubcommandHelp> helps;
    HelpCapture capture;
    for (const Subcommand &s : kSubcommands) {
        if (s.run)
            s.run({QString::fromLatin1(s.name), QStringLiteral("--help")});
        helps.append({QString::fromLatin1(s.name), QString::fromLatin1(s.summary), capture.take()});
    }
    return helps;
}

QStringList topLevelOptions()
{
    return {QStringLiteral("--help"), QStringLiteral("-h"), QStringLiteral("--help-all"), QStringLiteral("--version")};
}

bool isSubcommand(const char *name)
{
    for (const Subcommand &s : kSubcommands) {
        if (std::strcmp(s.name, name) == 0)
            return true;
    }
    return false;
}

bool runsHere(const char *name)
{
    for (const Subcommand &s : kSubcommands) {
        if (std::strcmp(s.name, name) == 0)
            return s.run != nullptr;
    }
    return false;
}

bool hasGui()
{
#if defined(MBSCOPE_HAVE_UI) && !defined(MBSCOPE_LIGHT)
    return true;
#else
    return false;
#endif
}

int runHeadless(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QString first = arguments.value(1);
    if (first == QLatin1String("--version")) {
        out << "mbscope " << MBSCOPE_VERSION << '\n';
        return ExitOk;
    }
    if (first == QLatin1String("--help-all")) {
        // The usage, then each subcommand's own --help under a heading.
        printUsage(out);
        for (const Subcommand &s : kSubcommands) {
            out << "\n== mbscope " << s.name << " ==\n";
            out.flush();
            if (s.run)
                s.run({QString::fromLatin1(s.name), QStringLiteral("--help")});
        }
        return ExitOk;
    }
    if (first == QLatin1String("help") && arguments.size() > 2) {
        // `mbscope help NAME` is `mbscope NAME --help`.
        const QString name = arguments.at(2);
        for (const Subcommand &s : kSubcommands) {
            if (name != QLatin1String(s.name))
                continue;
            if (!s.run) {
                err << "mbscope: '" << name << "' runs in mbscope-full, which this executable could not start\n";
                return ExitUsage;
            }
            return s.run({name, QStringLiteral("--help")});
        }
        err << "mbscope help: unknown subcommand '" << name << "'\n";
        printUsage(err);
        return ExitUsage;
    }
    if (first.isEmpty() || first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
        printUsage(out);
        return first.isEmpty() && !hasGui() ? ExitUsage : ExitOk;
    }
    for (const Subcommand &s : kSubcommands) {
        if (first != QLatin1String(s.name))
            continue;
        if (!s.run) {
            // `mbscope` execs mbscope-full for these before it gets here (launcher.h).
            err << "mbscope: '" << first << "' runs in mbscope-full, which this executable could not start\n";
            return ExitUsage;
        }
        if (!arguments.contains(QLatin1String("--json")))
            return s.run(arguments.mid(1));
        // --json: standard output holds one JSON document, an error object when the command fails
        // before printing its result.
        JsonFailureReport report(first);
        return report.finish(s.run(arguments.mid(1)));
    }
    err << "mbscope: unknown subcommand '" << first << "'\n";
    printUsage(err);
    return ExitUsage;
}

} // namespace mbscope::app
