// CaptureFileReader, pcapng (IETF draft-ietf-opsawg-pcapng, "PCAP Now Generic"): blocks of
//   type (4), total length (4), body, total length again (4), lengths a multiple of 4.
// A section header block (0x0A0D0D0A, byte-order magic 0x1A2B3C4D) starts a section in its own
// byte order; interface description blocks (1) number the section's interfaces from 0 and give
// each its link type and time stamp resolution; packets come in enhanced (6), simple (3) or
// obsolete (2) packet blocks. Every other block (names, statistics, secrets, custom) is skipped.
#include "capturefilereader.h"

#include "protocol/hexnumber.h"
#include "capture/capturebytesource.h"

#include <QtCore/QtEndian>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mbscope {

namespace {

constexpr quint32 kSectionHeader = 0x0a0d0d0a;
constexpr quint32 kInterfaceDescription = 1;
constexpr quint32 kObsoletePacket = 2;
constexpr quint32 kSimplePacket = 3;
constexpr quint32 kEnhancedPacket = 6;
constexpr quint32 kMaxBlockBytes = 256 * 1024 * 1024;
constexpr quint16 kOptionEnd = 0;
constexpr quint16 kOptionTsResol = 9;
constexpr quint16 kOptionTsOffset = 14;

struct Interface {
    quint32 linkType = 0;
    quint32 snapLength = 0;
    quint64 unitsPerSecond = 1000000; // if_tsresol absent: microseconds
    qint64 offsetSeconds = 0;
};

struct Order {
    bool bigEndian = false;
    [[nodiscard]] quint32 u32(const uchar *p) const { return bigEndian ? qFromBigEndian<quint32>(p) : qFromLittleEndian<quint32>(p); }
    [[nodiscard]] quint16 u16(const uchar *p) const { return bigEndian ? qFromBigEndian<quint16>(p) : qFromLittleEndian<quint16>(p); }
    [[nodiscard]] quint64 u64(const uchar *p) const { return bigEndian ? qFromBigEndian<quint64>(p) : qFromLittleEndian<quint64>(p); }
};

// Time stamps are kept between 1970 and 2^62 ns (about 146 years) later: a damaged file's stamps
// (or offsets) beyond that are clamped, so that differences between any two stay in range.
constexpr qint64 kLatestNs = qint64(1) << 62;
constexpr qint64 kLatestSeconds = kLatestNs / 1000000000LL;

qint64 toNs(quint64 units, const Interface &iface)
{
    const quint64 perSecond = iface.unitsPerSecond;
    const quint64 seconds = units / perSecond;
    const quint64 rest = units % perSecond;
    if (seconds > quint64(kLatestSeconds))
        return kLatestNs;
    qint64 restNs = 0;
    if (perSecond == 1000000000ULL)
        restNs = qint64(rest);
    else if (1000000000ULL % perSecond == 0)
        restNs = qint64(rest * (1000000000ULL / perSecond));
    else
        restNs = qint64(std::llround(static_cast<long double>(rest) * 1e9L / static_cast<long double>(perSecond)));
    const qint64 offsetSeconds = std::clamp<qint64>(iface.offsetSeconds, -kLatestSeconds, kLatestSeconds);
    const qint64 ns = qint64(seconds) * 1000000000LL + restNs + offsetSeconds * 1000000000LL;
    return std::clamp<qint64>(ns, 0, kLatestNs);
}

// if_tsresol: the most significant bit picks the base (0: 10^-n, 1: 2^-n). Resolutions finer
// than 2^-63 or 10^-19 cannot be counted in 64 bits: refused.
bool unitsFromResolution(quint8 resolution, quint64 *perSecond)
{
    const int exponent = resolution & 0x7f;
    if (resolution & 0x80) {
        if (exponent > 63)
            return false;
        *perSecond = quint64(1) << exponent;
        return true;
    }
    if (exponent > 19)
        return false;
    quint64 v = 1;
    for (int i = 0; i < exponent; ++i)
        v *= 10;
    *perSecond = v;
    return true;
}

} // namespace

