#pragma once

#include "capture/trafficformat.h"

#include "capture/capturepacket.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QString>

#include <functional>

class QIODevice;

namespace mbscope {

class CaptureByteSource;

// Reads pcap and pcapng files (Wireshark, tcpdump, dumpcap, mbscope's own exports) packet by
// packet, in file order, without libpcap.
//
// pcap (tcpdump.org "PCAP Capture File Format"): both byte orders, microsecond (a1b2c3d4) and
// nanosecond (a1b23c4d) timestamps. pcapng (IETF draft "PCAP Now Generic"): any number of
// sections in either byte order, interfaces with their link types and if_tsresol / if_tsoffset,
// enhanced, simple and obsolete packet blocks; other blocks are skipped.
//
// A damaged file is read up to the damage: every packet before it reaches the sink, and the
// result says what is wrong and at which byte ("at byte 1340: packet 12 is cut short: its record
// says 66 captured bytes, the file ends 20 bytes after its header"). Nothing is thrown.
class CaptureFileReader
{
public:

    struct Result {
        TrafficFormat format = TrafficFormat::Unknown; // Pcap, Pcapng or Unknown
        quint64 packets = 0;   // delivered to the sink
        qint64 fileBytes = 0;
        qint64 goodBytes = 0;  // where the last whole record or block ends
        qint64 errorOffset = -1;
        QString error;         // empty when the file was read to its end
        [[nodiscard]] bool isComplete() const { return error.isEmpty(); }
    };
    using Sink = std::function<void(const CapturePacket &)>;

    [[nodiscard]] static Result readFile(const QString &path, const Sink &sink);
    [[nodiscard]] static Result readDevice(QIODevice *device, const Sink &sink);
    [[nodiscard]] static Result readBytes(QByteArrayView bytes, const Sink &sink);

    // The format the first bytes announce (4 are enough).
    [[nodiscard]] static TrafficFormat detect(QByteArrayView firstBytes); // Pcap, Pcapng or Unknown

private:
    static Result read(CaptureByteSource &source, const Sink &sink);
    static void readPcap(CaptureByteSource &source, const Sink &sink, Result &result);
    static void readPcapng(CaptureByteSource &source, const Sink &sink, Result &result);
};

} // namespace mbscope
