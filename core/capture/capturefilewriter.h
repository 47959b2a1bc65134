#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QFile>
#include <QtCore/QString>

namespace mbscope {

// Writes Ethernet packets to a pcapng file (one section, one interface, nanosecond time stamps:
// if_tsresol 9) or a classic pcap file (nanosecond magic a1b23c4d), in the writer's byte order as
// both formats allow. Buffered: one write(2) per megabyte. Errors are kept, not thrown: after
// the first one nothing more is written and close() returns it.
class CaptureFileWriter
{
public:
    enum class Format : quint8 { Pcap, Pcapng };

    CaptureFileWriter() = default;
    ~CaptureFileWriter();
    CaptureFileWriter(const CaptureFileWriter &) = delete;
    CaptureFileWriter &operator=(const CaptureFileWriter &) = delete;

    // ".pcap" gives Pcap, anything else Pcapng.
    [[nodiscard]] static Format formatFor(const QString &path);

    [[nodiscard]] bool open(const QString &path, Format format, QString *error);
    // Into memory instead of a file (tests): bytes() holds the file.
    void openInMemory(Format format);
    void write(qint64 timeNs, QByteArrayView ethernetFrame);
    // Writes what is buffered and closes; false with the first error.
    [[nodiscard]] bool close(QString *error);

    [[nodiscard]] quint64 packets() const { return m_packets; }
    [[nodiscard]] const QByteArray &bytes() const { return m_buffer; } // in memory only

private:
    void writeHeader();
    void flushBuffer();

    QFile m_file;
    Format m_format = Format::Pcapng;
    QByteArray m_buffer;
    bool m_inMemory = false;
    bool m_open = false;
    quint64 m_packets = 0;
    QString m_error;
};

} // namespace mbscope
