#include "profileunitreader.h"

#include "protocol/hexnumber.h"
#include "protocol/hextext.h"
#include "faultrulereader.h"
#include "json/jsonreader.h"
#include "profiletablereader.h"
#include "scriptsettingsreader.h"
#include "sim/simunit.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

// Basic and regular object names of Read Device Identification (V1.1b3 6.21, table of objects).
constexpr const char *kObjectNames[] = {"VendorName", "ProductCode", "MajorMinorRevision", "VendorUrl",
                                        "ProductName", "ModelName", "UserApplicationName"};

// A 2B/0E response PDU holds function, MEI type, code, conformity, more follows, next object id
// and object count (7 bytes) before an object's id and length: 253 - 7 - 2 bytes are left.
constexpr int kMaxObjectBytes = 244;
// A 11 response PDU: function and byte count, then at most 251 bytes (V1.1b3 6.13, 253-byte PDU).
constexpr int kMaxServerIdBytes = 251;
constexpr int kMaxFifo = 1000; // more than 31 answers exception 03, on purpose (V1.1b3 6.18)

QString codeList(const QList<quint8> &codes)
{
    QStringList parts;
    for (quint8 code : codes)
        parts.append(QStringLiteral("%1").arg(code, 2, 16, QLatin1Char('0')).toUpper());
    return parts.join(QStringLiteral(", "));
}

std::optional<QByteArray> latin1Text(JsonReader &reader, const QJsonValue &v, const QString &path, int maxBytes)
{
    const auto text = reader.stringValue(v, path);
    if (!text)
        return std::nullopt;
    for (QChar c : *text) {
        if (c.unicode() > 0xFF) {
            reader.error(path, QStringLiteral("'%1' is not a Latin-1 character: device strings are bytes").arg(c));
            return std::nullopt;
        }
    }
    const QByteArray bytes = text->toLatin1();
    if (bytes.size() > maxBytes) {
        reader.error(path, QStringLiteral("%1 bytes are more than the %2 a response can hold").arg(bytes.size()).arg(maxBytes));
        return std::nullopt;
    }
    return bytes;
}

} // namespace

