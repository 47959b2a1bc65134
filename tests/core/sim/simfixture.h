#pragma once

// A unit with every kind of data the simulator serves, for the SimProcessor tests.

#include "protocol/buildresult.h"
#include "protocol/dissector.h"
#include "protocol/hextext.h"
#include "sim/simunit.h"

#include <QtTest/QtTest>

#include <memory>

namespace mbscope::simtest {

// The fixture's map (every test relies on these numbers):
//   coils 0-63 writable, coil i ON when i % 3 == 0; coils 100-107 read-only, all ON
//   discrete inputs 0-31, input i ON when i is odd
//   input registers 0-9: 1000 + i
//   holding registers 0-31 writable: 10 x i; 40-47 read-only: 0xA000 + i
//   file 1: 30 records 0x0100 + r, writable; file 2: 4 records 0x0200 + r, read-only
//   FIFO at 0x04DE: 01B8 1284 (V1.1b3 6.18's example); FIFO at 0x0500: 32 registers (too many)
//   device id objects 00-06 and 0x80; server id 42, running, additional data "sim"
//   exception status 0x6D (V1.1b3 6.7's example)
inline std::unique_ptr<SimUnit> makeUnit(quint8 id = 1)
{
    auto unit = std::make_unique<SimUnit>(id);
    auto add = [&](SimTable table, int start, int count, bool writable, auto value) {
        SimRange r;
        r.table = table;
        r.start = quint16(start);
        r.count = count;
        r.writable = writable;
        for (int i = 0; i < count; ++i)
            r.values.append(quint16(value(start + i)));
        QString error;
        if (!unit->addRange(r, &error))
            qFatal("fixture range refused: %s", qPrintable(error));
    };
    add(SimTable::Coils, 0, 64, true, [](int a) { return a % 3 == 0; });
    add(SimTable::Coils, 100, 8, false, [](int) { return 1; });
    add(SimTable::DiscreteInputs, 0, 32, false, [](int a) { return a % 2; });
    add(SimTable::InputRegisters, 0, 10, false, [](int a) { return 1000 + a; });
    add(SimTable::HoldingRegisters, 0, 32, true, [](int a) { return 10 * a; });
    add(SimTable::HoldingRegisters, 40, 8, false, [](int a) { return 0xA000 + a - 40; });
    QList<quint16> file1, file2;
    for (int r = 0; r < 30; ++r)
        file1.append(quint16(0x0100 + r));
    for (int r = 0; r < 4; ++r)
        file2.append(quint16(0x0200 + r));
    unit->setFile(1, file1, true);
    unit->setFile(2, file2, false);
    unit->setFifo(0x04DE, {0x01B8, 0x1284});
    QList<quint16> tooMany;
    for (int i = 0; i < 32; ++i)
        tooMany.append(quint16(i));
    unit->setFifo(0x0500, tooMany);
    unit->setDeviceIdObject(0x00, "mbscope");
    unit->setDeviceIdObject(0x01, "SIM");
    unit->setDeviceIdObject(0x02, "1.0");
    unit->setDeviceIdObject(0x03, "https://example.invalid");
    unit->setDeviceIdObject(0x04, "Simulator");
    unit->setDeviceIdObject(0x05, "S-1");
    unit->setDeviceIdObject(0x06, "tests");
    unit->setDeviceIdObject(0x80, "extended");
    unit->setServerId("\x42");
    unit->setRunIndicator(true);
    unit->setAdditionalData("sim");
    unit->setExceptionStatus(0x6D);
    return unit;
}

// The PDU of a builder result that must be valid.
inline QByteArray pduOf(const BuildResult &result)
{
    if (!result.isValid())
        qFatal("builder refused: %s", qPrintable(result.errorString()));
    return result.pdu;
}

inline QByteArray hex(const char *text)
{
    const auto parsed = HexText::parse(QString::fromLatin1(text));
    if (!parsed.ok)
        qFatal("bad hex in a test: %s", text);
    return parsed.bytes;
}

inline QString hexOf(const QByteArray &bytes)
{
    return HexText::format(bytes);
}

// The response as mbscope's dissector sees it, matched with its request: no error expected.
inline bool dissectsCleanly(const QByteArray &request, const QByteArray &response, QString *why)
{
    DissectOptions options;
    options.framing = Framing::Pdu;
    options.direction = Direction::Response;
    options.request = request;
    const Dissection d = Dissector::dissect(response, options);
    if (d.isValid())
        return true;
    for (int i = 0; i < d.fields.size(); ++i) {
        if (d.fields.at(i).severity >= Severity::Error)
            *why = d.fields.name(i) + QStringLiteral(": ") + d.fields.at(i).message;
    }
    return false;
}

} // namespace mbscope::simtest
