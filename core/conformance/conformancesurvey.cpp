#include "conformancesurvey.h"

#include "conformancecontext.h"
#include "conformancejudge.h"
#include "readchecks.h"

#include "protocol/functioncode.h"

namespace mbscope {

namespace {

constexpr int kAskAgain = 2;           // asks after the first when the link drops under a request
constexpr int kReconnectWaitMs = 300;  // before asking again a device that could not be reached

QString code(quint8 function)
{
    return QString::number(function, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

QByteArray surveyPdu(quint8 function, const ConformanceContext &ctx)
{
    const int table = ReadChecks::tableOf(function);
    if (table >= 0)
        return ReadChecks::readPdu(function, qMax(0, ctx.readable(SimTable(table))), 1);
    switch (function) {
    case 0x08:
        return QByteArray::fromHex("080000A537");
    case 0x2B:
        return QByteArray::fromHex("2B0E0100");
    default:
        return QByteArray(1, char(function));
    }
}

QString codes(const QList<quint8> &functions)
{
    QStringList out;
    for (quint8 f : functions)
        out.append(code(f));
    return out.join(QLatin1String(", "));
}

// "not judged: not surveyed (the link closed): 08, 2B; no answer could be matched: 03", or empty:
// the functions the survey learnt nothing of, which a pass of the survey's checks would claim.
QString unjudged(const ConformanceContext &ctx)
{
    QList<quint8> unsurveyed;
    QList<quint8> unmatched;
    for (quint8 f : ConformanceSurvey::functions()) {
        if (ctx.support(f) == SurveyedSupport::NotSurveyed)
            unsurveyed.append(f);
        else if (ctx.support(f) == SurveyedSupport::Unknown)
            unmatched.append(f);
    }
    QStringList why;
    if (!unsurveyed.isEmpty())
        why.append(QStringLiteral("not surveyed (the link closed): %1").arg(codes(unsurveyed)));
    if (!unmatched.isEmpty())
        why.append(QStringLiteral("no answer could be matched to the survey's request: %1").arg(codes(unmatched)));
    return why.isEmpty() ? QString() : QStringLiteral("not judged: ") + why.join(QLatin1String("; "));
}

} // namespace

QList<quint8> ConformanceSurvey::functions()
{
    return {0x03, 0x04, 0x01, 0x02, 0x07, 0x08, 0x0B, 0x0C, 0x11, 0x2B};
}

ConformanceSurvey::Outcome ConformanceSurvey::run(ConformanceContext &ctx)
{
    Outcome outcome;
    bool answered = false;
    for (quint8 f : functions()) {
        ConformanceExchange e = ctx.ask(surveyPdu(f, ctx));
        if (e.linkFailed() && outcome.exchanges.isEmpty()) {
            outcome.exchanges.append(e);
            outcome.linkFailed = true;
            outcome.message = e.transaction.problem;
            return outcome;
        }
        // The link dropped under the request: ask again on a new connection (a device restarting
        // comes back), waiting a little while it cannot be reached.
        for (int again = 0; again < kAskAgain && e.linkFailed(); ++again) {
            if (e.unreachable())
                (void)ctx.link().listen(kReconnectWaitMs);
            e = ctx.ask(surveyPdu(f, ctx));
        }
        outcome.exchanges.append(e);
        if (e.linkFailed()) {
            // Sent each time and closed each time: the device's own reply to this function is no
            // answer at all (exception.unsupported-function says so). Not even sent: nothing is
            // known of it, and its checks are skipped.
            if (e.unreachable()) {
                ctx.setSupport(f, SurveyedSupport::NotSurveyed);
            } else {
                ctx.setSupport(f, SurveyedSupport::Silent);
                ctx.setClosedOn(f);
            }
            continue;
        }
        const Transaction &t = e.transaction;
        SurveyedSupport s = SurveyedSupport::Unknown;
        if (e.silent())
            s = SurveyedSupport::Silent;
        else if (t.status == TransactionStatus::Exception)
            s = t.exceptionCode == 0x01 ? SurveyedSupport::Unsupported : SurveyedSupport::Supported;
        else if (t.status == TransactionStatus::Ok || t.status == TransactionStatus::Malformed)
            s = SurveyedSupport::Supported;
        answered = answered || !e.silent();
        ctx.setSupport(f, s);
        const int table = ReadChecks::tableOf(f);
        if (table >= 0 && t.status == TransactionStatus::Ok && ctx.readable(SimTable(table)) < 0)
            ctx.setReadable(SimTable(table), 0);
    }
    // A request the survey took for unanswered may have been answered after its timeout (the
    // answer came during a later request): supported, only slow (answer.late says so).
    (void)ctx.link().listen(qMin(ctx.link().timeoutMs(), 200));
    const QList<quint8> surveyed = functions();
    for (qsizetype i = 0; i < outcome.exchanges.size() && i < surveyed.size(); ++i) {
        const ConformanceExchange &e = outcome.exchanges.at(i);
        if (ctx.support(surveyed.at(i)) == SurveyedSupport::Silent && ctx.link().answeredLate(e.transaction.id)) {
            ctx.setSupport(surveyed.at(i), SurveyedSupport::Supported);
            answered = true;
        }
    }
    if (!answered) {
        outcome.silent = true;
        outcome.message = QStringLiteral("the device answered none of %1 requests (functions %2) to unit %3 within %4 ms: "
                                         "check the target, the unit id and the timeout")
                              .arg(outcome.exchanges.size())
                              .arg(codes(functions()))
                              .arg(ctx.unit())
                              .arg(ctx.link().timeoutMs());
    }
    return outcome;
}

QList<ConformanceCheck> ConformanceSurvey::checks()
{
    QList<ConformanceCheck> out;
    ConformanceCheck silent;
    silent.id = QStringLiteral("exception.unsupported-function");
    silent.title = QStringLiteral("a public function the device lacks gets exception 01, not silence");
    silent.clause = QStringLiteral("Application Protocol V1.1b3, 7");
    silent.run = [](ConformanceContext &ctx, CheckResult &res) {
        QList<quint8> quiet;
        QList<quint8> refused;
        for (quint8 f : functions()) {
            if (ctx.support(f) == SurveyedSupport::Silent)
                quiet.append(f);
            else if (ctx.support(f) == SurveyedSupport::Unsupported)
                refused.append(f);
        }
        if (quiet.isEmpty()) {
            // A pass says every function answers: not when some could not be asked or matched.
            if (const QString why = unjudged(ctx); !why.isEmpty()) {
                res.skip(why);
                return;
            }
            res.pass(refused.isEmpty() ? QStringLiteral("the device supports every function surveyed")
                                       : QStringLiteral("exception 01 for %1").arg(codes(refused)));
            return;
        }
        QList<quint8> closed;
        for (quint8 f : quiet) {
            if (ctx.closedOn().contains(f))
                closed.append(f);
        }
        const QString how = closed.isEmpty() ? QString()
                                             : QStringLiteral(" (to %1 it closed the connection instead, each of the %2 times it was asked)")
                                                   .arg(codes(closed))
                                                   .arg(1 + kAskAgain);
        res.fail(QStringLiteral("the device answers other requests but gave no answer at all to %1 %2%3; %4 requires "
                                "exception 01 (Illegal Function) for a function it does not support")
                     .arg(quiet.size() == 1 ? QStringLiteral("function") : QStringLiteral("functions"), codes(quiet), how, res.clause));
    };
    out.append(silent);

    ConformanceCheck promise;
    promise.id = QStringLiteral("promise.functions");
    promise.title = QStringLiteral("the functions the profile promises are the ones the device supports");
    promise.clause = QStringLiteral("the device's profile");
    promise.run = [](ConformanceContext &ctx, CheckResult &res) {
        if (!ctx.settings().promised) {
            res.skip(QStringLiteral("no profile declares what the device promises (--profile)"));
            return;
        }
        QList<quint8> missing;
        QList<quint8> extra;
        for (quint8 f : functions()) {
            const bool promised = ctx.settings().promisedFunctions.contains(f);
            const SurveyedSupport s = ctx.support(f);
            if (promised && (s == SurveyedSupport::Unsupported || s == SurveyedSupport::Silent))
                missing.append(f);
            else if (!promised && s == SurveyedSupport::Supported)
                extra.append(f);
        }
        if (missing.isEmpty() && extra.isEmpty()) {
            if (const QString why = unjudged(ctx); !why.isEmpty()) {
                res.skip(why);
                return;
            }
            res.pass(QStringLiteral("every function surveyed is supported exactly as %1 promises").arg(ctx.settings().promiseSource));
            return;
        }
        QStringList why;
        if (!missing.isEmpty())
            why.append(QStringLiteral("%1 promises %2 but the device does not support it").arg(ctx.settings().promiseSource, codes(missing)));
        if (!extra.isEmpty())
            why.append(QStringLiteral("the device supports %1, which %2 does not list").arg(codes(extra), ctx.settings().promiseSource));
        res.fail(why.join(QLatin1String("; ")));
    };
    out.append(promise);
    return out;
}

} // namespace mbscope
