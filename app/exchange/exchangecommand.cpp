#include "exchange/exchangecommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "exchange/deviceexchange.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

namespace mbscope::app {

std::optional<int> parseExchangeCommand(const ExchangeCommandSpec &spec, const QStringList &arguments,
                                        QTextStream &out, QTextStream &err, ExchangeCommandInput &input)
{
    const QString command = QString::fromLatin1(spec.name);
    QCommandLineParser parser;
    parser.setApplicationDescription(spec.description);
    parser.addHelpOption();
    const TargetOptions targetOptions;
    const RequestOptions requestOptions(spec.requestGroups);
    const QCommandLineOption jsonOpt(QStringLiteral("json"), spec.jsonHelp);
    const QCommandLineOption terseOpt(QStringList{QStringLiteral("q"), QStringLiteral("terse")},
                                      QStringLiteral("Print only the values, one a line as mbpoll prints them: [ADDRESS]: "
                                                     "VALUE (counted from 1 with --one-based); a failed transaction is said "
                                                     "on standard error."));
    const QCommandLineOption onceOpt(QStringList{QStringLiteral("1"), QStringLiteral("once")},
                                     QStringLiteral("Read once, which read always does: accepted for mbpoll's -1 (mbscope "
                                                    "poll polls, with -1 once)."));
    const RecordOptions recordOptions;
    const PrintOptions printOptions(false);
    targetOptions.addTo(parser);
    requestOptions.addTo(parser);
    parser.addOption(jsonOpt);
    if (spec.readOutput)
        parser.addOptions({terseOpt, onceOpt});
    recordOptions.addTo(parser);
    printOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope " << command << ": " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), spec.name);
        return ExitOk;
    }
    if (!targetOptions.read(parser, command, input.target, err, spec.positionalHint)
        || !requestOptions.read(parser, command, input.target, input.plan, err)
        || !recordOptions.read(parser, command, input.record, err, printOptions.frameLogSet(parser))
        || !printOptions.read(parser, command, input.record.overwrite, input.print, err))
        return ExitUsage;
    input.json = parser.isSet(jsonOpt);
    input.terse = spec.readOutput && parser.isSet(terseOpt);
    if (input.json && input.terse) {
        err << "mbscope " << command << ": -q/--terse prints values as text lines, --json one JSON document: give one "
            << "of them\n";
        return ExitUsage;
    }
    return std::nullopt;
}

std::optional<QList<Transaction>> runExchangeCommand(const ExchangeCommandSpec &spec, const QStringList &arguments,
                                                   const ExchangeCommandInput &input, QTextStream &err)
{
    const QString command = QString::fromLatin1(spec.name);
    FrameLog frames;
    if (!openFrameLog(frames, input.print, command, err))
        return std::nullopt;
    TrafficRecording recording;
    if (!openRecording(recording, input.record, clientMetadata(command, arguments, input.target, input.plan), command, err))
        return std::nullopt;
    const QList<Transaction> records = exchange(input.target, input.plan.requests,
                                                recording.isOpen() ? recording.log() : nullptr,
                                                frames.isOpen() ? &frames : nullptr);
    finishRecording(recording, err);
    return records;
}

} // namespace mbscope::app