void CaptureFileReader::readPcapng(CaptureByteSource &source, const Sink &sink, Result &result)
{
    const auto fail = [&](qint64 at, const QString &what) {
        result.errorOffset = at;
        result.error = QStringLiteral("at byte %1: %2").arg(at).arg(what);
    };
    Order order;
    std::vector<Interface> interfaces;
    bool inSection = false;
    CapturePacket packet;

    while (!source.atEnd()) {
        const qint64 at = source.offset();
        const uchar *head = source.peek(12);
        if (!head) {
            fail(at, QStringLiteral("a block is cut short: its header needs 8 bytes (12 for a section header), the file has %1")
                         .arg(source.remaining()));
            return;
        }
        const quint32 rawType = qFromLittleEndian<quint32>(head);
        if (rawType == kSectionHeader) {
            const quint32 magic = qFromLittleEndian<quint32>(head + 8);
            if (magic == 0x1a2b3c4d) {
                order.bigEndian = false;
            } else if (magic == 0x4d3c2b1a) {
                order.bigEndian = true;
            } else {
                fail(at + 8, QStringLiteral("the section header's byte-order magic is %1, not 1A2B3C4D in either byte order: "
                                            "the section is damaged")
                                 .arg(hexNumber(magic, 8)));
                return;
            }
        } else if (!inSection) {
            fail(at, QStringLiteral("a block of type 0x%1 comes before any section header block").arg(hexNumber(rawType, 8)));
            return;
        }
        const quint32 type = order.u32(head);
        const quint32 length = order.u32(head + 4);
        const auto typeText = [type] { return QStringLiteral("0x%1").arg(hexNumber(type, 8)); }; // errors only
        if (length < 12 || length % 4 != 0 || length > kMaxBlockBytes) {
            fail(at, QStringLiteral("the block of type %1 says it is %2 bytes long, %3: the file is damaged")
                         .arg(typeText())
                         .arg(length)
                         .arg(length < 12 ? QStringLiteral("less than the 12 every block takes")
                                          : length % 4 != 0 ? QStringLiteral("not a multiple of 4")
                                                            : QStringLiteral("more than 256 MiB")));
            return;
        }
        const uchar *block = source.peek(qsizetype(length));
        if (!block) {
            fail(at, QStringLiteral("the block of type %1 is cut short: it says %2 bytes, the file has %3")
                         .arg(typeText()).arg(length).arg(source.remaining()));
            return;
        }
        const quint32 trailing = order.u32(block + length - 4);
        if (trailing != length) {
            fail(at + length - 4, QStringLiteral("the block of type %1 that starts at byte %2 ends with a length of %3 "
                                                 "where it began with %4: the file is damaged")
                                      .arg(typeText()).arg(at).arg(trailing).arg(length));
            return;
        }
        const uchar *body = block + 8;
        const quint32 bodyLength = length - 12;

        // Options from optionsAt to the body's end: code, length, value padded to 4 bytes.
        const auto forOptions = [&](quint32 optionsAt, const auto &onOption) {
            quint32 p = optionsAt;
            while (p + 4 <= bodyLength) {
                const quint16 code = order.u16(body + p);
                const quint16 size = order.u16(body + p + 2);
                if (code == kOptionEnd || p + 4 + size > bodyLength)
                    break;
                onOption(code, body + p + 4, size);
                p += 4 + ((size + 3u) & ~3u);
            }
        };
        const auto deliver = [&](quint32 iface, quint64 units, const uchar *data, quint32 captured, quint32 original, bool timed) {
            packet.number = result.packets + 1;
            packet.fileOffset = at;
            packet.timeNs = timed ? toNs(units, interfaces[iface]) : 0;
            packet.linkType = interfaces[iface].linkType;
            packet.originalLength = original;
            packet.data = QByteArrayView(data, qsizetype(captured));
            sink(packet);
            result.packets = packet.number;
        };
        const auto checkInterface = [&](quint32 iface) {
            if (iface < interfaces.size())
                return true;
            fail(at, QStringLiteral("packet %1 is on interface %2, but its section describes %3 interface(s): the file is damaged")
                         .arg(result.packets + 1).arg(iface).arg(interfaces.size()));
            return false;
        };

        // Enhanced (6) and obsolete (2) packet blocks share their layout: interface (4 bytes, or
        // 2 followed by a drops count), time stamp high and low, captured and original lengths,
        // then the data. False when the block is damaged (the failure is recorded).
        const auto readTimedPacket = [&](const QString &blockName, int interfaceIdBytes) {
            if (bodyLength < 20) {
                fail(at, QStringLiteral("the %1 block is %2 bytes long, less than the 32 it takes").arg(blockName).arg(length));
                return false;
            }
            const quint32 iface = interfaceIdBytes == 2 ? order.u16(body) : order.u32(body);
            const quint64 units = quint64(order.u32(body + 4)) << 32 | order.u32(body + 8);
            const quint32 captured = order.u32(body + 12);
            const quint32 original = order.u32(body + 16);
            if (captured > bodyLength - 20) {
                fail(at, QStringLiteral("packet %1 says %2 captured bytes, more than its block of %3 bytes holds: the file is damaged")
                             .arg(result.packets + 1).arg(captured).arg(length));
                return false;
            }
            if (!checkInterface(iface))
                return false;
            deliver(iface, units, body + 20, captured, original, true);
            return true;
        };

        switch (type) {
        case kSectionHeader: {
            if (bodyLength < 16) {
                fail(at, QStringLiteral("the section header block is %1 bytes long, less than the 28 it takes").arg(length));
                return;
            }
            const quint16 major = order.u16(body + 4);
            if (major != 1) {
                fail(at + 12, QStringLiteral("pcapng version %1.%2 is not 1.x, the version this reader knows").arg(major).arg(order.u16(body + 6)));
                return;
            }
            inSection = true;
            interfaces.clear();
            break;
        }
        case kInterfaceDescription: {
            if (bodyLength < 8) {
                fail(at, QStringLiteral("the interface description block is %1 bytes long, less than the 20 it takes").arg(length));
                return;
            }
            Interface iface;
            iface.linkType = order.u16(body);
            iface.snapLength = order.u32(body + 4);
            bool resolutionOk = true;
            forOptions(8, [&](quint16 code, const uchar *value, quint16 size) {
                if (code == kOptionTsResol && size >= 1)
                    resolutionOk = unitsFromResolution(value[0], &iface.unitsPerSecond);
                else if (code == kOptionTsOffset && size >= 8)
                    iface.offsetSeconds = qint64(order.u64(value));
            });
            if (!resolutionOk) {
                fail(at, QStringLiteral("interface %1 has a time stamp resolution (if_tsresol) too fine to count in 64 bits")
                             .arg(interfaces.size()));
                return;
            }
            interfaces.push_back(iface);
            break;
        }
        case kEnhancedPacket:
            if (!readTimedPacket(QStringLiteral("enhanced packet"), 4))
                return;
            break;
        case kSimplePacket: {
            if (bodyLength < 4) {
                fail(at, QStringLiteral("the simple packet block is %1 bytes long, less than the 16 it takes").arg(length));
                return;
            }
            if (!checkInterface(0))
                return;
            const quint32 original = order.u32(body);
            quint32 captured = std::min(original, bodyLength - 4);
            if (interfaces[0].snapLength > 0)
                captured = std::min(captured, interfaces[0].snapLength);
            deliver(0, 0, body + 4, captured, original, false);
            break;
        }
        case kObsoletePacket:
            if (!readTimedPacket(QStringLiteral("packet"), 2))
                return;
            break;
        default:
            break;
        }
        source.advance(qsizetype(length));
        result.goodBytes = source.offset();
    }
}

} // namespace mbscope
