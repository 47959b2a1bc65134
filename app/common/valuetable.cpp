#include "common/valuetable.h"

#include "protocol/modiconreference.h"
#include "protocol/readanswer.h"
#include "protocol/registervalue.h"

#include <QtCore/QJsonObject>
#include <QtCore/QStringList>

#include <cmath>
#include <optional>

namespace mbscope::app {

namespace {

QString reference(quint8 functionCode, int address)
{
    const auto table = ModiconReference::tableOf(functionCode);
    if (!table || address < 0 || address > 0xFFFF)
        return {};
    return ReadAnswer::referenceText(ModiconReference(*table, quint16(address)));
}

// The value of a format starting at register index, when the whole value is there.
std::optional<RegisterValue> valueAt(const QList<quint16> &registers, qsizetype index, RegisterFormat format)
{
    ReadAnswer answer;
    answer.registers = registers; // shared, not copied
    return answer.valueAt(int(index), format);
}

QJsonValue jsonOf(const RegisterValue &v)
{
    const RegisterFormat f = v.format();
    switch (f.type()) {
    case RegisterType::Hex16:
    case RegisterType::Binary16:
    case RegisterType::Ascii:
        return v.toText();
    case RegisterType::Float32:
    case RegisterType::Float64:
        return std::isfinite(v.toDouble()) ? QJsonValue(v.toDouble()) : QJsonValue(v.toText());
    case RegisterType::UInt64:
        return v.bits() <= (quint64(1) << 53) ? QJsonValue(double(v.bits())) : QJsonValue(v.toText());
    case RegisterType::Int64:
        return std::llabs(v.toInt64()) <= (qint64(1) << 53) ? QJsonValue(double(v.toInt64())) : QJsonValue(v.toText());
    default:
        return double(v.toInt64());
    }
}

} // namespace

ValueTable ValueTable::fromReadResponse(quint8 functionCode, int address, int quantity, const QByteArray &pdu,
                                        const QList<RegisterFormat> &formats)
{
    ValueTable t;
    t.functionCode = functionCode;
    t.address = address;
    t.formats = formats;
    const ReadAnswerResult r = ReadAnswer::fromResponse(functionCode, address, quantity, pdu);
    if (r.ok) {
        t.registers = r.answer.registers;
        t.bits = r.answer.bits;
    }
    return t;
}

QStringList ValueTable::valueTexts(RegisterFormat format) const
{
    QStringList texts;
    for (qsizetype i = 0; i + format.registerCount() <= registers.size(); i += format.registerCount()) {
        const auto v = valueAt(registers, i, format);
        texts.append(v ? v->toText() : QString());
    }
    return texts;
}

QStringList ValueTable::bitTexts() const
{
    QStringList texts;
    for (bool bit : bits)
        texts.append(bit ? QStringLiteral("1") : QStringLiteral("0"));
    return texts;
}

QString ValueTable::text() const
{
    QList<QStringList> rows;
    // Counted from 1, the number the user typed leads the row; the PDU address follows.
    const auto lead = [this](int i) {
        QStringList row{ReadAnswer::addressText(address + i), reference(functionCode, address + i)};
        if (oneBased)
            row.prepend(QString::number(address + i + 1));
        return row;
    };
    QStringList heading{QStringLiteral("ADDRESS"), QStringLiteral("REFERENCE")};
    if (oneBased)
        heading.prepend(QStringLiteral("1-BASED"));
    const int leading = int(heading.size());
    if (!bits.isEmpty()) {
        rows.append(heading + QStringList{QStringLiteral("VALUE")});
        for (qsizetype i = 0; i < bits.size(); ++i)
            rows.append(lead(int(i)) + QStringList{bits.at(i) ? QStringLiteral("1  ON") : QStringLiteral("0  OFF")});
    } else {
        for (const RegisterFormat &f : formats)
            heading.append(f.name());
        rows.append(heading);
        for (qsizetype i = 0; i < registers.size(); ++i) {
            QStringList row = lead(int(i));
            for (const RegisterFormat &f : formats) {
                const auto v = valueAt(registers, i, f);
                row.append(v ? v->toText() : QString());
            }
            rows.append(row);
        }
    }
    QList<int> widths;
    for (const QStringList &row : rows) {
        for (qsizetype c = 0; c < row.size(); ++c) {
            if (widths.size() <= c)
                widths.append(0);
            widths[c] = qMax(widths.at(c), int(row.at(c).size()));
        }
    }
    QString out;
    for (const QStringList &row : rows) {
        QString line;
        for (qsizetype c = 0; c < row.size(); ++c) {
            // Numbers read best right-aligned; the address and reference columns lead on the left.
            const bool right = c >= leading && bits.isEmpty();
            line += right ? row.at(c).rightJustified(widths.at(c)) : row.at(c).leftJustified(widths.at(c));
            line += QStringLiteral("  ");
        }
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        out += line + QLatin1Char('\n');
    }
    return out;
}

QString ValueTable::terse() const
{
    QString out;
    const int base = oneBased ? 1 : 0;
    for (qsizetype i = 0; i < bits.size(); ++i)
        out += QStringLiteral("[%1]: \t%2\n").arg(address + int(i) + base).arg(bits.at(i) ? 1 : 0);
    if (formats.isEmpty())
        return out;
    const int step = formats.constFirst().registerCount();
    for (qsizetype i = 0; i + step <= registers.size(); i += step) {
        QStringList values;
        for (const RegisterFormat &f : formats) {
            const auto v = valueAt(registers, i, f);
            values.append(v ? v->toText() : QStringLiteral("-"));
        }
        out += QStringLiteral("[%1]: \t%2\n").arg(address + int(i) + base).arg(values.join(QLatin1Char('\t')));
    }
    return out;
}

QJsonArray ValueTable::json() const
{
    QJsonArray array;
    for (qsizetype i = 0; i < bits.size(); ++i) {
        QJsonObject o{{QStringLiteral("address"), address + int(i)},
                      {QStringLiteral("reference"), reference(functionCode, address + int(i))},
                      {QStringLiteral("value"), bits.at(i) ? 1 : 0}};
        if (oneBased)
            o.insert(QStringLiteral("one_based"), address + int(i) + 1);
        array.append(o);
    }
    for (qsizetype i = 0; i < registers.size(); ++i) {
        QJsonObject o{{QStringLiteral("address"), address + int(i)},
                      {QStringLiteral("reference"), reference(functionCode, address + int(i))},
                      {QStringLiteral("raw"), int(registers.at(i))}};
        if (oneBased)
            o.insert(QStringLiteral("one_based"), address + int(i) + 1);
        for (const RegisterFormat &f : formats) {
            if (const auto v = valueAt(registers, i, f))
                o.insert(f.name(), jsonOf(*v));
        }
        array.append(o);
    }
    return array;
}

} // namespace mbscope::app
