#include "common/transactionreport.h"

#include "common/cli.h"

#include "protocol/dissectionformat.h"
#include "protocol/dissector.h"
#include "protocol/functioncode.h"
#include "protocol/hextext.h"
#include "session/expectationcheck.h"

#include <QtCore/QJsonValue>

namespace mbscope::app {

namespace {

Dissection dissect(const QByteArray &bytes, const LinkUrl &url, Direction direction, const QByteArray &request = {})
{
    DissectOptions options;
    options.framing = url.framing();
    options.direction = direction;
    options.request = request;
    return Dissector::dissect(bytes, options);
}

QString hexOf(const QByteArray &bytes)
{
    return HexText::format(bytes);
}

// Delimited frames are often text ("$01R#"): printable bytes as they are, others as \xNN.
QString printable(const QByteArray &bytes)
{
    QString text;
    for (const char c : bytes) {
        const auto u = quint8(c);
        if (u >= 0x20 && u < 0x7F && u != '\\')
            text += QLatin1Char(c);
        else
            text += QStringLiteral("\\x") + QString::number(u, 16).toUpper().rightJustified(2, QLatin1Char('0'));
    }
    return text;
}

QString frameText(const QByteArray &bytes, const LinkUrl &url, Direction direction, const QByteArray &request)
{
    if (url.delimited.enabled)
        return QStringLiteral("hex   %1\ntext  %2\n").arg(hexOf(bytes), printable(bytes));
    return DissectionFormat::toTable(dissect(bytes, url, direction, request), 16);
}

QJsonObject frameJson(const QByteArray &bytes, const LinkUrl &url, Direction direction, const QByteArray &request)
{
    QJsonObject o{{QStringLiteral("hex"), hexOf(bytes)}, {QStringLiteral("length"), int(bytes.size())}};
    if (url.delimited.enabled)
        o.insert(QStringLiteral("text"), printable(bytes));
    else
        o.insert(QStringLiteral("dissection"), DissectionFormat::toJson(dissect(bytes, url, direction, request)));
    return o;
}

QString indented(const QString &block)
{
    QString out;
    for (const QString &line : block.split(QLatin1Char('\n'))) {
        if (!line.isEmpty())
            out += QStringLiteral("  ") + line;
        out += QLatin1Char('\n');
    }
    while (out.endsWith(QLatin1String("\n\n")))
        out.chop(1);
    return out;
}

} // namespace

QString latencyText(qint64 ns)
{
    if (ns < 1'000'000)
        return QString::number(double(ns) / 1e3, 'f', 1) + QStringLiteral(" µs");
    if (ns < 10'000'000'000LL)
        return QString::number(double(ns) / 1e6, 'f', 3) + QStringLiteral(" ms");
    return QString::number(double(ns) / 1e9, 'f', 3) + QStringLiteral(" s");
}

QString TransactionReport::outcome(const Transaction &t)
{
    QString line = transactionStatusName(t.status);
    switch (t.status) {
    case TransactionStatus::Ok:
        line += QStringLiteral(": answered in %1").arg(latencyText(t.latencyNs()));
        break;
    case TransactionStatus::Broadcast:
        line += QStringLiteral(": sent to every unit, no answer expected");
        break;
    case TransactionStatus::Exception:
        line += QStringLiteral(" 0x%1 %2; answered in %3")
                    .arg(QString::number(t.exceptionCode, 16).toUpper().rightJustified(2, QLatin1Char('0')),
                         QString::fromLatin1(exceptionMeaning(t.exceptionCode)), latencyText(t.latencyNs()));
        break;
    default:
        if (!t.problem.isEmpty())
            line += QStringLiteral(": ") + t.problem;
        if (t.latencyNs() >= 0)
            line += QStringLiteral(" (answered in %1)").arg(latencyText(t.latencyNs()));
        break;
    }
    if (t.attempt > 0)
        line += QStringLiteral(" [attempt %1]").arg(t.attempt + 1);
    return line;
}

QString TransactionReport::timingNote(const Transaction &t)
{
    if (t.latencyNs() < 0)
        return {};
    if (t.outranLine)
        return QStringLiteral("warning: the answer came before the serial line could have carried the request (%1 on the line) "
                              "and the answer at its baud rate: the link does not honour it (a pseudo terminal, or a USB "
                              "adapter that buffers); latency measured from the write")
            .arg(latencyText(t.transmitNs));
    if (t.transmitNs > 0)
        return QStringLiteral("latency from the computed end of the request's transmission: the write, %1%2 on the line "
                              "(%3 bytes at the baud rate)")
            .arg(t.lineQueuedNs > 0 ? QStringLiteral("%1 queued, then ").arg(latencyText(t.lineQueuedNs)) : QString(),
                 latencyText(t.transmitNs))
            .arg(t.request.size());
    return QStringLiteral("latency from the request's write to the link");
}

QString TransactionReport::text(const Transaction &t, const LinkUrl &url)
{
    QString out = QStringLiteral("REQUEST to %1, %2 bytes: %3\n").arg(url.toString()).arg(t.request.size()).arg(hexOf(t.request));
    out += indented(frameText(t.request, url, Direction::Request, {}));
    out += QLatin1Char('\n');
    if (!t.response.isEmpty()) {
        QString timing = latencyText(t.latencyNs());
        if (t.firstByteNs > 0 && t.doneNs > t.firstByteNs)
            timing += QStringLiteral(" (first byte after %1)").arg(latencyText(t.firstByteNs - t.sentNs));
        out += QStringLiteral("RESPONSE after %1, %2 bytes: %3\n").arg(timing).arg(t.response.size()).arg(hexOf(t.response));
        out += indented(frameText(t.response, url, Direction::Response, url.delimited.enabled ? QByteArray() : t.request));
        out += QLatin1Char('\n');
    } else if (t.status != TransactionStatus::Broadcast) {
        out += QStringLiteral("RESPONSE none\n\n");
    }
    if (const QString timing = timingNote(t); !timing.isEmpty())
        out += QStringLiteral("TIMING %1\n").arg(timing);
    out += QStringLiteral("RESULT %1\n").arg(outcome(t));
    const QString malformed = requestProblem(t, url);
    if (!malformed.isEmpty())
        out += QStringLiteral("RESULT %1\n").arg(malformed);
    return out;
}

QJsonObject TransactionReport::json(const Transaction &t, const LinkUrl &url)
{
    const auto us = [](qint64 ns) { return ns >= 0 ? QJsonValue(double(ns) / 1e3) : QJsonValue(); };
    QJsonObject o;
    o.insert(QStringLiteral("status"), transactionStatusName(t.status));
    o.insert(QStringLiteral("problem"), t.problem.isEmpty() ? QJsonValue() : QJsonValue(t.problem));
    o.insert(QStringLiteral("exception_code"),
             t.status == TransactionStatus::Exception ? QJsonValue(int(t.exceptionCode)) : QJsonValue());
    o.insert(QStringLiteral("latency_us"), us(t.latencyNs()));
    o.insert(QStringLiteral("first_byte_us"), us(t.firstByteNs > 0 ? t.firstByteNs - t.sentNs : -1));
    o.insert(QStringLiteral("latency_from"), t.latencyNs() < 0 ? QJsonValue()
                                             : QJsonValue(t.measuredFromLineEnd() ? QStringLiteral("line_end") : QStringLiteral("write")));
    o.insert(QStringLiteral("transmit_us"), t.transmitNs > 0 ? us(t.transmitNs) : QJsonValue());
    o.insert(QStringLiteral("outran_line"), t.outranLine);
    o.insert(QStringLiteral("attempts"), t.attempt + 1);
    const QString malformed = requestProblem(t, url);
    o.insert(QStringLiteral("request_problem"), malformed.isEmpty() ? QJsonValue() : QJsonValue(malformed));
    o.insert(QStringLiteral("request"), frameJson(t.request, url, Direction::Request, {}));
    o.insert(QStringLiteral("response"),
             t.response.isEmpty() ? QJsonValue()
                                  : QJsonValue(frameJson(t.response, url, Direction::Response,
                                                         url.delimited.enabled ? QByteArray() : t.request)));
    return o;
}

QString TransactionReport::requestProblem(const Transaction &t, const LinkUrl &url)
{
    // One wording for send and run (a plan step): the core's.
    return ExpectationCheck::requestProblem(t, url.framing(), url.delimited.enabled);
}

int TransactionReport::exitStatus(const Transaction &t, const LinkUrl &url)
{
    if (t.status != TransactionStatus::LinkError && !requestProblem(t, url).isEmpty())
        return ExitFailure;
    switch (t.status) {
    case TransactionStatus::Ok:
    case TransactionStatus::Broadcast:
        return ExitOk;
    case TransactionStatus::LinkError:
        return ExitLinkError;
    default:
        return ExitFailure;
    }
}

} // namespace mbscope::app
