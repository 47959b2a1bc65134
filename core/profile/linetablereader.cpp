#include "linetablereader.h"

#include "json/jsonreader.h"
#include "scriptsettingsreader.h"
#include "linetemplate.h"

namespace mbscope {

namespace {

// Every capture a template names must be one of the pattern's named groups.
void checkTemplate(JsonReader &reader, const QString &text, const QString &at, const QStringList &captures,
                   bool tablesAllowed)
{
    QString error;
    const auto fields = LineTemplate::fields(text, &error);
    if (!fields) {
        reader.error(at, error);
        return;
    }
    for (const LineTemplate::Field &f : *fields) {
        if (!f.capture.isEmpty() && !captures.contains(f.capture)) {
            reader.error(at, QStringLiteral("{%1} is not a capture of the request pattern: expected one of %2")
                                 .arg(f.capture, captures.isEmpty() ? QStringLiteral("(none: name one with (?<name>...))")
                                                                    : captures.join(QStringLiteral(", "))));
        } else if (f.capture.isEmpty() && !tablesAllowed) {
            reader.error(at, QStringLiteral("expected a capture such as {bit}, not a table's values"));
        }
    }
}

std::optional<LineRule> readRule(JsonReader &reader, const QJsonValue &value, const QString &path, qsizetype index)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    reader.checkKeys(*o, path, {"name", "request", "answer", "writes"});
    LineRule rule;
    rule.name = reader.string(*o, path, "name").value_or(QStringLiteral("rule %1").arg(index));
    if (reader.require(*o, path, "request"))
        rule.pattern = reader.string(*o, path, "request").value_or(QString());
    const QString requestAt = JsonReader::member(path, "request");
    // The whole frame must match, not a part of it.
    rule.request = QRegularExpression(QStringLiteral("\\A(?:%1)\\z").arg(rule.pattern));
    QStringList captures;
    if (o->value(QLatin1String("request")).isString()) {
        const QRegularExpression alone(rule.pattern);
        if (!alone.isValid()) {
            reader.error(requestAt, QStringLiteral("not a regular expression: %1 at character %2")
                                        .arg(alone.errorString())
                                        .arg(alone.patternErrorOffset() + 1));
        } else {
            for (const QString &name : alone.namedCaptureGroups()) {
                if (!name.isEmpty())
                    captures.append(name);
            }
        }
    }
    const QJsonValue answer = o->value(QLatin1String("answer"));
    const QString answerAt = JsonReader::member(path, "answer");
    if (answer.isNull()) {
        rule.silent = true;
    } else if (answer.isString()) {
        rule.answer = answer.toString();
        checkTemplate(reader, rule.answer, answerAt, captures, true);
    } else if (answer.isUndefined()) {
        reader.error(path, QStringLiteral("'answer' is missing: give the answer's text, or null for no answer"));
    } else {
        reader.error(answerAt, QStringLiteral("expected the answer's text such as \"${unit} {holding:0-7} #\", or null, found %1")
                                   .arg(JsonReader::describe(answer)));
    }
    if (const auto writes = reader.array(*o, path, "writes")) {
        const QString writesAt = JsonReader::member(path, "writes");
        for (qsizetype i = 0; i < writes->size(); ++i) {
            const QString at = JsonReader::element(writesAt, i);
            const auto w = reader.objectValue(writes->at(i), at);
            if (!w)
                continue;
            reader.checkKeys(*w, at, {"table", "address", "value"});
            LineWrite write;
            if (reader.require(*w, at, "table")) {
                const QString table = reader.string(*w, at, "table").value_or(QString());
                if (table == QLatin1String("coils"))
                    write.table = SimTable::Coils;
                else if (table == QLatin1String("holding"))
                    write.table = SimTable::HoldingRegisters;
                else if (w->value(QLatin1String("table")).isString())
                    reader.error(JsonReader::member(at, "table"),
                                 QStringLiteral("'%1' cannot be written: expected coils or holding").arg(table));
            }
            for (const char *key : {"address", "value"}) {
                if (!reader.require(*w, at, key))
                    continue;
                const QJsonValue v = w->value(QLatin1String(key));
                const QString text = v.isDouble() ? QString::number(v.toInteger()) : reader.string(*w, at, key).value_or(QString());
                checkTemplate(reader, text, JsonReader::member(at, key), captures, false);
                (QLatin1String(key) == QLatin1String("address") ? write.address : write.value) = text;
            }
            rule.writes.append(write);
        }
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return rule;
}

} // namespace

LineTable LineTableReader::read(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    LineTable table;
    const auto o = reader.objectValue(value, path);
    if (!o)
        return table;
    reader.checkKeys(*o, path, {"unitCapture", "rules", "script"});
    table.unitCapture = reader.string(*o, path, "unitCapture").value_or(QStringLiteral("unit"));
    if (o->contains(QLatin1String("script"))) {
        if (const auto script = ScriptSettingsReader::read(reader, o->value(QLatin1String("script")),
                                                           JsonReader::member(path, "script")))
            table.script = *script;
    }
    // A script alone may serve the protocol; without one the rules are the protocol.
    if ((o->contains(QLatin1String("script")) && !o->contains(QLatin1String("rules"))) || reader.require(*o, path, "rules")) {
        if (const auto rules = reader.array(*o, path, "rules")) {
            const QString at = JsonReader::member(path, "rules");
            if (rules->isEmpty())
                reader.error(at, QStringLiteral("the list is empty: a delimited protocol needs at least one rule"));
            for (qsizetype i = 0; i < rules->size(); ++i) {
                if (const auto rule = readRule(reader, rules->at(i), JsonReader::element(at, i), i))
                    table.rules.append(*rule);
            }
        }
    }
    return table;
}

} // namespace mbscope
