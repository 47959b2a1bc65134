#include "dissectionformat.h"

#include <QtCore/QJsonArray>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

QJsonValue jsonValue(const FieldTree &tree, int i)
{
    const Field &f = tree.at(i);
    switch (f.format) {
    case ValueFormat::None:
        return QJsonValue::Null;
    case ValueFormat::Bytes:
    case ValueFormat::Ascii:
        return tree.valueText(i);
    default:
        // A Modbus value never exceeds 64 bits; JSON numbers are exact up to 2^53.
        return f.value <= (quint64(1) << 53) ? QJsonValue(double(f.value)) : QJsonValue(QString::number(f.value));
    }
}

QJsonObject jsonField(const FieldTree &tree, int i)
{
    const Field &f = tree.at(i);
    QJsonObject o;
    o.insert(QStringLiteral("key"), QString::fromLatin1(f.key));
    o.insert(QStringLiteral("name"), tree.name(i));
    o.insert(QStringLiteral("offset"), f.offset);
    o.insert(QStringLiteral("length"), f.length);
    o.insert(QStringLiteral("raw"), QString::fromLatin1(tree.raw(i).toHex(' ').toUpper()));
    o.insert(QStringLiteral("value"), jsonValue(tree, i));
    if (f.address >= 0)
        o.insert(QStringLiteral("address"), f.address);
    o.insert(QStringLiteral("display"), tree.display(i));
    o.insert(QStringLiteral("severity"), severityName(f.severity));
    o.insert(QStringLiteral("message"), f.message);
    QJsonArray children;
    for (int c = tree.firstChild(i); c >= 0; c = tree.nextSibling(c))
        children.append(jsonField(tree, c));
    o.insert(QStringLiteral("children"), children);
    return o;
}

QString rawText(const FieldTree &tree, int i, int maxRawBytes)
{
    const QByteArray raw = tree.raw(i);
    if (raw.size() <= maxRawBytes)
        return QString::fromLatin1(raw.toHex(' ').toUpper());
    return QString::fromLatin1(raw.first(maxRawBytes).toHex(' ').toUpper())
           + QStringLiteral(" ... (%1 bytes)").arg(raw.size());
}

struct Row {
    QString offset, bytes, field, value, problem;
};

// The VALUE column of a field of many bytes (a frame's trailing bytes, a long write's data) is cut
// as the BYTES column is: the table of a 1 MB input is a table of its fields, not its bytes again
// and again (every row with a problem is padded to the widest value: 11 MB of output for 1 MB of
// input, issue 26 item 10). --json keeps every byte.
QString valueColumn(const FieldTree &tree, int i, int maxRawBytes)
{
    constexpr qsizetype kLongest = 200; // characters: any other value (text, a group's meaning) at most this
    const Field &f = tree.at(i);
    const int keep = qMax(maxRawBytes, 16);
    if (f.format != ValueFormat::Bytes || f.length <= keep) {
        const QString text = tree.display(i);
        return text.size() <= kLongest ? text : text.left(kLongest) + QStringLiteral(" ...");
    }
    QString text = QString::fromLatin1(tree.raw(i).left(keep).toHex(' ').toUpper())
                   + QStringLiteral(" ... (%1 bytes)").arg(f.length);
    if (f.meaning && *f.meaning)
        text += QLatin1Char(' ') + QString::fromUtf8(f.meaning);
    return text;
}

void collect(const FieldTree &tree, int parent, int depth, int maxRawBytes, QList<Row> &rows)
{
    for (int i = tree.firstChild(parent); i >= 0; i = tree.nextSibling(i)) {
        const Field &f = tree.at(i);
        Row r;
        r.offset = f.length > 0 ? QString::number(f.offset) : QStringLiteral("%1").arg(f.offset);
        if (f.length > 1)
            r.offset += QLatin1Char('-') + QString::number(f.offset + f.length - 1);
        r.bytes = rawText(tree, i, maxRawBytes);
        r.field = QString(depth * 2, QLatin1Char(' ')) + tree.name(i);
        r.value = valueColumn(tree, i, maxRawBytes);
        if (f.severity != Severity::Ok)
            r.problem = severityName(f.severity).toUpper() + (f.message.isEmpty() ? QString() : QStringLiteral(": ") + f.message);
        rows.append(r);
        collect(tree, i, depth + 1, maxRawBytes, rows);
    }
}

} // namespace

QJsonObject DissectionFormat::toJson(const Dissection &d)
{
    QJsonObject o;
    o.insert(QStringLiteral("framing"), framingName(d.framing));
    o.insert(QStringLiteral("direction"), directionName(d.direction));
    if (!d.framingReason.isEmpty())
        o.insert(QStringLiteral("framing_reason"), d.framingReason.toString());
    if (!d.directionReason.isEmpty())
        o.insert(QStringLiteral("direction_reason"), d.directionReason.toString());
    if (!d.note.isEmpty())
        o.insert(QStringLiteral("note"), d.note);
    o.insert(QStringLiteral("summary"), d.summary());
    o.insert(QStringLiteral("valid"), d.isValid());
    QJsonArray fields;
    for (int i = d.fields.firstChild(-1); i >= 0; i = d.fields.nextSibling(i))
        fields.append(jsonField(d.fields, i));
    o.insert(QStringLiteral("fields"), fields);
    return o;
}

QString DissectionFormat::toTable(const Dissection &d, int maxRawBytes)
{
    QList<Row> rows;
    rows.append(Row{QStringLiteral("OFFSET"), QStringLiteral("BYTES"), QStringLiteral("FIELD"),
                    QStringLiteral("VALUE"), QStringLiteral("PROBLEM")});
    collect(d.fields, -1, 0, maxRawBytes, rows);
    int w[4] = {0, 0, 0, 0};
    for (const Row &r : rows) {
        w[0] = qMax(w[0], int(r.offset.size()));
        w[1] = qMax(w[1], int(r.bytes.size()));
        w[2] = qMax(w[2], int(r.field.size()));
        w[3] = qMax(w[3], int(r.value.size()));
    }
    QString out = d.summary() + QLatin1Char('\n');
    if (!d.framingReason.isEmpty())
        out += QStringLiteral("framing: %1 (%2)\n").arg(framingName(d.framing), d.framingReason.toString());
    if (!d.directionReason.isEmpty())
        out += QStringLiteral("direction: %1 (%2)\n").arg(directionName(d.direction), d.directionReason.toString());
    if (!d.note.isEmpty())
        out += QStringLiteral("note: ") + d.note + QLatin1Char('\n');
    out += QLatin1Char('\n');
    for (const Row &r : rows) {
        QString line = r.offset.leftJustified(w[0]) + QStringLiteral("  ") + r.bytes.leftJustified(w[1]) + QStringLiteral("  ")
                       + r.field.leftJustified(w[2]) + QStringLiteral("  ");
        line += r.problem.isEmpty() ? r.value : r.value.leftJustified(w[3]) + QStringLiteral("  ") + r.problem;
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        out += line + QLatin1Char('\n');
    }
    out += d.isValid() ? QStringLiteral("\nvalid frame\n")
                       : QStringLiteral("\nINVALID: %1 error(s), %2 warning(s)\n")
                             .arg(d.fields.count(Severity::Error)).arg(d.fields.count(Severity::Warning));
    return out;
}

} // namespace mbscope
