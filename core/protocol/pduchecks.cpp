#include "pduchecks.h"
#include "quantitylimits.h"

#include "functioncode.h"

#include <cstring>

namespace mbscope::pdu::checks {

namespace {

const char *const kMissingKey = "modbus.missing";
const char *const kMissingName = QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes");

// The missing field itself: from pduOffset (clamped into the PDU) to its end, showing any partial
// bytes, flagged with message.
int missingField(const PduContext &ctx, int parent, int pduOffset, const QString &message)
{
    const int from = qBound(0, pduOffset, qMax(ctx.length, 0));
    const int have = qMax(0, ctx.length - from);
    const int f = ctx.addChild(parent, kMissingKey, kMissingName, from, have, 0,
                               have > 0 ? ValueFormat::Bytes : ValueFormat::None);
    ctx.tree.flag(f, Severity::Error, message);
    return f;
}

QString moreBytes(int n, bool atLeast)
{
    return QStringLiteral("expected %1%2").arg(atLeast ? QStringLiteral("at least ") : QString(),
                                               amount(n, "more byte", "more bytes"));
}

// "Output address" -> "output address", but "AND mask" stays as it is.
QString lowerFirst(const QString &name)
{
    if (name.size() >= 2 && name.at(0).isUpper() && name.at(1).isLower())
        return name.at(0).toLower() + name.mid(1);
    return name;
}

} // namespace

QString amount(qint64 n, const char *singular, const char *plural)
{
    return QString::number(n) + QLatin1Char(' ') + QLatin1String(n == 1 ? singular : plural);
}

QString valueText(quint64 value, ValueFormat format, int bytes)
{
    const int digits = 2 * qBound(1, bytes, 8);
    switch (format) {
    case ValueFormat::Hex:
        return hex(value, digits);
    case ValueFormat::DecimalHex:
        return QString::number(value) + QStringLiteral(" (") + hex(value, digits) + QLatin1Char(')');
    case ValueFormat::Bytes: {
        QString text;
        for (int i = qBound(1, bytes, 8) - 1; i >= 0; --i) {
            if (!text.isEmpty())
                text += QLatin1Char(' ');
            text += hexDigits((value >> (8 * i)) & 0xFF, 2);
        }
        return text;
    }
    case ValueFormat::None:
    case ValueFormat::Decimal:
    case ValueFormat::Ascii:
    case ValueFormat::Bit:
    default:
        break;
    }
    return QString::number(value);
}

QString functionLabel(const PduContext &ctx)
{
    return QString::fromLatin1(functionName(ctx.function()));
}

int missing(const PduContext &ctx, int parent, int pduOffset, int pduSize, bool atLeast, const char *what)
{
    return missingField(ctx, parent, pduOffset,
                        QStringLiteral("missing: %1; %2")
                            .arg(QLatin1String(what), moreBytes(qMax(1, pduSize - ctx.length), atLeast)));
}

int missingData(const PduContext &ctx, int parent, int from, int countStart, int countEnd, const char *counter)
{
    const int announced = countEnd - countStart;
    const int present = qBound(0, ctx.length - countStart, announced);
    return missingField(ctx, parent, from,
                        QStringLiteral("missing: %1 %2 announces %3 but only %4 present; %5")
                            .arg(QLatin1String(counter), QString::number(announced),
                                 amount(announced, "data byte", "data bytes"),
                                 present == 1 ? QStringLiteral("1 is") : QString::number(present) + QStringLiteral(" are"),
                                 moreBytes(countEnd - ctx.length, false)));
}

bool trailing(const PduContext &ctx, int pduEnd)
{
    if (ctx.length <= pduEnd)
        return false;
    const int n = ctx.length - pduEnd;
    const int f = ctx.add("modbus.trailing", QT_TRANSLATE_NOOP("mbscope::Field", "Unexpected bytes"), pduEnd, n, 0, ValueFormat::Bytes);
    ctx.tree.flag(f, Severity::Error,
                  QStringLiteral("%1 after the end of the PDU: it should be %2 long, %3 are present")
                      .arg(amount(n, "byte", "bytes"), amount(pduEnd, "byte", "bytes"), QString::number(ctx.length)));
    return true;
}

int countedFields(const PduContext &ctx, const Slot *layout, int count, int *indexes, const char *tooSmall)
{
    int fixed = 0;
    for (int i = 1; i < count; ++i)
        fixed += layout[i].size;
    if (!addFixed(ctx, ctx.parent, 1, layout, 1, indexes, 2 + fixed, true))
        return -1;
    const int byteCount = ctx.byte(1);
    if (byteCount < fixed) {
        ctx.tree.flag(indexes[0], Severity::Error,
                      QStringLiteral("byte count %1 is too small: %2")
                          .arg(QString::number(byteCount), QLatin1String(tooSmall)));
    }
    const int end = 2 + qMax(byteCount, fixed);
    if (!addFixed(ctx, ctx.parent, 2, layout + 1, count - 1, indexes + 1, end, byteCount < fixed))
        return -1;
    return end;
}

bool serialLineResponse(const PduContext &ctx, const QString &note)
{
    ctx.tree.flag(functionField(ctx), Severity::Info, note);
    if (isResponse(ctx))
        return true;
    trailing(ctx, 1);
    return false;
}

void rawData(const PduContext &ctx, int pduOffset, const char *key)
{
    if (ctx.length > pduOffset)
        ctx.add(key, QT_TRANSLATE_NOOP("mbscope::Field", "Data"), pduOffset, ctx.length - pduOffset, 0, ValueFormat::Bytes);
}

void countedEnd(const PduContext &ctx, int end)
{
    if (ctx.length < end)
        missingData(ctx, ctx.parent, ctx.length, 2, end);
    trailing(ctx, end);
}

bool requestUsable(const PduContext &ctx, int minSize)
{
    return ctx.request.size() >= minSize && quint8(ctx.request.at(0)) == ctx.function();
}

void checkQuantity(const PduContext &ctx, int field, int quantity, int max, const char *label)
{
    if (quantity >= 1 && quantity <= max)
        return;
    ctx.tree.flag(field, Severity::Error,
                  QStringLiteral("%1 %2 is out of range: %3 allows 1-%4 (0x0001-%5)")
                      .arg(QLatin1String(label), QString::number(quantity), functionLabel(ctx),
                           QString::number(max), hexWord(quint64(max))));
}

void checkRange(const PduContext &ctx, int field, int start, int quantity, const char *label)
{
    // V1.1b3, 4.4: data items are addressed 0-65535; a block cannot run past the last one.
    if (quantity < 1 || start + quantity <= 0x10000)
        return;
    ctx.tree.flag(field, Severity::Error,
                  QStringLiteral("range wraps past 0xFFFF: start address %1 + %2 %3 would end at address %4, "
                                 "beyond the last address 65535 (0xFFFF)")
                      .arg(QString::number(start), QLatin1String(label), QString::number(quantity),
                           QString::number(start + quantity - 1)));
}

void checkBlock(const PduContext &ctx, int field, int start, int quantity, int max, const char *label)
{
    checkQuantity(ctx, field, quantity, max, label);
    checkRange(ctx, field, start, quantity, label);
}

bool checkByteCount(const PduContext &ctx, int field, int byteCount, int needed, const char *label, int quantity,
                    bool ofRequest, const char *rule)
{
    if (byteCount == needed)
        return false;
    const QString text = ofRequest
        ? QStringLiteral("byte count %1 does not match the request: %2 %3 needs %4 (%5)")
        : QStringLiteral("byte count %1 does not match %2 %3, which needs %4 (%5)");
    ctx.tree.flag(field, Severity::Error,
                  text.arg(QString::number(byteCount), QLatin1String(label), QString::number(quantity),
                           amount(needed, "byte", "bytes"), QLatin1String(rule)));
    return true;
}

void checkEvenByteCount(const PduContext &ctx, int field, int byteCount)
{
    if (byteCount % 2 != 0) {
        ctx.tree.flag(field, Severity::Error,
                      QStringLiteral("byte count %1 is odd: registers are 2 bytes each").arg(byteCount));
    }
}

bool startAndQuantity(const PduContext &ctx, int maxQuantity)
{
    static const Slot layout[] = {
        {"modbus.start_address", QT_TRANSLATE_NOOP("mbscope::Field", "Start address"), 2, ValueFormat::DecimalHex, "start address and quantity"},
        {"modbus.quantity", QT_TRANSLATE_NOOP("mbscope::Field", "Quantity"), 2, ValueFormat::Decimal, "quantity"},
    };
    int f[2];
    if (!addFixed(ctx, ctx.parent, 1, layout, 2, f, 5, false))
        return false;
    checkBlock(ctx, f[1], ctx.u16(1), ctx.u16(3), maxQuantity, "quantity");
    trailing(ctx, 5);
    return true;
}

void registerReadResponse(const PduContext &ctx, const char *label, const char *what)
{
    constexpr int kMaxRegisters = QuantityLimits::kReadRegisters; // V1.1b3 6.3, 6.4 and the read block of 6.17
    if (!ctx.has(1)) {
        missing(ctx, ctx.parent, 1, 4, true, what);
        return;
    }
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, 1, quint64(byteCount), ValueFormat::Decimal);
    // The request starts with start address and quantity (of the read block, for 17).
    const bool known = requestUsable(ctx, 5);
    const int quantity = known ? ctx.requestU16(3) : -1;
    const bool mismatched =
        known && checkByteCount(ctx, bc, byteCount, 2 * quantity, label, quantity, true, "2 per register");
    if (!mismatched && (byteCount == 0 || byteCount > 2 * kMaxRegisters)) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is out of range: a %2 response carries 1-125 registers "
                                     "(2-250 bytes)")
                          .arg(QString::number(byteCount), functionLabel(ctx)));
    }
    checkEvenByteCount(ctx, bc, byteCount);
    registerBlock(ctx, ctx.parent, 2, 2, 2 + byteCount, known ? QT_TRANSLATE_NOOP("mbscope::Field", "Register") : QT_TRANSLATE_NOOP("mbscope::Field", "Register index"),
                  known ? int(ctx.requestU16(1)) : -1);
    trailing(ctx, 2 + byteCount);
}

