#include "profiletablereader.h"

#include "entrymeaningreader.h"
#include "json/jsonreader.h"
#include "scaledvalue.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>

#include <algorithm>

namespace mbscope {

namespace {

constexpr double kMaxPeriodMs = 24.0 * 3600.0 * 1000.0;
constexpr SimTable kTables[] = {SimTable::Coils, SimTable::DiscreteInputs, SimTable::InputRegisters,
                                SimTable::HoldingRegisters};

ScaledValue scaled(const TableEntry &entry)
{
    return ScaledValue{entry.format, entry.scale, entry.offset};
}

// The values an entry's generator may produce, in engineering units.
std::pair<double, double> entryRange(const TableEntry &entry)
{
    if (isBitTable(entry.table))
        return {0.0, 1.0};
    return scaled(entry).range();
}

QString rangeText(int first, int end)
{
    return first + 1 == end ? QString::number(first) : QStringLiteral("%1-%2").arg(first).arg(end - 1);
}

} // namespace

void ProfileTableReader::readTables(JsonReader &reader, const QJsonValue &value, const QString &path,
                                    UnitProfile *unit)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"coils", "discrete", "input", "holding"});
    QList<TableEntry> entries;
    QStringList paths;
    // Entries whose scale is read from another register come second, once that register is known.
    for (const bool scaledByRegister : {false, true}) {
        for (SimTable table : kTables) {
            const auto list = scaledByRegister ? std::optional<QJsonArray>(o->value(QLatin1String(simTableKey(table))).toArray())
                                               : reader.array(*o, path, simTableKey(table));
            if (!list)
                continue;
            const QString at = JsonReader::member(path, simTableKey(table));
            for (qsizetype i = 0; i < list->size(); ++i) {
                if (list->at(i).toObject().contains(QLatin1String("scaleRegister")) != scaledByRegister)
                    continue;
                const QString entryPath = JsonReader::element(at, i);
                if (auto entry = readEntry(reader, list->at(i), entryPath, table, entries)) {
                    entries.append(*entry);
                    paths.append(entryPath);
                }
            }
        }
    }

    // Overlaps, reported on the later entry of each pair.
    for (qsizetype i = 0; i < entries.size(); ++i) {
        for (qsizetype j = 0; j < i; ++j) {
            const TableEntry &a = entries.at(j);
            const TableEntry &b = entries.at(i);
            if (a.table != b.table || b.address >= a.end() || a.address >= b.end())
                continue;
            reader.error(paths.at(i), QStringLiteral("addresses %1 overlap %2 (%3)")
                                          .arg(rangeText(b.address, b.end()),
                                               paths.at(j).mid(paths.at(j).lastIndexOf(QLatin1Char('.')) + 1),
                                               rangeText(a.address, a.end())));
        }
    }

    // Copy generators: the source must be the first address of a value in some entry.
    for (qsizetype i = 0; i < entries.size(); ++i) {
        const TableEntry &e = entries.at(i);
        if (!e.generator || e.generator->kind != GeneratorSpec::Kind::Copy)
            continue;
        const SimTable t = e.generator->sourceTable;
        const int address = e.generator->sourceAddress;
        const auto source = std::find_if(entries.cbegin(), entries.cend(), [&](const TableEntry &s) {
            return s.table == t && address >= s.address && address < s.end();
        });
        const QString at = JsonReader::member(JsonReader::member(paths.at(i), "generator"), "address");
        if (source == entries.cend())
            reader.error(at, QStringLiteral("%1 %2 is not in any %1 entry of this unit")
                                 .arg(QLatin1String(simTableKey(t))).arg(address));
        else if ((address - source->address) % source->width() != 0)
            reader.error(at, QStringLiteral("%1 %2 is inside a %3 value that starts at %4: expected the first "
                                            "address of a value")
                                 .arg(QLatin1String(simTableKey(t))).arg(address)
                                 .arg(source->format.name())
                                 .arg(address - (address - source->address) % source->width()));
    }

    std::stable_sort(entries.begin(), entries.end(), [](const TableEntry &a, const TableEntry &b) {
        return a.table != b.table ? a.table < b.table : a.address < b.address;
    });
    unit->entries.append(entries);
}

