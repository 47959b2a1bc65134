#include "sendcommand.h"

#include "commands.h"
#include "deviceexchange.h"
#include "requestoptions.h"
#include "targetoptions.h"
#include "transactionreport.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

int runSend(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QString command = QStringLiteral("send");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Sends bytes to a device exactly as given (a wrong CRC included), or with --complete a PDU wrapped for the "
        "target's framing (MBAP header, or unit id and CRC/LRC), then prints the request and the response decoded field "
        "by field, and the latency.\n"
        "Example: mbscope send --target rtu-tcp://192.168.127.254:4001 --hex \"01 03 00 79 00 16 15 DD\"\n"
        "Exit status: 0 ok, 1 the transaction failed (exception, timeout, bad answer), 2 usage or link error."));
    parser.addHelpOption();
    const TargetOptions targetOptions;
    const RequestOptions requestOptions(RequestOptions::Hex);
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the transaction as JSON."));
    targetOptions.addTo(parser);
    requestOptions.addTo(parser);
    parser.addOption(jsonOpt);
    if (!parser.parse(arguments)) {
        err << "mbscope send: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "send");
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope send: unexpected argument '" << parser.positionalArguments().constFirst()
            << "': give the bytes with --hex \"01 03 00 79 00 16 15 DD\"\n";
        return ExitUsage;
    }
    TargetSettings target;
    RequestPlan plan;
    if (!targetOptions.read(parser, command, target, err) || !requestOptions.read(parser, command, target, plan, err))
        return ExitUsage;

    const QList<Transaction> records = exchange(target, plan.requests);
    const Transaction &t = records.constFirst();
    if (parser.isSet(jsonOpt)) {
        QJsonObject o = TransactionReport::json(t, target.url);
        o.insert(QStringLiteral("target"), target.url.toString());
        out << QJsonDocument(o).toJson(QJsonDocument::Indented);
    } else {
        out << TransactionReport::text(t, target.url);
    }
    if (t.status == TransactionStatus::LinkError)
        err << "mbscope send: " << t.problem << '\n';
    return TransactionReport::exitStatus(t);
}

} // namespace mbscope::app
