#include "session/sessionrequestreader.h"

#include "json/jsonreader.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

constexpr qint64 kMaxMs = 366LL * 24 * 3600 * 1000; // a year

} // namespace

bool SessionRequestReader::checkName(JsonReader &reader, const QString &path, const QString &name,
                                     const QStringList &requestNames)
{
    if (requestNames.contains(name))
        return true;
    reader.error(path, requestNames.isEmpty()
                           ? QStringLiteral("no request named '%1': the document's request list is empty").arg(name)
                           : QStringLiteral("no request named '%1': expected one of '%2'")
                                 .arg(name, requestNames.join(QStringLiteral("', '"))));
    return false;
}

std::optional<SessionRequest> SessionRequestReader::read(JsonReader &reader, const QJsonValue &value,
                                                         const QString &path, bool named)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    SessionRequest r;
    const bool isHex = o->contains(QLatin1String("hex"));
    const bool isForm = o->contains(QLatin1String("function"));
    if (isHex && isForm) {
        reader.error(path, QStringLiteral("give either 'hex' (exact bytes) or 'function' (a form), not both"));
        return std::nullopt;
    }
    if (!isHex && !isForm) {
        reader.error(path, QStringLiteral("give 'hex' (exact bytes, such as \"01 03 00 79 00 16 15 DD\") or "
                                          "'function' with its parameters (a form)"));
        return std::nullopt;
    }
    if (isHex)
        reader.checkKeys(*o, path, {"name", "notes", "hex", "complete", "unit"});
    else
        reader.checkKeys(*o, path, {"name", "notes", "function", "unit", "address", "quantity", "values", "coils"});

    if (named && reader.require(*o, path, "name")) {
        r.name = reader.string(*o, path, "name").value_or(QString());
        if (o->value(QLatin1String("name")).isString() && r.name.trimmed().isEmpty())
            reader.error(JsonReader::member(path, "name"), QStringLiteral("the name is empty"));
    } else if (!named && o->contains(QLatin1String("name"))) {
        reader.error(JsonReader::member(path, "name"),
                     QStringLiteral("a step's own request has no name of its own: name the step instead"));
    }
    r.notes = reader.string(*o, path, "notes").value_or(QString());
    if (const auto unit = reader.integer(*o, path, "unit", 0, 255))
        r.unit = int(*unit);

    if (isHex) {
        r.kind = SessionRequest::Kind::Hex;
        r.hex = reader.string(*o, path, "hex").value_or(QString());
        r.complete = reader.boolean(*o, path, "complete").value_or(false);
        if (o->contains(QLatin1String("unit")) && !r.complete)
            reader.error(JsonReader::member(path, "unit"),
                         QStringLiteral("'unit' applies only with \"complete\": true; exact bytes carry their own unit id"));
        if (o->value(QLatin1String("hex")).isString()) {
            const SessionRequest::Bytes bytes = r.hexBytes();
            if (!bytes.ok())
                reader.error(JsonReader::member(path, "hex"), bytes.error);
        }
    } else {
        r.kind = SessionRequest::Kind::Form;
        const int formBefore = reader.problemCount();
        r.function = int(reader.integer(*o, path, "function", 1, 255).value_or(0));
        if (r.function != 0 && !SessionRequest::formSupports(r.function))
            reader.error(JsonReader::member(path, "function"), r.pdu().error);
        const bool reads = r.function >= 1 && r.function <= 4;
        if (reader.require(*o, path, "address"))
            r.address = int(reader.integer(*o, path, "address", 0, 65535).value_or(0));
        if (reads && reader.require(*o, path, "quantity"))
            r.quantity = int(reader.integer(*o, path, "quantity", 0, 65535).value_or(0));
        if (!reads && o->contains(QLatin1String("quantity")))
            reader.error(JsonReader::member(path, "quantity"),
                         QStringLiteral("a write's quantity is the number of values or coils given: leave 'quantity' out"));
        const bool writesRegisters = r.function == 6 || r.function == 16;
        const bool writesCoils = r.function == 5 || r.function == 15;
        if (const auto values = reader.array(*o, path, "values")) {
            if (!writesRegisters)
                reader.error(JsonReader::member(path, "values"),
                             QStringLiteral("'values' are written by functions 6 and 16 only"));
            for (qsizetype i = 0; i < values->size(); ++i) {
                if (const auto v = reader.integerValue(values->at(i), JsonReader::element(JsonReader::member(path, "values"), i), 0, 65535))
                    r.values.append(quint16(*v));
            }
        } else if (writesRegisters) {
            reader.require(*o, path, "values");
        }
        if (const auto coils = reader.array(*o, path, "coils")) {
            if (!writesCoils)
                reader.error(JsonReader::member(path, "coils"), QStringLiteral("'coils' are written by functions 5 and 15 only"));
            for (qsizetype i = 0; i < coils->size(); ++i) {
                const QJsonValue c = coils->at(i);
                if (!c.isBool())
                    reader.error(JsonReader::element(JsonReader::member(path, "coils"), i),
                                 QStringLiteral("expected true or false, found %1").arg(JsonReader::describe(c)));
                else
                    r.coils.append(c.toBool());
            }
        } else if (writesCoils) {
            reader.require(*o, path, "coils");
        }
        // Build it only when every form parameter was read, so each problem is reported once.
        if (reader.problemCount() == formBefore) {
            const SessionRequest::Bytes pdu = r.pdu();
            if (!pdu.ok())
                reader.error(JsonReader::member(path, pdu.parameter), pdu.error);
        }
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return r;
}

