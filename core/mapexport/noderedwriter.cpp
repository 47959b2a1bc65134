#include "noderedwriter.h"

#include <algorithm>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

// The function node's body: msg.payload is the registers (or bits) modbus-read answered; POINTS
// says where each value lies in them and how to read it.
const char *const kConvert = R"JS(// Written by mbscope export-map: converts the block's registers into its values.
const points = POINTS;
const regs = msg.payload;
const out = {};
function bytesOf(off, n, order) {
    let words = [];
    for (let i = 0; i < n; i++) {
        const r = Number(regs[off + i]);
        words.push([(r >> 8) & 0xFF, r & 0xFF]);
    }
    if (order === 'CDAB' || order === 'DCBA') words.reverse();
    if (order === 'BADC' || order === 'DCBA') words = words.map(w => [w[1], w[0]]);
    return new Uint8Array([].concat(...words));
}
for (const p of points) {
    if (p.type === 'bit') { out[p.name] = regs[p.offset] ? 1 : 0; continue; }
    const bytes = bytesOf(p.offset, p.registers, p.order);
    if (p.type === 'string') {
        let s = '';
        for (let i = 0; i < p.length; i++) s += String.fromCharCode(bytes[i]);
        out[p.name] = s.replace(p.space ? /[ \0]+$/ : /\0+$/, '');
        continue;
    }
    const v = new DataView(bytes.buffer);
    let pattern = 0n;
    for (const b of bytes) pattern = (pattern << 8n) | BigInt(b);
    let raw;
    switch (p.type) {
    case 'i16': raw = v.getInt16(0); break;
    case 'u32': raw = v.getUint32(0); break;
    case 'i32': raw = v.getInt32(0); break;
    case 'u64': raw = Number(v.getBigUint64(0)); break;
    case 'i64': raw = Number(v.getBigInt64(0)); break;
    case 'f32': raw = v.getFloat32(0); break;
    case 'f64': raw = v.getFloat64(0); break;
    default: raw = v.getUint16(0);
    }
    if ((p.na !== undefined && pattern === BigInt(p.na)) || (p.nan && Number.isNaN(raw))) { out[p.name] = null; continue; }
    out[p.name] = raw * p.scale + p.add;
    if (p.enums) out[p.name + '_text'] = p.enums[String(raw)] ?? null;
    if (p.bits) {
        const named = {};
        for (const [bit, name] of Object.entries(p.bits)) named[name] = ((pattern >> BigInt(bit)) & 1n) === 1n;
        out[p.name + '_bits'] = named;
    }
}
msg.payload = out;
return msg;
)JS";

QString typeOf(const MapPoint &p)
{
    if (p.isBit())
        return QStringLiteral("bit");
    if (p.isString())
        return QStringLiteral("string");
    switch (p.format.type()) {
    case RegisterType::Int16: return QStringLiteral("i16");
    case RegisterType::UInt32: return QStringLiteral("u32");
    case RegisterType::Int32: return QStringLiteral("i32");
    case RegisterType::UInt64: return QStringLiteral("u64");
    case RegisterType::Int64: return QStringLiteral("i64");
    case RegisterType::Float32: return QStringLiteral("f32");
    case RegisterType::Float64: return QStringLiteral("f64");
    default: return QStringLiteral("u16");
    }
}

QString orderOf(const MapPoint &p)
{
    switch (p.format.order()) {
    case RegisterOrder::ABCD: return QStringLiteral("ABCD");
    case RegisterOrder::CDAB: return QStringLiteral("CDAB");
    case RegisterOrder::BADC: return QStringLiteral("BADC");
    case RegisterOrder::DCBA: return QStringLiteral("DCBA");
    }
    return QStringLiteral("ABCD");
}

QString readDataType(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return QStringLiteral("Coil");
    case SimTable::DiscreteInputs: return QStringLiteral("Input");
    case SimTable::InputRegisters: return QStringLiteral("InputRegister");
    case SimTable::HoldingRegisters: return QStringLiteral("HoldingRegister");
    }
    return QStringLiteral("HoldingRegister");
}

