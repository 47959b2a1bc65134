#include "capture/analyzecommand.h"

#include "capture/captureinput.h"
#include "common/cli.h"
#include "plot/exchangeplots.h"
#include "common/outputpath.h"
#include "plot/plotfile.h"

#include "capture/captureanalysis.h"
#include "capture/exchangesource.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

int runAnalyze(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Reads a capture offline and analyses its Modbus traffic without any device: a pcap or pcapng file (Wireshark, "
        "tcpdump, dumpcap, mbscope export --pcap) with Modbus TCP, Modbus UDP or RTU over TCP, an mbscope traffic "
        "journal, or a session document (its captured traffic). Requests are paired with their answers (the transaction id for MBAP; order, unit and function for RTU), "
        "every frame is decoded, and the statistics are those poll prints: counts by outcome, latency percentiles, "
        "histogram. Latency is the capture time of the answer's last packet minus the request's.\n"
        "Example, a capture made first (with mbscope simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:4001 "
        "running):\n"
        "  mbscope poll --target rtu-tcp://127.0.0.1:4001 --address 0x79 --quantity 10 --count 20 --interval 0 --record bench.mbscope.journal\n"
        "  mbscope export bench.mbscope.journal --pcap bench.pcapng\n"
        "  mbscope analyze bench.pcapng --histogram latency.svg\n"
        "A damaged file is analysed up to the damage, which is reported with its byte offset. Packets the capture lost "
        "are counted as gaps (bytes never captured, per conversation and direction) and framing resumes at the next "
        "frame, so only the exchanges whose packets were lost count as timeouts or unmatched answers.\n"
        "Without --port and --rtu-port, a capture with no traffic on port 502 is searched for Modbus TCP and RTU over "
        "TCP or UDP on any port, and what is found is analysed (stderr says which port). With them, the ports are "
        "kept and an error names the ports where Modbus was found.\n"
        "Exit status: 0 every transaction ok, 1 some failed, the file is damaged or it holds no Modbus traffic, "
        "2 usage error (also: no Modbus on the ports given, but on others) or unreadable file."));
    parser.addHelpOption();
    const CaptureInput input;
    input.addTo(parser);
    const QCommandLineOption histogramOpt(QStringLiteral("histogram"),
                                          QStringLiteral("Draw the latency histogram into a file: .png, .svg or .pdf."),
                                          QStringLiteral("file"));
    const QCommandLineOption timeSeriesOpt(QStringLiteral("timeseries"),
                                           QStringLiteral("Draw latency over time into a file: .png, .svg or .pdf."),
                                           QStringLiteral("file"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the statistics as JSON (poll --json's shape, "
                                                                            "with \"source\", \"conversations\", \"functions\" and \"units\")."));
    const QCommandLineOption forceOpt = OutputPath::forceOption();
    parser.addOptions({histogramOpt, timeSeriesOpt, jsonOpt, forceOpt});
    parser.addPositionalArgument(QStringLiteral("capture"), QStringLiteral("A .pcap, .pcapng or traffic journal file, or a session document with a capture."));
    if (!parser.parse(arguments)) {
        err << "mbscope analyze: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "analyze");
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope analyze: " << (positional.isEmpty() ? QStringLiteral("no capture given") : QStringLiteral("one capture at a time"))
            << ": mbscope analyze CAPTURE [options]\n";
        return ExitUsage;
    }
    CaptureOptions options;
    QString error;
    if (!input.read(parser, &options, &error)) {
        err << "mbscope analyze: " << error << '\n';
        return ExitUsage;
    }
    for (const QCommandLineOption &plot : {histogramOpt, timeSeriesOpt}) {
        if (!parser.isSet(plot))
            continue;
        const QString problem = PlotFile::formatProblem(parser.value(plot));
        if (!problem.isEmpty()) {
            err << "mbscope analyze: --" << plot.names().constFirst() << ' ' << problem << '\n';
            return ExitUsage;
        }
        // The file is written once the capture is read: said now if it cannot be.
        const QString option = QStringLiteral("--") + plot.names().constFirst();
        const QString unwritable = OutputPath::problem(option, parser.value(plot), option + QStringLiteral(" latency.svg"), parser.isSet(forceOpt));
        if (!unwritable.isEmpty()) {
            err << "mbscope analyze: " << unwritable << '\n';
            return ExitUsage;
        }
    }
    QString path;
    if (!CaptureInput::resolve(positional.constFirst(), &path, &error)) {
        err << "mbscope analyze: " << error << '\n';
        return ExitUsage;
    }

    CaptureAnalysis analysis;
    ExchangePlots plots(parser.isSet(timeSeriesOpt));
    const auto read = [&](const CaptureOptions &with) {
        return ExchangeSource::read(path, with, [&](const CaptureExchange &exchange) {
            analysis.add(exchange);
            plots.add(exchange);
        });
    };
    ExchangeSourceReport report = read(options);
    if (!report.isReadable()) {
        err << "mbscope analyze: " << path << ": " << report.error << '\n';
        return ExitUsage;
    }
    // No Modbus on the ports asked (so nothing was analysed yet): the ports where it was found
    // instead, used when the ports were the defaults, offered when the user named them.
    const CaptureInput::Fallback fallback = input.fallback(parser, options, report, QStringLiteral("analysed"));
    switch (fallback.action) {
    case CaptureInput::Fallback::Action::Retry:
        err << "mbscope analyze: " << fallback.message << '\n';
        report = read(fallback.options);
        break;
    case CaptureInput::Fallback::Action::Refuse:
        err << "mbscope analyze: " << fallback.message << '\n';
        return ExitUsage;
    case CaptureInput::Fallback::Action::Nothing:
    case CaptureInput::Fallback::Action::Keep:
        break;
    }
    if (parser.isSet(jsonOpt))
        out << QJsonDocument(analysis.toJson(report)).toJson(QJsonDocument::Indented);
    else
        out << analysis.summary(report);
    out.flush();
    if (!report.error.isEmpty())
        err << "mbscope analyze: " << path << ": " << report.error << "; everything before it was analysed\n";
    if (fallback.action == CaptureInput::Fallback::Action::Nothing)
        err << "mbscope analyze: " << fallback.message << '\n';

    int status = ExitOk;
    // Each plot written gets the line poll prints for its own ("plot          FILE"), on the text
    // output only: --json keeps standard output one JSON document.
    const auto wrote = [&](const QString &file) {
        if (!parser.isSet(jsonOpt))
            out << "plot          " << file << '\n';
    };
    if (parser.isSet(histogramOpt)) {
        if (ExchangePlots::writeHistogram(parser.value(histogramOpt), path, analysis.statistics(), &error)) {
            wrote(parser.value(histogramOpt));
        } else {
            err << "mbscope analyze: --histogram: " << error << '\n';
            status = ExitFailure;
        }
    }
    if (parser.isSet(timeSeriesOpt)) {
        if (plots.writeTimeSeries(parser.value(timeSeriesOpt), path, &error)) {
            wrote(parser.value(timeSeriesOpt));
        } else {
            err << "mbscope analyze: --timeseries: " << error << '\n';
            status = ExitFailure;
        }
    }
    out.flush();
    if (!report.error.isEmpty() || analysis.statistics().failed() > 0 || analysis.unmatchedResponses() > 0
        || fallback.action == CaptureInput::Fallback::Action::Nothing)
        status = ExitFailure;
    return status;
}

} // namespace mbscope::app
