#pragma once

// Private helpers shared by the PDU dissectors (core/protocol/pdu*.cpp), data access and
// diagnostics alike. Not part of the core's API: include only from core/protocol/pdu*.cpp.
//
// A PDU that ends early gets one field, modbus.missing ("Missing bytes", error), where it ends:
// it covers any partial bytes and its message names every field still absent and how many more
// bytes the PDU needs ("missing: quantity; expected 2 more bytes"), as frame.missing does for a
// frame. Bytes after the PDU's end get one modbus.trailing field.

#include "hexformat.h"
#include "pducontext.h"

#include <QtCore/QString>

namespace mbscope::pdu::checks {

// One fixed-size field of a PDU layout. what names this field and everything after it, for the
// message of a PDU cut short here ("quantity, byte count and register values").
struct Slot {
    const char *key;
    const char *name;
    int size; // 1 or 2 bytes, big-endian
    ValueFormat format;
    const char *what;
};

// Adds layout[0..count) from pduOffset on under parent, writing each field's index to indexes.
// At the first slot not wholly present it adds one missing field instead and returns false.
// pduSize is the size the PDU should reach; atLeast says it is only a lower bound.
bool addFixed(const PduContext &ctx, int parent, int pduOffset, const Slot *layout, int count,
              int *indexes, int pduSize, bool atLeast);

// Adds the field for a PDU cut short at pduOffset (covering any partial bytes up to ctx.length):
// "missing: <what>; expected N more bytes" (or "at least N").
int missing(const PduContext &ctx, int parent, int pduOffset, int pduSize, bool atLeast, const char *what);

// Adds the field for data announced by a count field (counter: "byte count", "object length")
// but cut short: from is where the absent (or partial) item starts, countStart..countEnd the
// bytes the count covers.
int missingData(const PduContext &ctx, int parent, int from, int countStart, int countEnd,
                const char *counter = "byte count");

// Flags bytes after pduEnd as modbus.trailing (error). Returns true when there were any.
bool trailing(const PduContext &ctx, int pduEnd);

// A response whose byte count (PDU offset 1, layout[0]) covers fixed fields (layout[1..count))
// then data of its own length: 0C and 11 (V1.1b3 6.10, 6.13). Adds the byte count and the fixed
// fields, flags a byte count too small for them ("byte count 1 is too small: <tooSmall>") and
// returns where the PDU should end, or -1 when it ends before the fixed fields do.
int countedFields(const PduContext &ctx, const Slot *layout, int count, int *indexes, const char *tooSmall);
// After the data of countedFields: the missing field when the PDU ends before end, then trailing.
void countedEnd(const PduContext &ctx, int end);

// 07, 0B, 0C and 11 (V1.1b3 6.7, 6.9, 6.10, 6.13) are serial line only: notes that on the
// function code (note is a literal, so nothing allocates). Their requests carry no data: for a
// request, flags any bytes after the function code and returns false; for a response, true.
bool serialLineResponse(const PduContext &ctx, const QString &note);

// Shows the bytes from pduOffset to the end of the PDU raw, as key (codes whose data the
// specification leaves open, reserved sub-functions and MEI types).
void rawData(const PduContext &ctx, int pduOffset, const char *key = "modbus.data");

// The function code field: the dispatch (pdu::dissect) adds it just before calling a family's
// dissector.
[[nodiscard]] inline int functionField(const PduContext &ctx) { return ctx.tree.size() - 1; }

// The matching request when it is for the same function and holds at least minSize bytes.
[[nodiscard]] bool requestUsable(const PduContext &ctx, int minSize);
[[nodiscard]] inline bool isResponse(const PduContext &ctx) { return ctx.direction == Direction::Response; }

// Quantity limits (V1.1b3, 6.x tables): flags field when quantity is outside 1..max.
// label is "quantity", "read quantity", ...
void checkQuantity(const PduContext &ctx, int field, int quantity, int max, const char *label);
// Flags field when start + quantity runs past address 0xFFFF.
void checkRange(const PduContext &ctx, int field, int start, int quantity, const char *label);
// Both of the above: a block of quantity items from start.
void checkBlock(const PduContext &ctx, int field, int start, int quantity, int max, const char *label);

// Flags field when byteCount is not the needed bytes that quantity calls for; rule says why
// ("2 per register"). ofRequest: the quantity is the matching request's. Returns true when flagged.
bool checkByteCount(const PduContext &ctx, int field, int byteCount, int needed, const char *label, int quantity,
                    bool ofRequest, const char *rule);
// Flags field when the byte count of register data is odd.
void checkEvenByteCount(const PduContext &ctx, int field, int byteCount);

// Start address and quantity, checked against 1..maxQuantity and the end of the address space,
// then trailing bytes: 01-04 requests and 0F/10 responses (V1.1b3 6.1-6.4, 6.11, 6.12).
// Returns false when the PDU ends first.
bool startAndQuantity(const PduContext &ctx, int maxQuantity);
// Byte count and registers of a register read response (03, 04, 17: V1.1b3 6.3, 6.4, 6.17),
// checked against the request's quantity when it is known. label names that quantity
// ("read quantity"); what is the missing text for a PDU that ends after the function code.
void registerReadResponse(const PduContext &ctx, const char *label, const char *what);

// Items. An address < 0 means unknown: items are then numbered from 0 by index.
void addRegisters(const PduContext &ctx, int parent, int pduOffset, int count, const char *name,
                  int firstAddress);
void addBits(const PduContext &ctx, int parent, int pduOffset, int bits, const char *key,
             const char *name, int firstAddress);

// The data of a register block: the bytes countStart..countEnd announced by a byte count,
// registers from dataOffset to itemsEnd (default countEnd; less for one file sub-response).
// Shows every whole register present, then a field for an odd byte left over, or the missing
// field when the PDU ends early (returns true then).
bool registerBlock(const PduContext &ctx, int parent, int dataOffset, int countStart, int countEnd,
                   const char *name, int firstAddress, int itemsEnd = -1);
// The data of a bit block (01/02 responses, 0F requests). quantity < 0: unknown, show every bit
// of the bytes present. With a quantity whose byte count matches, shows quantity bits and the
// padding bits of the last byte.
void bitBlock(const PduContext &ctx, int parent, int dataOffset, int byteCount, int quantity,
              const char *key, const char *name, int firstAddress);

// Compares every value field from firstField on with the request's bytes at the same PDU
// offsets, flagging each mismatch with the request's value. strict: a field the request does
// not have is a mismatch too (15 echoes the whole request).
void checkEcho(const PduContext &ctx, int firstField, bool strict);

// Text for messages only (allocates): "121 (0x0079)", "0xFF00", "3 bytes" (hex: hexformat.h).
[[nodiscard]] QString valueText(quint64 value, ValueFormat format, int bytes);
[[nodiscard]] QString amount(qint64 n, const char *singular, const char *plural);
[[nodiscard]] QString functionLabel(const PduContext &ctx); // "Read Coils"

} // namespace mbscope::pdu::checks
