#include "capturefilereader.h"

#include "capture/capturebytesource.h"

#include <QtCore/QFile>

namespace mbscope {

TrafficFormat CaptureFileReader::detect(QByteArrayView first)
{
    if (first.size() < 4)
        return TrafficFormat::Unknown;
    const auto b = [&](int i) { return quint8(first[i]); };
    const quint32 be = quint32(b(0)) << 24 | quint32(b(1)) << 16 | quint32(b(2)) << 8 | b(3);
    switch (be) {
    case 0xa1b2c3d4: case 0xd4c3b2a1: // microseconds
    case 0xa1b23c4d: case 0x4d3cb2a1: // nanoseconds
        return TrafficFormat::Pcap;
    case 0x0a0d0d0a: // a section header block: the same in both byte orders
        return TrafficFormat::Pcapng;
    default:
        return TrafficFormat::Unknown;
    }
}

CaptureFileReader::Result CaptureFileReader::readFile(const QString &path, const Sink &sink)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        Result result;
        result.errorOffset = 0;
        result.error = QStringLiteral("cannot open: %1").arg(file.errorString());
        return result;
    }
    return readDevice(&file, sink);
}

CaptureFileReader::Result CaptureFileReader::readDevice(QIODevice *device, const Sink &sink)
{
    CaptureByteSource source(device);
    return read(source, sink);
}

CaptureFileReader::Result CaptureFileReader::readBytes(QByteArrayView bytes, const Sink &sink)
{
    CaptureByteSource source(bytes);
    return read(source, sink);
}

CaptureFileReader::Result CaptureFileReader::read(CaptureByteSource &source, const Sink &sink)
{
    Result result;
    const qint64 available = source.remaining();
    result.fileBytes = source.size();
    if (available <= 0) {
        result.errorOffset = 0;
        result.error = source.error().isEmpty() ? QStringLiteral("the file is empty: not a capture")
                                                : QStringLiteral("cannot read: %1").arg(source.error());
        return result;
    }
    const uchar *head = source.peek(std::min<qint64>(available, 4));
    const QByteArrayView first(head, std::min<qint64>(available, 4));
    result.format = detect(first);
    switch (result.format) {
    case TrafficFormat::Pcap:
        readPcap(source, sink, result);
        break;
    case TrafficFormat::Pcapng:
        readPcapng(source, sink, result);
        break;
    case TrafficFormat::Journal: // detect() names only captures
    case TrafficFormat::Csv:
    case TrafficFormat::JsonLines:
    case TrafficFormat::Unknown:
        result.format = TrafficFormat::Unknown;
        result.errorOffset = 0;
        result.error = QStringLiteral("not a capture file: it starts with %1, where a pcap file starts with "
                                      "D4 C3 B2 A1 (or A1 B2 C3 D4, 4D 3C B2 A1, A1 B2 3C 4D) and a pcapng file "
                                      "with 0A 0D 0D 0A")
                           .arg(QString::fromLatin1(first.toByteArray().toHex(' ').toUpper()));
        break;
    }
    result.fileBytes = std::max(result.fileBytes, source.offset() + source.remaining());
    if (result.error.isEmpty() && !source.error().isEmpty()) {
        result.errorOffset = source.offset();
        result.error = QStringLiteral("at byte %1: read error: %2").arg(source.offset()).arg(source.error());
    }
    return result;
}

} // namespace mbscope
