#include "capturefilewriter.h"

#include <QtCore/QtEndian>

namespace mbscope {

namespace {

constexpr qsizetype kFlushBytes = 1 << 20;
constexpr quint32 kLinkTypeEthernet = 1;

void append32(QByteArray &b, quint32 v)
{
    const quint32 le = qToLittleEndian(v);
    b.append(reinterpret_cast<const char *>(&le), 4);
}

void append16(QByteArray &b, quint16 v)
{
    const quint16 le = qToLittleEndian(v);
    b.append(reinterpret_cast<const char *>(&le), 2);
}

void padTo4(QByteArray &b)
{
    while (b.size() % 4)
        b.append('\0');
}

// A pcapng option: code, length, value padded to 4 bytes.
void appendOption(QByteArray &b, quint16 code, QByteArrayView value)
{
    append16(b, code);
    append16(b, quint16(value.size()));
    b.append(value);
    padTo4(b);
}

} // namespace

CaptureFileWriter::~CaptureFileWriter()
{
    if (m_open && !m_inMemory) {
        QString ignored;
        (void)close(&ignored);
    }
}

TrafficFormat CaptureFileWriter::formatFor(const QString &path)
{
    return trafficformat::ofEnding(path) == TrafficFormat::Pcap ? TrafficFormat::Pcap : TrafficFormat::Pcapng;
}

bool CaptureFileWriter::open(const QString &path, TrafficFormat format, QString *error)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        *error = QStringLiteral("cannot create %1: %2").arg(path, m_file.errorString());
        return false;
    }
    m_format = format;
    m_inMemory = false;
    m_open = true;
    m_buffer.reserve(kFlushBytes + 4096);
    writeHeader();
    return true;
}

void CaptureFileWriter::openInMemory(TrafficFormat format)
{
    m_format = format;
    m_inMemory = true;
    m_open = true;
    m_buffer.clear();
    writeHeader();
}

void CaptureFileWriter::writeHeader()
{
    if (m_format == TrafficFormat::Pcap) {
        append32(m_buffer, 0xa1b23c4d); // nanosecond time stamps
        append16(m_buffer, 2);
        append16(m_buffer, 4);
        append32(m_buffer, 0); // thiszone
        append32(m_buffer, 0); // sigfigs
        append32(m_buffer, 262144);
        append32(m_buffer, kLinkTypeEthernet);
        return;
    }
    // Section header block.
    QByteArray shb;
    append32(shb, 0x1a2b3c4d);
    append16(shb, 1);
    append16(shb, 0);
    append32(shb, 0xffffffff); // section length unknown (-1)
    append32(shb, 0xffffffff);
    appendOption(shb, 4, "mbscope"); // shb_userappl
    appendOption(shb, 0, {});
    append32(m_buffer, 0x0a0d0d0a);
    append32(m_buffer, quint32(shb.size() + 12));
    m_buffer.append(shb);
    append32(m_buffer, quint32(shb.size() + 12));
    m_interfaces = 0;
    (void)addInterface(quint16(kLinkTypeEthernet), QStringLiteral("mbscope"), {});
}

int CaptureFileWriter::addInterface(quint16 linkType, const QString &name, const QString &description)
{
    if (m_format == TrafficFormat::Pcap || !m_open)
        return -1;
    // Interface description block: no snap length limit, nanoseconds.
    QByteArray idb;
    append16(idb, linkType);
    append16(idb, 0);
    append32(idb, 0);
    appendOption(idb, 2, name.toUtf8()); // if_name
    if (!description.isEmpty())
        appendOption(idb, 3, description.toUtf8()); // if_description
    const char nine = 9;
    appendOption(idb, 9, QByteArrayView(&nine, 1)); // if_tsresol: 10^-9
    appendOption(idb, 0, {});
    append32(m_buffer, 1);
    append32(m_buffer, quint32(idb.size() + 12));
    m_buffer.append(idb);
    append32(m_buffer, quint32(idb.size() + 12));
    return m_interfaces++;
}

void CaptureFileWriter::write(qint64 timeNs, QByteArrayView frame, quint32 interfaceIndex)
{
    if (!m_open || !m_error.isEmpty())
        return;
    const quint64 t = quint64(std::max<qint64>(timeNs, 0));
    const auto length = quint32(frame.size());
    if (m_format == TrafficFormat::Pcap) {
        append32(m_buffer, quint32(t / 1000000000ULL));
        append32(m_buffer, quint32(t % 1000000000ULL));
        append32(m_buffer, length);
        append32(m_buffer, length);
        m_buffer.append(frame);
    } else {
        const quint32 total = 32 + ((length + 3u) & ~3u);
        append32(m_buffer, 6);
        append32(m_buffer, total);
        append32(m_buffer, interfaceIndex);
        append32(m_buffer, quint32(t >> 32));
        append32(m_buffer, quint32(t & 0xffffffffULL));
        append32(m_buffer, length);
        append32(m_buffer, length);
        m_buffer.append(frame);
        padTo4(m_buffer);
        append32(m_buffer, total);
    }
    ++m_packets;
    if (!m_inMemory && m_buffer.size() >= kFlushBytes)
        flushBuffer();
}

void CaptureFileWriter::flushBuffer()
{
    if (m_buffer.isEmpty() || !m_error.isEmpty())
        return;
    if (m_file.write(m_buffer) != m_buffer.size())
        m_error = QStringLiteral("cannot write %1 after %2 packets: %3").arg(m_file.fileName()).arg(m_packets).arg(m_file.errorString());
    m_buffer.resize(0); // keeps the capacity for the next megabyte
}

bool CaptureFileWriter::close(QString *error)
{
    if (m_open && !m_inMemory) {
        flushBuffer();
        m_file.close();
    }
    m_open = false;
    if (!m_error.isEmpty()) {
        *error = m_error;
        return false;
    }
    return true;
}

} // namespace mbscope
