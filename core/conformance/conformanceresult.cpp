#include "conformanceresult.h"

#include "conformancejudge.h"

#include "session/junitreport.h"

#include <QtCore/QJsonArray>

namespace mbscope {

namespace {

QString code(quint8 function)
{
    return QString::number(function, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace

const char *ConformanceResult::label(const CheckResult &r)
{
    switch (r.verdict) {
    case CheckVerdict::Passed:
        return r.level == CheckLevel::Informational ? "INFO" : "PASS";
    case CheckVerdict::Failed:
        return r.level == CheckLevel::Mandatory ? "FAIL" : "WARN";
    case CheckVerdict::Skipped:
        return "SKIP";
    case CheckVerdict::Error:
        return "ERROR";
    }
    return "";
}

QString ConformanceResult::verdictSentence() const
{
    if (passed())
        return QStringLiteral("every mandatory check passed");
    if (linkFailed)
        return QStringLiteral("not tested: ") + linkMessage;
    if (!linkLostAt.isEmpty())
        return QStringLiteral("cut short: the link was lost at check %1 (%2): %3 check(s) after it not judged")
            .arg(linkLostAt, linkLostMessage)
            .arg(notJudged());
    if (interrupted)
        return QStringLiteral("interrupted");
    return QStringLiteral("%1 mandatory check(s) failed").arg(failed(CheckLevel::Mandatory) + count(CheckVerdict::Error));
}

QString ConformanceResult::countsSentence() const
{
    return QStringLiteral("%1 checks: %2 passed, %3 failed (%4 mandatory, %5 recommended), %6 skipped, %7 errors")
        .arg(checks.size())
        .arg(count(CheckVerdict::Passed))
        .arg(count(CheckVerdict::Failed))
        .arg(failed(CheckLevel::Mandatory))
        .arg(failed(CheckLevel::Recommended))
        .arg(count(CheckVerdict::Skipped))
        .arg(count(CheckVerdict::Error));
}

QString ConformanceResult::supportSentence() const
{
    QStringList functions;
    for (auto it = support.cbegin(); it != support.cend(); ++it)
        functions.append(QStringLiteral("%1 %2").arg(code(it.key()), QLatin1String(supportName(it.value()))));
    return functions.join(QLatin1String(", "));
}

const char *checkLevelName(CheckLevel level)
{
    switch (level) {
    case CheckLevel::Mandatory: return "mandatory";
    case CheckLevel::Recommended: return "recommended";
    case CheckLevel::Informational: return "informational";
    }
    return "";
}

const char *checkVerdictName(CheckVerdict verdict)
{
    switch (verdict) {
    case CheckVerdict::Passed: return "passed";
    case CheckVerdict::Failed: return "failed";
    case CheckVerdict::Skipped: return "skipped";
    case CheckVerdict::Error: return "error";
    }
    return "";
}

const char *ConformanceResult::supportName(SurveyedSupport support)
{
    switch (support) {
    case SurveyedSupport::Supported: return "supported";
    case SurveyedSupport::Unsupported: return "unsupported";
    case SurveyedSupport::Silent: return "silent";
    case SurveyedSupport::Unknown: return "unknown";
    case SurveyedSupport::NotSurveyed: return "not surveyed";
    }
    return "";
}

int ConformanceResult::count(CheckVerdict verdict) const
{
    int n = 0;
    for (const CheckResult &c : checks)
        n += c.verdict == verdict ? 1 : 0;
    return n;
}

int ConformanceResult::notJudged() const
{
    int n = 0;
    bool after = false;
    for (const CheckResult &c : checks) {
        n += after ? 1 : 0;
        after = after || (!linkLostAt.isEmpty() && c.id == linkLostAt);
    }
    return n;
}

int ConformanceResult::failed(CheckLevel level) const
{
    int n = 0;
    for (const CheckResult &c : checks)
        n += c.verdict == CheckVerdict::Failed && c.level == level ? 1 : 0;
    return n;
}

QString ConformanceResult::toText() const
{
    QString out;
    out += QStringLiteral("target     %1, unit %2\n").arg(target).arg(unit);
    if (!support.isEmpty())
        out += QStringLiteral("functions  %1\n").arg(supportSentence());
    out += QLatin1Char('\n');
    for (const CheckResult &c : checks) {
        out += QStringLiteral("%1  %2  %3  [%4]\n").arg(QString::fromLatin1(label(c)).leftJustified(5), c.id, c.title, c.clause);
        if (c.verdict != CheckVerdict::Passed || c.level == CheckLevel::Informational)
            out += QStringLiteral("       %1\n").arg(c.sentence);
    }
    out += QStringLiteral("\n%1 in %2 s\n").arg(countsSentence()).arg(double(elapsedNs) / 1e9, 0, 'f', 3);
    out += QStringLiteral("verdict    %1\n").arg(verdictSentence());
    return out;
}

QJsonObject ConformanceResult::toJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("target"), target);
    o.insert(QStringLiteral("unit"), unit);
    o.insert(QStringLiteral("started"), started.toUTC().toString(Qt::ISODateWithMs));
    o.insert(QStringLiteral("elapsed_ms"), double(elapsedNs) / 1e6);
    o.insert(QStringLiteral("passed"), passed());
    QJsonObject counts;
    for (CheckVerdict v : {CheckVerdict::Passed, CheckVerdict::Failed, CheckVerdict::Skipped, CheckVerdict::Error})
        counts.insert(QLatin1String(checkVerdictName(v)), count(v));
    counts.insert(QStringLiteral("failed_mandatory"), failed(CheckLevel::Mandatory));
    o.insert(QStringLiteral("counts"), counts);
    QJsonObject functions;
    for (auto it = support.cbegin(); it != support.cend(); ++it)
        functions.insert(code(it.key()), QLatin1String(supportName(it.value())));
    o.insert(QStringLiteral("functions"), functions);
    QJsonArray list;
    for (const CheckResult &c : checks) {
        QJsonObject j;
        j.insert(QStringLiteral("id"), c.id);
        j.insert(QStringLiteral("title"), c.title);
        j.insert(QStringLiteral("clause"), c.clause);
        j.insert(QStringLiteral("level"), QLatin1String(checkLevelName(c.level)));
        j.insert(QStringLiteral("verdict"), QLatin1String(checkVerdictName(c.verdict)));
        j.insert(QStringLiteral("sentence"), c.sentence);
        j.insert(QStringLiteral("request"), ConformanceJudge::hex(c.request));
        j.insert(QStringLiteral("answer"), ConformanceJudge::hex(c.answer));
        if (!c.measured.isEmpty())
            j.insert(QStringLiteral("measured"), c.measured);
        j.insert(QStringLiteral("elapsed_ms"), double(c.elapsedNs) / 1e6);
        list.append(j);
    }
    o.insert(QStringLiteral("checks"), list);
    if (linkFailed)
        o.insert(QStringLiteral("link_error"), linkMessage);
    if (!linkLostAt.isEmpty()) {
        QJsonObject lost;
        lost.insert(QStringLiteral("check"), linkLostAt);
        lost.insert(QStringLiteral("problem"), linkLostMessage);
        lost.insert(QStringLiteral("not_judged"), notJudged());
        o.insert(QStringLiteral("link_lost"), lost);
    }
    o.insert(QStringLiteral("interrupted"), interrupted);
    return o;
}

JUnitTestSuite ConformanceResult::toJUnit() const
{
    JUnitTestSuite suite;
    suite.name = QStringLiteral("mbscope conform");
    suite.started = started;
    suite.elapsedNs = elapsedNs;
    suite.properties.append({QStringLiteral("target"), target});
    suite.properties.append({QStringLiteral("unit"), QString::number(unit)});
    for (const CheckResult &c : checks) {
        JUnitTestCase t;
        t.name = c.id;
        t.classname = suite.name + QLatin1Char('.') + c.id.section(QLatin1Char('.'), 0, 0);
        t.elapsedNs = c.elapsedNs;
        t.type = QLatin1String(checkLevelName(c.level));
        t.message = c.sentence;
        t.text = QStringLiteral("%1 [%2]\nrequest: %3\nanswer: %4\n%5")
                     .arg(c.title, c.clause, ConformanceJudge::hex(c.request),
                          c.answer.isEmpty() ? QStringLiteral("(none)") : ConformanceJudge::hex(c.answer), c.sentence);
        switch (c.verdict) {
        case CheckVerdict::Passed:
            t.outcome = JUnitTestCase::Outcome::Passed;
            t.systemOut = t.text;
            break;
        case CheckVerdict::Failed:
            // A recommended check's failure is a deviation, not a failed test: said in system-out.
            t.outcome = c.level == CheckLevel::Mandatory ? JUnitTestCase::Outcome::Failed : JUnitTestCase::Outcome::Passed;
            t.systemOut = c.level == CheckLevel::Mandatory ? QString() : QStringLiteral("deviation (%1): %2").arg(t.type, t.text);
            break;
        case CheckVerdict::Skipped:
            t.outcome = JUnitTestCase::Outcome::Skipped;
            break;
        case CheckVerdict::Error:
            t.outcome = JUnitTestCase::Outcome::Error;
            break;
        }
        suite.cases.append(t);
    }
    return suite;
}

} // namespace mbscope
