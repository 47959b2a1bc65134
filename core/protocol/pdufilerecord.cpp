// 14 Read File Record and 15 Write File Record (MODBUS Application Protocol Specification
// V1.1b3, 6.14 and 6.15). Both requests carry a byte count and sub-requests of reference type
// (always 6), file number, record number (0-9999) and record length; 15 adds the record data and
// its normal response echoes the request. 14's response carries one sub-response per
// sub-request: a length byte, the reference type and the registers read.
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kHeader = 7;          // reference type, file number, record number, record length
constexpr int kLastRecord = 9999;   // 0x270F: a file holds records 0-9999
constexpr int kMaxPdu = 253;        // V1.1b3 4.1
constexpr quint8 kReferenceType = 6;

const char *groupKey(const PduContext &ctx)
{
    return isResponse(ctx) ? "modbus.file_subresponse" : "modbus.file_subrequest";
}

void checkReferenceType(const PduContext &ctx, int field, quint8 type)
{
    if (type == kReferenceType) {
        ctx.tree.setMeaning(field, QT_TRANSLATE_NOOP("mbscope::Field", "file record"));
        return;
    }
    ctx.tree.flag(field, Severity::Error,
                  QStringLiteral("reference type %1 is not allowed: it must be 6 (0x06)").arg(type));
}

// Adds the header fields of the sub-request at pos that lie wholly before end, checks them and
// returns the offset after the last field added (pos + 7 when the header is whole).
int subHeader(const PduContext &ctx, int group, int pos, int end)
{
    static const Slot layout[] = {
        {"modbus.reference_type", QT_TRANSLATE_NOOP("mbscope::Field", "Reference type"), 1, ValueFormat::Hex, ""},
        {"modbus.file_number", QT_TRANSLATE_NOOP("mbscope::Field", "File number"), 2, ValueFormat::Decimal, ""},
        {"modbus.record_number", QT_TRANSLATE_NOOP("mbscope::Field", "Record number"), 2, ValueFormat::DecimalHex, ""},
        {"modbus.record_length", QT_TRANSLATE_NOOP("mbscope::Field", "Record length"), 2, ValueFormat::Decimal, ""},
    };
    int at = pos;
    int f[4] = {-1, -1, -1, -1};
    for (int i = 0; i < 4; ++i) {
        const Slot &s = layout[i];
        if (at + s.size > end)
            return at;
        f[i] = ctx.addChild(group, s.key, s.name, at, s.size, s.size == 1 ? ctx.byte(at) : ctx.u16(at), s.format);
        if (i == 0) {
            checkReferenceType(ctx, f[0], ctx.byte(at));
        } else if (i == 1 && ctx.u16(at) == 0) {
            ctx.tree.flag(f[1], Severity::Warning,
                          QStringLiteral("file number 0: the specification numbers files 1-65535 (0x0001-0xFFFF)"));
        } else if (i == 2 && ctx.u16(at) > kLastRecord) {
            ctx.tree.flag(f[2], Severity::Error,
                          QStringLiteral("record number %1 is out of range: a file holds records 0-9999 "
                                         "(0x0000-0x270F)")
                              .arg(ctx.u16(at)));
        } else if (i == 3) {
            const int record = ctx.u16(pos + 3);
            const int length = ctx.u16(at);
            if (length == 0) {
                ctx.tree.flag(f[3], Severity::Warning,
                              QStringLiteral("record length 0: the sub-request %1 no registers")
                                  .arg(ctx.function() == 0x14 ? QStringLiteral("reads") : QStringLiteral("writes")));
            } else if (record <= kLastRecord && record + length > kLastRecord + 1) {
                ctx.tree.flag(f[3], Severity::Warning,
                              QStringLiteral("records %1-%2 run past record 9999, the last one in a file")
                                  .arg(record).arg(record + length - 1));
            }
        }
        at += s.size;
    }
    return at;
}

// The byte count of 14/15 requests and 15 responses, checked against the specification's range.
int byteCountField(const PduContext &ctx, int min, int max)
{
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, 1, quint64(byteCount), ValueFormat::Decimal);
    if (byteCount < min || byteCount > max) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is out of range: %2 allows %3-%4 (%5-%6)")
                          .arg(QString::number(byteCount), functionLabel(ctx), QString::number(min),
                               QString::number(max), hexByte(quint64(min)), hexByte(quint64(max))));
    }
    return bc;
}

// The header of the sub-request at pos cut short at after: either the byte count ends inside
// it, or the PDU does. Returns true when the missing field was added.
bool headerCut(const PduContext &ctx, int group, int pos, int after, int dataEnd)
{
    if (ctx.length < dataEnd) {
        missingData(ctx, group, after, 2, dataEnd);
        return true;
    }
    const int f = ctx.addChild(group, "modbus.data", QT_TRANSLATE_NOOP("mbscope::Field", "Incomplete sub-request"), after, dataEnd - after, 0,
                               dataEnd > after ? ValueFormat::Bytes : ValueFormat::None);
    ctx.tree.flag(f, Severity::Error,
                  QStringLiteral("the byte count ends %1 into a sub-request, whose header is 7 bytes")
                      .arg(amount(dataEnd - pos, "byte", "bytes")));
    return false;
}

