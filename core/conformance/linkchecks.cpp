#include "linkchecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"
#include "readchecks.h"

#include "exchange/latencysamples.h"
#include "protocol/adubuilder.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace mbscope {

namespace {

QByteArray harmlessRead(const ConformanceContext &ctx)
{
    for (quint8 f : {quint8(0x03), quint8(0x04), quint8(0x01), quint8(0x02)}) {
        const int at = ctx.readable(SimTable(ReadChecks::tableOf(f)));
        if (at >= 0 && ctx.support(f) == SurveyedSupport::Supported)
            return ReadChecks::readPdu(f, at, 1);
    }
    return ReadChecks::readPdu(0x03, 0, 1);
}

QString ms(qint64 ns)
{
    return QStringLiteral("%1 ms").arg(double(ns) / 1e6, 0, 'f', 2);
}

ConformanceCheck check(const char *id, const char *title, const char *clause, CheckLevel level,
                       std::function<void(ConformanceContext &, CheckResult &)> run)
{
    ConformanceCheck c;
    c.id = QLatin1String(id);
    c.title = QLatin1String(title);
    c.clause = QLatin1String(clause);
    c.level = level;
    c.run = std::move(run);
    return c;
}

} // namespace

QList<ConformanceCheck> LinkChecks::checks()
{
    QList<ConformanceCheck> out;

    ConformanceCheck broadcast = check(
        "serial.broadcast", "a read sent to unit 0 (broadcast) is not answered", "Serial Line V1.02, 2.1", CheckLevel::Mandatory,
        [](ConformanceContext &ctx, CheckResult &res) {
            const ConformanceExchange e = ctx.link().ask(0, harmlessRead(ctx));
            const QByteArray later = e.silent() ? ctx.link().listen(ctx.link().timeoutMs()) : QByteArray();
            ConformanceJudge::silence(res, e, QStringLiteral("that no slave answer a broadcast (unit 0)"), later);
        });
    broadcast.needs.serial = true;
    out.append(broadcast);

    ConformanceCheck reserved = check(
        "serial.reserved-unit", "a request to reserved unit 248 is not answered", "Serial Line V1.02, 2.2", CheckLevel::Mandatory,
        [](ConformanceContext &ctx, CheckResult &res) {
            const ConformanceExchange e = ctx.link().ask(248, harmlessRead(ctx));
            // Over TCP or UDP the serial frames reach the line through a gateway, which may say
            // that no device answered (exception 0A or 0B, V1.1b3 7): that is not a slave answering.
            if (!ctx.link().url().isSerial() && e.transaction.status == TransactionStatus::Exception
                && (e.transaction.exceptionCode == 0x0A || e.transaction.exceptionCode == 0x0B)) {
                ConformanceJudge::record(res, e);
                res.pass(QStringLiteral("the gateway answered %1: no slave answered").arg(ConformanceJudge::exceptionText(e.transaction.exceptionCode)));
                return;
            }
            ConformanceJudge::silence(res, e, QStringLiteral("slave addresses 1-247: 248-255 are reserved, so no slave answers them"));
        });
    reserved.needs.serial = true;
    out.append(reserved);

    ConformanceCheck checksum = check(
        "serial.bad-checksum", "a request with a wrong CRC or LRC is not answered", "Serial Line V1.02, 2.5.1.2 and 2.5.2.2",
        CheckLevel::Mandatory, [](ConformanceContext &ctx, CheckResult &res) {
            QByteArray adu = ctx.link().frame(ctx.unit(), harmlessRead(ctx));
            if (ctx.link().framing() == Framing::Ascii) {
                // The LRC's two hex digits before CR LF: change the first.
                const qsizetype at = adu.size() - 4;
                adu[at] = adu.at(at) == '0' ? '1' : '0';
            } else {
                adu[adu.size() - 1] = char(~quint8(adu.at(adu.size() - 1)));
                adu[adu.size() - 2] = char(~quint8(adu.at(adu.size() - 2)));
            }
            ConformanceJudge::silence(res, ctx.link().exchange(adu),
                                      QStringLiteral("that a frame whose checksum fails be discarded without an answer"));
        });
    checksum.needs.serial = true;
    out.append(checksum);

    out.append(check("request.truncated", "a request cut short gets no answer or an exception, never data",
                     "Application Protocol V1.1b3, 7 and 4.1", CheckLevel::Mandatory,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const QByteArray pdu = harmlessRead(ctx).left(4); // the quantity's last byte missing
                         ConformanceJudge::silenceOrException(res, ctx.ask(pdu),
                                                              QStringLiteral("no answer or an exception to a request that is not whole"));
                     }));

    out.append(check("answer.single", "one request gets one answer", "Application Protocol V1.1b3, 4.1", CheckLevel::Mandatory,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const ConformanceExchange e = ctx.ask(harmlessRead(ctx));
                         ConformanceJudge::record(res, e);
                         if (e.silent()) {
                             res.skip(QStringLiteral("the read was not answered (other checks say why)"));
                             return;
                         }
                         // Bytes read with the answer beyond it (a copy sent at once)...
                         const QByteArray with = e.transaction.response.isEmpty() ? QByteArray() : e.answer.mid(e.answer.indexOf(e.transaction.response) + e.transaction.response.size());
                         if (!e.transaction.response.isEmpty() && !with.isEmpty()) {
                             res.fail(QStringLiteral("sent %1; got %2, then %3 with it; %4 requires one answer per request")
                                          .arg(ConformanceJudge::hex(e.request), ConformanceJudge::hex(e.transaction.response), ConformanceJudge::hex(with), res.clause));
                             return;
                         }
                         // ...or after it: wait as long again as the answer took, and at least 300 ms.
                         const int waitMs = int(qMax<qint64>(300, 2 * qMax<qint64>(0, e.transaction.latencyNs()) / 1000000));
                         const qsizetype from = ctx.link().framesRead();
                         const QByteArray more = ctx.link().listen(waitMs);
                         ctx.link().excuse(from, ctx.link().framesRead()); // said here, not again by answer.unsolicited
                         if (more.isEmpty()) {
                             res.pass(QStringLiteral("nothing more came in the %1 ms after the answer").arg(waitMs));
                             return;
                         }
                         res.answer += more;
                         res.fail(QStringLiteral("sent %1; got %2, then %3 within %4 ms; %5 requires one answer per request")
                                      .arg(ConformanceJudge::hex(e.request), ConformanceJudge::hex(e.answer), ConformanceJudge::hex(more))
                                      .arg(waitMs)
                                      .arg(res.clause));
                     }));

    ConformanceCheck stays = check(
        "tcp.keeps-connection", "the connection stays open across requests", "TCP/IP Guide V1.0b, 4.2.1", CheckLevel::Mandatory,
        [](ConformanceContext &ctx, CheckResult &res) {
            const int before = ctx.link().opens();
            constexpr int kRequests = 3;
            ConformanceExchange last;
            for (int i = 0; i < kRequests; ++i) {
                last = ctx.ask(harmlessRead(ctx));
                (void)ctx.link().listen(20); // a close after the answer arrives now
            }
            ConformanceJudge::record(res, last);
            const int opened = ctx.link().opens() - before;
            if (opened == 0) {
                res.pass(QStringLiteral("%1 requests on one connection").arg(kRequests));
                return;
            }
            res.fail(QStringLiteral("%1 requests needed %2 new connections: the device closed the connection; %3 requires the "
                                    "server to keep it open until the client closes it")
                         .arg(kRequests)
                         .arg(opened)
                         .arg(res.clause));
        });
    stays.needs.stream = true;
    out.append(stays);

    ConformanceCheck reconnect = check(
        "tcp.reconnect", "a new connection is served after the master closed its last one", "TCP/IP Guide V1.0b, 4.2.1",
        CheckLevel::Mandatory, [](ConformanceContext &ctx, CheckResult &res) {
            ctx.link().closeLink();
            ConformanceJudge::normal(res, ctx.ask(harmlessRead(ctx)),
                                     QStringLiteral("a server to accept a new connection once the client closed its own"));
        });
    reconnect.needs.stream = true;
    out.append(reconnect);

    ConformanceCheck concurrent = check(
        "tcp.second-client", "a second connection is served while the first stays open", "TCP/IP Guide V1.0b, 4.2.1",
        CheckLevel::Recommended, [](ConformanceContext &ctx, CheckResult &res) {
            const QByteArray pdu = harmlessRead(ctx);
            const ConformanceExchange first = ctx.ask(pdu); // the first connection is open
            const auto second = std::make_unique<ConformanceLink>(ctx.link().url(), ctx.link().timeoutMs());
            const ConformanceExchange other = second->ask(ctx.unit(), pdu);
            if (!ConformanceJudge::normal(res, other,
                                          QStringLiteral("a server to serve several clients at once (the first connection "
                                                         "was still open)")))
                return;
            const ConformanceExchange again = ctx.ask(pdu);
            ConformanceJudge::normal(res, again, QStringLiteral("the first client to be served still once a second connected"));
            if (res.verdict == CheckVerdict::Passed)
                res.pass(QStringLiteral("both connections answered"));
            Q_UNUSED(first);
        });
    concurrent.needs.stream = true;
    out.append(concurrent);

    // How many connections at once (reads only): client k opens while the k - 1 before it and the
    // battery's own stay open; each is asked again once the last has connected. At its limit a
    // server closes its oldest idle connection to take the new one (TCP/IP Guide V1.0b, 4.2.1).
    ConformanceCheck clients = check(
        "tcp.clients", "connections at once: each stays served, and at the limit the oldest idle one makes room",
        "TCP/IP Guide V1.0b, 4.2.1", CheckLevel::Recommended, [](ConformanceContext &ctx, CheckResult &res) {
            const QByteArray pdu = harmlessRead(ctx);
            const int most = ctx.settings().maxClients;
            std::vector<std::unique_ptr<ConformanceLink>> held;
            enum class Asked : quint8 { Served, Dropped, Unanswered };
            const auto ask = [&](ConformanceLink &link, ConformanceExchange *seen) {
                const int opensBefore = link.opens();
                *seen = link.ask(ctx.unit(), pdu);
                // A link that had to connect again, or found its connection closed, lost it.
                if (seen->linkFailed() || (opensBefore > 0 && link.opens() != opensBefore))
                    return Asked::Dropped;
                return !seen->silent() && seen->transaction.status == TransactionStatus::Ok ? Asked::Served : Asked::Unanswered;
            };
            const auto served = [&](ConformanceLink &link, ConformanceExchange *seen) { return ask(link, seen) == Asked::Served; };
            ConformanceExchange seen;
            if (!served(ctx.link(), &seen)) {
                ConformanceJudge::record(res, seen);
                res.skip(QStringLiteral("not judged: the battery's own connection was not answered a read"));
                return;
            }
            for (int k = 1; k <= most; ++k) {
                auto client = std::make_unique<ConformanceLink>(ctx.link().url(), ctx.link().timeoutMs());
                const bool newServed = served(*client, &seen);
                ConformanceJudge::record(res, seen);
                if (!newServed) {
                    res.measured = QStringLiteral("%1 connections at once").arg(k);
                    res.fail(QStringLiteral("with %1 connections open and served, connection %2 got %3; %4 has a server at "
                                            "its limit close its oldest idle connection and serve the new one")
                                 .arg(k)
                                 .arg(k + 1)
                                 .arg(ConformanceJudge::seen(seen), res.clause));
                    return;
                }
                held.push_back(std::move(client));
                // Every connection still served: the oldest (the battery's own) first.
                for (int i = -1; i < int(held.size()) - 1; ++i) {
                    ConformanceLink &older = i < 0 ? ctx.link() : *held.at(size_t(i));
                    const Asked asked = ask(older, &seen);
                    if (asked == Asked::Served)
                        continue;
                    ConformanceJudge::record(res, seen);
                    if (i == -1 && asked == Asked::Dropped) {
                        res.measured = QStringLiteral("%1 connections at once").arg(k);
                        res.pass(QStringLiteral("%1 connections served at once; connection %2 was served by closing the "
                                                "oldest idle one, as %3 asks of a server at its limit")
                                     .arg(k)
                                     .arg(k + 1)
                                     .arg(res.clause));
                        ctx.link().closeLink(); // the next check connects again
                        return;
                    }
                    res.measured = QStringLiteral("%1 connections at once").arg(k + 1);
                    res.fail(QStringLiteral("with %1 connections open, connection %2 got %3 once connection %1 came; %4 asks "
                                            "a server to keep serving the connections it accepted (at its limit, to close the "
                                            "oldest idle one only)")
                                 .arg(k + 1)
                                 .arg(i + 2)
                                 .arg(ConformanceJudge::seen(seen), res.clause));
                    return;
                }
            }
            res.measured = QStringLiteral("%1 connections at once or more").arg(most + 1);
            res.pass(QStringLiteral("%1 connections open at once (the battery's own and %2 more), each answered again once the "
                                    "last had connected")
                         .arg(most + 1)
                         .arg(most));
        });
    clients.needs.stream = true;
    out.append(clients);

    out.append(check("timing.response", "response time distribution", "Application Protocol V1.1b3, 4.1 (informational)",
                     CheckLevel::Informational, [](ConformanceContext &ctx, CheckResult &res) {
                         LatencySamples samples;
                         int unanswered = 0;
                         const QByteArray pdu = harmlessRead(ctx);
                         for (int i = 0; i < ctx.settings().timingSamples; ++i) {
                             const ConformanceExchange e = ctx.ask(pdu);
                             ConformanceJudge::record(res, e);
                             if (e.transaction.latencyNs() >= 0 && !e.silent())
                                 samples.add(e.transaction.latencyNs());
                             else
                                 ++unanswered;
                         }
                         if (samples.isEmpty()) {
                             res.skip(QStringLiteral("none of %1 reads was answered").arg(ctx.settings().timingSamples));
                             return;
                         }
                         res.measured = QStringLiteral("%1 reads: min %2, median %3, p95 %4, max %5%6")
                                            .arg(ctx.settings().timingSamples)
                                            .arg(ms(samples.minNs()), ms(samples.medianNs()), ms(samples.percentileNs(95)), ms(samples.maxNs()))
                                            .arg(unanswered > 0 ? QStringLiteral(", %1 unanswered").arg(unanswered) : QString());
                         res.pass(res.measured);
                     }));
    return out;
}

