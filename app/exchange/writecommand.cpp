#include "exchange/writecommand.h"

#include "common/cli.h"
#include "exchange/exchangecommand.h"
#include "common/recordoptions.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"
#include "common/transactionreport.h"
#include "common/valuetable.h"


#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QTextStream>

#include <algorithm>

namespace mbscope::app {

int runWrite(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    ExchangeCommandSpec spec;
    spec.name = "write";
    spec.description = QStringLiteral(
        "Writes coils or holding registers from --address with Write Multiple Coils (15) / Write Multiple Registers "
        "(16), or with --single one Write Single Coil (05) / Write Single Register (06) per value, and prints each "
        "request and response decoded, the latency and the values written with their Modicon references.\n"
        "Examples (with mbscope simulate --profile conformance --listen tcp://127.0.0.1:5020 running):\n"
        "  mbscope write --target tcp://127.0.0.1:5020 --coils 1,0,0 --address 0\n"
        "  mbscope write --target tcp://127.0.0.1:5020 --registers 205,172,73 --address 0 --single\n"
        "  mbscope write --target tcp://127.0.0.1:5020 --registers 123.456 --format f32-cdab --address 10\n"
        "Exit status: 0 every write ok, 1 some failed (exception, timeout, bad answer), 2 usage or link error.");
    spec.requestGroups = RequestOptions::Write;
    spec.jsonHelp = QStringLiteral("Print the transactions and values as JSON.");
    spec.positionalHint = QStringLiteral("give values with --coils 1,0,0 or --registers 205,172,73");
    ExchangeCommandInput input;
    if (const std::optional<int> status = parseExchangeCommand(spec, arguments, out, err, input))
        return *status;
    const TargetSettings &target = input.target;
    const RequestPlan &plan = input.plan;

    const std::optional<QList<Transaction>> exchanged = runExchangeCommand(spec, arguments, input, err);
    if (!exchanged)
        return ExitUsage;
    const QList<Transaction> &records = *exchanged;
    int status = ExitOk;
    for (const Transaction &t : records)
        status = qMax(status, TransactionReport::exitStatus(t, target.url));

    // What was asked, whatever came of it: the values table says what each request carried.
    ValueTable values;
    values.functionCode = plan.requests.constFirst().functionCode;
    values.address = plan.requests.constFirst().address;
    values.formats = plan.formats;
    values.oneBased = plan.oneBased;
    for (const PlannedRequest &r : plan.requests) {
        values.registers += r.registers;
        values.bits += r.coils;
    }
    const int written = int(plan.requests.size());
    const bool complete = records.size() == written;

    if (input.json) {
        QJsonArray transactions;
        for (qsizetype i = 0; i < records.size(); ++i) {
            QJsonObject o = TransactionReport::json(records.at(i), target.url);
            o.insert(QStringLiteral("description"), plan.requests.at(i).description);
            const QString hint = addressHintFor(plan.requests.at(i), records.at(i).exceptionCode,
                                                records.at(i).status == TransactionStatus::Exception);
            o.insert(QStringLiteral("hint"), hint.isEmpty() ? QJsonValue() : QJsonValue(hint));
            transactions.append(o);
        }
        out << QJsonDocument(QJsonObject{{QStringLiteral("target"), target.url.toString()},
                                         {QStringLiteral("transactions"), transactions},
                                         {QStringLiteral("values"), values.json()}})
                   .toJson(QJsonDocument::Indented);
    } else {
        for (qsizetype i = 0; i < records.size(); ++i) {
            if (records.size() > 1)
                out << (i > 0 ? "\n" : "") << "#" << (i + 1) << " of " << written << ": " << plan.requests.at(i).description
                    << "\n";
            out << TransactionReport::text(records.at(i), target.url);
            const QString hint = addressHintFor(plan.requests.at(i), records.at(i).exceptionCode,
                                                records.at(i).status == TransactionStatus::Exception);
            if (!hint.isEmpty())
                out << "HINT " << hint << '\n';
        }
        if (!complete)
            out << "\nstopped after " << records.size() << " of " << written << " requests: the link failed\n";
        // A broadcast is never answered (Serial Line V1.02, 2.1): nothing says the values were written.
        const bool broadcast = complete && std::all_of(records.cbegin(), records.cend(), [](const Transaction &t) {
            return t.status == TransactionStatus::Broadcast;
        });
        out << "\nVALUES " << (broadcast ? "broadcast, no answer expected" : status == ExitOk ? "written" : "sent") << ": "
            << plan.summary;
        if (written > 1)
            out << " (" << written << " requests)";
        out << "\n" << values.text();
    }
    if (!records.isEmpty() && records.constLast().status == TransactionStatus::LinkError)
        err << "mbscope write: " << records.constLast().problem << '\n';
    return status;
}

} // namespace mbscope::app
