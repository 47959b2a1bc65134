#pragma once

// Rows for tst_profileloader: contentErrors (a profile with one mistake, the JSON path of the
// first problem and its message: what was found and what was expected) and encodedValues (an
// entry and the registers its initial value becomes).

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtTest/QtTest>

namespace profilecases {

inline QByteArray unit(const char *unitBody)
{
    return QByteArray(R"({"name": "t", "units": [{"id": 1)") + unitBody + "}]}";
}

inline QByteArray holding(const char *entries)
{
    return unit((QByteArray(R"(, "tables": {"holding": [)") + entries + "]}").constData());
}

inline QByteArray table(const char *name, const char *entries)
{
    return unit((QByteArray(R"(, "tables": {")") + name + R"(": [)" + entries + "]}").constData());
}

inline QByteArray generator(const char *entryExtra, const char *gen)
{
    return holding((QByteArray(R"({"address": 0)") + entryExtra + R"(, "generator": )" + gen + "}").constData());
}

inline QByteArray faults(const char *rules)
{
    return QByteArray(R"({"name": "t", "units": [{"id": 1}], "faults": {"rules": [)") + rules + "]}}";
}

inline void row(const char *name, const QByteArray &json, const char *path, const QString &message)
{
    QTest::newRow(name) << json << QString::fromLatin1(path) << message;
}

inline void addErrorRows()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("message");
    const auto S = [](const char *s) { return QString::fromUtf8(s); };

    // The document
    row("top-level array", "[]", "", S("expected a JSON object at the top level, found an array"));
    row("name missing", R"({"units": [{"id": 1}]})", "", S("'name' is missing"));
    row("name empty", R"({"name": " ", "units": [{"id": 1}]})", "name", S("the name is empty"));
    row("name a number", R"({"name": 5, "units": [{"id": 1}]})", "name", S("expected a string, found the number 5"));
    row("unknown top-level key", R"({"name": "t", "unit": [], "units": [{"id": 1}]})", "",
        S("unknown key 'unit': expected one of $schema, name, description, endpoints, seed, units, faults, unknownUnit, answersBroadcasts, "
          "limits, delimited"));
    row("units missing", R"({"name": "t"})", "", S("'units' is missing"));
    row("units empty", R"({"name": "t", "units": []})", "units", S("the list is empty: a profile has at least one unit"));
    row("units an object", R"({"name": "t", "units": {}})", "units", S("expected an array, found an object"));
    row("seed negative", R"({"name": "t", "seed": -1, "units": [{"id": 1}]})", "seed", S("-1 is below 0"));
    row("endpoint scheme", R"({"name": "t", "endpoints": ["modbus://x:1"], "units": [{"id": 1}]})", "endpoints[0]",
        S("modbus://x:1: unknown scheme 'modbus': expected one of tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, ascii, tls"));

    // Units
    row("unit id missing", R"({"name": "t", "units": [{"name": "x"}]})", "units[0]", S("'id' is missing"));
    row("unit id 0", R"({"name": "t", "units": [{"id": 0}]})", "units[0].id",
        S("0 is the broadcast address, not a unit's: expected 1-255 (TCP requests to unit 0 or 255 reach the first unit)"));
    row("unit id 0x00", R"({"name": "t", "units": [{"id": "0x00"}]})", "units[0].id",
        S("0 is the broadcast address, not a unit's: expected 1-255 (TCP requests to unit 0 or 255 reach the first unit)"));
    row("unit id 256", R"({"name": "t", "units": [{"id": 256}]})", "units[0].id", S("256 is beyond 255"));
    row("unit id fraction", R"({"name": "t", "units": [{"id": 1.5}]})", "units[0].id", S("1.5 is not a whole number"));
    row("unit id bad hex", R"({"name": "t", "units": [{"id": "0xZZ"}]})", "units[0].id",
        S("expected a whole number or hex text such as \"0x0079\", found a string \"0xZZ\""));
    row("unit id twice", R"({"name": "t", "units": [{"id": 3}, {"id": "0x03"}]})", "units[1].id",
        S("unit 3 is given twice (also an earlier unit)"));
    row("unit unknown key", unit(R"(, "table": {})"), "units[0]",
        S("unknown key 'table': expected one of id, name, description, functions, responseDelay, tables, fifos, files, "
          "deviceIdentification, serverId, exceptionStatus, script, gapReads, sharedTables"));
    row("function not implemented", unit(R"(, "functions": ["0x03", "0x41"])"), "units[0].functions[1]",
        S("function code 41 is not one the simulator implements (01, 02, 03, 04, 05, 06, 07, 08, 0B, 0C, 0F, 10, 11, 14, "
          "15, 16, 17, 18, 2B)"));
    row("function code 0", unit(R"(, "functions": [0])"), "units[0].functions[0]", S("0 is below 1"));
    row("function twice", unit(R"(, "functions": [3, "0x03"])"), "units[0].functions[1]", S("function code 03 is listed twice"));
    row("functions empty", unit(R"(, "functions": [])"), "units[0].functions",
        S("the list is empty: a unit answers at least one function code"));
    row("delay unknown distribution", unit(R"(, "responseDelay": {"distribution": "gamma"})"),
        "units[0].responseDelay.distribution",
        S("'gamma' is not a distribution: expected fixed, uniform, normal, exponential or lognormal"));
    row("delay negative", unit(R"(, "responseDelay": -3)"), "units[0].responseDelay", S("-3 is below 0"));
    row("delay text", unit(R"(, "responseDelay": "4ms")"), "units[0].responseDelay",
        S("expected milliseconds or an object such as {\"distribution\": \"normal\", \"meanMs\": 4, \"stddevMs\": 1}, "
          "found a string \"4ms\""));
    row("delay uniform reversed", unit(R"(, "responseDelay": {"distribution": "uniform", "minMs": 5, "maxMs": 2})"),
        "units[0].responseDelay.maxMs", S("2 is below minMs 5"));
    row("delay normal without stddev", unit(R"(, "responseDelay": {"distribution": "normal", "meanMs": 5})"),
        "units[0].responseDelay", S("'stddevMs' is missing"));
    row("delay key of another distribution", unit(R"(, "responseDelay": {"distribution": "fixed", "ms": 1, "meanMs": 2})"),
        "units[0].responseDelay", S("unknown key 'meanMs': expected one of distribution, ms"));

    // Table entries
    row("address beyond 65535", holding(R"({"address": 1}, {"address": 2}, {"address": 70000})"),
        "units[0].tables.holding[2].address", S("70000 is beyond 65535"));
    row("unknown table", unit(R"(, "tables": {"holdings": []})"), "units[0].tables",
        S("unknown key 'holdings': expected one of coils, discrete, input, holding"));
    row("address missing", holding(R"({"name": "x"})"), "units[0].tables.holding[0]", S("'address' is missing"));
    row("entry not an object", holding("5"), "units[0].tables.holding[0]", S("expected an object, found the number 5"));
    row("unknown type", holding(R"({"address": 0, "type": "f33"})"), "units[0].tables.holding[0].type",
        S("'f33' is not a register format: expected u16, i16, hex, bin, ascii, u32, i32, u64, i64, f32 or f64, "
          "optionally followed by an order as in f32-cdab"));
    row("scale zero", holding(R"({"address": 0, "scale": 0})"), "units[0].tables.holding[0].scale",
        S("0 would make every value the same: expected a non-zero factor"));
    row("count not whole values", holding(R"({"address": 0, "type": "f32", "count": 3})"), "units[0].tables.holding[0].count",
        S("3 registers are not a whole number of f32-abcd values (2 registers each)"));
    row("more values than count", holding(R"({"address": 0, "count": 2, "values": [1, 2, 3]})"),
        "units[0].tables.holding[0].count", S("3 values take 3 registers, more than count 2"));
    row("runs past 65535", holding(R"({"address": 65530, "type": "u32", "count": 10})"), "units[0].tables.holding[0]",
        S("addresses 65530-65539 run past 65535 (10 registers from 65530)"));
    row("overlap", holding(R"({"address": 0, "count": 10}, {"address": 20}, {"address": 5, "count": 10})"),
        "units[0].tables.holding[2]", S("addresses 5-14 overlap holding[0] (0-9)"));
    row("value and values", holding(R"({"address": 0, "value": 1, "values": [1]})"), "units[0].tables.holding[0]",
        S("give 'value' (every value the same) or 'values' (a list), not both"));
    row("value out of range", holding(R"({"address": 0, "values": [1, 70000]})"), "units[0].tables.holding[0].values[1]",
        S("70000 is out of range for u16 (raw 0 to 65535)"));
    row("scaled value out of range", holding(R"({"address": 0, "type": "i16", "scale": 0.1, "value": 4000})"),
        "units[0].tables.holding[0].value", S("4000 is out of range for i16 (raw -32768 to 32767)"));
    row("raw text refused", holding(R"({"address": 0, "type": "hex", "value": "0xG1"})"), "units[0].tables.holding[0].value",
        S("'0xG1': 'G' is not a hex digit"));
    row("value a boolean", holding(R"({"address": 0, "value": true})"), "units[0].tables.holding[0].value",
        S("expected a number or the raw value as text (\"0x1A2B\"), found true"));
    row("coil value 2", table("coils", R"({"address": 0, "values": [1, 2]})"), "units[0].tables.coils[0].values[1]",
        S("expected true, false, 0 or 1, found the number 2"));
    row("type on coils", table("coils", R"({"address": 0, "type": "u16"})"), "units[0].tables.coils[0]",
        S("unknown key 'type': expected one of address, count, name, description, writable, value, values, generator, "
          "kind"));
    row("writable on input registers", table("input", R"({"address": 0, "writable": true})"), "units[0].tables.input[0]",
        S("unknown key 'writable': expected one of address, count, name, description, unit, type, scale, offset, value, "
          "values, generator, kind, min, max, scaleRegister, bits, enum, length, padding, notImplemented"));

    // What a register map says (docs/profiles.md, "What a register map says")
    row("kind unknown", holding(R"({"address": 0, "kind": "gauge"})"), "units[0].tables.holding[0].kind",
        S("'gauge' is not a kind of value: expected measurement, counter, setting, status, enumeration, constant or "
          "reserved"));
    row("max below min", holding(R"({"address": 0, "min": 5, "max": 1})"), "units[0].tables.holding[0].max",
        S("1 is below min 5"));
    row("bits of a float", holding(R"({"address": 0, "type": "f32", "bits": {"0": "alarm"}})"),
        "units[0].tables.holding[0].bits", S("a f32-abcd value has no bits to name: expected an integer type (u16, u32, hex, bin...)"));
    row("bit 16 of a u16", holding(R"({"address": 0, "bits": {"16": "alarm"}})"), "units[0].tables.holding[0].bits.16",
        S("'16' is not a bit of a u16: expected 0-15 (0 the least significant)"));
    row("bit 31 of a u32 is fine, 32 is not", holding(R"({"address": 0, "type": "u32", "bits": {"31": "a", "32": "b"}})"),
        "units[0].tables.holding[0].bits.32", S("'32' is not a bit of a u32-abcd: expected 0-31 (0 the least significant)"));
    row("bit name a number", holding(R"({"address": 0, "bits": {"3": 4}})"), "units[0].tables.holding[0].bits.3",
        S("expected a string, found the number 4"));
    row("enum of a float", holding(R"({"address": 0, "type": "f64", "enum": {"0": "off"}})"),
        "units[0].tables.holding[0].enum", S("a f64-abcdefgh value cannot be an enumeration: expected an integer type"));
    row("enum key out of range", holding(R"({"address": 0, "type": "i16", "enum": {"40000": "x"}})"),
        "units[0].tables.holding[0].enum.40000",
        S("'40000' is not a raw i16 value: expected a whole number -32768 to 32767 (decimal or 0x hex)"));
    row("length on a u16", holding(R"({"address": 0, "length": 8})"), "units[0].tables.holding[0].length",
        S("a string of characters is an ascii entry: expected \"type\": \"ascii\" (or \"ascii-ba\"), found u16"));
    row("padding unknown", holding(R"({"address": 0, "type": "ascii", "length": 4, "padding": "zero"})"),
        "units[0].tables.holding[0].padding", S("'zero' is not a padding: expected nul or space"));
    row("padding without length", holding(R"({"address": 0, "type": "ascii", "padding": "space"})"),
        "units[0].tables.holding[0].padding", S("padding needs 'length' (a string)"));
    row("string too long", holding(R"({"address": 0, "type": "ascii", "length": 4, "value": "ABCDE"})"),
        "units[0].tables.holding[0].value", S("\"ABCDE\" has 5 characters, more than length 4"));
    row("string count disagrees", holding(R"({"address": 0, "type": "ascii", "length": 5, "count": 2})"),
        "units[0].tables.holding[0].count", S("a string of 5 characters takes 3 registers, not 2"));
    row("string with values", holding(R"({"address": 0, "type": "ascii", "length": 4, "values": ["AB"]})"),
        "units[0].tables.holding[0].values", S("a string entry holds one text: give it as 'value'"));
    row("notImplemented NaN on a u16", holding(R"({"address": 0, "notImplemented": "NaN"})"),
        "units[0].tables.holding[0].notImplemented", S("'NaN' is not a whole number: u16 takes decimal digits with an optional sign, or a 0x or 0b bit pattern"));
    row("notImplemented an array", holding(R"({"address": 0, "notImplemented": [1]})"),
        "units[0].tables.holding[0].notImplemented",
        S("expected the raw value as text (\"0x8000\", \"0xFFFF\", \"NaN\"), found an array"));
    row("scaleRegister and scale", holding(R"({"address": 0, "scale": 0.1, "scaleRegister": 1}, {"address": 1, "type": "i16"})"),
        "units[0].tables.holding[0].scaleRegister",
        S("give 'scale' (a fixed factor) or 'scaleRegister' (a factor read from a register), not both"));
    row("scaleRegister missing", holding(R"({"address": 0, "scaleRegister": 9})"), "units[0].tables.holding[0].scaleRegister",
        S("holding 9 is not in any holding entry of this unit (without a scaleRegister of its own)"));
    row("scaleRegister a float", holding(R"({"address": 0, "scaleRegister": 2}, {"address": 2, "type": "f32"})"),
        "units[0].tables.holding[0].scaleRegister",
        S("holding 2 is a f32-abcd value: a scale factor is one i16 register (a power of ten; give that entry \"type\": \"i16\")"));
    // A u16 (an untyped block) was taken as an i16 without a word (a new user's try).
    row("scaleRegister a u16", holding(R"({"address": 0, "count": 10}, {"address": 20, "type": "i16", "scaleRegister": 9})"),
        "units[0].tables.holding[1].scaleRegister",
        S("holding 9 is a u16 value: a scale factor is one i16 register (a power of ten; give that entry \"type\": \"i16\")"));
    row("scaleRegister too large", holding(R"({"address": 0, "scaleRegister": 1}, {"address": 1, "type": "i16", "value": 40})"),
        "units[0].tables.holding[0].scaleRegister",
        S("holding 1 holds 40: a scale factor of 10^40 is outside 10^-10..10^10"));
    row("kind on coils takes no min", table("coils", R"({"address": 0, "kind": "status", "min": 0})"), "units[0].tables.coils[0]",
        S("unknown key 'min': expected one of address, count, name, description, writable, value, values, generator, kind"));
    row("gapReads unknown", unit(R"(, "gapReads": "ones")"), "units[0].gapReads",
        S("'ones' is not how a read over a gap is answered: expected exception (02) or zeros"));
    row("sharedTables bits with registers", unit(R"(, "sharedTables": {"input": "coils"})"), "units[0].sharedTables.input",
        S("'coils' cannot answer reads of input: expected the other register table (input or holding)"));
    row("sharedTables unknown table", unit(R"(, "sharedTables": {"inputs": "holding"})"), "units[0].sharedTables.inputs",
        S("'inputs' is not a table: expected coils, discrete, input or holding"));
    row("sharedTables table with entries", unit(R"(, "tables": {"input": [{"address": 0}]}, "sharedTables": {"input": "holding"})"),
        "units[0].sharedTables.input",
        S("the input table has entries of its own: a shared table is read through holding and has none"));
    row("sharedTables both ways", unit(R"(, "sharedTables": {"input": "holding", "holding": "input"})"), "units[0].sharedTables",
        S("input and holding are shared with each other: one of them must hold the entries"));
    row("writable a string", holding(R"({"address": 0, "writable": "yes"})"), "units[0].tables.holding[0].writable",
        S("expected true or false, found a string \"yes\""));

    // Generators
    row("generator kind unknown", generator("", R"({"kind": "triangle"})"), "units[0].tables.holding[0].generator.kind",
        S("'triangle' is not a generator: expected constant, counter, randomWalk, sine, poisson or copy"));
    row("generator kind missing", generator("", R"({"step": 1})"), "units[0].tables.holding[0].generator",
        S("'kind' is missing"));
    row("key of another generator", generator("", R"({"kind": "counter", "amplitude": 3})"),
        "units[0].tables.holding[0].generator",
        S("unknown key 'amplitude': expected one of kind, periodMs, seed, step, min, max, wrap"));
    row("counter max below min", generator("", R"({"kind": "counter", "min": 10, "max": 5})"),
        "units[0].tables.holding[0].generator.max", S("5 is not above min 10"));
    row("counter max beyond type", generator(R"(, "type": "i16")", R"({"kind": "counter", "max": 40000})"),
        "units[0].tables.holding[0].generator.max", S("40000 is beyond 32767"));
    row("walk step negative", generator("", R"({"kind": "randomWalk", "step": -1})"),
        "units[0].tables.holding[0].generator.step", S("-1 is below 0"));
    row("period zero", generator("", R"({"kind": "sine", "periodMs": 0})"), "units[0].tables.holding[0].generator.periodMs",
        S("0 is below 1"));
    row("poisson without rate", generator("", R"({"kind": "poisson"})"), "units[0].tables.holding[0].generator",
        S("'rate' is missing"));
    row("poisson gate longer than period", generator("", R"({"kind": "poisson", "rate": 5, "gateMs": 2000, "periodMs": 1000})"),
        "units[0].tables.holding[0].generator.gateMs", S("2000 is longer than periodMs 1000: gates would overlap"));
    row("constant out of range", generator("", R"({"kind": "constant", "value": -1})"),
        "units[0].tables.holding[0].generator.value", S("-1 is below 0"));
    row("copy source missing", generator("", R"({"kind": "copy", "table": "input", "address": 9})"),
        "units[0].tables.holding[0].generator.address", S("input 9 is not in any input entry of this unit"));
    row("copy source inside a value", holding(R"({"address": 0, "type": "f32"}, {"address": 2, "generator": {"kind": "copy", "address": 1}})"),
        "units[0].tables.holding[1].generator.address",
        S("holding 1 is inside a f32-abcd value that starts at 0: expected the first address of a value"));
    row("copy table unknown", generator("", R"({"kind": "copy", "table": "coil", "address": 0})"),
        "units[0].tables.holding[0].generator.table",
        S("'coil' is not a table: expected coils, discrete, input or holding"));

    // FIFOs, files, identification, server id
    const QByteArray thousandAndOne = QByteArray("0,").repeated(1000) + "0";
    row("fifo too long", unit((R"(, "fifos": [{"address": 1, "values": [)" + thousandAndOne + "]}]").constData()),
        "units[0].fifos[0].values", S("1001 values are more than 1000"));
    row("fifo twice", unit(R"(, "fifos": [{"address": 7}, {"address": 7}])"), "units[0].fifos[1].address", S("FIFO 7 is given twice"));
    row("file number 0", unit(R"(, "files": [{"file": 0, "length": 1}])"), "units[0].files[0].file", S("0 is below 1"));
    row("file without records", unit(R"(, "files": [{"file": 1}])"), "units[0].files[0]",
        S("the file has no records: give 'records' or 'length'"));
    row("file length short", unit(R"(, "files": [{"file": 1, "length": 1, "records": [1, 2]}])"), "units[0].files[0].length",
        S("1 is shorter than the 2 records given"));
    row("file too long", unit(R"(, "files": [{"file": 1, "length": 10001}])"), "units[0].files[0].length", S("10001 is beyond 10000"));
    row("device id basic missing", unit(R"(, "deviceIdentification": {"objects": {"VendorName": "x"}})"),
        "units[0].deviceIdentification.objects",
        S("ProductCode, MajorMinorRevision are missing: VendorName, ProductCode and MajorMinorRevision are mandatory (V1.1b3 6.21)"));
    row("device id unknown object", unit(R"(, "deviceIdentification": {"objects": {"Vendor": "x", "ProductCode": "p", "MajorMinorRevision": "1"}})"),
        "units[0].deviceIdentification.objects",
        S("unknown key 'Vendor': expected VendorName, ProductCode, MajorMinorRevision, VendorUrl, ProductName, ModelName, "
          "UserApplicationName or an object id \"0x00\"-\"0xFF\""));
    row("device id conformity", unit(R"(, "deviceIdentification": {"conformityLevel": 4})"),
        "units[0].deviceIdentification.conformityLevel",
        S("4 is not a conformity level: expected 0x01, 0x02, 0x03, 0x81, 0x82 or 0x83"));
    row("device id not latin-1", unit(R"(, "deviceIdentification": {"objects": {"VendorName": "\u20ac", "ProductCode": "p", "MajorMinorRevision": "1"}})"),
        "units[0].deviceIdentification.objects.VendorName", S("'\u20ac' is not a Latin-1 character: device strings are bytes"));
    row("server id not hex", unit(R"(, "serverId": {"id": "XY"})"), "units[0].serverId.id",
        S("expected hex bytes such as \"2A\" or \"4D 42 53\": line 1, column 1: 'X' is not a hex digit or a separator "
          "(0x may only start a byte, as in 0x01 0x03)"));
    row("server id missing", unit(R"(, "serverId": {"running": true})"), "units[0].serverId", S("'id' is missing"));

    // Fault rules in a profile
    row("fault kind unknown", faults(R"({"kind": "explode"})"), "faults.rules[0].kind",
        S("'explode' is not a fault: expected one of delay, drop, wrongChecksum, wrongTransactionId, wrongUnit, exception, "
          "fewerRegisters, chunks, trickle, junk, duplicate, close, noise"));
    row("fault probability", faults(R"({"kind": "drop", "probability": 1.5})"), "faults.rules[0].probability",
        S("1.5 is beyond 1"));
    row("fault addresses reversed", faults(R"({"kind": "drop", "addresses": [10, 5]})"), "faults.rules[0].addresses[1]",
        S("5 is below the first address 10"));
    row("fault addresses three", faults(R"({"kind": "drop", "addresses": [1, 2, 3]})"), "faults.rules[0].addresses",
        S("expected [first, last] (two addresses), found 3 values"));
    row("fault unit not in profile", faults(R"({"kind": "drop", "units": [1, 5]})"), "faults.rules[0].units[1]",
        S("unit 5 is not in this profile"));
    row("fault key of another kind", faults(R"({"kind": "drop", "code": 4})"), "faults.rules[0]",
        S("unknown key 'code': expected one of kind, name, units, functions, meets, addresses, start, quantity, values, "
          "probability"));
    row("junk without bytes", faults(R"({"kind": "junk"})"), "faults.rules[0]",
        S("junk needs 'before' or 'after' (a byte count or hex bytes)"));
    row("close when", faults(R"({"kind": "close", "when": "soon"})"), "faults.rules[0].when",
        S("'soon' is not a moment: expected before, midway or after"));
    row("delay rule without delay", faults(R"({"kind": "delay"})"), "faults.rules[0]", S("'delay' is missing"));
    row("exception code 0", faults(R"({"kind": "exception", "code": 0})"), "faults.rules[0].code", S("0 is below 1"));

    // Exact matching
    row("fault start beyond 65535", faults(R"({"kind": "drop", "start": 65536})"), "faults.rules[0].start",
        S("65536 is beyond 65535"));
    row("fault start list empty", faults(R"({"kind": "drop", "start": []})"), "faults.rules[0].start",
        S("the list is empty: leave 'start' out to match every value"));
    row("fault quantity text", faults(R"({"kind": "drop", "quantity": "two"})"), "faults.rules[0].quantity",
        S("expected a whole number or hex text such as \"0x0079\", found a string \"two\""));
    row("fault values a number", faults(R"({"kind": "drop", "values": 5})"), "faults.rules[0].values",
        S("expected a list of the values written, such as [1, 0] or [\"0x1234\"], found the number 5"));
    row("fault values empty", faults(R"({"kind": "drop", "values": []})"), "faults.rules[0].values",
        S("expected 1 to 123 values (a write carries at most 123 registers), found 0"));
    row("fault value beyond a register", faults(R"({"kind": "drop", "values": [1, 70000]})"), "faults.rules[0].values[1]",
        S("70000 is beyond 65535"));
    row("fault meets and addresses", faults(R"({"kind": "drop", "meets": 1, "addresses": 1})"), "faults.rules[0].addresses",
        S("give 'meets' or its older name 'addresses', not both"));
    row("fault meets reversed", faults(R"({"kind": "drop", "meets": [10, 5]})"), "faults.rules[0].meets[1]",
        S("5 is below the first address 10"));

    // Time-dependent faults and noise
    row("fault probability text", faults(R"({"kind": "drop", "probability": "often"})"), "faults.rules[0].probability",
        S("expected a number 0-1, {\"byIntervalMs\": [[ms, p], ...]} or {\"turnaround\": DELAY}, found a string \"often\""));
    row("fault probability both", faults(R"({"kind": "drop", "probability": {"byIntervalMs": [[1, 1]], "turnaround": 5}})"),
        "faults.rules[0].probability", S("give one of 'byIntervalMs' or 'turnaround'"));
    row("fault probability unknown key", faults(R"({"kind": "drop", "probability": {"byGapMs": []}})"),
        "faults.rules[0].probability", S("unknown key 'byGapMs': expected one of byIntervalMs, turnaround"));
    row("fault interval table empty", faults(R"({"kind": "drop", "probability": {"byIntervalMs": []}})"),
        "faults.rules[0].probability.byIntervalMs", S("the list is empty: expected [interval ms, probability] points"));
    row("fault interval point", faults(R"({"kind": "drop", "probability": {"byIntervalMs": [100]}})"),
        "faults.rules[0].probability.byIntervalMs[0]", S("expected [interval ms, probability], found the number 100"));
    row("fault interval chance", faults(R"({"kind": "drop", "probability": {"byIntervalMs": [[100, 1.5]]}})"),
        "faults.rules[0].probability.byIntervalMs[0][1]", S("1.5 is beyond 1"));
    row("fault intervals down", faults(R"({"kind": "drop", "probability": {"byIntervalMs": [[200, 0.5], [100, 0.2]]}})"),
        "faults.rules[0].probability.byIntervalMs[1][0]", S("100 ms does not follow 200 ms: intervals go up"));
    row("fault turnaround", faults(R"({"kind": "drop", "probability": {"turnaround": {"distribution": "poisson"}}})"),
        "faults.rules[0].probability.turnaround.distribution",
        S("'poisson' is not a distribution: expected fixed, uniform, normal, exponential or lognormal"));
    row("fault turnaround lognormal without spread",
        faults(R"({"kind": "drop", "probability": {"turnaround": {"distribution": "lognormal", "meanMs": 112}}})"),
        "faults.rules[0].probability.turnaround", S("'stddevMs' is missing"));
    row("noise without rate", faults(R"({"kind": "noise"})"), "faults.rules[0]", S("'bitErrorRate' is missing"));
    row("noise rate too high", faults(R"({"kind": "noise", "bitErrorRate": 0.6})"), "faults.rules[0].bitErrorRate",
        S("0.6 is beyond 0.5"));
    row("noise direction", faults(R"({"kind": "noise", "bitErrorRate": 0.001, "on": "line"})"), "faults.rules[0].on",
        S("'line' is not a direction: expected both, request or answer"));

    // Unknown units and device limits
    row("unknownUnit word", R"({"name": "t", "unknownUnit": "answer", "units": [{"id": 1}]})", "unknownUnit",
        S("'answer' is not one of first, exception, silent, auto"));
    row("limits unknown key", R"({"name": "t", "limits": {"gapMs": 5}, "units": [{"id": 1}]})", "limits",
        S("unknown key 'gapMs': expected one of minGapMs, tooSoon, maxClients, extraClients, maxQuantity, warmUpMs, closesAfterAnswer"));
    row("limits gap negative", R"({"name": "t", "limits": {"minGapMs": -1}, "units": [{"id": 1}]})", "limits.minGapMs",
        S("-1 is below 0"));
    row("limits tooSoon word", R"({"name": "t", "limits": {"minGapMs": 5, "tooSoon": "later"}, "units": [{"id": 1}]})",
        "limits.tooSoon", S("'later' is not one of busy, silent"));
    row("limits tooSoon without gap", R"({"name": "t", "limits": {"tooSoon": "silent"}, "units": [{"id": 1}]})",
        "limits.tooSoon", S("'tooSoon' needs 'minGapMs' (the gap it is about)"));
    row("limits clients 0", R"({"name": "t", "limits": {"maxClients": 0}, "units": [{"id": 1}]})", "limits.maxClients",
        S("0 is below 1"));
    row("limits extraClients word", R"({"name": "t", "limits": {"maxClients": 1, "extraClients": "queue"}, "units": [{"id": 1}]})",
        "limits.extraClients", S("'queue' is not one of refuse, dropOldest"));
    row("limits extraClients without max", R"({"name": "t", "limits": {"extraClients": "dropOldest"}, "units": [{"id": 1}]})",
        "limits.extraClients", S("'extraClients' needs 'maxClients' (how many clients are too many)"));
    row("limits quantity over the spec", R"({"name": "t", "limits": {"maxQuantity": {"0x03": 126}}, "units": [{"id": 1}]})",
        "limits.maxQuantity.0x03", S("126 is beyond 125"));
    row("limits quantity of 06", R"({"name": "t", "limits": {"maxQuantity": {"0x06": 1}}, "units": [{"id": 1}]})",
        "limits.maxQuantity.0x06",
        S("function 0x06 has no quantity to limit: expected one of 0x01, 0x02, 0x03, 0x04, 0x0F, 0x10, 0x17"));
    row("limits quantity key", R"({"name": "t", "limits": {"maxQuantity": {"read": 1}}, "units": [{"id": 1}]})",
        "limits.maxQuantity.read", S("'read' is not a function code: expected hex text such as \"0x03\""));
    // Delimited protocols
    const auto line = [](const char *rules) {
        return QByteArray(R"({"name": "t", "units": [{"id": 1}], "delimited": {"rules": [)") + rules + "]}}";
    };
    row("delimited rules empty", R"({"name": "t", "units": [{"id": 1}], "delimited": {"rules": []}})", "delimited.rules",
        S("the list is empty: a delimited protocol needs at least one rule"));
    row("delimited unknown key", R"({"name": "t", "units": [{"id": 1}], "delimited": {"rule": []}})", "delimited",
        S("unknown key 'rule': expected one of unitCapture, rules, script"));
    row("delimited bad pattern", line(R"({"request": "\$(?<unit>0[12]R#", "answer": "x"})"), "delimited.rules[0].request",
        S("not a regular expression: missing closing parenthesis at character 17"));
    row("delimited answer missing", line(R"({"request": "a"})"), "delimited.rules[0]",
        S("'answer' is missing: give the answer's text, or null for no answer"));
    row("delimited answer a number", line(R"({"request": "a", "answer": 5})"), "delimited.rules[0].answer",
        S("expected the answer's text such as \"${unit} {holding:0-7} #\", or null, found the number 5"));
    row("delimited unknown capture", line(R"({"request": "\\$(?<unit>0[12])R#", "answer": "${slave} #"})"),
        "delimited.rules[0].answer", S("{slave} is not a capture of the request pattern: expected one of unit"));
    row("delimited unknown table", line(R"({"request": "a", "answer": "{registers:0-7}"})"), "delimited.rules[0].answer",
        S("character 1: 'registers' is not a table: expected coils, discrete, input or holding"));
    row("delimited range reversed", line(R"({"request": "a", "answer": "{holding:7-0}"})"), "delimited.rules[0].answer",
        S("character 1: range 7-0 ends before it starts"));
    row("delimited brace open", line("{\"request\": \"a\", \"answer\": \"{holding:0\"}") /* a normal literal: moc counts braces in raw strings */, "delimited.rules[0].answer",
        S("character 1: '{' is not closed (write {{ for a brace)"));
    row("delimited write to input", line(R"({"request": "a", "answer": null, "writes": [{"table": "input", "address": 0, "value": 1}]})"),
        "delimited.rules[0].writes[0].table", S("'input' cannot be written: expected coils or holding"));
    row("delimited write value a table", line(R"({"request": "(?<b>.)W", "answer": null, "writes": [{"table": "coils", "address": "{b}", "value": "{coils:0}"}]})"),
        "delimited.rules[0].writes[0].value", S("expected a capture such as {bit}, not a table's values"));

    row("limits warm-up text", R"({"name": "t", "limits": {"warmUpMs": "1s"}, "units": [{"id": 1}]})", "limits.warmUpMs",
        S("expected a number, found a string \"1s\""));
}

inline void addEncodingRows()
{
    QTest::addColumn<QByteArray>("entry");
    QTest::addColumn<QList<quint16>>("registers");
    auto row = [](const char *name, const char *entry, QList<quint16> regs) {
        QTest::newRow(name) << QByteArray(entry) << regs;
    };
    row("42F6 E979 f32 123.456", R"({"address": 0, "type": "f32", "value": 123.456})", {0x42F6, 0xE979});
    row("E979 42F6 f32-cdab 123.456", R"({"address": 0, "type": "f32-cdab", "value": 123.456})", {0xE979, 0x42F6});
    row("F642 79E9 f32-badc", R"({"address": 0, "type": "f32-badc", "value": 123.456})", {0xF642, 0x79E9});
    row("5678 1234 u32-cdab", R"({"address": 0, "type": "u32-cdab", "value": 305419896})", {0x5678, 0x1234});
    row("FFFF FFFE i32 -2", R"({"address": 0, "type": "i32", "value": -2})", {0xFFFF, 0xFFFE});
    row("FF83 i16 scale 0.1 -12.5", R"({"address": 0, "type": "i16", "scale": 0.1, "value": -12.5})", {0xFF83});
    // Strings of N characters, NUL or space padded, in either byte order
    row("string MB1 nul padded", R"({"address": 0, "type": "ascii", "length": 6, "value": "MB1"})", {0x4D42, 0x3100, 0x0000});
    row("string MB1 space padded", R"({"address": 0, "type": "ascii", "length": 6, "padding": "space", "value": "MB1"})",
        {0x4D42, 0x3120, 0x2020});
    row("string odd length", R"({"address": 0, "type": "ascii", "length": 3, "padding": "space", "value": "AB"})",
        {0x4142, 0x2020});
    row("string byte swapped", R"({"address": 0, "type": "ascii-ba", "length": 4, "value": "ABCD"})", {0x4241, 0x4443});
    // A sentinel as the initial value, given raw
    row("i16 0x8000 not implemented", R"({"address": 0, "type": "i16", "notImplemented": "0x8000", "value": "0x8000"})",
        {0x8000});
    row("2C3D u16 scale 0.01 offset 900", R"({"address": 0, "scale": 0.01, "offset": 900, "value": 1013.25})", {11325});
    row("0004 u16 rounds 3.6", R"({"address": 0, "value": 3.6})", {4});
    row("4009 21FB 5444 2D18 f64 pi", R"({"address": 0, "type": "f64", "value": 3.141592653589793})",
        {0x4009, 0x21FB, 0x5444, 0x2D18});
    row("FFFF hex raw text", R"({"address": 0, "type": "hex", "value": "0xFFFF"})", {0xFFFF});
    row("FFFF i16 raw text", R"({"address": 0, "type": "i16", "scale": 10, "value": "0xFFFF"})", {0xFFFF});
    row("4D42 5343 ascii", R"({"address": 0, "type": "ascii", "values": ["MB", "SC"]})", {0x4D42, 0x5343});
    row("0007 0007 0007 fill", R"({"address": 0, "count": 3, "value": 7})", {7, 7, 7});
    row("0001 0002 0000 padded", R"({"address": 0, "count": 3, "values": [1, 2]})", {1, 2, 0});
    row("0000 0000 f32 count 2 no value", R"({"address": 0, "type": "f32"})", {0, 0});
    row("1234 5678 9ABC DEF0 u64 raw", R"({"address": 0, "type": "u64", "value": "0x123456789ABCDEF0"})",
        {0x1234, 0x5678, 0x9ABC, 0xDEF0});
}

} // namespace profilecases
