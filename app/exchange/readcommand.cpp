#include "exchange/readcommand.h"

#include "common/cli.h"
#include "exchange/exchangecommand.h"
#include "common/recordoptions.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"
#include "common/transactionreport.h"
#include "common/valuetable.h"

#include "protocol/adubuilder.h"


#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QTextStream>

namespace mbscope::app {

int runRead(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    ExchangeCommandSpec spec;
    spec.name = "read";
    spec.description = QStringLiteral(
        "Reads coils, discrete inputs, holding or input registers with a request built from the options, prints the "
        "request and the response decoded field by field, the latency, and the values with their Modicon references in "
        "the formats asked.\n"
        "The second example is mbpoll's habits (-a unit, -r reference, -c count, -t 4 holding registers, -q values "
        "only).\n"
        "Examples (with mbscope simulate --profile rosrao-gamma --listen tcp://127.0.0.1:5020 running):\n"
        "  mbscope read --target tcp://127.0.0.1:5020 --unit 1 --function 3 --address 0x79 --quantity 22 --format u16,hex\n"
        "  mbscope read -a 1 -r 122 -c 10 -t 4 --one-based -q 127.0.0.1:5020\n"
        "Exit status: 0 ok, 1 the transaction failed (exception, timeout, bad answer), 2 usage or link error.");
    spec.requestGroups = RequestOptions::Read;
    spec.jsonHelp = QStringLiteral("Print the transaction and the values as JSON.");
    spec.positionalHint = QStringLiteral("every setting is an option (see mbscope read --help)");
    spec.readOutput = true;
    ExchangeCommandInput input;
    if (const std::optional<int> status = parseExchangeCommand(spec, arguments, out, err, input))
        return *status;
    const TargetSettings &target = input.target;
    const RequestPlan &plan = input.plan;

    const PlannedRequest &request = plan.requests.constFirst();
    const std::optional<QList<Transaction>> exchanged = runExchangeCommand(spec, arguments, input, err);
    if (!exchanged)
        return ExitUsage;
    const QList<Transaction> &records = *exchanged;
    const Transaction &t = records.constFirst();
    ValueTable values;
    if (t.status == TransactionStatus::Ok) {
        values = ValueTable::fromReadResponse(request.functionCode, request.address, request.quantity,
                                              AduBuilder::parse(t.response, target.url.framing()).pdu, plan.formats);
        values.oneBased = plan.oneBased;
    }

    if (input.terse) {
        // Values alone on standard output; what went wrong, and the hint, on standard error.
        out << values.terse();
        if (t.status != TransactionStatus::Ok) {
            err << "mbscope read: " << request.description << ": " << TransactionReport::outcome(t) << '\n';
            const QString hint = addressHintFor(request, t.exceptionCode, t.status == TransactionStatus::Exception);
            if (!hint.isEmpty())
                err << "HINT " << hint << '\n';
        }
        return TransactionReport::exitStatus(t, target.url);
    }

    if (input.json) {
        QJsonObject o = TransactionReport::json(t, target.url);
        o.insert(QStringLiteral("target"), target.url.toString());
        o.insert(QStringLiteral("description"), request.description);
        if (plan.oneBased)
            o.insert(QStringLiteral("one_based"), true);
        o.insert(QStringLiteral("values"), values.json());
        const QString hint = addressHintFor(request, t.exceptionCode, t.status == TransactionStatus::Exception);
        o.insert(QStringLiteral("hint"), hint.isEmpty() ? QJsonValue() : QJsonValue(hint));
        out << QJsonDocument(o).toJson(QJsonDocument::Indented);
    } else {
        out << TransactionReport::text(t, target.url);
        const QString hint = addressHintFor(request, t.exceptionCode, t.status == TransactionStatus::Exception);
        if (!hint.isEmpty())
            out << "HINT " << hint << '\n';
        if (!values.isEmpty())
            out << "\nVALUES " << request.description << "\n" << values.text();
    }
    if (t.status == TransactionStatus::LinkError)
        err << "mbscope read: " << t.problem << '\n';
    return TransactionReport::exitStatus(t, target.url);
}

} // namespace mbscope::app
