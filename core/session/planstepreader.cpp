#include "session/planstepreader.h"

#include "protocol/hextext.h"
#include "session/sessionrequestreader.h"
#include "json/jsonreader.h"
#include "time/duration.h"

#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

constexpr qint64 kMaxWaitMs = 24LL * 3600 * 1000;
constexpr qint64 kMaxFieldValue = 0xFFFFFFFFFFFFLL; // the largest field value a frame holds is 48 bits (a reference)

} // namespace

PlanStepReader::PlanStepReader(JsonReader &reader, const QStringList &requestNames)
    : m_reader(reader), m_requestNames(requestNames)
{
}

std::vector<PlanStep> PlanStepReader::readSteps(const QJsonArray &steps, const QString &path)
{
    std::vector<PlanStep> out;
    for (qsizetype i = 0; i < steps.size(); ++i) {
        PlanStep step;
        if (readStep(steps.at(i), JsonReader::element(path, i), &step))
            out.push_back(std::move(step));
    }
    return out;
}

bool PlanStepReader::readStep(const QJsonValue &value, const QString &path, PlanStep *step)
{
    const auto o = m_reader.objectValue(value, path);
    if (!o)
        return false;
    const int before = m_reader.problemCount();
    m_reader.checkKeys(*o, path, {"name", "notes", "send", "expect", "poll", "wait", "repeat", "steps"});
    if (m_reader.require(*o, path, "name")) {
        step->name = m_reader.string(*o, path, "name").value_or(QString());
        if (o->value(QLatin1String("name")).isString() && step->name.trimmed().isEmpty())
            m_reader.error(JsonReader::member(path, "name"), QStringLiteral("the name is empty: a step's result is reported under its name"));
    }
    step->notes = m_reader.string(*o, path, "notes").value_or(QString());

    QStringList actions;
    for (const char *key : {"send", "poll", "wait", "repeat"}) {
        if (o->contains(QLatin1String(key)))
            actions.append(QLatin1String(key));
    }
    if (actions.size() > 1) {
        m_reader.error(path, QStringLiteral("a step does one thing: found %1 (make one step of each)")
                                 .arg(actions.join(QStringLiteral(" and "))));
        return false;
    }
    const QString action = actions.isEmpty() ? QString() : actions.constFirst();
    if (action.isEmpty() && !o->contains(QLatin1String("expect"))) {
        m_reader.error(path, QStringLiteral("a step needs one of send, expect, poll, wait or repeat"));
        return false;
    }
    if (o->contains(QLatin1String("steps")) && action != QLatin1String("repeat"))
        m_reader.error(JsonReader::member(path, "steps"), QStringLiteral("'steps' belong to a repeat step only"));
    if (o->contains(QLatin1String("expect")) && (action == QLatin1String("wait") || action == QLatin1String("repeat")))
        m_reader.error(JsonReader::member(path, "expect"),
                       QStringLiteral("a %1 step has nothing to check: put expectations on send and poll steps").arg(action));

    const QString expectPath = JsonReader::member(path, "expect");
    if (action == QLatin1String("send")) {
        step->kind = PlanStep::Kind::Send;
        const QJsonValue send = o->value(QLatin1String("send"));
        const QString sendPath = JsonReader::member(path, "send");
        if (send.isString()) {
            step->requestName = send.toString();
            SessionRequestReader::checkName(m_reader, sendPath, step->requestName, m_requestNames);
        } else if (send.isObject()) {
            if (const auto r = SessionRequestReader::read(m_reader, send, sendPath, false))
                step->request = *r;
        } else {
            m_reader.error(sendPath, QStringLiteral("expected the name of a request of the document or a request "
                                                    "({\"hex\": ...} or {\"function\": ...}), found %1")
                                         .arg(JsonReader::describe(send)));
        }
        if (o->contains(QLatin1String("expect")))
            readExpectation(o->value(QLatin1String("expect")), expectPath, &step->expect);
        m_sawSend = true;
    } else if (action.isEmpty()) {
        step->kind = PlanStep::Kind::Expect;
        if (!m_sawSend)
            m_reader.error(path, QStringLiteral("an expect step checks the answer of the send step before it: there is none"));
        readExpectation(o->value(QLatin1String("expect")), expectPath, &step->expect);
    } else if (action == QLatin1String("poll")) {
        step->kind = PlanStep::Kind::Poll;
        if (const auto poll = SessionRequestReader::readPoll(m_reader, o->value(QLatin1String("poll")),
                                                             JsonReader::member(path, "poll"), m_requestNames, false))
            step->poll = *poll;
        if (o->contains(QLatin1String("expect")))
            readBounds(o->value(QLatin1String("expect")), expectPath, &step->bounds);
    } else if (action == QLatin1String("wait")) {
        step->kind = PlanStep::Kind::Wait;
        readWait(o->value(QLatin1String("wait")), JsonReader::member(path, "wait"), &step->waitMs);
    } else {
        step->kind = PlanStep::Kind::Repeat;
        step->times = int(m_reader.integer(*o, path, "repeat", 1, 1'000'000).value_or(1));
        if (m_reader.require(*o, path, "steps")) {
            if (const auto steps = m_reader.array(*o, path, "steps")) {
                if (steps->isEmpty())
                    m_reader.error(JsonReader::member(path, "steps"), QStringLiteral("the list is empty: a repeat step repeats at least one step"));
                step->steps = readSteps(*steps, JsonReader::member(path, "steps"));
            }
        }
    }
    return m_reader.problemCount() == before;
}

