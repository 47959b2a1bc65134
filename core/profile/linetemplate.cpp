#include "linetemplate.h"

namespace mbscope {

namespace {

// Walks text, calling literal(chunk) and field(inner, offset) in order; false with *error.
template<typename Literal, typename FieldFn>
bool walk(const QString &text, QString *error, Literal &&literal, FieldFn &&field)
{
    qsizetype i = 0;
    while (i < text.size()) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('{') || c == QLatin1Char('}')) {
            if (i + 1 < text.size() && text.at(i + 1) == c) {
                literal(QString(c));
                i += 2;
                continue;
            }
            if (c == QLatin1Char('}')) {
                *error = QStringLiteral("character %1: '}' without '{' (write }} for a brace)").arg(i + 1);
                return false;
            }
            const qsizetype end = text.indexOf(QLatin1Char('}'), i + 1);
            if (end < 0) {
                *error = QStringLiteral("character %1: '{' is not closed (write {{ for a brace)").arg(i + 1);
                return false;
            }
            if (!field(text.mid(i + 1, end - i - 1), i + 1))
                return false;
            i = end + 1;
            continue;
        }
        const qsizetype next = [&] {
            qsizetype j = i;
            while (j < text.size() && text.at(j) != QLatin1Char('{') && text.at(j) != QLatin1Char('}'))
                ++j;
            return j;
        }();
        literal(text.mid(i, next - i));
        i = next;
    }
    return true;
}

std::optional<LineTemplate::Field> parseField(const QString &inner, qsizetype at, QString *error)
{
    LineTemplate::Field f;
    const qsizetype colon = inner.indexOf(QLatin1Char(':'));
    if (colon < 0) {
        if (inner.isEmpty()) {
            *error = QStringLiteral("character %1: an empty field {}: expected a capture's name or table:address").arg(at);
            return std::nullopt;
        }
        f.capture = inner;
        return f;
    }
    const auto table = LineTemplate::tableNamed(QStringView(inner).left(colon));
    if (!table) {
        *error = QStringLiteral("character %1: '%2' is not a table: expected coils, discrete, input or holding")
                     .arg(at)
                     .arg(inner.left(colon));
        return std::nullopt;
    }
    f.table = *table;
    const QString range = inner.mid(colon + 1);
    const QStringList ends = range.split(QLatin1Char('-'));
    bool ok1 = false;
    bool ok2 = true;
    f.first = ends.value(0).toInt(&ok1, 0);
    f.last = ends.size() == 2 ? ends.at(1).toInt(&ok2, 0) : f.first;
    if (ends.size() > 2 || !ok1 || !ok2 || f.first < 0 || f.last > 65535) {
        *error = QStringLiteral("character %1: '%2' is not an address or a range such as 0-7").arg(at).arg(range);
        return std::nullopt;
    }
    if (f.last < f.first) {
        *error = QStringLiteral("character %1: range %2 ends before it starts").arg(at).arg(range);
        return std::nullopt;
    }
    return f;
}

} // namespace

std::optional<SimTable> LineTemplate::tableNamed(QStringView name)
{
    if (name == u"coils")
        return SimTable::Coils;
    if (name == u"discrete")
        return SimTable::DiscreteInputs;
    if (name == u"input")
        return SimTable::InputRegisters;
    if (name == u"holding")
        return SimTable::HoldingRegisters;
    return std::nullopt;
}

std::optional<QList<LineTemplate::Field>> LineTemplate::fields(const QString &text, QString *error)
{
    QList<Field> out;
    const bool ok = walk(text, error, [](const QString &) {}, [&](const QString &inner, qsizetype at) {
        const auto f = parseField(inner, at, error);
        if (f)
            out.append(*f);
        return f.has_value();
    });
    if (!ok)
        return std::nullopt;
    return out;
}

std::optional<QString> LineTemplate::expand(const QString &text, const std::function<QString(const QString &)> &capture,
                                            const Lookup &lookup, QString *error)
{
    QString out;
    const bool ok = walk(text, error, [&](const QString &chunk) { out += chunk; }, [&](const QString &inner, qsizetype at) {
        const auto f = parseField(inner, at, error);
        if (!f)
            return false;
        if (!f->capture.isEmpty()) {
            out += capture(f->capture);
            return true;
        }
        const auto values = lookup(f->table, f->first, f->last - f->first + 1);
        if (!values) {
            *error = QStringLiteral("{%1}: an address the unit does not have").arg(inner);
            return false;
        }
        QStringList parts;
        for (quint16 v : *values)
            parts.append(QString::number(v));
        out += parts.join(QLatin1Char(' '));
        return true;
    });
    if (!ok)
        return std::nullopt;
    return out;
}

} // namespace mbscope