void addRegisters(const PduContext &ctx, int parent, int pduOffset, int count, const char *name, int firstAddress)
{
    for (int i = 0; i < count; ++i) {
        const int at = pduOffset + 2 * i;
        if (!ctx.has(at, 2))
            return;
        const int f = ctx.addChild(parent, "modbus.register_value", name, at, 2, ctx.u16(at), ValueFormat::Decimal);
        ctx.tree.setAddress(f, firstAddress >= 0 ? firstAddress + i : i);
    }
}

void addBits(const PduContext &ctx, int parent, int pduOffset, int bits, const char *key, const char *name,
             int firstAddress)
{
    for (int i = 0; i < bits; ++i) {
        const int at = pduOffset + i / 8;
        if (!ctx.has(at))
            return;
        // V1.1b3, 6.1: the first item is the least significant bit of the first data byte.
        const quint8 bit = (ctx.byte(at) >> (i % 8)) & 1;
        const int f = ctx.addChild(parent, key, name, at, 1, bit, ValueFormat::Bit, bit ? QT_TRANSLATE_NOOP("mbscope::Field", "ON") : QT_TRANSLATE_NOOP("mbscope::Field", "OFF"));
        ctx.tree.setAddress(f, firstAddress >= 0 ? firstAddress + i : i);
    }
}

