#include "exchangerow.h"

#include "protocol/hexnumber.h"
#include "capture/exchangefields.h"
#include "protocol/functioncode.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonValue>

namespace mbscope {

namespace {

QString hex2(quint8 v)
{
    return QStringLiteral("0x%1").arg(hexNumber(v, 2));
}

bool isUnmatched(const CaptureExchange &e)
{
    return e.kind == CaptureExchange::Kind::UnmatchedResponse;
}

} // namespace

QStringList ExchangeRow::columns()
{
    return {QStringLiteral("index"), QStringLiteral("kind"), QStringLiteral("request_time"), QStringLiteral("response_time"),
            QStringLiteral("latency_us"), QStringLiteral("client"), QStringLiteral("server"), QStringLiteral("framing"),
            QStringLiteral("unit"), QStringLiteral("function"), QStringLiteral("function_name"), QStringLiteral("address"),
            QStringLiteral("quantity"), QStringLiteral("values"), QStringLiteral("status"), QStringLiteral("exception"),
            QStringLiteral("problem"), QStringLiteral("request_packet"), QStringLiteral("response_packet"),
            QStringLiteral("request_hex"), QStringLiteral("response_hex")};
}

QString ExchangeRow::isoTime(qint64 ns)
{
    const qint64 seconds = ns >= 0 ? ns / 1000000000LL : (ns - 999999999LL) / 1000000000LL;
    const qint64 fraction = ns - seconds * 1000000000LL;
    return QDateTime::fromSecsSinceEpoch(seconds, Qt::UTC).toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss"))
           + QStringLiteral(".%1Z").arg(fraction, 9, 10, QLatin1Char('0'));
}

QString ExchangeRow::csvCell(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n'))
        && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QStringList ExchangeRow::cells(const CaptureExchange &e, const CaptureConversation *c)
{
    const Transaction &t = e.transaction;
    const ExchangeFields f = ExchangeFields::of(t, e.framing);
    const bool answered = !t.response.isEmpty() && t.doneNs != 0;
    const bool timed = answered && t.sentNs != 0;
    return {QString::number(t.id),
            isUnmatched(e) ? QStringLiteral("unmatched_response")
            : e.kind == CaptureExchange::Kind::Unanswered ? QStringLiteral("unanswered_at_end")
                                                          : QStringLiteral("transaction"),
            t.sentNs != 0 ? isoTime(t.sentNs) : QString(),
            answered ? isoTime(t.doneNs) : QString(),
            timed ? QString::number(double(t.doneNs - t.sentNs) / 1e3, 'f', 3) : QString(),
            c ? c->clientText() : QString(),
            c ? c->serverText() : QString(),
            framingName(e.framing),
            f.valid ? QString::number(f.unit) : QString(),
            f.valid ? hex2(f.function) : QString(),
            f.valid ? QString::fromLatin1(functionName(f.function)) : QString(),
            f.hasAddress ? QString::number(f.address) : QString(),
            f.hasAddress ? QString::number(f.quantity) : QString(),
            f.values,
            isUnmatched(e) ? QStringLiteral("unmatched")
            : e.kind == CaptureExchange::Kind::Unanswered ? QStringLiteral("unanswered")
                                                          : transactionStatusName(t.status),
            t.status == TransactionStatus::Exception ? hex2(t.exceptionCode) : QString(),
            t.problem,
            e.requestPacket ? QString::number(e.requestPacket) : QString(),
            e.responsePacket ? QString::number(e.responsePacket) : QString(),
            QString::fromLatin1(t.request.toHex().toUpper()),
            QString::fromLatin1(t.response.toHex().toUpper())};
}

QJsonObject ExchangeRow::json(const CaptureExchange &e, const CaptureConversation *c)
{
    const QStringList text = cells(e, c);
    const QStringList names = columns();
    const Transaction &t = e.transaction;
    const ExchangeFields f = ExchangeFields::of(t, e.framing);
    QJsonObject o;
    for (qsizetype i = 0; i < names.size(); ++i)
        o.insert(names.at(i), text.at(i).isEmpty() ? QJsonValue() : QJsonValue(text.at(i)));
    // Numbers as numbers.
    o.insert(QStringLiteral("index"), double(t.id));
    const bool timed = !t.response.isEmpty() && t.doneNs != 0 && t.sentNs != 0;
    o.insert(QStringLiteral("latency_us"), timed ? QJsonValue(double(t.doneNs - t.sentNs) / 1e3) : QJsonValue());
    o.insert(QStringLiteral("unit"), f.valid ? QJsonValue(f.unit) : QJsonValue());
    o.insert(QStringLiteral("address"), f.hasAddress ? QJsonValue(f.address) : QJsonValue());
    o.insert(QStringLiteral("quantity"), f.hasAddress ? QJsonValue(f.quantity) : QJsonValue());
    o.insert(QStringLiteral("request_packet"), e.requestPacket ? QJsonValue(double(e.requestPacket)) : QJsonValue());
    o.insert(QStringLiteral("response_packet"), e.responsePacket ? QJsonValue(double(e.responsePacket)) : QJsonValue());
    o.insert(QStringLiteral("request_time_ns"), t.sentNs != 0 ? QJsonValue(QString::number(t.sentNs)) : QJsonValue());
    o.insert(QStringLiteral("response_time_ns"), t.doneNs != 0 ? QJsonValue(QString::number(t.doneNs)) : QJsonValue());
    return o;
}

} // namespace mbscope
