#include "identitychecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"

#include "protocol/diagnosticrules.h"

#include <QtCore/QMap>

namespace mbscope {

namespace {

ConformanceCheck check(const char *id, const QString &title, const char *clause, CheckLevel level, quint8 function,
                       std::function<void(ConformanceContext &, CheckResult &)> run)
{
    ConformanceCheck c;
    c.id = QLatin1String(id);
    c.title = title;
    c.clause = QLatin1String(clause);
    c.level = level;
    c.needs.function = function;
    c.run = std::move(run);
    return c;
}

// The objects of one 2B/0E answer PDU: id -> value; more follows and the next object id.
struct IdAnswer {
    bool ok = false;
    quint8 conformity = 0;
    bool moreFollows = false;
    quint8 nextObject = 0;
    QMap<quint8, QByteArray> objects;
};

IdAnswer parseId(const QByteArray &pdu)
{
    IdAnswer a;
    if (pdu.size() < 7 || quint8(pdu.at(0)) != 0x2B || quint8(pdu.at(1)) != 0x0E)
        return a;
    a.conformity = quint8(pdu.at(3));
    a.moreFollows = quint8(pdu.at(4)) == 0xFF;
    a.nextObject = quint8(pdu.at(5));
    const int count = quint8(pdu.at(6));
    qsizetype at = 7;
    for (int i = 0; i < count; ++i) {
        if (at + 2 > pdu.size())
            return a;
        const quint8 id = quint8(pdu.at(at));
        const int length = quint8(pdu.at(at + 1));
        if (at + 2 + length > pdu.size())
            return a;
        a.objects.insert(id, pdu.mid(at + 2, length));
        at += 2 + length;
    }
    a.ok = at == pdu.size();
    return a;
}

QByteArray idRequest(quint8 code, quint8 object)
{
    QByteArray pdu = QByteArray::fromHex("2B0E");
    pdu.append(char(code));
    pdu.append(char(object));
    return pdu;
}

} // namespace

QList<ConformanceCheck> IdentityChecks::checks()
{
    QList<ConformanceCheck> out;
    out.append(check("diag.echo", QStringLiteral("08 Diagnostics sub-function 0000 echoes its data unchanged"),
                     "Application Protocol V1.1b3, 6.8.1", CheckLevel::Mandatory, 0x08,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const QByteArray pdu = QByteArray::fromHex("08000012345AA5");
                         const ConformanceExchange e = ctx.ask(pdu);
                         if (!ConformanceJudge::normal(res, e, QStringLiteral("the request echoed")))
                             return;
                         if (ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()) != pdu)
                             res.fail(ConformanceJudge::failure(res, e, QStringLiteral("the request's PDU echoed byte for byte (08 0000 12 34 5A A5)")));
                     }));

    out.append(check("diag.subfunctions", QStringLiteral("08 Diagnostics sub-functions that only read, offered or not"),
                     "Application Protocol V1.1b3, 6.8.1 (informational)", CheckLevel::Informational, 0x08,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         // Only those that change nothing: 02 the diagnostic register, 0B-12 the counters.
                         QStringList offered;
                         QStringList refused;
                         QStringList unmatched; // no answer matched to the request: nothing known of it
                         for (int sub : {0x02, 0x0B, 0x0C, 0x0D, 0x0E, 0x0F, 0x10, 0x11, 0x12}) {
                             QByteArray pdu = QByteArray::fromHex("08");
                             pdu.append(char(sub >> 8));
                             pdu.append(char(sub & 0xFF));
                             pdu.append(QByteArray::fromHex("0000"));
                             const ConformanceExchange e = ctx.ask(pdu);
                             ConformanceJudge::record(res, e);
                             const QString name = QStringLiteral("%1 %2").arg(sub, 2, 16, QLatin1Char('0')).arg(QLatin1String(diagnosticrules::subFunctionName(sub)));
                             const TransactionStatus status = e.transaction.status;
                             (status == TransactionStatus::Ok ? offered : status == TransactionStatus::Exception ? refused : unmatched)
                                 .append(name.toUpper().left(2) + name.mid(2));
                         }
                         if (offered.isEmpty() && refused.isEmpty()) {
                             res.skip(QStringLiteral("not judged: no answer could be matched to any of the %1 requests").arg(unmatched.size()));
                             return;
                         }
                         res.measured = QStringLiteral("offered: %1; not offered: %2")
                                            .arg(offered.isEmpty() ? QStringLiteral("none") : offered.join(QLatin1String(", ")),
                                                 refused.isEmpty() ? QStringLiteral("none") : refused.join(QLatin1String(", ")));
                         if (!unmatched.isEmpty())
                             res.measured += QStringLiteral("; no answer matched: %1").arg(unmatched.join(QLatin1String(", ")));
                         res.pass(res.measured);
                     }));

    out.append(check("ident.basic", QStringLiteral("2B/0E basic identification: VendorName, ProductCode, MajorMinorRevision"),
                     "Application Protocol V1.1b3, 6.21", CheckLevel::Mandatory, 0x2B,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         QMap<quint8, QByteArray> objects;
                         quint8 next = 0;
                         for (int round = 0; round < 8; ++round) {
                             const ConformanceExchange e = ctx.ask(idRequest(0x01, next));
                             if (!ConformanceJudge::normal(res, e, QStringLiteral("a Read Device Identification answer")))
                                 return;
                             const IdAnswer a = parseId(ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()));
                             if (!a.ok) {
                                 res.fail(ConformanceJudge::failure(res, e, QStringLiteral("objects that fill the answer exactly")));
                                 return;
                             }
                             objects.insert(a.objects);
                             if (!a.moreFollows)
                                 break;
                             if (a.nextObject <= next) {
                                 res.fail(ConformanceJudge::failure(res, e, QStringLiteral("a next object id beyond the one asked for when more follows")));
                                 return;
                             }
                             next = a.nextObject;
                         }
                         QStringList absent;
                         const char *names[] = {"VendorName", "ProductCode", "MajorMinorRevision"};
                         for (quint8 id = 0; id < 3; ++id) {
                             if (!objects.contains(id))
                                 absent.append(QLatin1String(names[id]));
                         }
                         if (absent.isEmpty())
                             res.pass(QStringLiteral("%1 / %2 / %3").arg(QString::fromLatin1(objects.value(0)), QString::fromLatin1(objects.value(1)),
                                                                        QString::fromLatin1(objects.value(2))));
                         else
                             res.fail(QStringLiteral("the basic identification lacks %1; %2 makes objects 00-02 mandatory")
                                          .arg(absent.join(QLatin1String(", ")), res.clause));
                     }));

    out.append(check("ident.individual", QStringLiteral("2B/0E individual access returns the one object asked for"),
                     "Application Protocol V1.1b3, 6.21", CheckLevel::Mandatory, 0x2B,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         const ConformanceExchange basic = ctx.ask(idRequest(0x01, 0x00));
                         const IdAnswer b = parseId(ConformanceJudge::pdu(basic.transaction.response, ctx.link().framing()));
                         if (!b.ok || (b.conformity & 0x80) == 0) {
                             ConformanceJudge::record(res, basic);
                             res.skip(QStringLiteral("the conformity level does not claim individual access (bit 0x80)"));
                             return;
                         }
                         const ConformanceExchange e = ctx.ask(idRequest(0x04, 0x01));
                         if (!ConformanceJudge::normal(res, e, QStringLiteral("object 01 (ProductCode) alone")))
                             return;
                         const IdAnswer a = parseId(ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()));
                         if (a.ok && a.objects.size() == 1 && a.objects.contains(0x01) && !a.moreFollows)
                             res.pass(QStringLiteral("object 01 alone"));
                         else
                             res.fail(ConformanceJudge::failure(res, e, QStringLiteral("exactly one object, 01 (ProductCode), and no more to follow")));
                     }));

    out.append(check("ident.bad-code", QStringLiteral("2B/0E with access code 05 (none such) gets exception 03"),
                     "Application Protocol V1.1b3, 6.21", CheckLevel::Mandatory, 0x2B,
                     [](ConformanceContext &ctx, CheckResult &res) {
                         ConformanceJudge::exception(res, ctx.ask(idRequest(0x05, 0x00)), {0x03},
                                                     QStringLiteral("exception 03 (Illegal Data Value) for Read Device ID code 05"));
                     }));
    return out;
}

} // namespace mbscope