QJsonObject pointJson(const MapPoint &p, int offset)
{
    QJsonObject o{{QStringLiteral("name"), p.name},
                  {QStringLiteral("offset"), offset},
                  {QStringLiteral("registers"), p.registers},
                  {QStringLiteral("type"), typeOf(p)},
                  {QStringLiteral("order"), orderOf(p)},
                  {QStringLiteral("scale"), p.scale},
                  {QStringLiteral("add"), p.offset}};
    if (p.isString()) {
        o.insert(QStringLiteral("length"), p.stringLength);
        o.insert(QStringLiteral("space"), p.spacePadded);
    }
    if (p.notImplemented)
        o.insert(QStringLiteral("na"), QStringLiteral("0x%1").arg(*p.notImplemented, 0, 16));
    if (p.notImplementedNaN)
        o.insert(QStringLiteral("nan"), true);
    if (!p.enumNames.isEmpty()) {
        QJsonObject enums;
        for (auto it = p.enumNames.cbegin(); it != p.enumNames.cend(); ++it)
            enums.insert(QString::number(it.key()), it.value());
        o.insert(QStringLiteral("enums"), enums);
    }
    if (!p.bitNames.isEmpty()) {
        QJsonObject bits;
        for (auto it = p.bitNames.cbegin(); it != p.bitNames.cend(); ++it)
            bits.insert(QString::number(it.key()), MapPoint::slug(it.value()).isEmpty() ? it.value() : MapPoint::slug(it.value()));
        o.insert(QStringLiteral("bits"), bits);
    }
    return o;
}

} // namespace