std::optional<TableEntry> ProfileTableReader::readEntry(JsonReader &reader, const QJsonValue &value,
                                                        const QString &path, SimTable table,
                                                        const QList<TableEntry> &known)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    const bool bits = isBitTable(table);
    const bool writableTable = table == SimTable::Coils || table == SimTable::HoldingRegisters;
    QList<const char *> keys{"address", "count", "name", "description"};
    if (!bits)
        keys.append({"unit", "type", "scale", "offset"});
    if (writableTable)
        keys.append("writable");
    keys.append({"value", "values", "generator"});
    keys.append(EntryMeaningReader::keys(bits));
    reader.checkKeys(*o, path, keys);

    TableEntry entry;
    entry.table = table;
    entry.writable = writableTable;
    if (reader.require(*o, path, "address"))
        entry.address = quint16(reader.integer(*o, path, "address", 0, 65535).value_or(0));
    entry.name = reader.string(*o, path, "name").value_or(QString());
    entry.description = reader.string(*o, path, "description").value_or(QString());
    entry.unit = reader.string(*o, path, "unit").value_or(QString());
    entry.writable = reader.boolean(*o, path, "writable").value_or(writableTable);
    if (const auto type = reader.string(*o, path, "type")) {
        const RegisterFormatResult parsed = RegisterFormat::parse(*type);
        if (parsed.ok)
            entry.format = parsed.format;
        else
            reader.error(JsonReader::member(path, "type"), parsed.error);
    }
    if (const auto scale = reader.number(*o, path, "scale", -1e300, 1e300)) {
        if (*scale == 0)
            reader.error(JsonReader::member(path, "scale"),
                         QStringLiteral("0 would make every value the same: expected a non-zero factor"));
        else
            entry.scale = *scale;
    }
    entry.offset = reader.number(*o, path, "offset", -1e300, 1e300).value_or(0);
    if (reader.problemCount() == before)
        EntryMeaningReader::read(reader, *o, path, &entry);
    if (reader.problemCount() == before)
        EntryMeaningReader::resolveScaleRegister(reader, known, path, &entry);
    if (reader.problemCount() != before)
        return std::nullopt; // the values cannot be read without a valid type and scale

    const int width = entry.width();
    const QString kind = bits ? QStringLiteral("bits") : QStringLiteral("registers");
    const qsizetype listed = o->value(QLatin1String("values")).toArray().size();
    const int stringRegisters = (entry.stringLength + 1) / 2;
    if (entry.isString() && o->contains(QLatin1String("values")))
        reader.error(JsonReader::member(path, "values"),
                     QStringLiteral("a string entry holds one text: give it as 'value'"));
    else if (entry.isString() && o->contains(QLatin1String("generator")))
        reader.error(JsonReader::member(path, "generator"), QStringLiteral("a string entry takes no generator"));
    if (entry.isString()) {
        entry.count = int(reader.integer(*o, path, "count", 1, 65536).value_or(stringRegisters));
        if (entry.count != stringRegisters)
            reader.error(JsonReader::member(path, "count"),
                         QStringLiteral("a string of %1 characters takes %2 registers, not %3")
                             .arg(entry.stringLength).arg(stringRegisters).arg(entry.count));
    } else if (const auto count = reader.integer(*o, path, "count", 1, 65536)) {
        entry.count = int(*count);
        if (entry.count % width != 0)
            reader.error(JsonReader::member(path, "count"),
                         QStringLiteral("%1 registers are not a whole number of %2 values (%3 registers each)")
                             .arg(entry.count).arg(entry.format.name()).arg(width));
        else if (listed * width > entry.count)
            reader.error(JsonReader::member(path, "count"),
                         QStringLiteral("%1 values take %2 %3, more than count %4")
                             .arg(listed).arg(listed * width).arg(kind).arg(entry.count));
    } else if (!o->contains(QLatin1String("count"))) {
        entry.count = int(std::max<qsizetype>(1, listed)) * width;
    }
    if (entry.end() > 65536)
        reader.error(path, QStringLiteral("addresses %1-%2 run past 65535 (%3 %4 from %1)")
                               .arg(entry.address).arg(entry.end() - 1).arg(entry.count).arg(kind));
    if (reader.problemCount() != before)
        return std::nullopt;

    if (!readInitialValues(reader, *o, path, &entry))
        return std::nullopt;
    if (o->contains(QLatin1String("generator"))) {
        entry.generator = readGenerator(reader, o->value(QLatin1String("generator")),
                                        JsonReader::member(path, "generator"), entry);
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return entry;
}