void readRequest(const PduContext &ctx)
{
    const int bc = byteCountField(ctx, 0x07, 0xF5);
    const int byteCount = ctx.byte(1);
    if (byteCount % kHeader != 0) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is not a multiple of 7: each sub-request is 7 bytes").arg(byteCount));
    }
    const int dataEnd = 2 + byteCount;
    const int avail = qMin(dataEnd, ctx.length);
    bool reported = false;
    int registers = 0;
    int responseSize = 2;
    for (int pos = 2; pos < avail; pos += kHeader) {
        const int end = qMin(pos + kHeader, avail);
        const int g = ctx.add(groupKey(ctx), QT_TRANSLATE_NOOP("mbscope::Field", "Sub-request"), pos, end - pos);
        const int after = subHeader(ctx, g, pos, end);
        if (after < pos + kHeader) {
            reported = headerCut(ctx, g, pos, after, dataEnd);
            break;
        }
        const int length = ctx.u16(pos + 5);
        registers += length;
        responseSize += 2 + 2 * length;
    }
    if (!reported && ctx.length < dataEnd)
        missingData(ctx, ctx.parent, ctx.length, 2, dataEnd);
    // V1.1b3, 6.14: the registers asked for, with every other field of the response, must fit
    // the 253-byte PDU.
    if (responseSize > kMaxPdu) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("the sub-requests ask for %1: the response would be %2, more than the "
                                     "253 bytes a PDU holds")
                          .arg(amount(registers, "register", "registers"), amount(responseSize, "byte", "bytes")));
    }
    trailing(ctx, dataEnd);
}

void readResponse(const PduContext &ctx)
{
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, 1, quint64(byteCount), ValueFormat::Decimal);
    // V1.1b3, 6.14 tabulates the response length as 0x07-0xF5, copied from the request; the
    // only hard bound is the 253-byte PDU, which a request for 124 registers reaches (250 bytes).
    if (byteCount == 0 || byteCount > 251) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is out of range: a Read File Record response carries "
                                     "1-251 bytes of sub-responses (a PDU holds 253 bytes)")
                          .arg(byteCount));
    } else if (byteCount > 0xF5) {
        ctx.tree.flag(bc, Severity::Warning,
                      QStringLiteral("byte count %1 is above the 0xF5 (245) the specification's table gives; it fits "
                                     "the 253-byte PDU, but some servers and clients stop at 245")
                          .arg(byteCount));
    }
    // The matching request's sub-requests give each sub-response's length and record numbers.
    const bool known = requestUsable(ctx, 2);
    const int requested = known ? int(qMin<qsizetype>(ctx.requestByte(1), ctx.request.size() - 2)) / kHeader : 0;
    if (known) {
        int expected = 0;
        for (int i = 0; i < requested; ++i)
            expected += 2 + 2 * ctx.requestU16(2 + kHeader * i + 5);
        if (byteCount != expected) {
            ctx.tree.flag(bc, Severity::Error,
                          QStringLiteral("byte count %1 does not match the request: %2 expected for its %3 "
                                         "(2 + 2 per register each)")
                              .arg(QString::number(byteCount), amount(expected, "byte", "bytes"),
                                   amount(requested, "sub-request", "sub-requests")));
        }
    }
    const int dataEnd = 2 + byteCount;
    const int avail = qMin(dataEnd, ctx.length);
    bool reported = false;
    int i = 0;
    for (int pos = 2; pos < avail && !reported; ++i) {
        const int length = ctx.byte(pos);
        const int subEnd = pos + 1 + length;
        const int blockEnd = qMin(subEnd, dataEnd);
        const int g = ctx.add(groupKey(ctx), QT_TRANSLATE_NOOP("mbscope::Field", "Sub-response"), pos, qMin(blockEnd, ctx.length) - pos);
        const int lf = ctx.addChild(g, "modbus.subresponse_length", QT_TRANSLATE_NOOP("mbscope::Field", "Sub-response length"), pos, 1, quint64(length),
                                    ValueFormat::Decimal);
        if (length % 2 == 0) {
            ctx.tree.flag(lf, Severity::Error,
                          QStringLiteral("sub-response length %1 is even: it counts 1 reference type byte plus "
                                         "2 bytes per register")
                              .arg(length));
        }
        if (subEnd > dataEnd) {
            ctx.tree.flag(lf, Severity::Error,
                          QStringLiteral("sub-response length %1 runs past the byte count: only %2 left")
                              .arg(QString::number(length), amount(dataEnd - pos - 1, "byte is", "bytes are")));
        }
        int firstRecord = -1;
        if (known && i >= requested) {
            ctx.tree.flag(g, Severity::Error,
                          QStringLiteral("no matching sub-request: the request has %1")
                              .arg(amount(requested, "sub-request", "sub-requests")));
        } else if (known) {
            const int asked = ctx.requestU16(2 + kHeader * i + 5);
            firstRecord = ctx.requestU16(2 + kHeader * i + 3);
            if (length != 1 + 2 * asked) {
                ctx.tree.flag(lf, Severity::Error,
                              QStringLiteral("sub-response length %1 does not match the request: sub-request %2 "
                                             "asks for %3, which need length %4")
                                  .arg(QString::number(length), QString::number(i + 1),
                                       amount(asked, "register", "registers"), QString::number(1 + 2 * asked)));
            }
        }
        if (pos + 1 < blockEnd) {
            if (!ctx.has(pos + 1)) {
                missingData(ctx, g, pos + 1, 2, dataEnd);
                reported = true;
                break;
            }
            const int rt = ctx.addChild(g, "modbus.reference_type", QT_TRANSLATE_NOOP("mbscope::Field", "Reference type"), pos + 1, 1, ctx.byte(pos + 1),
                                        ValueFormat::Hex);
            checkReferenceType(ctx, rt, ctx.byte(pos + 1));
            reported = registerBlock(ctx, g, pos + 2, 2, dataEnd, firstRecord >= 0 ? QT_TRANSLATE_NOOP("mbscope::Field", "Record") : QT_TRANSLATE_NOOP("mbscope::Field", "Record index"),
                                     firstRecord, blockEnd);
        }
        pos = subEnd;
    }
    if (!reported && ctx.length < dataEnd)
        missingData(ctx, ctx.parent, ctx.length, 2, dataEnd);
    if (known && !reported && ctx.length >= dataEnd && i < requested) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("the response carries %1 but the request has %2")
                          .arg(amount(i, "sub-response", "sub-responses"),
                               amount(requested, "sub-request", "sub-requests")));
    }
    trailing(ctx, dataEnd);
}

