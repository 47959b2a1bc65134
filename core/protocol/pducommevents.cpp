// Functions 07 Read Exception Status, 0B Get Comm Event Counter and 0C Get Comm Event Log
// (MODBUS Application Protocol Specification V1.1b3, 6.7, 6.9, 6.10). All three are serial
// line only, and their requests carry no data.
//
// Keys:
//   modbus.exception_status      07 response: the status byte (Hex)
//   modbus.exception_status_bit  its 8 outputs, address 0-7 (Bit, ON/OFF)
//   modbus.status                0B/0C response: 0x0000 ready, 0xFFFF busy (Hex)
//   modbus.event_count           0B/0C response (Decimal)
//   modbus.byte_count            0C response (Decimal)
//   modbus.message_count         0C response (Decimal)
//   modbus.event                 0C response: one per event byte, address 0 = most recent (Hex,
//                                meaning the event type and its flags)
#include "pduchecks.h"
#include "pdudissector.h"

#include <array>

namespace mbscope::pdu {
namespace {

using namespace checks;

// V1.1b3, 6.10: the event byte types and their bit flags. Every byte value gets a static
// meaning, built at compile time, so the event list allocates nothing.
constexpr int kEventTextSize = 192;

struct EventTexts {
    std::array<std::array<char, kEventTextSize>, 256> text{};
};

constexpr void appendText(std::array<char, kEventTextSize> &out, int &at, const char *s)
{
    while (*s)
        out[size_t(at++)] = *s++;
}

constexpr void appendFlags(std::array<char, kEventTextSize> &out, int &at, int value, const char *const *flags)
{
    bool first = true;
    for (int bit = 0; bit < 6; ++bit) {
        if (!(value & (1 << bit)) || !flags[bit])
            continue;
        appendText(out, at, first ? ": " : ", ");
        appendText(out, at, flags[bit]);
        first = false;
    }
}

constexpr EventTexts makeEventTexts()
{
    // Receive event, bit 7 set: bits 0, 2 and 3 are not used.
    const char *const receive[7] = {nullptr, "communication error", nullptr, nullptr, "character overrun",
                                    "in listen only mode", "broadcast received"};
    // Send event, bit 7 clear and bit 6 set.
    const char *const send[6] = {"read exception sent (codes 01-03)", "abort exception sent (code 04)",
                                 "busy exception sent (codes 05-06)", "program NAK exception sent (code 07)",
                                 "write timeout", "in listen only mode"};
    EventTexts t;
    for (int v = 0; v < 256; ++v) {
        auto &out = t.text[size_t(v)];
        int at = 0;
        if (v & 0x80) {
            appendText(out, at, "Receive event");
            bool first = true;
            for (int bit = 0; bit < 7; ++bit) {
                if (!(v & (1 << bit)) || !receive[bit])
                    continue;
                appendText(out, at, first ? ": " : ", ");
                appendText(out, at, receive[bit]);
                first = false;
            }
            if (v & 0x0D)
                appendText(out, at, first ? ": unused bits set" : ", unused bits set");
        } else if (v & 0x40) {
            appendText(out, at, "Send event");
            appendFlags(out, at, v, send);
        } else if (v == 0x04) {
            appendText(out, at, "Entered listen only mode");
        } else if (v == 0x00) {
            appendText(out, at, "Communication restart");
        } else {
            appendText(out, at, "Undefined event (bits 7 and 6 clear, neither 0x00 nor 0x04)");
        }
        out[size_t(at)] = '\0';
    }
    return t;
}

constexpr EventTexts kEventTexts = makeEventTexts();

[[nodiscard]] bool isDefinedEvent(quint8 v)
{
    return (v & 0xC0) != 0 || v == 0x00 || v == 0x04;
}

// The status field s (V1.1b3 6.9), when present.
void checkStatus(const PduContext &ctx, int s, int pduOffset)
{
    if (s < 0)
        return;
    const quint16 status = ctx.u16(pduOffset);
    if (status == 0x0000) {
        ctx.tree.setMeaning(s, QT_TRANSLATE_NOOP("mbscope::Field", "Ready: no previous command is in progress"));
    } else if (status == 0xFFFF) {
        ctx.tree.setMeaning(s, QT_TRANSLATE_NOOP("mbscope::Field", "Busy: a previous command is still being processed"));
    } else {
        ctx.tree.flag(s, Severity::Error,
                      QStringLiteral("%1 is not a status: 0x0000 means ready, 0xFFFF busy (V1.1b3 6.9)")
                          .arg(hexWord(status)));
    }
}

} // namespace

void dissectReadExceptionStatus(const PduContext &ctx)
{
    if (!serialLineResponse(
            ctx, QStringLiteral("serial line only: V1.1b3 6.7 defines Read Exception Status for serial line devices")))
        return;
    static const Slot layout[] = {
        {"modbus.exception_status", QT_TRANSLATE_NOOP("mbscope::Field", "Exception status"), 1, ValueFormat::Hex, "exception status"},
    };
    int s = -1;
    if (!addFixed(ctx, ctx.parent, 1, layout, 1, &s, 2, false))
        return;
    // The meaning of each of the eight outputs is device specific (V1.1b3, 6.7).
    const quint8 status = ctx.byte(1);
    for (int bit = 0; bit < 8; ++bit) {
        const bool on = (status >> bit) & 1;
        const int b = ctx.addChild(s, "modbus.exception_status_bit", QT_TRANSLATE_NOOP("mbscope::Field", "Output"), 1, 1, on ? 1 : 0,
                                   ValueFormat::Bit, on ? QT_TRANSLATE_NOOP("mbscope::Field", "ON") : QT_TRANSLATE_NOOP("mbscope::Field", "OFF"));
        ctx.tree.setAddress(b, bit);
    }
    trailing(ctx, 2);
}

void dissectCommEventCounter(const PduContext &ctx)
{
    if (!serialLineResponse(
            ctx, QStringLiteral("serial line only: V1.1b3 6.9 defines Get Comm Event Counter for serial line devices")))
        return;
    static const Slot layout[] = {
        {"modbus.status", QT_TRANSLATE_NOOP("mbscope::Field", "Status"), 2, ValueFormat::Hex, "status and event count"},
        {"modbus.event_count", QT_TRANSLATE_NOOP("mbscope::Field", "Event count"), 2, ValueFormat::Decimal, "event count"},
    };
    int f[2] = {-1, -1};
    const bool whole = addFixed(ctx, ctx.parent, 1, layout, 2, f, 5, false);
    checkStatus(ctx, f[0], 1);
    if (whole)
        trailing(ctx, 5);
}

void dissectCommEventLog(const PduContext &ctx)
{
    if (!serialLineResponse(
            ctx, QStringLiteral("serial line only: V1.1b3 6.10 defines Get Comm Event Log for serial line devices")))
        return;
    // Byte count = 6 (status, event count, message count) + one byte per event, 0-64 events.
    static const Slot layout[] = {
        {"modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, ValueFormat::Decimal,
         "byte count, status, event count, message count and any events"},
        {"modbus.status", QT_TRANSLATE_NOOP("mbscope::Field", "Status"), 2, ValueFormat::Hex, "status, event count, message count and any events"},
        {"modbus.event_count", QT_TRANSLATE_NOOP("mbscope::Field", "Event count"), 2, ValueFormat::Decimal, "event count, message count and any events"},
        {"modbus.message_count", QT_TRANSLATE_NOOP("mbscope::Field", "Message count"), 2, ValueFormat::Decimal, "message count and any events"},
    };
    int f[4] = {-1, -1, -1, -1};
    const int end = countedFields(ctx, layout, 4, f, "status, event count and message count take 6 bytes");
    const int count = ctx.has(1) ? ctx.byte(1) : 0;
    if (count > 6 + 64) {
        ctx.tree.flag(f[0], Severity::Error,
                      QStringLiteral("byte count %1 announces %2 events: the log holds at most 64 (byte count 6-70)")
                          .arg(count).arg(count - 6));
    }
    checkStatus(ctx, f[1], 2);
    if (end < 0)
        return;
    // Events end where the byte count says, or where the PDU does if that comes first.
    for (int at = 8; at < qMin(end, ctx.length); ++at) {
        const quint8 v = ctx.byte(at);
        const int e = ctx.add("modbus.event", QT_TRANSLATE_NOOP("mbscope::Field", "Event"), at, 1, v, ValueFormat::Hex, kEventTexts.text[v].data());
        ctx.tree.setAddress(e, at - 8);
        if (!isDefinedEvent(v)) {
            ctx.tree.flag(e, Severity::Warning,
                          QStringLiteral("%1 is not an event type of V1.1b3 6.10: receive events set bit 7, send "
                                         "events bit 6, 0x04 is listen only mode and 0x00 a restart").arg(hexByte(v)));
        }
    }
    countedEnd(ctx, end);
}

} // namespace mbscope::pdu