bool ProfileTableReader::readInitialValues(JsonReader &reader, const QJsonObject &o, const QString &path,
                                           TableEntry *entry)
{
    const int before = reader.problemCount();
    const bool bits = isBitTable(entry->table);
    const QJsonValue single = o.value(QLatin1String("value"));
    const auto list = reader.array(o, path, "values");
    if (!single.isUndefined() && list)
        reader.error(path, QStringLiteral("give 'value' (every value the same) or 'values' (a list), not both"));
    if (reader.problemCount() != before)
        return false;

    const int width = entry->width();
    entry->initial.fill(0, entry->count);
    const ScaledValue codec = scaled(*entry);
    for (int i = 0; i < entry->valueCount(); ++i) {
        QJsonValue v;
        QString at;
        if (list && i < list->size()) {
            v = list->at(i);
            at = JsonReader::element(JsonReader::member(path, "values"), i);
        } else if (!single.isUndefined()) {
            v = single;
            at = JsonReader::member(path, "value");
        } else {
            break; // the rest stays raw 0
        }
        if (entry->isString()) {
            if (!v.isString()) {
                reader.error(at, QStringLiteral("expected the text of the string, found %1").arg(JsonReader::describe(v)));
                break;
            }
            const QString text = v.toString();
            if (text.size() > entry->stringLength) {
                reader.error(at, QStringLiteral("\"%1\" has %2 characters, more than length %3")
                                     .arg(text).arg(text.size()).arg(entry->stringLength));
                break;
            }
            QString padded = text.leftJustified(entry->stringLength, entry->spacePadded ? QLatin1Char(' ') : QChar(0));
            if (padded.size() % 2)
                padded.append(entry->spacePadded ? QLatin1Char(' ') : QChar(0));
            const RegisterListResult words = RegisterValue::asciiRegisters(padded, entry->format.isByteSwapped());
            if (!words.ok) {
                reader.error(at, words.error);
                break;
            }
            std::copy(words.registers.cbegin(), words.registers.cend(), entry->initial.begin());
            break;
        }
        if (bits) {
            if (v.isBool())
                entry->initial[i] = v.toBool() ? 1 : 0;
            else if (v.isDouble() && (v.toDouble() == 0 || v.toDouble() == 1))
                entry->initial[i] = quint16(v.toDouble());
            else
                reader.error(at, QStringLiteral("expected true, false, 0 or 1, found %1").arg(JsonReader::describe(v)));
            continue;
        }
        RegisterValueResult encoded;
        if (v.isDouble()) {
            encoded = codec.encode(v.toDouble());
        } else if (v.isString()) {
            encoded = RegisterValue::fromText(v.toString(), entry->format); // raw text: no scaling
        } else {
            reader.error(at, QStringLiteral("expected a number or the raw value as text (\"0x1A2B\"), found %1")
                                 .arg(JsonReader::describe(v)));
            continue;
        }
        if (!encoded.ok) {
            reader.error(at, encoded.error);
            continue;
        }
        encoded.value.writeRegisters(std::span<quint16>(entry->initial.data() + i * width, size_t(width)));
    }
    return reader.problemCount() == before;
}

