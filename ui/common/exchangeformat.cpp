#include "exchangeformat.h"

#include "protocol/dissectionformat.h"
#include "protocol/hextext.h"

namespace mbscope {

namespace {

bool present(const Dissection *d)
{
    return d && !d->fields.isEmpty();
}

} // namespace

QString ExchangeFormat::latencyText(qint64 ns)
{
    if (ns < 0)
        return {};
    // Microseconds below a millisecond (a loopback simulator answers in tens of µs), milliseconds
    // with µs resolution above, as the poll statistics print them.
    if (ns < 1'000'000)
        return QStringLiteral("%1 µs").arg(double(ns) / 1e3, 0, 'f', 1);
    return QStringLiteral("%1 ms").arg(double(ns) / 1e6, 0, 'f', 3);
}

QString ExchangeFormat::toText(const Exchange &exchange)
{
    QString text;
    const auto section = [&text](const QString &title, const Dissection &d) {
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += QStringLiteral("== ") + title + QStringLiteral(" ==\n");
        text += DissectionFormat::toTable(d);
        if (!text.endsWith(QLatin1Char('\n')))
            text += QLatin1Char('\n');
    };
    if (present(exchange.request))
        section(QStringLiteral("Request"), *exchange.request);
    if (present(exchange.response))
        section(QStringLiteral("Response"), *exchange.response);
    QStringList tail;
    if (!exchange.verdict.isEmpty())
        tail << QStringLiteral("Verdict: ") + exchange.verdict;
    if (exchange.latencyNs >= 0)
        tail << QStringLiteral("Latency: ") + latencyText(exchange.latencyNs);
    if (!tail.isEmpty()) {
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += tail.join(QStringLiteral(", ")) + QLatin1Char('\n');
    }
    return text;
}

QJsonObject ExchangeFormat::toJson(const Exchange &exchange)
{
    QJsonObject o;
    if (present(exchange.request))
        o.insert(QStringLiteral("request"), DissectionFormat::toJson(*exchange.request));
    if (present(exchange.response))
        o.insert(QStringLiteral("response"), DissectionFormat::toJson(*exchange.response));
    if (exchange.latencyNs >= 0)
        o.insert(QStringLiteral("latency_ns"), exchange.latencyNs);
    if (!exchange.verdict.isEmpty())
        o.insert(QStringLiteral("verdict"), exchange.verdict);
    return o;
}

QString ExchangeFormat::toHex(const Exchange &exchange)
{
    QStringList lines;
    if (present(exchange.request))
        lines << HexText::format(exchange.request->fields.frame());
    if (present(exchange.response))
        lines << HexText::format(exchange.response->fields.frame());
    return lines.join(QLatin1Char('\n'));
}

} // namespace mbscope
