#include "readcommand.h"

#include "commands.h"
#include "deviceexchange.h"
#include "requestoptions.h"
#include "targetoptions.h"
#include "transactionreport.h"
#include "valuetable.h"

#include "protocol/adubuilder.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

int runRead(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QString command = QStringLiteral("read");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Reads coils, discrete inputs, holding or input registers with a request built from the options, prints the "
        "request and the response decoded field by field, the latency, and the values with their Modicon references in "
        "the formats asked.\n"
        "Example: mbscope read --target tcp://192.168.1.10 --unit 1 --function 3 --address 0x79 --quantity 22 "
        "--format u16,hex\n"
        "Exit status: 0 ok, 1 the transaction failed (exception, timeout, bad answer), 2 usage or link error."));
    parser.addHelpOption();
    const TargetOptions targetOptions;
    const RequestOptions requestOptions(RequestOptions::Read);
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the transaction and the values as JSON."));
    targetOptions.addTo(parser);
    requestOptions.addTo(parser);
    parser.addOption(jsonOpt);
    if (!parser.parse(arguments)) {
        err << "mbscope read: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "read");
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope read: unexpected argument '" << parser.positionalArguments().constFirst()
            << "': every setting is an option (see mbscope read --help)\n";
        return ExitUsage;
    }
    TargetSettings target;
    RequestPlan plan;
    if (!targetOptions.read(parser, command, target, err) || !requestOptions.read(parser, command, target, plan, err))
        return ExitUsage;

    const PlannedRequest &request = plan.requests.constFirst();
    const QList<Transaction> records = exchange(target, plan.requests);
    const Transaction &t = records.constFirst();
    ValueTable values;
    if (t.status == TransactionStatus::Ok) {
        values = ValueTable::fromReadResponse(request.functionCode, request.address, request.quantity,
                                              AduBuilder::parse(t.response, target.url.framing()).pdu, plan.formats);
    }

    if (parser.isSet(jsonOpt)) {
        QJsonObject o = TransactionReport::json(t, target.url);
        o.insert(QStringLiteral("target"), target.url.toString());
        o.insert(QStringLiteral("description"), request.description);
        o.insert(QStringLiteral("values"), values.json());
        out << QJsonDocument(o).toJson(QJsonDocument::Indented);
    } else {
        out << TransactionReport::text(t, target.url);
        if (!values.isEmpty())
            out << "\nVALUES " << request.description << "\n" << values.text();
    }
    if (t.status == TransactionStatus::LinkError)
        err << "mbscope read: " << t.problem << '\n';
    return TransactionReport::exitStatus(t);
}

} // namespace mbscope::app
