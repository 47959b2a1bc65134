#include "exchange/sendcommand.h"

#include "common/cli.h"
#include "exchange/exchangecommand.h"
#include "common/recordoptions.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"
#include "common/transactionreport.h"


#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

int runSend(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    ExchangeCommandSpec spec;
    spec.name = "send";
    spec.description = QStringLiteral(
        "Sends bytes to a device exactly as given (a wrong CRC included), or with --complete a PDU wrapped for the "
        "target's framing (MBAP header, or unit id and CRC/LRC), then prints the request and the response decoded field "
        "by field, and the latency.\n"
        "Example (with mbscope simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:4001 running):\n"
        "  mbscope send --target rtu-tcp://127.0.0.1:4001 --hex \"01 03 00 79 00 16 15 DD\"\n"
        "Exit status: 0 ok, 1 the transaction failed (exception, timeout, bad answer), 2 usage or link error.");
    spec.requestGroups = RequestOptions::Hex;
    spec.jsonHelp = QStringLiteral("Print the transaction as JSON.");
    spec.positionalHint = QStringLiteral("give the bytes with --hex \"01 03 00 79 00 16 15 DD\"");
    ExchangeCommandInput input;
    if (const std::optional<int> status = parseExchangeCommand(spec, arguments, out, err, input))
        return *status;
    const TargetSettings &target = input.target;

    const std::optional<QList<Transaction>> exchanged = runExchangeCommand(spec, arguments, input, err);
    if (!exchanged)
        return ExitUsage;
    const QList<Transaction> &records = *exchanged;
    const Transaction &t = records.constFirst();
    if (input.json) {
        QJsonObject o = TransactionReport::json(t, target.url);
        o.insert(QStringLiteral("target"), target.url.toString());
        out << QJsonDocument(o).toJson(QJsonDocument::Indented);
    } else {
        out << TransactionReport::text(t, target.url);
    }
    if (t.status == TransactionStatus::LinkError)
        err << "mbscope send: " << t.problem << '\n';
    return TransactionReport::exitStatus(t, target.url);
}

} // namespace mbscope::app