std::optional<UnitProfile> ProfileUnitReader::read(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    reader.checkKeys(*o, path, {"id", "name", "description", "functions", "responseDelay", "tables", "fifos", "files",
                                "deviceIdentification", "serverId", "exceptionStatus", "script", "gapReads", "sharedTables"});
    UnitProfile unit;
    if (reader.require(*o, path, "id")) {
        const QJsonValue id = o->value(QLatin1String("id"));
        bool hex = false;
        const int hexValue = id.toString().trimmed().mid(2).toInt(&hex, 16);
        if ((id.isDouble() && id.toDouble() == 0)
            || (id.isString() && id.toString().trimmed().startsWith(QLatin1String("0x"), Qt::CaseInsensitive) && hex
                && hexValue == 0))
            // Serial Line V1.02, 2.2: 0 is the broadcast address, no unit's own. Over TCP the
            // simulator's endpoints route unit ids 0 and 255 to the first unit.
            reader.error(JsonReader::member(path, "id"),
                         QStringLiteral("0 is the broadcast address, not a unit's: expected 1-255 (TCP requests to "
                                        "unit 0 or 255 reach the first unit)"));
        else
            unit.id = quint8(reader.integer(*o, path, "id", 1, 255).value_or(1));
    }
    unit.name = reader.string(*o, path, "name").value_or(QString());
    unit.description = reader.string(*o, path, "description").value_or(QString());
    unit.exceptionStatus = quint8(reader.integer(*o, path, "exceptionStatus", 0, 255).value_or(0));
    if (o->contains(QLatin1String("functions")))
        readFunctions(reader, o->value(QLatin1String("functions")), JsonReader::member(path, "functions"), &unit);
    if (o->contains(QLatin1String("responseDelay"))) {
        if (const auto delay = FaultRuleReader::readDelay(reader, o->value(QLatin1String("responseDelay")),
                                                          JsonReader::member(path, "responseDelay")))
            unit.responseDelay = *delay;
    }
    if (o->contains(QLatin1String("tables")))
        ProfileTableReader::readTables(reader, o->value(QLatin1String("tables")), JsonReader::member(path, "tables"), &unit);
    if (o->contains(QLatin1String("sharedTables")))
        readSharedTables(reader, o->value(QLatin1String("sharedTables")), JsonReader::member(path, "sharedTables"), &unit);
    if (const auto gaps = reader.string(*o, path, "gapReads")) {
        if (*gaps == QLatin1String("zeros"))
            unit.gapReadsZeros = true;
        else if (*gaps != QLatin1String("exception"))
            reader.error(JsonReader::member(path, "gapReads"),
                         QStringLiteral("'%1' is not how a read over a gap is answered: expected exception (02) or "
                                        "zeros").arg(*gaps));
    }
    if (o->contains(QLatin1String("fifos")))
        readFifos(reader, o->value(QLatin1String("fifos")), JsonReader::member(path, "fifos"), &unit);
    if (o->contains(QLatin1String("files")))
        readFiles(reader, o->value(QLatin1String("files")), JsonReader::member(path, "files"), &unit);
    if (o->contains(QLatin1String("deviceIdentification")))
        readDeviceId(reader, o->value(QLatin1String("deviceIdentification")),
                     JsonReader::member(path, "deviceIdentification"), &unit);
    if (o->contains(QLatin1String("serverId")))
        readServerId(reader, o->value(QLatin1String("serverId")), JsonReader::member(path, "serverId"), &unit);
    if (o->contains(QLatin1String("script"))) {
        if (const auto script = ScriptSettingsReader::read(reader, o->value(QLatin1String("script")),
                                                           JsonReader::member(path, "script")))
            unit.script = *script;
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return unit;
}

void ProfileUnitReader::readSharedTables(JsonReader &reader, const QJsonValue &value, const QString &path,
                                         UnitProfile *unit)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    for (auto it = o->begin(); it != o->end(); ++it) {
        const QString at = JsonReader::member(path, it.key());
        const auto asked = simTableFromKey(it.key());
        if (!asked) {
            reader.error(at, QStringLiteral("'%1' is not a table: expected coils, discrete, input or holding").arg(it.key()));
            continue;
        }
        const auto name = reader.stringValue(it.value(), at);
        if (!name)
            continue;
        const auto answering = simTableFromKey(*name);
        if (!answering || *answering == *asked || isBitTable(*answering) != isBitTable(*asked)) {
            reader.error(at, QStringLiteral("'%1' cannot answer reads of %2: expected %3")
                                 .arg(*name, it.key(),
                                      isBitTable(*asked) ? QStringLiteral("the other bit table (coils or discrete)")
                                                         : QStringLiteral("the other register table (input or holding)")));
            continue;
        }
        if (!unit->entriesOf(*asked).isEmpty()) {
            reader.error(at, QStringLiteral("the %1 table has entries of its own: a shared table is read through "
                                            "%2 and has none").arg(it.key(), *name));
            continue;
        }
        unit->sharedTables.insert(*asked, *answering);
    }
    for (auto it = unit->sharedTables.cbegin(); it != unit->sharedTables.cend(); ++it) {
        if (unit->sharedTables.contains(it.value())) {
            reader.error(path, QStringLiteral("%1 and %2 are shared with each other: one of them must hold the entries")
                                   .arg(QLatin1String(simTableKey(it.key())),
                                        QLatin1String(simTableKey(it.value()))));
            break; // said once for the pair
        }
    }
}

void ProfileUnitReader::readFunctions(JsonReader &reader, const QJsonValue &value, const QString &path,
                                      UnitProfile *unit)
{
    if (!value.isArray()) {
        reader.error(path, QStringLiteral("expected an array of function codes such as [\"0x03\", \"0x10\"], found %1")
                               .arg(JsonReader::describe(value)));
        return;
    }
    const QJsonArray a = value.toArray();
    const QList<quint8> implemented = SimUnit::implementedFunctions();
    if (a.isEmpty())
        reader.error(path, QStringLiteral("the list is empty: a unit answers at least one function code"));
    for (qsizetype i = 0; i < a.size(); ++i) {
        const QString at = JsonReader::element(path, i);
        const auto code = reader.integerValue(a.at(i), at, 1, 127);
        if (!code)
            continue;
        if (!implemented.contains(quint8(*code)))
            reader.error(at, QStringLiteral("function code %1 is not one the simulator implements (%2)")
                                 .arg(hexNumber(quint8(*code), 2)).arg(codeList(implemented)));
        else if (unit->functions.contains(quint8(*code)))
            reader.error(at, QStringLiteral("function code %1 is listed twice").arg(hexNumber(quint8(*code), 2)));
        else
            unit->functions.append(quint8(*code));
    }
}