std::optional<GeneratorSpec> ProfileTableReader::readGenerator(JsonReader &reader, const QJsonValue &value,
                                                               const QString &path, const TableEntry &entry)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    if (!reader.require(*o, path, "kind"))
        return std::nullopt;
    const auto name = reader.string(*o, path, "kind");
    if (!name)
        return std::nullopt;
    const auto kind = GeneratorSpec::kindFromName(*name);
    if (!kind) {
        reader.error(JsonReader::member(path, "kind"),
                     QStringLiteral("'%1' is not a generator: expected constant, counter, randomWalk, sine, "
                                    "poisson or copy").arg(*name));
        return std::nullopt;
    }

    using K = GeneratorSpec::Kind;
    GeneratorSpec spec;
    spec.kind = *kind;
    const auto [low, high] = entryRange(entry);
    spec.min = low;
    spec.max = high;
    switch (*kind) {
    case K::Constant:
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "value"});
        if (reader.require(*o, path, "value"))
            spec.value = reader.number(*o, path, "value", low, high).value_or(0);
        break;
    case K::Counter:
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "step", "min", "max", "wrap"});
        spec.step = reader.number(*o, path, "step", -1e300, 1e300).value_or(1);
        spec.wrap = reader.boolean(*o, path, "wrap").value_or(true);
        break;
    case K::RandomWalk:
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "step", "min", "max"});
        spec.step = reader.number(*o, path, "step", 0, 1e300).value_or(1);
        break;
    case K::Sine:
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "amplitude", "offset", "wavePeriodMs", "phaseDeg"});
        spec.amplitude = reader.number(*o, path, "amplitude", -1e300, 1e300).value_or(1);
        spec.offset = reader.number(*o, path, "offset", -1e300, 1e300).value_or(0);
        spec.wavePeriodMs = reader.number(*o, path, "wavePeriodMs", 1, kMaxPeriodMs).value_or(60000);
        spec.phaseDeg = reader.number(*o, path, "phaseDeg", -360, 360).value_or(0);
        break;
    case K::Poisson:
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "rate", "gateMs", "accumulate"});
        if (reader.require(*o, path, "rate"))
            spec.rate = reader.number(*o, path, "rate", 0, 1e9).value_or(0);
        spec.accumulate = reader.boolean(*o, path, "accumulate").value_or(false);
        break;
    case K::Copy: {
        reader.checkKeys(*o, path, {"kind", "periodMs", "seed", "table", "address"});
        spec.sourceTable = entry.table;
        if (const auto table = reader.string(*o, path, "table")) {
            if (const auto t = simTableFromKey(*table))
                spec.sourceTable = *t;
            else
                reader.error(JsonReader::member(path, "table"),
                             QStringLiteral("'%1' is not a table: expected coils, discrete, input or holding").arg(*table));
        }
        if (reader.require(*o, path, "address"))
            spec.sourceAddress = quint16(reader.integer(*o, path, "address", 0, 65535).value_or(0));
        break;
    }
    }
    spec.periodMs = reader.number(*o, path, "periodMs", 1, kMaxPeriodMs).value_or(kind == K::Copy ? 100 : 1000);
    if (*kind == K::Poisson) {
        // A count every period, counted over the gate: each defaults to the other.
        const auto gate = reader.number(*o, path, "gateMs", 1, kMaxPeriodMs);
        if (gate && !o->contains(QLatin1String("periodMs")))
            spec.periodMs = *gate;
        spec.gateMs = gate.value_or(spec.periodMs);
        if (spec.gateMs > spec.periodMs)
            reader.error(JsonReader::member(path, "gateMs"),
                         QStringLiteral("%1 is longer than periodMs %2: gates would overlap")
                             .arg(JsonReader::numberText(spec.gateMs), JsonReader::numberText(spec.periodMs)));
    }
    if (const auto seed = reader.integer(*o, path, "seed", 0, qint64(9007199254740991LL)))
        spec.seed = quint64(*seed);
    if (*kind == K::Counter || *kind == K::RandomWalk) {
        spec.min = reader.number(*o, path, "min", low, high).value_or(low);
        spec.max = reader.number(*o, path, "max", low, high).value_or(high);
        if (spec.max <= spec.min)
            reader.error(JsonReader::member(path, "max"),
                         QStringLiteral("%1 is not above min %2").arg(JsonReader::numberText(spec.max),
                                                                      JsonReader::numberText(spec.min)));
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return spec;
}

} // namespace mbscope