QList<ConformanceCheck> LinkChecks::afterChecks()
{
    QList<ConformanceCheck> out;
    const auto framesOf = [](ConformanceContext &ctx, std::initializer_list<TrafficVerdict> verdicts, QByteArray *bytes) {
        int n = 0;
        const QList<TrafficFrame> &frames = ctx.link().framesIn();
        for (qsizetype i = 0; i < frames.size(); ++i) {
            const TrafficFrame &f = frames.at(i);
            if (ctx.link().isExcused(i))
                continue;
            if (std::find(verdicts.begin(), verdicts.end(), f.verdict) == verdicts.end())
                continue;
            ++n;
            if (bytes->size() < 64)
                *bytes += (bytes->isEmpty() ? QByteArray() : QByteArray(" | ")) + ConformanceJudge::hex(f.bytes).toLatin1();
        }
        return n;
    };
    out.append(check("answer.late", "no answer came after the master's timeout", "Serial Line V1.02, 2.4.1 (response time-out)",
                     CheckLevel::Recommended, [framesOf](ConformanceContext &ctx, CheckResult &res) {
                         QByteArray shown;
                         const int n = framesOf(ctx, {TrafficVerdict::Late}, &shown);
                         if (n == 0) {
                             res.pass(QStringLiteral("every answer of the run came within %1 ms").arg(ctx.link().timeoutMs()));
                             return;
                         }
                         res.answer = shown;
                         res.fail(QStringLiteral("%1 %2 came after the %3 ms timeout (%4); a master has given up on the request "
                                                 "by then, and %5 has it retry or go on: answer faster or ask for a longer --timeout")
                                      .arg(n)
                                      .arg(n == 1 ? QStringLiteral("answer") : QStringLiteral("answers"))
                                      .arg(ctx.link().timeoutMs())
                                      .arg(QString::fromLatin1(shown), res.clause));
                     }));
    out.append(check("answer.unsolicited", "no frame came that answers no request", "Application Protocol V1.1b3, 4.1",
                     CheckLevel::Mandatory, [framesOf](ConformanceContext &ctx, CheckResult &res) {
                         QByteArray shown;
                         const int n = framesOf(ctx, {TrafficVerdict::Unsolicited, TrafficVerdict::Garbage}, &shown);
                         if (n == 0) {
                             res.pass(QStringLiteral("every frame of the run answered a request"));
                             return;
                         }
                         res.answer = shown;
                         res.fail(QStringLiteral("%1 %2 of the run answered no request (%3): a second copy of an answer, or "
                                                 "bytes nobody asked for; %4 has a server answer each request once")
                                      .arg(n)
                                      .arg(n == 1 ? QStringLiteral("frame") : QStringLiteral("frames"))
                                      .arg(QString::fromLatin1(shown), res.clause));
                     }));
    return out;
}

} // namespace mbscope