bool PlanStepReader::readExpectation(const QJsonValue &value, const QString &path, StepExpectation *out)
{
    const auto o = m_reader.objectValue(value, path);
    if (!o)
        return false;
    const int before = m_reader.problemCount();
    m_reader.checkKeys(*o, path, {"bytes", "fields", "exception", "noAnswer"});
    if (const auto bytes = m_reader.string(*o, path, "bytes")) {
        const HexTextResult parsed = HexText::parse(*bytes);
        if (!parsed.ok)
            m_reader.error(JsonReader::member(path, "bytes"), parsed.error.message);
        out->bytes = *bytes;
    }
    if (const auto code = m_reader.integer(*o, path, "exception", 1, 255))
        out->exception = int(*code);
    out->noAnswer = m_reader.boolean(*o, path, "noAnswer").value_or(false);
    if (const auto fields = m_reader.object(*o, path, "fields")) {
        if (fields->isEmpty())
            m_reader.error(JsonReader::member(path, "fields"), QStringLiteral("the object is empty: name at least one field"));
        for (auto it = fields->begin(); it != fields->end(); ++it) {
            const QString at = JsonReader::member(JsonReader::member(path, "fields"), it.key());
            FieldExpectation f;
            QString error;
            if (!FieldExpectation::parseSelector(it.key(), &f, &error)) {
                m_reader.error(JsonReader::member(path, "fields"), error);
                continue;
            }
            const QJsonValue v = it.value();
            if (v.isObject()) {
                const QJsonObject range = v.toObject();
                m_reader.checkKeys(range, at, {"min", "max"});
                f.min = m_reader.integer(range, at, "min", 0, kMaxFieldValue);
                f.max = m_reader.integer(range, at, "max", 0, kMaxFieldValue);
                if (!range.contains(QLatin1String("min")) && !range.contains(QLatin1String("max")))
                    m_reader.error(at, QStringLiteral("a range needs 'min', 'max' or both"));
                else if (f.min && f.max && *f.min > *f.max)
                    m_reader.error(at, QStringLiteral("min %1 is above max %2").arg(*f.min).arg(*f.max));
            } else if (v.isDouble() || v.isString()) {
                f.equals = m_reader.integerValue(v, at, 0, kMaxFieldValue);
            } else {
                m_reader.error(at, QStringLiteral("expected a whole number (exact value) or {\"min\": .., \"max\": ..}, found %1")
                                       .arg(JsonReader::describe(v)));
            }
            out->fields.append(f);
        }
    }
    if (out->noAnswer && (out->bytes || out->exception || !out->fields.isEmpty()))
        m_reader.error(path, QStringLiteral("\"noAnswer\": true stands alone: an answer that must not come has no bytes, fields or exception"));
    if (o->isEmpty())
        m_reader.error(path, QStringLiteral("the expectation is empty: give bytes, fields, exception or noAnswer"));
    return m_reader.problemCount() == before;
}

bool PlanStepReader::readBounds(const QJsonValue &value, const QString &path, QList<PollBound> *out)
{
    if (!value.isArray()) {
        m_reader.error(path, QStringLiteral("a poll step expects a list of bounds such as [\"p95 < 20 ms\", \"timeouts == 0\"], found %1")
                                 .arg(JsonReader::describe(value)));
        return false;
    }
    const QJsonArray list = value.toArray();
    const int before = m_reader.problemCount();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString at = JsonReader::element(path, i);
        const auto text = m_reader.stringValue(list.at(i), at);
        if (!text)
            continue;
        const PollBound::Parsed parsed = PollBound::parse(*text);
        if (!parsed.bound)
            m_reader.error(at, parsed.error);
        else
            out->append(*parsed.bound);
    }
    return m_reader.problemCount() == before;
}

bool PlanStepReader::readWait(const QJsonValue &value, const QString &path, qint64 *ms)
{
    if (value.isDouble()) {
        const auto v = m_reader.integerValue(value, path, 0, kMaxWaitMs);
        *ms = v.value_or(0);
        return v.has_value();
    }
    const DurationResult d = value.isString() ? parseDuration(value.toString()) : DurationResult{};
    if (d.problem == DurationResult::Problem::TooLong || (d.ok() && d.ns / Duration::Millisecond > kMaxWaitMs)) {
        m_reader.error(path, QStringLiteral("%1 is beyond a day").arg(value.toString()));
        return false;
    }
    if (!d.ok()) {
        m_reader.error(path, QStringLiteral("expected a duration such as 500 (ms), \"500 ms\", \"2 s\" or \"1 min\", found %1")
                                 .arg(JsonReader::describe(value)));
        return false;
    }
    *ms = d.ns / Duration::Millisecond;
    return true;
}

} // namespace mbscope
