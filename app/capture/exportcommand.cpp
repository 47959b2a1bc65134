#include "capture/exportcommand.h"

#include "capture/captureinput.h"
#include "common/cli.h"
#include "plot/exchangeplots.h"
#include "common/outputpath.h"
#include "plot/plotfile.h"

#include "capture/captureanalysis.h"
#include "capture/capturefilewriter.h"
#include "capture/exchangewriter.h"
#include "capture/exchangesource.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QTextStream>


namespace mbscope::app {

int runExport(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Writes the transactions of a capture (pcap, pcapng), an mbscope traffic journal or a session document's "
        "captured traffic out again:\n"
        "  --csv: one row per transaction: times, unit, function, address, quantity, values, latency, status, bytes;\n"
        "  --jsonl: the same as one JSON object per line;\n"
        "  --pcap: packets Wireshark and tshark decode as Modbus (pcapng, or classic pcap for a name ending in .pcap), "
        "each conversation a TCP connection with correct checksums between its own addresses; RTU frames go to their own "
        "port, for which the tshark option to decode them is printed; a journal's serial line goes, in pcapng, on an "
        "interface named after the port (decoded by tshark -d rtacser.data,mbrtu);\n"
        "  --histogram, --timeseries: the latency histogram and latency over time as PNG, SVG or PDF.\n"
        "Use - as the file to write CSV or JSON lines to standard output. A file that exists is refused unless --force "
        "is given (the policy of every command's output files).\n"
        "Example, a journal recorded first (with mbscope simulate --profile rosrao-gamma --listen tcp://127.0.0.1:5020 "
        "running):\n"
        "  mbscope poll --target tcp://127.0.0.1:5020 --address 0x79 --quantity 10 --count 20 --interval 0 --record bench.mbscope.journal\n"
        "  mbscope export bench.mbscope.journal --csv bench.csv --pcap bench.pcapng\n"
        "Without --port and --rtu-port, a capture with no traffic on port 502 is searched for Modbus on any port, as "
        "analyze does.\n"
        "Exit status: 0 written, 1 written from a damaged source (up to the damage) or one without Modbus traffic, "
        "2 usage error (also: no Modbus on the ports given, but on others), unreadable source or an output that could "
        "not be written."));
    parser.addHelpOption();
    const CaptureInput input;
    input.addTo(parser);
    const QCommandLineOption csvOpt(QStringLiteral("csv"), QStringLiteral("Write CSV, one row per transaction."), QStringLiteral("file"));
    const QCommandLineOption jsonlOpt(QStringLiteral("jsonl"), QStringLiteral("Write JSON lines, one object per transaction."),
                                      QStringLiteral("file"));
    const QCommandLineOption pcapOpt(QStringLiteral("pcap"), QStringLiteral("Write a capture: pcapng, or pcap for a name ending in .pcap."),
                                     QStringLiteral("file"));
    const QCommandLineOption histogramOpt(QStringLiteral("histogram"), QStringLiteral("Draw the latency histogram: .png, .svg or .pdf."),
                                          QStringLiteral("file"));
    const QCommandLineOption timeSeriesOpt(QStringLiteral("timeseries"), QStringLiteral("Draw latency over time: .png, .svg or .pdf."),
                                           QStringLiteral("file"));
    const QCommandLineOption forceOpt = OutputPath::forceOption();
    parser.addOptions({csvOpt, jsonlOpt, pcapOpt, histogramOpt, timeSeriesOpt, forceOpt});
    parser.addPositionalArgument(QStringLiteral("source"), QStringLiteral("A .pcap, .pcapng or traffic journal file, or a session document with a capture."));
    if (!parser.parse(arguments)) {
        err << "mbscope export: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "export");
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope export: " << (positional.isEmpty() ? QStringLiteral("no source given") : QStringLiteral("one source at a time"))
            << ": mbscope export SOURCE --csv FILE | --jsonl FILE | --pcap FILE | --histogram FILE | --timeseries FILE\n";
        return ExitUsage;
    }
    const QList<QCommandLineOption> outputs{csvOpt, jsonlOpt, pcapOpt, histogramOpt, timeSeriesOpt};
    bool any = false;
    for (const QCommandLineOption &o : outputs)
        any = any || parser.isSet(o);
    if (!any) {
        err << "mbscope export: nothing to write: give --csv, --jsonl, --pcap, --histogram or --timeseries with a file name\n";
        return ExitUsage;
    }
    CaptureOptions options;
    QString error;
    if (!input.read(parser, &options, &error)) {
        err << "mbscope export: " << error << '\n';
        return ExitUsage;
    }
    QString path;
    if (!CaptureInput::resolve(positional.constFirst(), &path, &error)) {
        err << "mbscope export: " << error << '\n';
        return ExitUsage;
    }
    for (const QCommandLineOption &o : outputs) {
        if (parser.isSet(o) && QFileInfo(parser.value(o)) == QFileInfo(path)) {
            err << "mbscope export: --" << o.names().constFirst() << " would overwrite the source " << path << '\n';
            return ExitUsage;
        }
    }
    if (parser.isSet(csvOpt) && parser.isSet(jsonlOpt) && parser.value(csvOpt) == QLatin1String("-")
        && parser.value(jsonlOpt) == QLatin1String("-")) {
        err << "mbscope export: --csv and --jsonl cannot both go to standard output\n";
        return ExitUsage;
    }
    for (const QCommandLineOption &plot : {histogramOpt, timeSeriesOpt}) {
        const QString problem = parser.isSet(plot) ? PlotFile::formatProblem(parser.value(plot)) : QString();
        if (!problem.isEmpty()) {
            err << "mbscope export: --" << plot.names().constFirst() << ' ' << problem << '\n';
            return ExitUsage;
        }
    }
    // Every output under one policy (OutputPath): an existing file is refused unless --force, a
    // new one must be creatable, all said before the source is read.
    for (const QCommandLineOption &o : outputs) {
        if (!parser.isSet(o))
            continue;
        const QString option = QStringLiteral("--") + o.names().constFirst();
        const QString problem = OutputPath::problem(option, parser.value(o), option + QStringLiteral(" FILE"), parser.isSet(forceOpt));
        if (!problem.isEmpty()) {
            err << "mbscope export: " << problem << '\n';
            return ExitUsage;
        }
    }

    // One writer per output asked for, each as the window's Save Traffic As writes it.
    struct Output {
        const QCommandLineOption *option;
        TrafficFormat format;
        ExchangeWriter writer;
        bool open = false;
    };
    const QString pcapFile = parser.value(pcapOpt);
    Output written[] = {
        {&csvOpt, TrafficFormat::Csv, {}, false},
        {&jsonlOpt, TrafficFormat::JsonLines, {}, false},
        {&pcapOpt, CaptureFileWriter::formatFor(pcapFile), {}, false},
    };
    for (Output &o : written) {
        if (!parser.isSet(*o.option))
            continue;
        if (!o.writer.open(parser.value(*o.option), o.format, &error)) {
            err << "mbscope export: " << error << '\n';
            return ExitUsage;
        }
        o.open = true;
    }

    CaptureAnalysis analysis;
    ExchangePlots plots(parser.isSet(timeSeriesOpt));
    const auto onConversation = [&](const CaptureConversation &c) {
        for (Output &o : written) {
            if (o.open)
                o.writer.addConversation(c);
        }
    };
    const auto onExchange = [&](const CaptureExchange &e) {
        for (Output &o : written) {
            if (o.open)
                o.writer.add(e);
        }
        analysis.add(e);
        plots.add(e);
    };
    ExchangeSourceReport report = ExchangeSource::read(path, options, onExchange, onConversation);
    if (!report.isReadable()) {
        err << "mbscope export: " << path << ": " << report.error << '\n';
        return ExitUsage;
    }
    // No Modbus on the ports asked, so nothing was written but the outputs' headers: as analyze.
    const CaptureInput::Fallback fallback = input.fallback(parser, options, report, QStringLiteral("exported"));
    switch (fallback.action) {
    case CaptureInput::Fallback::Action::Retry:
        err << "mbscope export: " << fallback.message << '\n';
        report = ExchangeSource::read(path, fallback.options, onExchange, onConversation);
        break;
    case CaptureInput::Fallback::Action::Refuse:
        err << "mbscope export: " << fallback.message << '\n';
        return ExitUsage;
    case CaptureInput::Fallback::Action::Nothing:
        err << "mbscope export: " << fallback.message << '\n';
        break;
    case CaptureInput::Fallback::Action::Keep:
        break;
    }

    int status = report.error.isEmpty() && fallback.action != CaptureInput::Fallback::Action::Nothing ? ExitOk : ExitFailure;
    if (!report.error.isEmpty())
        err << "mbscope export: " << path << ": " << report.error << "; everything before it was exported\n";
    // What was written goes to stderr when a table goes to standard output.
    const bool toStdout = (parser.isSet(csvOpt) && parser.value(csvOpt) == QLatin1String("-"))
        || (parser.isSet(jsonlOpt) && parser.value(jsonlOpt) == QLatin1String("-"));
    QTextStream &note = toStdout ? err : out;
    for (Output &o : written) {
        if (!o.open)
            continue;
        const QString file = parser.value(*o.option);
        if (!o.writer.close(&error)) {
            err << "mbscope export: " << error << '\n';
            status = ExitUsage;
        } else if (o.format == TrafficFormat::Csv) {
            if (file != QLatin1String("-"))
                note << "csv      " << file << ": " << o.writer.rows() << " row(s)\n";
        } else if (o.format == TrafficFormat::JsonLines) {
            if (file != QLatin1String("-"))
                note << "jsonl    " << file << ": " << o.writer.rows() << " line(s)\n";
        } else {
            note << "pcap     " << file << ": " << o.writer.packets() << " packet(s), "
                 << (o.format == TrafficFormat::Pcap ? "pcap" : "pcapng") << '\n';
            // Ports tshark does not know by itself (Wireshark: Analyze > Decode As...).
            for (const QString &option : o.writer.decodeOptions())
                note << "         " << option << '\n';
        }
    }
    if (parser.isSet(histogramOpt)) {
        if (!ExchangePlots::writeHistogram(parser.value(histogramOpt), path, analysis.statistics(), &error)) {
            err << "mbscope export: --histogram: " << error << '\n';
            status = ExitUsage;
        } else {
            note << "histogram " << parser.value(histogramOpt) << '\n';
        }
    }
    if (parser.isSet(timeSeriesOpt)) {
        if (!plots.writeTimeSeries(parser.value(timeSeriesOpt), path, &error)) {
            err << "mbscope export: --timeseries: " << error << '\n';
            status = ExitUsage;
        } else {
            note << "timeseries " << parser.value(timeSeriesOpt) << '\n';
        }
    }
    return status;
}

} // namespace mbscope::app
