#pragma once

#include "protocol/registerformat.h"
#include "script/scriptsettings.h"
#include "delayspec.h"
#include "devicelimits.h"
#include "faultrule.h"
#include "generatorspec.h"
#include "linerule.h"
#include "simtable.h"
#include "valuekind.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>
#include <span>

namespace mbscope {

// One entry of a table in a device profile: a block of consecutive addresses, holding one or
// more values of one type (registers) or bits. Registers carry engineering meaning:
//   value = raw * scale + offset        raw = (value - offset) / scale
// where raw is the number the register format encodes (u16, i32, f32-cdab...).
struct TableEntry {
    SimTable table = SimTable::HoldingRegisters;
    quint16 address = 0;
    int count = 1;               // addresses covered: values x registers per value (bits: values)
    QString name;
    QString description;
    QString unit;                // engineering unit text ("V", "cps", "degC")
    RegisterFormat format;       // registers only
    double scale = 1;
    double offset = 0;
    bool writable = true;        // coils and holding registers; the other tables are read-only
    QList<quint16> initial;      // count raw words (bits as 0/1), wire order
    std::optional<GeneratorSpec> generator; // drives every value of the entry

    // What a register map says besides the numbers (docs/profiles.md, "What a register map says").
    ValueKind kind = ValueKind::Unspecified; // "kind"
    std::optional<double> min, max;          // "min", "max": the declared range, engineering values
    std::optional<quint16> scaleRegister;    // "scaleRegister": scale = 10^(i16 at this address, same table)
    QMap<int, QString> bitNames;             // "bits": bit 0 (least significant) .. 63 -> name
    QMap<qint64, QString> enumNames;         // "enum": raw value -> meaning
    int stringLength = 0;                    // "length": an ascii entry is one string of this many characters
    bool spacePadded = false;                // "padding": "space" (else NUL) after the text of a string
    std::optional<quint64> notImplemented;   // "notImplemented": raw bit pattern that means "no value"
    bool notImplementedNaN = false;          // "notImplemented": "NaN": any NaN means "no value"

    [[nodiscard]] bool isString() const { return stringLength > 0; }
    // The raw words of one value (width() registers, wire order) are the "not implemented" sentinel.
    [[nodiscard]] bool isNotImplemented(std::span<const quint16> words) const;

    [[nodiscard]] int end() const { return int(address) + count; }
    [[nodiscard]] int width() const { return isBitTable(table) ? 1 : format.registerCount(); }
    [[nodiscard]] int valueCount() const { return count / width(); }
};

struct FifoSpec {
    quint16 address = 0;     // the FIFO pointer address (V1.1b3 6.18)
    QList<quint16> values;   // at most 31
};

struct FileSpec {
    quint16 number = 1;      // 1..65535 (V1.1b3 6.14)
    QList<quint16> records;  // the file's length is records.size() (at most 10000)
    bool writable = true;
};

struct ServerIdSpec {
    QByteArray id;            // device specific bytes (V1.1b3 6.13)
    bool running = true;      // run indicator ON (FF) or OFF (00)
    QByteArray additionalData;
};

struct UnitProfile {
    quint8 id = 1;
    QString name;
    QString description;
    QList<quint8> functions;  // empty: every function code the simulator implements
    DelaySpec responseDelay;
    QList<TableEntry> entries; // every table, each table's entries in address order
    QList<FifoSpec> fifos;
    QList<FileSpec> files;
    QMap<quint8, QByteArray> deviceId; // Read Device Identification objects (V1.1b3 6.21)
    quint8 conformityLevel = 0;        // 0: derived from the objects present
    std::optional<ServerIdSpec> serverId;
    quint8 exceptionStatus = 0;        // 07 (V1.1b3 6.7)
    ScriptSettings script;             // "script": answers computed in JavaScript (empty: none)
    // "gapReads": a read that spans addresses between entries of a table gets exception 02
    // (false) or zeros there (true); a read outside the first..last entry always gets 02.
    bool gapReadsZeros = false;
    // "sharedTables": a table read through another's function code ({"input": "holding"}: 04 reads
    // the holding registers, as 03 does). Key: the table asked for; value: the table answering.
    QMap<SimTable, SimTable> sharedTables;

    [[nodiscard]] QList<TableEntry> entriesOf(SimTable table) const;
    // The entry holding address in table, or nullptr.
    [[nodiscard]] const TableEntry *entryAt(SimTable table, int address) const;
};

// A device profile as loaded: everything checked, nothing missing (ProfileLoader).
struct DeviceProfile {
    QString name;
    QString description;
    QString source;           // where it came from: ":/profiles/rosrao-gamma.json" or a path
    QStringList endpoints;    // default listen URLs
    quint64 seed = 1;         // generators and fault rules derive their seeds from it
    QList<UnitProfile> units;
    FaultRuleSet faults;
    DeviceLimits limits;      // "unknownUnit" and "limits"
    LineTable delimited;      // "delimited": a non-Modbus protocol's requests and answers

    [[nodiscard]] const UnitProfile *unit(quint8 id) const;
};

} // namespace mbscope