QString NodeRedWriter::write(const MapExportInput &input)
{
    int next = 0;
    auto id = [&next]() { return QStringLiteral("6d627363%1").arg(++next, 8, 16, QLatin1Char('0')); };
    QJsonArray flow;
    const QString tab = id();
    flow.append(QJsonObject{{QStringLiteral("id"), tab},
                            {QStringLiteral("type"), QStringLiteral("tab")},
                            {QStringLiteral("label"), input.name},
                            {QStringLiteral("disabled"), false},
                            {QStringLiteral("info"), QStringLiteral("Written by mbscope export-map from %1").arg(input.source)}});
    const QString client = id();
    const LinkUrl &e = input.endpoint;
    QJsonObject c{{QStringLiteral("id"), client},
                  {QStringLiteral("type"), QStringLiteral("modbus-client")},
                  {QStringLiteral("name"), input.name},
                  {QStringLiteral("clienttype"), e.isSerial() ? QStringLiteral("serial") : QStringLiteral("tcp")},
                  {QStringLiteral("bufferCommands"), true},
                  {QStringLiteral("stateLogEnabled"), false},
                  {QStringLiteral("queueLogEnabled"), false},
                  {QStringLiteral("failureLogEnabled"), true},
                  {QStringLiteral("tcpHost"), e.isSerial() ? QStringLiteral("127.0.0.1") : e.host},
                  {QStringLiteral("tcpPort"), QString::number(e.isSerial() ? 502 : e.port)},
                  {QStringLiteral("tcpType"), e.kind == LinkKind::RtuTcp ? QStringLiteral("TCP-RTU-BUFFERED") : QStringLiteral("DEFAULT")},
                  {QStringLiteral("serialPort"), e.isSerial() ? e.serial.device : QStringLiteral("/dev/ttyUSB")},
                  {QStringLiteral("serialType"), QStringLiteral("RTU-BUFFERD")},
                  {QStringLiteral("serialBaudrate"), QString::number(e.serial.baud)},
                  {QStringLiteral("serialDatabits"), QString::number(e.serial.dataBits)},
                  {QStringLiteral("serialStopbits"), QString::number(e.serial.stopBits)},
                  {QStringLiteral("serialParity"), e.serial.parity == 'E' ? QStringLiteral("even")
                                                   : e.serial.parity == 'O' ? QStringLiteral("odd") : QStringLiteral("none")},
                  // The device's pace (profile limits): a serial port waits warmUpMs after it
                  // opens; a TCP connection's reads wait whole seconds (delayOnStart below).
                  {QStringLiteral("serialConnectionDelay"), QString::number(std::max(100, input.warmUpMs))},
                  {QStringLiteral("unit_id"), input.points.isEmpty() ? 1 : int(input.points.constFirst().unitId)},
                  // Between an answer and the next request: the device's gap (1 ms: the node's least).
                  {QStringLiteral("commandDelay"), std::max(1, input.minGapMs)},
                  {QStringLiteral("clientTimeout"), input.timeoutMs},
                  {QStringLiteral("reconnectOnTimeout"), true},
                  {QStringLiteral("reconnectTimeout"), 2000},
                  // Units in turn when the device needs a gap: in parallel, each unit's queue
                  // would send regardless of the others'.
                  {QStringLiteral("parallelUnitIdsAllowed"), input.minGapMs == 0}};
    // Reads wait after each connection opens: whole seconds, the node's unit.
    const bool delayOnStart = input.warmUpMs > 0 && !e.isSerial();
    flow.append(c);

    int y = 60;
    for (const ExportBlock &b : input.blocks) {
        const QString read = id();
        const QString convert = id();
        const QString debug = id();
        const QString what = QStringLiteral("unit %1 %2 %3-%4")
                                 .arg(int(b.unitId))
                                 .arg(input.points.at(b.points.constFirst()).tableKey())
                                 .arg(b.start)
                                 .arg(b.start + b.quantity - 1);
        flow.append(QJsonObject{{QStringLiteral("id"), read},
                                {QStringLiteral("type"), QStringLiteral("modbus-read")},
                                {QStringLiteral("z"), tab},
                                {QStringLiteral("name"), QStringLiteral("read ") + what},
                                {QStringLiteral("topic"), what},
                                {QStringLiteral("showStatusActivities"), false},
                                {QStringLiteral("logIOActivities"), false},
                                {QStringLiteral("showErrors"), true},
                                {QStringLiteral("showWarnings"), true},
                                {QStringLiteral("unitid"), QString::number(b.unitId)},
                                {QStringLiteral("dataType"), readDataType(b.table)},
                                {QStringLiteral("adr"), QString::number(b.start)},
                                {QStringLiteral("quantity"), QString::number(b.quantity)},
                                {QStringLiteral("rate"), QString::number(input.intervalMs)},
                                {QStringLiteral("rateUnit"), QStringLiteral("ms")},
                                {QStringLiteral("delayOnStart"), delayOnStart},
                                {QStringLiteral("startDelayTime"), delayOnStart ? QString::number((input.warmUpMs + 999) / 1000) : QString()},
                                {QStringLiteral("server"), client},
                                {QStringLiteral("useIOFile"), false},
                                {QStringLiteral("ioFile"), QString()},
                                {QStringLiteral("useIOForPayload"), false},
                                {QStringLiteral("emptyMsgOnFail"), false},
                                {QStringLiteral("x"), 180},
                                {QStringLiteral("y"), y},
                                {QStringLiteral("wires"), QJsonArray{QJsonArray{convert}, QJsonArray{}}}});
        QJsonArray points;
        for (qsizetype i : b.points) {
            const MapPoint &p = input.points.at(i);
            points.append(pointJson(p, p.address - b.start));
        }
        QString code = QString::fromUtf8(kConvert);
        code.replace(QLatin1String("POINTS"), QString::fromUtf8(QJsonDocument(points).toJson(QJsonDocument::Compact)));
        flow.append(QJsonObject{{QStringLiteral("id"), convert},
                                {QStringLiteral("type"), QStringLiteral("function")},
                                {QStringLiteral("z"), tab},
                                {QStringLiteral("name"), QStringLiteral("values of ") + what},
                                {QStringLiteral("func"), code},
                                {QStringLiteral("outputs"), 1},
                                {QStringLiteral("noerr"), 0},
                                {QStringLiteral("x"), 440},
                                {QStringLiteral("y"), y},
                                {QStringLiteral("wires"), QJsonArray{QJsonArray{debug}}}});
        flow.append(QJsonObject{{QStringLiteral("id"), debug},
                                {QStringLiteral("type"), QStringLiteral("debug")},
                                {QStringLiteral("z"), tab},
                                {QStringLiteral("name"), what},
                                {QStringLiteral("active"), true},
                                {QStringLiteral("tosidebar"), true},
                                {QStringLiteral("console"), false},
                                {QStringLiteral("tostatus"), false},
                                {QStringLiteral("complete"), QStringLiteral("payload")},
                                {QStringLiteral("targetType"), QStringLiteral("msg")},
                                {QStringLiteral("x"), 700},
                                {QStringLiteral("y"), y},
                                {QStringLiteral("wires"), QJsonArray{}}});
        y += 60;
    }
    return QString::fromUtf8(QJsonDocument(flow).toJson(QJsonDocument::Indented));
}

} // namespace mbscope
