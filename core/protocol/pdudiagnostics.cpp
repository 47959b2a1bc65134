// Function 08 Diagnostics (MODBUS Application Protocol Specification V1.1b3, 6.8 and 6.8.1).
//
// Layout, request and response alike: function code, 2-byte sub-function, data (2-byte words).
// Keys:
//   modbus.subfunction          Hex, meaning the sub-function's name
//   modbus.echo_data            00 Return Query Data: the bytes to echo (Bytes)
//   modbus.restart_option       01 Restart Communications Option: 0000 keep / FF00 clear the log
//   modbus.diagnostic_register  02 response: the 16-bit diagnostic register (Hex)
//   modbus.ascii_delimiter      03: the new end-of-message character (Hex, meaning the character)
//   modbus.padding              03: the byte after the delimiter, fixed at 00 by the spec
//   modbus.counter_value        0B-12 response: the counter (Decimal, named after the counter)
//   modbus.diagnostic_data      the data word of every other sub-function (0000 in requests and in
//                               the echoes of 0A and 14), and the raw data of reserved ones (Bytes)
#include "pduchecks.h"
#include "pdudissector.h"

#include <array>

namespace mbscope::pdu {
namespace {

using namespace checks;

enum class Kind : quint8 {
    Echo,       // 00: any data, echoed
    Restart,    // 01: 0000 or FF00, echoed
    Register,   // 02: request 0000, response the diagnostic register
    Delimiter,  // 03: CHAR 00, echoed
    ListenOnly, // 04: request 0000, no response at all
    Clear,      // 0A, 14: request 0000, echoed
    Counter,    // 0B-12: request 0000, response a counter
    Reserved,   // everything else
};

struct SubFunction {
    const char *name;
    const char *valueName; // name of the response's value field
    Kind kind;
};

SubFunction subFunction(quint16 code)
{
    switch (code) {
    case 0x00: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Query Data"), QT_TRANSLATE_NOOP("mbscope::Field", "Echo data"), Kind::Echo};
    case 0x01: return {QT_TRANSLATE_NOOP("mbscope::Field", "Restart Communications Option"), QT_TRANSLATE_NOOP("mbscope::Field", "Restart option"), Kind::Restart};
    case 0x02: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Diagnostic Register"), QT_TRANSLATE_NOOP("mbscope::Field", "Diagnostic register"), Kind::Register};
    case 0x03: return {QT_TRANSLATE_NOOP("mbscope::Field", "Change ASCII Input Delimiter"), QT_TRANSLATE_NOOP("mbscope::Field", "ASCII input delimiter"), Kind::Delimiter};
    case 0x04: return {QT_TRANSLATE_NOOP("mbscope::Field", "Force Listen Only Mode"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::ListenOnly};
    case 0x0A: return {QT_TRANSLATE_NOOP("mbscope::Field", "Clear Counters and Diagnostic Register"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::Clear};
    case 0x0B: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Message Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Bus message count"), Kind::Counter};
    case 0x0C: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Communication Error Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Bus communication error count"), Kind::Counter};
    case 0x0D: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Exception Error Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Bus exception error count"), Kind::Counter};
    case 0x0E: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Server Message Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Server message count"), Kind::Counter};
    case 0x0F: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Server No Response Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Server no response count"), Kind::Counter};
    case 0x10: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Server NAK Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Server NAK count"), Kind::Counter};
    case 0x11: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Server Busy Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Server busy count"), Kind::Counter};
    case 0x12: return {QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Character Overrun Count"), QT_TRANSLATE_NOOP("mbscope::Field", "Bus character overrun count"), Kind::Counter};
    case 0x14: return {QT_TRANSLATE_NOOP("mbscope::Field", "Clear Overrun Counter and Flag"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::Clear};
    // V1.1b3 reserves these; older Modicon documents gave them the meanings quoted.
    case 0x13: return {QT_TRANSLATE_NOOP("mbscope::Field", "Reserved (legacy Modicon: Return IOP Overrun Count)"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::Reserved};
    case 0x15: return {QT_TRANSLATE_NOOP("mbscope::Field", "Reserved (legacy Modicon: Get/Clear Modbus Plus Statistics)"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::Reserved};
    default: return {QT_TRANSLATE_NOOP("mbscope::Field", "Reserved sub-function"), QT_TRANSLATE_NOOP("mbscope::Field", "Data"), Kind::Reserved};
    }
}

// Static names of every byte value, for the ASCII delimiter: "'A'", "LF (line feed)".
struct CharNames {
    std::array<std::array<char, 4>, 95> printable{};
};

constexpr CharNames makeCharNames()
{
    CharNames names;
    for (int i = 0; i < 95; ++i)
        names.printable[size_t(i)] = {'\'', char(0x20 + i), '\'', '\0'};
    return names;
}

constexpr CharNames kCharNames = makeCharNames();

const char *characterName(quint8 c)
{
    static const char *const control[32] = {
        "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", QT_TRANSLATE_NOOP("mbscope::Field", "BS (backspace)"), QT_TRANSLATE_NOOP("mbscope::Field", "HT (tab)"),
        QT_TRANSLATE_NOOP("mbscope::Field", "LF (line feed, the default delimiter)"), "VT", QT_TRANSLATE_NOOP("mbscope::Field", "FF (form feed)"), QT_TRANSLATE_NOOP("mbscope::Field", "CR (carriage return)"), "SO", "SI",
        "DLE", QT_TRANSLATE_NOOP("mbscope::Field", "DC1 (XON)"), "DC2", QT_TRANSLATE_NOOP("mbscope::Field", "DC3 (XOFF)"), "DC4", "NAK", "SYN", "ETB", "CAN", "EM", "SUB", "ESC",
        "FS", "GS", "RS", "US"};
    if (c < 0x20)
        return control[c];
    if (c == 0x20)
        return QT_TRANSLATE_NOOP("mbscope::Field", "' ' (space)");
    if (c < 0x7F)
        return kCharNames.printable[size_t(c - 0x20)].data();
    if (c == 0x7F)
        return "DEL";
    return QT_TRANSLATE_NOOP("mbscope::Field", "not an ASCII character");
}

// A matching Diagnostics request with its sub-function; a request of another function is
// already flagged by the dispatch and says nothing about this PDU's data.
[[nodiscard]] bool sameRequest(const PduContext &ctx)
{
    return ctx.request.size() >= 3 && ctx.requestByte(0) == 0x08;
}

// Adds one 2-byte field at PDU offset 3, the data word every sub-function but 00 and 03 carries,
// and flags bytes after it. Returns the field, or -1 when the PDU ends first.
int addDataWord(const PduContext &ctx, const char *key, const char *name, ValueFormat format, const char *what)
{
    const Slot slot{key, name, 2, format, what};
    int f = -1;
    if (addFixed(ctx, ctx.parent, 3, &slot, 1, &f, 5, false))
        trailing(ctx, 5);
    return f;
}

// Data word of the request of a sub-function that takes none (V1.1b3, 6.8.1: "0000").
void addZeroData(const PduContext &ctx, const SubFunction &sub, bool echo)
{
    const int d = addDataWord(ctx, "modbus.diagnostic_data", "Data", ValueFormat::Hex, "data");
    if (d < 0)
        return;
    if (ctx.u16(3) != 0) {
        ctx.tree.flag(d, Severity::Error,
                      QStringLiteral("%1 is not allowed: %2 %3 carries the data 0x0000")
                          .arg(hexWord(ctx.u16(3)), QString::fromLatin1(sub.name),
                               echo ? QStringLiteral("echoes the request and") : QStringLiteral("request")));
    }
}

// Flags a response whose data differs from the request's (sub-functions that echo). A fixed-size
// echo compares `bytes` bytes; a variable one (00) compares all the data.
void checkDataEcho(const PduContext &ctx, int field, int from, int bytes, bool variable = false)
{
    if (!isResponse(ctx) || !sameRequest(ctx) || ctx.requestU16(1) != ctx.u16(1))
        return;
    const int requestData = int(ctx.request.size()) - from;
    const int sent = variable ? requestData : qMin(requestData, bytes);
    const int got = qMin(bytes, ctx.length - from);
    for (int i = 0; i < qMin(sent, got); ++i) {
        if (ctx.byte(from + i) != ctx.requestByte(from + i)) {
            ctx.tree.flag(field, Severity::Error,
                          QStringLiteral("does not echo the request: data byte %1 is %2, the request sent %3")
                              .arg(from - 3 + i).arg(hexByte(ctx.byte(from + i)), hexByte(ctx.requestByte(from + i))));
            return;
        }
    }
    if (sent != got && got == bytes) {
        ctx.tree.flag(field, Severity::Error,
                      QStringLiteral("does not echo the request: %1 of data returned, the request sent %2")
                          .arg(amount(got, "byte", "bytes"), amount(qMax(sent, 0), "byte", "bytes")));
    }
}

void dissectEcho(const PduContext &ctx)
{
    const int bytes = ctx.length - 3;
    if (bytes <= 0) {
        // V1.1b3 allows any data, which includes none; the echo check still applies.
        if (isResponse(ctx) && sameRequest(ctx) && ctx.request.size() > 3 && ctx.requestU16(1) == 0) {
            const int e = ctx.add("modbus.echo_data", QT_TRANSLATE_NOOP("mbscope::Field", "Echo data"), 3, 0);
            ctx.tree.flag(e, Severity::Error,
                          QStringLiteral("missing: the request sent %1 of data to echo, none came back")
                              .arg(amount(ctx.request.size() - 3, "byte", "bytes")));
        }
        return;
    }
    const int e = ctx.add("modbus.echo_data", QT_TRANSLATE_NOOP("mbscope::Field", "Echo data"), 3, bytes, 0, ValueFormat::Bytes);
    if (bytes % 2 != 0) {
        ctx.tree.flag(e, Severity::Info,
                      QStringLiteral("odd length (%1): V1.1b3 6.8.1 gives the data as 2-byte words").arg(amount(bytes, "byte", "bytes")));
    }
    checkDataEcho(ctx, e, 3, bytes, true);
}

void dissectRestart(const PduContext &ctx)
{
    const int r = addDataWord(ctx, "modbus.restart_option", "Restart option", ValueFormat::Hex, "restart option");
    if (r < 0)
        return;
    const quint16 option = ctx.u16(3);
    if (option == 0x0000) {
        ctx.tree.setMeaning(r, QT_TRANSLATE_NOOP("mbscope::Field", "Restart, keep the communications event log"));
    } else if (option == 0xFF00) {
        ctx.tree.setMeaning(r, QT_TRANSLATE_NOOP("mbscope::Field", "Restart and clear the communications event log"));
    } else {
        ctx.tree.flag(r, Severity::Error,
                      QStringLiteral("%1 is not a restart option: 0x0000 keeps the event log, 0xFF00 clears it")
                          .arg(hexWord(option)));
    }
    checkDataEcho(ctx, r, 3, 2);
}

void dissectDelimiter(const PduContext &ctx)
{
    static const Slot layout[] = {
        {"modbus.ascii_delimiter", QT_TRANSLATE_NOOP("mbscope::Field", "ASCII input delimiter"), 1, ValueFormat::Hex, "ASCII input delimiter and padding"},
        {"modbus.padding", QT_TRANSLATE_NOOP("mbscope::Field", "Padding"), 1, ValueFormat::Hex, "padding"},
    };
    int f[2] = {-1, -1};
    const bool whole = addFixed(ctx, ctx.parent, 3, layout, 2, f, 5, false);
    const int d = f[0];
    if (d < 0)
        return;
    const quint8 c = ctx.byte(3);
    ctx.tree.setMeaning(d, characterName(c));
    // Serial Line V1.02, 2.5.2.1: ASCII frames start with ':' and carry hex digits, so either as
    // the end delimiter would cut frames apart.
    if (c == ':' || hexDigitValue(char16_t(c)) >= 0) {
        ctx.tree.flag(d, Severity::Warning,
                      QStringLiteral("%1 as the end delimiter breaks ASCII framing: ':' starts every frame and "
                                     "hex digits carry its content").arg(hexByte(c)));
    }
    checkDataEcho(ctx, d, 3, 2);
    if (!whole)
        return;
    if (ctx.byte(4) != 0) {
        ctx.tree.flag(f[1], Severity::Error,
                      QStringLiteral("%1 is not allowed: the byte after the delimiter is 0x00 (V1.1b3 6.8.1, sub-function 03)")
                          .arg(hexByte(ctx.byte(4))));
    }
    trailing(ctx, 5);
}

void dissectValue(const PduContext &ctx, const SubFunction &sub)
{
    const bool counter = sub.kind == Kind::Counter;
    if (counter)
        addDataWord(ctx, "modbus.counter_value", sub.valueName, ValueFormat::Decimal, "counter value");
    else
        addDataWord(ctx, "modbus.diagnostic_register", sub.valueName, ValueFormat::Hex, "diagnostic register");
}

} // namespace

void dissectDiagnostics(const PduContext &ctx)
{
    const int fc = functionField(ctx);
    ctx.tree.flag(fc, Severity::Info,
                  QStringLiteral("serial line only: V1.1b3 6.8 defines Diagnostics for serial line devices"));
    static const Slot layout[] = {{"modbus.subfunction", QT_TRANSLATE_NOOP("mbscope::Field", "Sub-function"), 2, ValueFormat::Hex, "sub-function and data"}};
    int s = -1;
    if (!addFixed(ctx, ctx.parent, 1, layout, 1, &s, 3, true))
        return;
    const quint16 code = ctx.u16(1);
    const SubFunction sub = subFunction(code);
    ctx.tree.setMeaning(s, sub.name);
    const bool response = isResponse(ctx);
    if (response && sameRequest(ctx) && ctx.requestU16(1) != code) {
        ctx.tree.flag(s, Severity::Error,
                      QStringLiteral("does not match the request: the request's sub-function is %1")
                          .arg(hexWord(ctx.requestU16(1))));
    }
    switch (sub.kind) {
    case Kind::Echo:
        dissectEcho(ctx);
        return;
    case Kind::Restart:
        dissectRestart(ctx);
        return;
    case Kind::Delimiter:
        dissectDelimiter(ctx);
        return;
    case Kind::Register:
    case Kind::Counter:
        if (response)
            dissectValue(ctx, sub);
        else
            addZeroData(ctx, sub, false);
        return;
    case Kind::ListenOnly:
        if (response) {
            ctx.tree.flag(s, Severity::Warning,
                          QStringLiteral("a device returns no response to Force Listen Only Mode (V1.1b3 6.8.1, "
                                         "sub-function 04): this frame is probably a request"));
        }
        addZeroData(ctx, sub, false);
        return;
    case Kind::Clear:
        addZeroData(ctx, sub, response);
        return;
    case Kind::Reserved:
        break;
    }
    ctx.tree.flag(s, Severity::Warning,
                  QStringLiteral("reserved sub-function %1: V1.1b3 6.8.1 defines 0x0000-0x0004, 0x000A-0x0012 and 0x0014; "
                                 "its data is shown raw").arg(hexWord(code)));
    rawData(ctx, 3, "modbus.diagnostic_data");
}

} // namespace mbscope::pdu
