#pragma once

#include "capture/trafficformat.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QFile>
#include <QtCore/QString>

namespace mbscope {

// Writes Ethernet packets to a pcapng file (one section, interface 0 Ethernet, nanosecond time
// stamps: if_tsresol 9) or a classic pcap file (nanosecond magic a1b23c4d), in the writer's byte
// order as both formats allow. A pcapng file may get further interfaces of other link types
// (a serial line's, named after its port). Buffered: one write(2) per megabyte. Errors are kept, not thrown: after
// the first one nothing more is written and close() returns it.
class CaptureFileWriter
{
public:

    CaptureFileWriter() = default;
    ~CaptureFileWriter();
    CaptureFileWriter(const CaptureFileWriter &) = delete;
    CaptureFileWriter &operator=(const CaptureFileWriter &) = delete;

    // ".pcap" gives Pcap, anything else Pcapng.
    [[nodiscard]] static TrafficFormat formatFor(const QString &path);

    [[nodiscard]] bool open(const QString &path, TrafficFormat format, QString *error);
    // Into memory instead of a file (tests): bytes() holds the file.
    void openInMemory(TrafficFormat format);
    // pcapng only: an interface of another link type, with its name (if_name) and description
    // (if_description); returns its index for write(). -1 for pcap, which has one link type.
    [[nodiscard]] int addInterface(quint16 linkType, const QString &name, const QString &description);
    void write(qint64 timeNs, QByteArrayView ethernetFrame, quint32 interfaceIndex = 0);

    // LINKTYPE_RTAC_SERIAL: a 12-byte header (time, event, control lines) before the bytes of a
    // serial line; Wireshark decodes the bytes as Modbus RTU with "Decode As" (rtacser.data).
    static constexpr quint16 kLinkTypeRtacSerial = 250;
    // Writes what is buffered and closes; false with the first error.
    [[nodiscard]] bool close(QString *error);

    [[nodiscard]] quint64 packets() const { return m_packets; }
    [[nodiscard]] const QByteArray &bytes() const { return m_buffer; } // in memory only

private:
    void writeHeader();
    void flushBuffer();

    QFile m_file;
    TrafficFormat m_format = TrafficFormat::Pcapng;
    QByteArray m_buffer;
    bool m_inMemory = false;
    bool m_open = false;
    quint64 m_packets = 0;
    int m_interfaces = 1;
    QString m_error;
};

} // namespace mbscope
