#include "valuetable.h"

#include "protocol/modiconreference.h"
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
    const ModiconReference r(*table, quint16(address));
    return r.hasFiveDigitForm() ? r.fiveDigit() : r.sixDigit();
}

QString addressText(int address)
{
    return QStringLiteral("%1 (0x%2)").arg(address).arg(QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0')));
}

// The value of a format starting at register index, when the whole value is there.
std::optional<RegisterValue> valueAt(const QList<quint16> &registers, qsizetype index, RegisterFormat format)
{
    const int n = format.registerCount();
    if (index % n != 0 || index + n > registers.size())
        return std::nullopt;
    const RegisterValueResult r =
        RegisterValue::fromRegisters(std::span<const quint16>(registers.constData() + index, std::size_t(n)), format);
    return r.ok ? std::optional<RegisterValue>(r.value) : std::nullopt;
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
    // V1.1b3 6.1-6.4: function code, byte count, then the data.
    if (pdu.size() < 2 || quint8(pdu.at(0)) != functionCode)
        return t;
    const int byteCount = quint8(pdu.at(1));
    const QByteArray data = pdu.mid(2, byteCount);
    if (data.size() != byteCount)
        return t;
    if (functionCode == 0x01 || functionCode == 0x02) {
        for (int i = 0; i < quantity && i / 8 < data.size(); ++i)
            t.bits.append((quint8(data.at(i / 8)) >> (i % 8)) & 1);
    } else {
        for (int i = 0; i + 1 < data.size(); i += 2)
            t.registers.append(quint16((quint8(data.at(i)) << 8) | quint8(data.at(i + 1))));
    }
    return t;
}

QString ValueTable::text() const
{
    QList<QStringList> rows;
    if (!bits.isEmpty()) {
        rows.append({QStringLiteral("ADDRESS"), QStringLiteral("REFERENCE"), QStringLiteral("VALUE")});
        for (qsizetype i = 0; i < bits.size(); ++i)
            rows.append({addressText(address + int(i)), reference(functionCode, address + int(i)),
                         bits.at(i) ? QStringLiteral("1  ON") : QStringLiteral("0  OFF")});
    } else {
        QStringList heading{QStringLiteral("ADDRESS"), QStringLiteral("REFERENCE")};
        for (const RegisterFormat &f : formats)
            heading.append(f.name());
        rows.append(heading);
        for (qsizetype i = 0; i < registers.size(); ++i) {
            QStringList row{addressText(address + int(i)), reference(functionCode, address + int(i))};
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
            const bool right = c >= 2 && bits.isEmpty();
            line += right ? row.at(c).rightJustified(widths.at(c)) : row.at(c).leftJustified(widths.at(c));
            line += QStringLiteral("  ");
        }
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        out += line + QLatin1Char('\n');
    }
    return out;
}

QJsonArray ValueTable::json() const
{
    QJsonArray array;
    for (qsizetype i = 0; i < bits.size(); ++i) {
        array.append(QJsonObject{{QStringLiteral("address"), address + int(i)},
                                 {QStringLiteral("reference"), reference(functionCode, address + int(i))},
                                 {QStringLiteral("value"), bits.at(i) ? 1 : 0}});
    }
    for (qsizetype i = 0; i < registers.size(); ++i) {
        QJsonObject o{{QStringLiteral("address"), address + int(i)},
                      {QStringLiteral("reference"), reference(functionCode, address + int(i))},
                      {QStringLiteral("raw"), int(registers.at(i))}};
        for (const RegisterFormat &f : formats) {
            if (const auto v = valueAt(registers, i, f))
                o.insert(f.name(), jsonOf(*v));
        }
        array.append(o);
    }
    return array;
}

} // namespace mbscope::app