QList<quint16> ProfileUnitReader::readWords(JsonReader &reader, const QJsonValue &value, const QString &path,
                                            qsizetype maxCount)
{
    QList<quint16> out;
    if (!value.isArray()) {
        reader.error(path, QStringLiteral("expected an array of register values, found %1").arg(JsonReader::describe(value)));
        return out;
    }
    const QJsonArray a = value.toArray();
    if (a.size() > maxCount) {
        reader.error(path, QStringLiteral("%1 values are more than %2").arg(a.size()).arg(maxCount));
        return out;
    }
    for (qsizetype i = 0; i < a.size(); ++i)
        out.append(quint16(reader.integerValue(a.at(i), JsonReader::element(path, i), 0, 65535).value_or(0)));
    return out;
}

void ProfileUnitReader::readFifos(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit)
{
    if (!value.isArray()) {
        reader.error(path, QStringLiteral("expected an array of FIFOs, found %1").arg(JsonReader::describe(value)));
        return;
    }
    const QJsonArray a = value.toArray();
    for (qsizetype i = 0; i < a.size(); ++i) {
        const QString at = JsonReader::element(path, i);
        const auto o = reader.objectValue(a.at(i), at);
        if (!o)
            continue;
        reader.checkKeys(*o, at, {"address", "name", "values"});
        FifoSpec fifo;
        if (reader.require(*o, at, "address"))
            fifo.address = quint16(reader.integer(*o, at, "address", 0, 65535).value_or(0));
        if (o->contains(QLatin1String("values")))
            fifo.values = readWords(reader, o->value(QLatin1String("values")), JsonReader::member(at, "values"), kMaxFifo);
        for (const FifoSpec &other : unit->fifos) {
            if (other.address == fifo.address)
                reader.error(JsonReader::member(at, "address"), QStringLiteral("FIFO %1 is given twice").arg(fifo.address));
        }
        unit->fifos.append(fifo);
    }
}

void ProfileUnitReader::readFiles(JsonReader &reader, const QJsonValue &value, const QString &path, UnitProfile *unit)
{
    if (!value.isArray()) {
        reader.error(path, QStringLiteral("expected an array of files, found %1").arg(JsonReader::describe(value)));
        return;
    }
    const QJsonArray a = value.toArray();
    for (qsizetype i = 0; i < a.size(); ++i) {
        const QString at = JsonReader::element(path, i);
        const auto o = reader.objectValue(a.at(i), at);
        if (!o)
            continue;
        reader.checkKeys(*o, at, {"file", "name", "length", "records", "writable"});
        FileSpec file;
        // File numbers 1-65535 and record numbers 0-9999 (V1.1b3 6.14).
        if (reader.require(*o, at, "file"))
            file.number = quint16(reader.integer(*o, at, "file", 1, 65535).value_or(1));
        file.writable = reader.boolean(*o, at, "writable").value_or(true);
        if (o->contains(QLatin1String("records")))
            file.records = readWords(reader, o->value(QLatin1String("records")), JsonReader::member(at, "records"), 10000);
        if (const auto length = reader.integer(*o, at, "length", 1, 10000)) {
            if (*length < file.records.size())
                reader.error(JsonReader::member(at, "length"),
                             QStringLiteral("%1 is shorter than the %2 records given").arg(*length).arg(file.records.size()));
            else
                file.records.resize(*length, 0);
        }
        if (file.records.isEmpty())
            reader.error(at, QStringLiteral("the file has no records: give 'records' or 'length'"));
        for (const FileSpec &other : unit->files) {
            if (other.number == file.number)
                reader.error(JsonReader::member(at, "file"), QStringLiteral("file %1 is given twice").arg(file.number));
        }
        unit->files.append(file);
    }
}