// 15 request, and its response which echoes it.
void writeRecords(const PduContext &ctx)
{
    const int first = ctx.tree.size();
    byteCountField(ctx, 0x09, 0xFB);
    const int dataEnd = 2 + ctx.byte(1);
    const int avail = qMin(dataEnd, ctx.length);
    const char *groupName = isResponse(ctx) ? QT_TRANSLATE_NOOP("mbscope::Field", "Sub-response") : QT_TRANSLATE_NOOP("mbscope::Field", "Sub-request");
    bool reported = false;
    for (int pos = 2; pos < avail && !reported;) {
        const int headerEnd = qMin(pos + kHeader, avail);
        const bool whole = pos + kHeader <= avail;
        const int subEnd = whole ? pos + kHeader + 2 * ctx.u16(pos + 5) : pos + kHeader;
        const int blockEnd = qMin(subEnd, dataEnd);
        const int g = ctx.add(groupKey(ctx), groupName, pos, qMin(blockEnd, ctx.length) - pos);
        const int after = subHeader(ctx, g, pos, headerEnd);
        if (!whole) {
            reported = headerCut(ctx, g, pos, after, dataEnd);
            break;
        }
        if (subEnd > dataEnd) {
            const int length = ctx.u16(pos + 5);
            ctx.tree.flag(ctx.tree.size() - 1, Severity::Error,
                          QStringLiteral("record length %1 needs %2 of record data but the byte count leaves %3")
                              .arg(QString::number(length), amount(2 * length, "byte", "bytes"),
                                   QString::number(dataEnd - pos - kHeader)));
        }
        reported = registerBlock(ctx, g, pos + kHeader, 2, dataEnd, "Record", ctx.u16(pos + 3), blockEnd);
        pos = subEnd;
    }
    if (!reported && ctx.length < dataEnd)
        missingData(ctx, ctx.parent, ctx.length, 2, dataEnd);
    trailing(ctx, dataEnd);
    if (isResponse(ctx) && requestUsable(ctx, 2))
        checkEcho(ctx, first, true);
}

} // namespace

void dissectReadFileRecord(const PduContext &ctx)
{
    if (!ctx.has(1)) {
        if (isResponse(ctx))
            missing(ctx, ctx.parent, 1, 6, true, "byte count and sub-responses");
        else
            missing(ctx, ctx.parent, 1, 2 + kHeader, true, "byte count and sub-requests");
        return;
    }
    if (isResponse(ctx))
        readResponse(ctx);
    else
        readRequest(ctx);
}

void dissectWriteFileRecord(const PduContext &ctx)
{
    if (!ctx.has(1)) {
        missing(ctx, ctx.parent, 1, 2 + kHeader + 2, true, "byte count and sub-requests");
        return;
    }
    writeRecords(ctx);
}

} // namespace mbscope::pdu
