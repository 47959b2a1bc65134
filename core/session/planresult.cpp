#include "session/planresult.h"

#include <QtCore/QJsonArray>

namespace mbscope {

const char *StepResult::outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Passed:
        return "passed";
    case Outcome::Failed:
        return "failed";
    case Outcome::Error:
        return "error";
    case Outcome::Skipped:
        return "skipped";
    }
    return "?";
}

QString planStepKindName(PlanStep::Kind kind)
{
    switch (kind) {
    case PlanStep::Kind::Send:
        return QStringLiteral("send");
    case PlanStep::Kind::Expect:
        return QStringLiteral("expect");
    case PlanStep::Kind::Poll:
        return QStringLiteral("poll");
    case PlanStep::Kind::Wait:
        return QStringLiteral("wait");
    case PlanStep::Kind::Repeat:
        return QStringLiteral("repeat");
    }
    return QStringLiteral("?");
}

int planStepCount(const std::vector<PlanStep> &steps)
{
    int n = 0;
    for (const PlanStep &s : steps)
        n += s.kind == PlanStep::Kind::Repeat ? s.times * planStepCount(s.steps) : 1;
    return n;
}

int PlanResult::count(StepResult::Outcome outcome) const
{
    int n = 0;
    for (const StepResult &s : steps)
        n += s.outcome == outcome ? s.runs : 0;
    return n;
}

int PlanResult::total() const
{
    int n = 0;
    for (const StepResult &s : steps)
        n += s.runs;
    return n;
}

QJsonObject PlanResult::toJson() const
{
    QJsonArray list;
    for (const StepResult &s : steps) {
        QJsonObject o;
        o.insert(QLatin1String("path"), s.path);
        o.insert(QLatin1String("name"), s.name);
        o.insert(QLatin1String("kind"), planStepKindName(s.kind));
        o.insert(QLatin1String("outcome"), QLatin1String(StepResult::outcomeName(s.outcome)));
        o.insert(QLatin1String("reasons"), QJsonArray::fromStringList(s.reasons));
        if (!s.detail.isEmpty())
            o.insert(QLatin1String("detail"), s.detail);
        o.insert(QLatin1String("elapsed_ms"), double(s.elapsedNs) / 1e6);
        if (s.runs > 1)
            o.insert(QLatin1String("runs"), s.runs);
        list.append(o);
    }
    QJsonObject counts;
    for (auto outcome : {StepResult::Outcome::Passed, StepResult::Outcome::Failed, StepResult::Outcome::Error,
                         StepResult::Outcome::Skipped})
        counts.insert(QLatin1String(StepResult::outcomeName(outcome)), count(outcome));
    QJsonObject root;
    root.insert(QLatin1String("plan"), name);
    root.insert(QLatin1String("target"), target);
    root.insert(QLatin1String("started"), started.toUTC().toString(Qt::ISODateWithMs));
    root.insert(QLatin1String("elapsed_ms"), double(elapsedNs) / 1e6);
    root.insert(QLatin1String("passed"), passed());
    root.insert(QLatin1String("total"), total());
    root.insert(QLatin1String("counts"), counts);
    root.insert(QLatin1String("steps"), list);
    if (linkFailed)
        root.insert(QLatin1String("link_error"), linkMessage);
    if (interrupted)
        root.insert(QLatin1String("interrupted"), true);
    return root;
}

} // namespace mbscope
