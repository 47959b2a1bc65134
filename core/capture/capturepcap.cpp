// CaptureFileReader, classic pcap (tcpdump.org "PCAP Capture File Format"):
//   file header, 24 bytes: magic, version 2.4, thiszone, sigfigs, snaplen, link type
//   (bits 0-27; bits 28-31 say whether frames carry an FCS);
//   then records: seconds, micro- or nanoseconds, captured length, original length, the bytes.
#include "capturefilereader.h"

#include "capture/capturebytesource.h"

#include <QtCore/QtEndian>

namespace mbscope {

namespace {

constexpr int kFileHeaderSize = 24;
constexpr int kRecordHeaderSize = 16;
// Larger than any snap length a capture tool uses (262144 for tcpdump and dumpcap): a record
// claiming more is damage, not a packet.
constexpr quint32 kMaxPacketBytes = 256 * 1024 * 1024;

struct PcapOrder {
    bool bigEndian = false;
    [[nodiscard]] quint32 u32(const uchar *p) const { return bigEndian ? qFromBigEndian<quint32>(p) : qFromLittleEndian<quint32>(p); }
    [[nodiscard]] quint16 u16(const uchar *p) const { return bigEndian ? qFromBigEndian<quint16>(p) : qFromLittleEndian<quint16>(p); }
};

} // namespace

void CaptureFileReader::readPcap(CaptureByteSource &source, const Sink &sink, Result &result)
{
    const auto fail = [&](qint64 at, const QString &what) {
        result.errorOffset = at;
        result.error = QStringLiteral("at byte %1: %2").arg(at).arg(what);
    };
    const uchar *header = source.peek(kFileHeaderSize);
    if (!header) {
        fail(0, QStringLiteral("the pcap file header is cut short: it needs %1 bytes, the file has %2")
                    .arg(kFileHeaderSize).arg(source.remaining()));
        return;
    }
    const quint32 magicBe = qFromBigEndian<quint32>(header);
    PcapOrder order;
    order.bigEndian = magicBe == 0xa1b2c3d4 || magicBe == 0xa1b23c4d;
    const bool nanoseconds = magicBe == 0xa1b23c4d || magicBe == 0x4d3cb2a1;
    const quint16 major = order.u16(header + 4);
    if (major != 2) {
        fail(4, QStringLiteral("pcap version %1.%2 is not 2.4, the only version there is").arg(major).arg(order.u16(header + 6)));
        return;
    }
    const quint32 snapLength = order.u32(header + 16);
    const quint32 linkType = order.u32(header + 20) & 0x0fffffff;
    const quint32 limit = std::max<quint32>(snapLength, 262144);
    source.advance(kFileHeaderSize);
    result.goodBytes = kFileHeaderSize;

    CapturePacket packet;
    packet.linkType = linkType;
    while (!source.atEnd()) {
        const qint64 at = source.offset();
        const quint64 number = result.packets + 1;
        const uchar *record = source.peek(kRecordHeaderSize);
        if (!record) {
            fail(at, QStringLiteral("packet %1 is cut short: its record header needs %2 bytes, the file has %3")
                         .arg(number).arg(kRecordHeaderSize).arg(source.remaining()));
            return;
        }
        const quint32 seconds = order.u32(record);
        const quint32 fraction = order.u32(record + 4);
        const quint32 captured = order.u32(record + 8);
        const quint32 original = order.u32(record + 12);
        if (captured > limit || captured > kMaxPacketBytes) {
            fail(at, QStringLiteral("packet %1 claims %2 captured bytes, more than the snap length of %3 in the file "
                                    "header: the record is damaged")
                         .arg(number).arg(captured).arg(snapLength));
            return;
        }
        if (fraction >= (nanoseconds ? 1000000000u : 1000000u)) {
            fail(at, QStringLiteral("packet %1 has %2 %3 in its time stamp, not a fraction of a second: the record is damaged")
                         .arg(number).arg(fraction).arg(nanoseconds ? QStringLiteral("nanoseconds") : QStringLiteral("microseconds")));
            return;
        }
        const uchar *whole = source.peek(kRecordHeaderSize + qsizetype(captured));
        if (!whole) {
            fail(at, QStringLiteral("packet %1 is cut short: its record says %2 captured bytes, the file ends %3 bytes "
                                    "after its header")
                         .arg(number).arg(captured).arg(source.remaining() - kRecordHeaderSize));
            return;
        }
        packet.number = number;
        packet.fileOffset = at;
        packet.timeNs = qint64(seconds) * 1000000000LL + qint64(fraction) * (nanoseconds ? 1 : 1000);
        packet.originalLength = original;
        packet.data = QByteArrayView(whole + kRecordHeaderSize, qsizetype(captured));
        sink(packet);
        source.advance(kRecordHeaderSize + qsizetype(captured));
        result.packets = number;
        result.goodBytes = source.offset();
    }
}

} // namespace mbscope