bool registerBlock(const PduContext &ctx, int parent, int dataOffset, int countStart, int countEnd,
                   const char *name, int firstAddress, int itemsEnd)
{
    const int end = itemsEnd < 0 ? countEnd : itemsEnd;
    if (end <= dataOffset)
        return false;
    const int presentEnd = qMin(end, ctx.length);
    const int count = presentEnd > dataOffset ? (presentEnd - dataOffset) / 2 : 0;
    addRegisters(ctx, parent, dataOffset, count, name, firstAddress);
    const int after = dataOffset + 2 * count;
    if (ctx.length < end) {
        missingData(ctx, parent, after, countStart, countEnd);
        return true;
    }
    if (after < end) {
        const int f = ctx.addChild(parent, "modbus.data", QT_TRANSLATE_NOOP("mbscope::Field", "Incomplete register"), after, end - after, 0,
                                   ValueFormat::Bytes);
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("%1 left over at the end of the register data: registers are 2 bytes each")
                          .arg(amount(end - after, "byte", "bytes")));
    }
    return false;
}

void bitBlock(const PduContext &ctx, int parent, int dataOffset, int byteCount, int quantity, const char *key,
              const char *name, int firstAddress)
{
    const int countEnd = dataOffset + byteCount;
    const int presentBytes = qMax(0, qMin(countEnd, ctx.length) - dataOffset);
    const bool matches = quantity > 0 && byteCount == (quantity + 7) / 8;
    if (matches) {
        addBits(ctx, parent, dataOffset, qMin(quantity, presentBytes * 8), key, name, firstAddress);
        const int used = quantity % 8;
        if (used != 0 && presentBytes == byteCount) {
            // V1.1b3, 6.1 and 6.11: the unused high bits of the last byte are padded with zeros.
            const int last = countEnd - 1;
            const quint8 pad = quint8(ctx.byte(last) >> used);
            const int f = ctx.addChild(parent, "modbus.padding_bits", QT_TRANSLATE_NOOP("mbscope::Field", "Padding bits"), last, 1, pad, ValueFormat::Hex,
                                       QT_TRANSLATE_NOOP("mbscope::Field", "unused high bits of the last data byte"));
            if (pad != 0) {
                ctx.tree.flag(f, Severity::Warning,
                              QStringLiteral("padding bits are %1, expected 0: the %2 of the last data byte "
                                             "beyond the quantity should be zero")
                                  .arg(hexByte(pad), amount(8 - used, "unused high bit", "unused high bits")));
            }
        }
    } else {
        addBits(ctx, parent, dataOffset, presentBytes * 8, key, name, firstAddress);
    }
    if (ctx.length < countEnd)
        missingData(ctx, parent, dataOffset + presentBytes, dataOffset, countEnd);
}

