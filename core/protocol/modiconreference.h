#pragma once

#include "functioncode.h"

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>
#include <span>

namespace mbscope {

// The four primary tables of the Modbus data model (V1.1b3, 4.3).
enum class ModbusTable : quint8 {
    Coils,            // 0xxxx: single bits, read-write
    DiscreteInputs,   // 1xxxx: single bits, read-only
    InputRegisters,   // 3xxxx: 16-bit words, read-only
    HoldingRegisters, // 4xxxx: 16-bit words, read-write
};

struct ModiconReferenceResult;

// One data element, named the three ways people name it:
//   PDU address      0-based, what travels on the wire (V1.1b3, 4.4: "data element numbered X is
//                    addressed in the Modbus PDU X-1")
//   element number   1-based: register number, coil number, discrete input number
//   Modicon reference  the table's leading digit then the element number:
//                    five digits  00001-09999, 10001-19999, 30001-39999, 40001-49999: PDU 0-9998
//                    six digits   000001-065536, 100001-165536, 300001-365536, 400001-465536: PDU 0-65535
// So 40001 and 400001 are holding register PDU address 0, and 40122 is PDU address 121 (0x0079).
// The five-digit form cannot reach PDU addresses 9999-65535; fiveDigit() is then empty.
//
// parse() accepts, surrounding spaces ignored:
//   five digits "40122", six digits "400122", and the prefixed form T "x" N ("4x122", "4X0122",
//   "0x1", "3x301") where T is the table digit and N the element number 1-65536. Note that "0x" in
//   a reference is the coil table (0x0079 is coil number 79, PDU address 78), not hexadecimal.
// Anything else is refused with what is wrong and the range that would be right.
class ModiconReference
{
public:
    enum class Form : quint8 {
        FiveDigit, // 40122
        SixDigit,  // 400122
        Prefixed,  // 4x122
    };

    constexpr ModiconReference() = default;
    constexpr ModiconReference(ModbusTable table, quint16 address) : m_address(address), m_table(table) {}

    [[nodiscard]] constexpr ModbusTable table() const { return m_table; }
    // 0-based PDU address, as in the request.
    [[nodiscard]] constexpr quint16 address() const { return m_address; }
    // 1-based element number: address() + 1, 1-65536.
    [[nodiscard]] constexpr int number() const { return int(m_address) + 1; }
    // 0, 1, 3 or 4.
    [[nodiscard]] constexpr int tableDigit() const { return tableDigit(m_table); }
    [[nodiscard]] constexpr bool hasFiveDigitForm() const { return m_address <= 9998; }

    [[nodiscard]] QString fiveDigit() const; // "40122"; empty beyond PDU address 9998
    [[nodiscard]] QString sixDigit() const;  // "400122"
    // "PDU address 121 (0x0079), register number 122, Modicon 40122 / 400122"; beyond 9998:
    // "PDU address 10000 (0x2710), register number 10001, Modicon 410001 (no five-digit form:
    //  40001-49999 reach PDU addresses 0-9998 only)"
    [[nodiscard]] QString describe() const;

    [[nodiscard]] static ModiconReferenceResult parse(QStringView text);
    // For a PDU address of 10001 or more that reads as a five- or six-digit reference, the mistake
    // the guide describes (a manual's 40122 typed where the wire address 121 belongs):
    // "40122 looks like a Modicon reference; its PDU address is 121 (0x0079)". Empty otherwise.
    [[nodiscard]] static QString addressHint(qint64 address);
    // From a 1-based element number (1-65536), as a device manual lists it.
    [[nodiscard]] static ModiconReferenceResult fromNumber(ModbusTable table, int number);

    [[nodiscard]] static constexpr int tableDigit(ModbusTable table)
    {
        switch (table) {
        case ModbusTable::Coils: return 0;
        case ModbusTable::DiscreteInputs: return 1;
        case ModbusTable::InputRegisters: return 3;
        case ModbusTable::HoldingRegisters: return 4;
        }
        return 4;
    }
    [[nodiscard]] static const char *tableName(ModbusTable table);  // "holding registers"
    [[nodiscard]] static const char *numberName(ModbusTable table); // "register number", "coil number"
    [[nodiscard]] static constexpr bool isWritable(ModbusTable table)
    {
        return table == ModbusTable::Coils || table == ModbusTable::HoldingRegisters;
    }
    // Function codes that read or write a table (V1.1b3, 6): coils 01 / 05 0F, discrete inputs
    // 02 / none, input registers 04 / none, holding registers 03 17 / 06 10 16 17.
    [[nodiscard]] static std::span<const FunctionCode> readFunctions(ModbusTable table);
    [[nodiscard]] static std::span<const FunctionCode> writeFunctions(ModbusTable table);
    // The table a function code's addresses refer to; none for codes without a table address
    // (07, 08, 0B, 0C, 11, 14, 15, 18, 2B, user-defined, exceptions).
    [[nodiscard]] static std::optional<ModbusTable> tableOf(quint8 functionCode);

    friend constexpr bool operator==(const ModiconReference &, const ModiconReference &) = default;

private:
    quint16 m_address = 0;
    ModbusTable m_table = ModbusTable::HoldingRegisters;
};

struct ModiconReferenceResult {
    ModiconReference reference;
    ModiconReference::Form form = ModiconReference::Form::FiveDigit;
    QString error; // "'40000' is not a reference: holding registers start at 40001"; empty when ok
    bool ok = false;
};

} // namespace mbscope
