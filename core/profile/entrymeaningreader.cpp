#include "entrymeaningreader.h"

#include "json/jsonreader.h"
#include "protocol/registervalue.h"
#include "simtable.h"
#include "scaledvalue.h"

#include <QtCore/QStringList>

#include <algorithm>
#include <cmath>

namespace mbscope {

namespace {

bool isIntegerFormat(RegisterFormat format)
{
    return !format.isFloat() && format.type() != RegisterType::Ascii;
}

// A key of "bits" or "enum": decimal or 0x hex.
std::optional<qint64> keyNumber(const QString &key)
{
    bool ok = false;
    const qint64 n = key.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? key.mid(2).toLongLong(&ok, 16)
                                                                              : key.toLongLong(&ok, 10);
    return ok ? std::optional<qint64>(n) : std::nullopt;
}

void readBits(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry)
{
    const auto bits = reader.object(o, path, "bits");
    if (!bits)
        return;
    const QString at = JsonReader::member(path, "bits");
    if (!isIntegerFormat(entry->format)) {
        reader.error(at, QStringLiteral("a %1 value has no bits to name: expected an integer type (u16, u32, hex, "
                                        "bin...)").arg(entry->format.name()));
        return;
    }
    const int width = 16 * entry->format.registerCount();
    for (auto it = bits->begin(); it != bits->end(); ++it) {
        const QString keyPath = JsonReader::member(at, it.key());
        const auto bit = keyNumber(it.key());
        if (!bit || *bit < 0 || *bit >= width) {
            reader.error(keyPath, QStringLiteral("'%1' is not a bit of a %2: expected 0-%3 (0 the least significant)")
                                      .arg(it.key(), entry->format.name()).arg(width - 1));
            continue;
        }
        if (const auto name = reader.stringValue(it.value(), keyPath))
            entry->bitNames.insert(int(*bit), *name);
    }
}

void readEnum(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry)
{
    const auto meanings = reader.object(o, path, "enum");
    if (!meanings)
        return;
    const QString at = JsonReader::member(path, "enum");
    if (!isIntegerFormat(entry->format)) {
        reader.error(at, QStringLiteral("a %1 value cannot be an enumeration: expected an integer type")
                             .arg(entry->format.name()));
        return;
    }
    const auto [low, high] = ScaledValue::rawRange(entry->format);
    for (auto it = meanings->begin(); it != meanings->end(); ++it) {
        const QString keyPath = JsonReader::member(at, it.key());
        const auto n = keyNumber(it.key());
        if (!n || double(*n) < low || double(*n) > high) {
            reader.error(keyPath, QStringLiteral("'%1' is not a raw %2 value: expected a whole number %3 to %4 "
                                                 "(decimal or 0x hex)")
                                      .arg(it.key(), entry->format.name(), JsonReader::numberText(low),
                                           JsonReader::numberText(high)));
            continue;
        }
        if (const auto name = reader.stringValue(it.value(), keyPath))
            entry->enumNames.insert(*n, *name);
    }
}

void readNotImplemented(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry)
{
    const QJsonValue v = o.value(QLatin1String("notImplemented"));
    if (v.isUndefined())
        return;
    const QString at = JsonReader::member(path, "notImplemented");
    if (entry->format.type() == RegisterType::Ascii) {
        reader.error(at, QStringLiteral("ascii registers have no sentinel: expected a number type"));
        return;
    }
    QString text;
    if (v.isString())
        text = v.toString();
    else if (v.isDouble())
        text = JsonReader::numberText(v.toDouble());
    else {
        reader.error(at, QStringLiteral("expected the raw value as text (\"0x8000\", \"0xFFFF\", \"NaN\"), found %1")
                             .arg(JsonReader::describe(v)));
        return;
    }
    const RegisterValueResult raw = RegisterValue::fromText(text, entry->format);
    if (!raw.ok) {
        reader.error(at, raw.error);
        return;
    }
    if (raw.value.isNaN())
        entry->notImplementedNaN = true;
    else
        entry->notImplemented = raw.value.bits();
}

void readString(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry)
{
    const auto length = reader.integer(o, path, "length", 1, 250);
    const auto padding = reader.string(o, path, "padding");
    if (!length) {
        if (padding)
            reader.error(JsonReader::member(path, "padding"), QStringLiteral("padding needs 'length' (a string)"));
        return;
    }
    if (entry->format.type() != RegisterType::Ascii) {
        reader.error(JsonReader::member(path, "length"),
                     QStringLiteral("a string of characters is an ascii entry: expected \"type\": \"ascii\" (or "
                                    "\"ascii-ba\"), found %1").arg(entry->format.name()));
        return;
    }
    entry->stringLength = int(*length);
    if (padding) {
        if (*padding == QLatin1String("space"))
            entry->spacePadded = true;
        else if (*padding != QLatin1String("nul"))
            reader.error(JsonReader::member(path, "padding"),
                         QStringLiteral("'%1' is not a padding: expected nul or space").arg(*padding));
    }
}

} // namespace

QList<const char *> EntryMeaningReader::keys(bool bits)
{
    if (bits)
        return {"kind"};
    return {"kind", "min", "max", "scaleRegister", "bits", "enum", "length", "padding", "notImplemented"};
}

void EntryMeaningReader::read(JsonReader &reader, const QJsonObject &o, const QString &path, TableEntry *entry)
{
    if (const auto kind = reader.string(o, path, "kind")) {
        if (const auto k = valueKindFromName(*kind))
            entry->kind = *k;
        else
            reader.error(JsonReader::member(path, "kind"),
                         QStringLiteral("'%1' is not a kind of value: expected %2").arg(*kind, valueKindNames()));
    }
    if (isBitTable(entry->table))
        return;
    entry->min = reader.number(o, path, "min", -1e300, 1e300);
    entry->max = reader.number(o, path, "max", -1e300, 1e300);
    if (entry->min && entry->max && *entry->max < *entry->min)
        reader.error(JsonReader::member(path, "max"), QStringLiteral("%1 is below min %2")
                                                          .arg(JsonReader::numberText(*entry->max),
                                                               JsonReader::numberText(*entry->min)));
    if (const auto sf = reader.integer(o, path, "scaleRegister", 0, 65535)) {
        if (o.contains(QLatin1String("scale")))
            reader.error(JsonReader::member(path, "scaleRegister"),
                         QStringLiteral("give 'scale' (a fixed factor) or 'scaleRegister' (a factor read from a "
                                        "register), not both"));
        else
            entry->scaleRegister = quint16(*sf);
    }
    readBits(reader, o, path, entry);
    readEnum(reader, o, path, entry);
    readString(reader, o, path, entry);
    readNotImplemented(reader, o, path, entry);
}

bool EntryMeaningReader::resolveScaleRegister(JsonReader &reader, const QList<TableEntry> &known,
                                              const QString &path, TableEntry *entry)
{
    if (!entry->scaleRegister)
        return true;
    const int address = *entry->scaleRegister;
    const auto source = std::find_if(known.cbegin(), known.cend(), [&](const TableEntry &s) {
        return s.table == entry->table && address >= s.address && address < s.end();
    });
    const QString at = JsonReader::member(path, "scaleRegister");
    const QString table = QLatin1String(simTableKey(entry->table));
    if (source == known.cend()) {
        reader.error(at, QStringLiteral("%1 %2 is not in any %1 entry of this unit (without a scaleRegister of its own)")
                             .arg(table).arg(address));
        return false;
    }
    // Signed: a factor below one is a negative power (SunSpec's sunssf is an int16). A u16 entry
    // would read 0xFFFF as 10^65535; it was taken as an i16 without a word.
    if (source->width() != 1 || source->format.type() != RegisterType::Int16) {
        reader.error(at, QStringLiteral("%1 %2 is a %3 value: a scale factor is one i16 register (a power of ten; give that "
                                        "entry \"type\": \"i16\")")
                             .arg(table).arg(address).arg(source->format.name()));
        return false;
    }
    const int exponent = qint16(source->initial.at(address - source->address));
    if (exponent < -10 || exponent > 10) {
        reader.error(at, QStringLiteral("%1 %2 holds %3: a scale factor of 10^%3 is outside 10^-10..10^10")
                             .arg(table).arg(address).arg(exponent));
        return false;
    }
    entry->scale = std::pow(10.0, exponent);
    return true;
}

} // namespace mbscope
