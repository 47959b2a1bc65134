#include "exchangecommand.h"

#include "cli.h"

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
    const RecordOptions recordOptions;
    targetOptions.addTo(parser);
    requestOptions.addTo(parser);
    parser.addOption(jsonOpt);
    recordOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope " << command << ": " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), spec.name);
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope " << command << ": unexpected argument '" << parser.positionalArguments().constFirst()
            << "': " << spec.positionalHint << '\n';
        return ExitUsage;
    }
    if (!targetOptions.read(parser, command, input.target, err)
        || !requestOptions.read(parser, command, input.target, input.plan, err)
        || !recordOptions.read(parser, command, input.record, err))
        return ExitUsage;
    input.json = parser.isSet(jsonOpt);
    return std::nullopt;
}

} // namespace mbscope::app
