#include "mbapchecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"
#include "readchecks.h"

#include "protocol/adubuilder.h"

namespace mbscope {

namespace {

// A harmless read the device answers: quantity items of the first table it has a readable address of.
QByteArray harmlessRead(const ConformanceContext &ctx, int quantity = 1)
{
    for (quint8 f : {quint8(0x03), quint8(0x04), quint8(0x01), quint8(0x02)}) {
        const int at = ctx.readable(SimTable(ReadChecks::tableOf(f)));
        if (at >= 0 && ctx.support(f) == SurveyedSupport::Supported)
            return ReadChecks::readPdu(f, at, quantity);
    }
    return ReadChecks::readPdu(0x03, 0, quantity);
}

QString hex4(int value)
{
    return QStringLiteral("0x%1").arg(QString::number(value, 16).toUpper().rightJustified(4, QLatin1Char('0')));
}

// The MBAP frames in bytes, cut by their length fields (a short tail is one frame as it is).
QList<QByteArray> mbapFrames(const QByteArray &bytes)
{
    QList<QByteArray> frames;
    qsizetype at = 0;
    while (at < bytes.size()) {
        if (bytes.size() - at < 6) {
            frames.append(bytes.mid(at));
            break;
        }
        const int length = (quint8(bytes.at(at + 4)) << 8) | quint8(bytes.at(at + 5));
        const qsizetype size = qMin<qsizetype>(6 + qMax(length, 0), bytes.size() - at);
        frames.append(bytes.mid(at, size));
        at += qMax<qsizetype>(size, 1);
    }
    return frames;
}

struct HeaderField {
    const char *id;
    const char *title;
    const char *clause;
};

const HeaderField kHeaderFields[] = {
    {"mbap.transaction-id", "the answer echoes the request's transaction id", "TCP/IP Guide V1.0b, 3.1.3"},
    {"mbap.protocol-id", "the answer's protocol id is 0", "TCP/IP Guide V1.0b, 3.1.3"},
    {"mbap.length", "the answer's length field counts the unit id and the PDU", "TCP/IP Guide V1.0b, 3.1.3"},
    {"mbap.unit-id", "the answer echoes the request's unit id", "TCP/IP Guide V1.0b, 3.1.3"},
};

void judgeHeader(const char *id, ConformanceContext &ctx, CheckResult &res)
{
    // A transaction id far from the ones counting up, so that an echo is not a coincidence.
    constexpr quint16 kTid = 0xA5C3;
    // Three items, a quantity no other check reads, so that a fault of the header alone can be
    // aimed at these checks; the header is judged whatever the PDU (an exception has one too).
    const QByteArray request = AduBuilder::mbap(harmlessRead(ctx, 3), ctx.unit(), kTid);
    const ConformanceExchange e = ctx.link().exchange(request);
    ConformanceJudge::record(res, e);
    if (e.silent()) {
        res.fail(ConformanceJudge::failure(res, e, QStringLiteral("an answer")));
        return;
    }
    // The answer the engine matched to the request (by timing, whatever its keys), else the
    // first frame read: a late or duplicate answer to an earlier request may come first.
    const QByteArray frame = e.transaction.response.isEmpty() ? mbapFrames(e.answer).constFirst() : e.transaction.response;
    const AduParts parts = AduBuilder::parseMbap(frame);
    const QString got = QStringLiteral("sent %1; got %2; %3 requires ").arg(ConformanceJudge::hex(request), ConformanceJudge::hex(e.answer), res.clause);
    const QLatin1String which(id);
    if (which == QLatin1String("mbap.transaction-id")) {
        if (parts.transactionId == kTid)
            res.pass(QStringLiteral("transaction id %1 echoed").arg(hex4(kTid)));
        else
            res.fail(got + QStringLiteral("the transaction id %1 copied into the answer (it carried %2)").arg(hex4(kTid), hex4(parts.transactionId)));
    } else if (which == QLatin1String("mbap.protocol-id")) {
        if (parts.protocolId == 0)
            res.pass(QStringLiteral("protocol id 0"));
        else
            res.fail(got + QStringLiteral("protocol id 0 (MODBUS) in the answer (it carried %1)").arg(hex4(parts.protocolId)));
    } else if (which == QLatin1String("mbap.length")) {
        // A matched, well-formed answer had its length checked by the dissector; otherwise every
        // byte read is the answer whose length is judged (the bytes a wrong length left over).
        const bool wellFormed = e.transaction.status == TransactionStatus::Ok || e.transaction.status == TransactionStatus::Exception;
        const AduParts whole = AduBuilder::parseMbap(wellFormed ? e.transaction.response : e.answer);
        if (whole.lengthMatches)
            res.pass(QStringLiteral("length %1 matches the %2 bytes that follow it").arg(parts.length).arg(parts.length));
        else
            res.fail(got + QStringLiteral("the length field to count the unit id and the PDU: it says %1, %2 bytes follow it")
                               .arg(whole.length)
                               .arg(qMax<qsizetype>(0, (wellFormed ? e.transaction.response : e.answer).size() - 6)));
    } else {
        if (parts.unitId == ctx.unit())
            res.pass(QStringLiteral("unit id %1 echoed").arg(ctx.unit()));
        else
            res.fail(got + QStringLiteral("the request's unit id %1 copied into the answer (it carried %2)").arg(ctx.unit()).arg(parts.unitId));
    }
}

} // namespace

QList<ConformanceCheck> MbapChecks::checks()
{
    QList<ConformanceCheck> out;
    for (const HeaderField &h : kHeaderFields) {
        ConformanceCheck c;
        c.id = QLatin1String(h.id);
        c.title = QLatin1String(h.title);
        c.clause = QLatin1String(h.clause);
        c.needs.mbap = true;
        const char *id = h.id;
        c.run = [id](ConformanceContext &ctx, CheckResult &res) { judgeHeader(id, ctx, res); };
        out.append(c);
    }

    ConformanceCheck foreign;
    foreign.id = QStringLiteral("mbap.foreign-protocol");
    foreign.title = QStringLiteral("a request whose protocol id is not 0 is discarded");
    foreign.clause = QStringLiteral("TCP/IP Guide V1.0b, 3.1.3 and 4.4.2.1");
    foreign.needs.mbap = true;
    foreign.run = [](ConformanceContext &ctx, CheckResult &res) {
        const QByteArray request = AduBuilder::mbap(harmlessRead(ctx), ctx.unit(), 0x5A01, 0x0001);
        const ConformanceExchange e = ctx.link().exchange(request);
        ConformanceJudge::silence(res, e, QStringLiteral("that a request of protocol id 1 (not MODBUS) be discarded, not answered"), {}, true);
    };
    out.append(foreign);

    ConformanceCheck unitFF;
    unitFF.id = QStringLiteral("mbap.unit-ff");
    unitFF.title = QStringLiteral("unit id 0xFF (the server itself) is answered");
    unitFF.clause = QStringLiteral("TCP/IP Guide V1.0b, 4.4.1.1");
    unitFF.needs.mbap = true;
    unitFF.run = [](ConformanceContext &ctx, CheckResult &res) {
        const ConformanceExchange e = ctx.link().ask(0xFF, harmlessRead(ctx));
        if (e.transaction.status == TransactionStatus::Exception && e.transaction.exceptionCode != 0x0A
            && e.transaction.exceptionCode != 0x0B) {
            ConformanceJudge::record(res, e);
            res.pass(QStringLiteral("answered %1 (the server took the request as its own)").arg(ConformanceJudge::exceptionText(e.transaction.exceptionCode)));
            return;
        }
        ConformanceJudge::normal(res, e, QStringLiteral("that a server addressed by its IP address answer unit id 0xFF"));
    };
    out.append(unitFF);

    ConformanceCheck pipelined;
    pipelined.id = QStringLiteral("mbap.pipelined");
    pipelined.title = QStringLiteral("three requests sent at once are each answered by transaction id (or exception 06)");
    pipelined.clause = QStringLiteral("TCP/IP Guide V1.0b, 4.2 and 3.1.3");
    pipelined.needs.mbap = true;
    pipelined.needs.stream = true;
    pipelined.run = [](ConformanceContext &ctx, CheckResult &res) {
        const QByteArray pdu = harmlessRead(ctx);
        const quint16 tids[] = {0x7101, 0x7102, 0x7103};
        QByteArray request;
        for (quint16 tid : tids)
            request += AduBuilder::mbap(pdu, ctx.unit(), tid);
        const qsizetype from = ctx.link().framesRead();
        const ConformanceExchange first = ctx.link().exchange(request);
        // The first answer ends the exchange; the others come after it.
        QByteArray all = ctx.link().bytesReadSince(from);
        if (!first.silent())
            all += ctx.link().listen(qMin(ctx.link().timeoutMs(), 500));
        ctx.link().excuse(from, ctx.link().framesRead());
        res.request = request;
        res.answer = all;
        QList<quint16> missing;
        for (quint16 tid : tids) {
            bool found = false;
            for (const QByteArray &frame : mbapFrames(all)) {
                const AduParts p = AduBuilder::parseMbap(frame);
                if (p.transactionId == tid && p.complete && !p.pdu.isEmpty()
                    && (quint8(p.pdu.at(0)) == quint8(pdu.at(0)) || (quint8(p.pdu.at(0)) == (quint8(pdu.at(0)) | 0x80))))
                    found = true;
            }
            if (!found)
                missing.append(tid);
        }
        if (missing.isEmpty()) {
            res.pass(QStringLiteral("three answers, one per transaction id"));
            return;
        }
        QStringList ids;
        for (quint16 tid : missing)
            ids.append(hex4(tid));
        res.fail(QStringLiteral("sent three requests in one write (transaction ids 0x7101-0x7103); got %1; %2 requires "
                                "each to be answered with its transaction id (or exception 06, busy): none came for %3")
                     .arg(all.isEmpty() ? QStringLiteral("no answer") : ConformanceJudge::hex(all), res.clause, ids.join(QLatin1String(", "))));
    };
    out.append(pipelined);
    return out;
}

} // namespace mbscope