std::optional<SessionPoll> SessionRequestReader::readPoll(JsonReader &reader, const QJsonValue &value,
                                                          const QString &path, const QStringList &requestNames,
                                                          bool sweep, QList<qint64> *intervalsMs)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    if (sweep)
        reader.checkKeys(*o, path, {"requests", "intervalsMs", "count", "durationMs"});
    else
        reader.checkKeys(*o, path, {"requests", "intervalMs", "count", "durationMs"});
    SessionPoll poll;
    if (reader.require(*o, path, "requests")) {
        if (const auto names = reader.array(*o, path, "requests")) {
            if (names->isEmpty())
                reader.error(JsonReader::member(path, "requests"), QStringLiteral("the list is empty: a poll sends at least one request"));
            for (qsizetype i = 0; i < names->size(); ++i) {
                const QString at = JsonReader::element(JsonReader::member(path, "requests"), i);
                if (const auto name = reader.stringValue(names->at(i), at)) {
                    if (checkName(reader, at, *name, requestNames))
                        poll.requests.append(*name);
                }
            }
        }
    }
    poll.intervalMs = reader.integer(*o, path, "intervalMs", 0, kMaxMs).value_or(0);
    poll.count = quint64(reader.integer(*o, path, "count", 0, 1'000'000'000'000LL).value_or(0));
    poll.durationMs = reader.integer(*o, path, "durationMs", 0, kMaxMs).value_or(0);
    if (sweep && reader.require(*o, path, "intervalsMs")) {
        if (const auto list = reader.array(*o, path, "intervalsMs")) {
            if (list->isEmpty())
                reader.error(JsonReader::member(path, "intervalsMs"), QStringLiteral("the list is empty: a sweep runs at least one interval"));
            for (qsizetype i = 0; i < list->size(); ++i) {
                const auto ms = reader.integerValue(list->at(i), JsonReader::element(JsonReader::member(path, "intervalsMs"), i), 0, kMaxMs);
                if (ms && intervalsMs)
                    intervalsMs->append(*ms);
            }
        }
    }
    if (poll.count == 0 && poll.durationMs == 0 && reader.problemCount() == before)
        reader.error(path, QStringLiteral("a poll ends: give 'count' (cycles) or 'durationMs', or both"));
    if (reader.problemCount() != before)
        return std::nullopt;
    return poll;
}

} // namespace mbscope