void ProfileUnitReader::readDeviceId(JsonReader &reader, const QJsonValue &value, const QString &path,
                                     UnitProfile *unit)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"conformityLevel", "objects"});
    if (const auto level = reader.integer(*o, path, "conformityLevel", 0, 255)) {
        // V1.1b3 6.21: 01-03 stream access only, 81-83 stream and individual access.
        const QList<qint64> valid = {0x01, 0x02, 0x03, 0x81, 0x82, 0x83};
        if (!valid.contains(*level))
            reader.error(JsonReader::member(path, "conformityLevel"),
                         QStringLiteral("%1 is not a conformity level: expected 0x01, 0x02, 0x03, 0x81, 0x82 or 0x83").arg(*level));
        else
            unit->conformityLevel = quint8(*level);
    }
    const auto objects = reader.object(*o, path, "objects");
    if (!objects)
        return;
    const QString at = JsonReader::member(path, "objects");
    for (auto it = objects->begin(); it != objects->end(); ++it) {
        const QString key = it.key();
        int id = -1;
        for (int i = 0; i < 7; ++i) {
            if (key == QLatin1String(kObjectNames[i]))
                id = i;
        }
        if (id < 0 && key.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
            bool ok = false;
            const int n = key.mid(2).toInt(&ok, 16);
            if (ok && n >= 0 && n <= 255)
                id = n;
        }
        const QString objectPath = JsonReader::member(at, key);
        if (id < 0) {
            reader.error(at, QStringLiteral("unknown key '%1': expected VendorName, ProductCode, MajorMinorRevision, "
                                            "VendorUrl, ProductName, ModelName, UserApplicationName or an object id "
                                            "\"0x00\"-\"0xFF\"").arg(key));
            continue;
        }
        if (unit->deviceId.contains(quint8(id))) {
            reader.error(objectPath, QStringLiteral("object 0x%1 is given twice").arg(hexNumber(id, 2)));
            continue;
        }
        if (const auto bytes = latin1Text(reader, it.value(), objectPath, kMaxObjectBytes))
            unit->deviceId.insert(quint8(id), *bytes);
    }
    // The basic category is mandatory for every conformity level (V1.1b3 6.21).
    QStringList missing;
    for (int i = 0; i < 3; ++i) {
        if (!objects->contains(QLatin1String(kObjectNames[i])) && !unit->deviceId.contains(quint8(i)))
            missing.append(QString::fromLatin1(kObjectNames[i]));
    }
    if (!missing.isEmpty())
        reader.error(at, QStringLiteral("%1 missing: VendorName, ProductCode and MajorMinorRevision are mandatory "
                                        "(V1.1b3 6.21)").arg(missing.join(QStringLiteral(", "))
                                                             + (missing.size() == 1 ? QStringLiteral(" is") : QStringLiteral(" are"))));
}

void ProfileUnitReader::readServerId(JsonReader &reader, const QJsonValue &value, const QString &path,
                                     UnitProfile *unit)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"id", "running", "additionalData", "additionalDataHex"});
    ServerIdSpec spec;
    if (reader.require(*o, path, "id")) {
        if (const auto text = reader.string(*o, path, "id")) {
            const HexTextResult hex = HexText::parse(*text);
            if (hex.ok)
                spec.id = hex.bytes;
            else
                reader.error(JsonReader::member(path, "id"),
                             QStringLiteral("expected hex bytes such as \"2A\" or \"4D 42 53\": %1").arg(hex.error.message));
        }
    }
    spec.running = reader.boolean(*o, path, "running").value_or(true);
    if (o->contains(QLatin1String("additionalData")) && o->contains(QLatin1String("additionalDataHex")))
        reader.error(path, QStringLiteral("give 'additionalData' (text) or 'additionalDataHex' (bytes), not both"));
    else if (o->contains(QLatin1String("additionalData")))
        spec.additionalData = latin1Text(reader, o->value(QLatin1String("additionalData")),
                                         JsonReader::member(path, "additionalData"), kMaxServerIdBytes).value_or(QByteArray());
    else if (const auto text = reader.string(*o, path, "additionalDataHex")) {
        const HexTextResult hex = HexText::parse(*text);
        if (hex.ok)
            spec.additionalData = hex.bytes;
        else
            reader.error(JsonReader::member(path, "additionalDataHex"), hex.error.message);
    }
    const qsizetype total = spec.id.size() + 1 + spec.additionalData.size();
    if (total > kMaxServerIdBytes)
        reader.error(path, QStringLiteral("id, run indicator and additional data take %1 bytes, more than the %2 a "
                                          "response can hold (V1.1b3 6.13)").arg(total).arg(kMaxServerIdBytes));
    unit->serverId = spec;
}

} // namespace mbscope