void checkEcho(const PduContext &ctx, int firstField, bool strict)
{
    const QByteArray &frame = ctx.tree.frame();
    for (int i = firstField; i < ctx.tree.size(); ++i) {
        const Field &f = ctx.tree.at(i);
        if (f.format == ValueFormat::None || f.length <= 0 || std::strcmp(f.key, "modbus.trailing") == 0
            || std::strcmp(f.key, kMissingKey) == 0 || std::strcmp(f.key, "modbus.data") == 0)
            continue;
        const int at = f.offset - ctx.offset;
        if (at < 0 || f.offset + f.length > frame.size())
            continue;
        if (at + f.length > ctx.request.size()) {
            if (strict) {
                ctx.tree.flag(i, Severity::Error,
                              QStringLiteral("does not match the request: the request ends before this %1; "
                                             "the response must echo the request")
                                  .arg(lowerFirst(ctx.tree.name(i))));
            }
            continue;
        }
        if (std::memcmp(frame.constData() + f.offset, ctx.request.data() + at, size_t(f.length)) == 0) {
            // Said, not only implied by silence: a write's echo that matched is the answer's point.
            ctx.tree.flag(i, Severity::Ok, QStringLiteral("matches the request"));
            continue;
        }
        quint64 requested = 0;
        for (int k = 0; k < f.length && k < 8; ++k)
            requested = (requested << 8) | quint8(ctx.request.at(at + k));
        ctx.tree.flag(i, Severity::Error,
                      QStringLiteral("does not match the request: the request's %1 is %2")
                          .arg(lowerFirst(ctx.tree.name(i)), valueText(requested, f.format, f.length)));
    }
}

bool addFixed(const PduContext &ctx, int parent, int pduOffset, const Slot *layout, int count, int *indexes,
              int pduSize, bool atLeast)
{
    int at = pduOffset;
    for (int i = 0; i < count; ++i) {
        const Slot &s = layout[i];
        if (!ctx.has(at, s.size)) {
            missing(ctx, parent, at, pduSize, atLeast, s.what);
            return false;
        }
        const quint64 value = s.size == 1 ? ctx.byte(at) : ctx.u16(at);
        indexes[i] = ctx.addChild(parent, s.key, s.name, at, s.size, value, s.format);
        at += s.size;
    }
    return true;
}

} // namespace mbscope::pdu::checks
