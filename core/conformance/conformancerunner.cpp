#include "conformancerunner.h"

#include "conformancecontext.h"
#include "conformancelink.h"
#include "conformancesurvey.h"
#include "identitychecks.h"
#include "linkchecks.h"
#include "mbapchecks.h"
#include "readchecks.h"
#include "serialtimingchecks.h"
#include "writechecks.h"

#include "profile/simtable.h"
#include "transport/monotonicclock.h"

namespace mbscope {

namespace {

QString code(quint8 function)
{
    return QString::number(function, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace

ConformanceRunner::ConformanceRunner(ConformanceSettings settings)
    : m_settings(std::move(settings))
{
}

QList<ConformanceCheck> ConformanceRunner::battery()
{
    QList<ConformanceCheck> all = ConformanceSurvey::checks();
    all += ReadChecks::checks();
    all += MbapChecks::checks();
    all += LinkChecks::checks();
    all += SerialTimingChecks::checks();
    all += IdentityChecks::checks();
    all += WriteChecks::checks();
    all += LinkChecks::afterChecks();
    return all;
}

QString ConformanceRunner::skipReason(const ConformanceCheck &check, const ConformanceContext &ctx)
{
    const CheckNeeds &n = check.needs;
    const ConformanceLink &link = const_cast<ConformanceContext &>(ctx).link();
    if (n.mbap && !link.isMbap())
        return QStringLiteral("the link's framing (%1) has no MBAP header").arg(framingName(link.framing()));
    if (n.serial && !link.isSerialFraming())
        return QStringLiteral("a serial framing's rule (rtu or ascii), and the link's framing is %1").arg(framingName(link.framing()));
    if (n.serialPort && !(link.url().isSerial() && link.framing() == Framing::Rtu))
        return QStringLiteral("not measurable on this link: the line's timing, and %1 is not RTU on a serial port (behind a "
                              "gateway or a device server the line is out of sight)")
            .arg(LinkUrl::schemeName(link.url().kind));
    if (n.stream && !link.isStream())
        return QStringLiteral("a rule of connections, and %1 has none").arg(LinkUrl::schemeName(link.url().kind));
    if (n.function != 0) {
        const QString fc = code(n.function);
        if (ctx.settings().promised && !ctx.settings().promisedFunctions.contains(n.function))
            return QStringLiteral("%1 does not promise function %2").arg(ctx.settings().promiseSource, fc);
        switch (ctx.support(n.function)) {
        case SurveyedSupport::Unsupported:
            return QStringLiteral("the device answers function %1 with exception 01: it does not support it").arg(fc);
        case SurveyedSupport::Silent:
            return QStringLiteral("the device did not answer function %1 at all (see exception.unsupported-function)").arg(fc);
        case SurveyedSupport::NotSurveyed:
            return QStringLiteral("not surveyed (the link closed each time the survey asked about function %1)").arg(fc);
        case SurveyedSupport::Supported:
        case SurveyedSupport::Unknown:
            break;
        }
    }
    if (n.readable >= 0 && ctx.readable(SimTable(n.readable)) < 0) {
        const char *key = simTableKey(SimTable(n.readable));
        return QStringLiteral("no readable address of the %1 is known (a read at 0 was refused): name one with --readable %2:ADDRESS")
            .arg(QLatin1String(simTableName(SimTable(n.readable))), QLatin1String(key));
    }
    if (n.writable >= 0 && !ctx.settings().writableIn(SimTable(n.writable))) {
        const char *key = simTableKey(SimTable(n.writable));
        return QStringLiteral("safe by default: it writes only where --writable %1:ADDRESS allows (the value found is put back)")
            .arg(QLatin1String(key));
    }
    return {};
}

ConformanceResult ConformanceRunner::run(const std::function<void(const CheckResult &)> &each)
{
    ConformanceResult result;
    result.target = m_settings.url.toString();
    result.unit = m_settings.unit;
    result.started = QDateTime::currentDateTime();
    const qint64 startNs = monotonicNowNs();

    ConformanceLink link(m_settings.url, m_settings.timeoutMs);
    if (m_log)
        link.setTrafficLog(m_log);
    if (m_framesLogged)
        link.onFramesLogged(m_framesLogged);
    ConformanceContext ctx(m_settings, link);
    const ConformanceSurvey::Outcome survey = ConformanceSurvey::run(ctx);
    result.support = ctx.supportTable();
    if (survey.linkFailed || survey.silent) {
        result.linkFailed = true;
        result.linkMessage = survey.message;
    } else {
        bool droppedInPrevious = false;
        for (const ConformanceCheck &check : battery()) {
            if (!m_settings.selected(check.id))
                continue;
            CheckResult r;
            r.id = check.id;
            r.title = check.title;
            r.clause = check.clause;
            r.level = check.level;
            if (m_stop) {
                result.interrupted = true;
                break;
            }
            const qint64 t0 = monotonicNowNs();
            const int unreachableBefore = link.unreachableCount();
            const int droppedBefore = link.droppedCount();
            const QString why = skipReason(check, ctx);
            if (!result.linkLostAt.isEmpty())
                r.skip(QStringLiteral("not judged: the link was lost at check %1").arg(result.linkLostAt));
            else if (!why.isEmpty())
                r.skip(why);
            else
                check.run(ctx, r);
            if (link.unreachableCount() > unreachableBefore) {
                // A request of this check could not even be sent: its evidence is incomplete, and
                // the device is gone. Said once; the checks after it are not run. When the
                // connection closed under the previous check's last request, the device died
                // there: that check is the one not judged, and this one follows it.
                CheckResult *lost = &r;
                if (droppedInPrevious && !result.checks.isEmpty())
                    lost = &result.checks.last();
                result.linkLostAt = lost->id;
                result.linkLostMessage = link.lastProblem();
                lost->verdict = CheckVerdict::Error;
                lost->sentence = QStringLiteral("not judged: the link was lost during this check (%1); the checks after it are not run")
                                     .arg(link.lastProblem());
                if (lost != &r)
                    r.skip(QStringLiteral("not judged: the link was lost at check %1").arg(result.linkLostAt));
            }
            droppedInPrevious = link.droppedCount() > droppedBefore;
            r.elapsedNs = monotonicNowNs() - t0;
            result.checks.append(r);
            if (each)
                each(r);
        }
    }
    if (m_log)
        link.setTrafficLog(nullptr);
    result.elapsedNs = monotonicNowNs() - startNs;
    return result;
}

} // namespace mbscope
