#pragma once

// Small capture files built byte by byte for the reader's tests: pcap and pcapng in either byte
// order, with packets of any link type.
#include <QtCore/QByteArray>
#include <QtCore/QtEndian>

namespace capturebytes {

inline void put16(QByteArray &b, quint16 v, bool big)
{
    char raw[2];
    if (big)
        qToBigEndian(v, raw);
    else
        qToLittleEndian(v, raw);
    b.append(raw, 2);
}

inline void put32(QByteArray &b, quint32 v, bool big)
{
    char raw[4];
    if (big)
        qToBigEndian(v, raw);
    else
        qToLittleEndian(v, raw);
    b.append(raw, 4);
}

inline QByteArray pcapHeader(bool big, bool nano, quint32 linkType, quint32 snapLength = 262144, quint16 major = 2)
{
    QByteArray b;
    put32(b, nano ? 0xa1b23c4d : 0xa1b2c3d4, big);
    put16(b, major, big);
    put16(b, 4, big);
    put32(b, 0, big);
    put32(b, 0, big);
    put32(b, snapLength, big);
    put32(b, linkType, big);
    return b;
}

inline QByteArray pcapRecord(bool big, quint32 seconds, quint32 fraction, const QByteArray &data, qint64 claimed = -1)
{
    QByteArray b;
    put32(b, seconds, big);
    put32(b, fraction, big);
    put32(b, claimed < 0 ? quint32(data.size()) : quint32(claimed), big);
    put32(b, quint32(data.size()), big);
    b.append(data);
    return b;
}

inline QByteArray block(bool big, quint32 type, const QByteArray &body, qint64 trailing = -1)
{
    QByteArray padded = body;
    while (padded.size() % 4)
        padded.append('\0');
    QByteArray b;
    put32(b, type, big);
    put32(b, quint32(padded.size() + 12), big);
    b.append(padded);
    put32(b, trailing < 0 ? quint32(padded.size() + 12) : quint32(trailing), big);
    return b;
}

inline QByteArray sectionHeader(bool big)
{
    QByteArray body;
    put32(body, 0x1a2b3c4d, big);
    put16(body, 1, big);
    put16(body, 0, big);
    put32(body, 0xffffffff, big);
    put32(body, 0xffffffff, big);
    return block(big, 0x0a0d0d0a, body);
}

// tsresol < 0: no if_tsresol option (microseconds).
inline QByteArray interfaceDescription(bool big, quint16 linkType, int tsresol = -1, qint64 tsoffset = 0)
{
    QByteArray body;
    put16(body, linkType, big);
    put16(body, 0, big);
    put32(body, 0, big);
    if (tsresol >= 0) {
        put16(body, 9, big);
        put16(body, 1, big);
        body.append(char(tsresol));
        body.append(3, '\0');
    }
    if (tsoffset != 0) {
        put16(body, 14, big);
        put16(body, 8, big);
        put32(body, big ? quint32(quint64(tsoffset) >> 32) : quint32(tsoffset), big);
        put32(body, big ? quint32(tsoffset) : quint32(quint64(tsoffset) >> 32), big);
    }
    put16(body, 0, big);
    put16(body, 0, big);
    return block(big, 1, body);
}

// Enhanced (6) and obsolete (2) packet blocks: the interface field, then the time stamp's high
// and low words, the captured and original lengths, and the data.
inline QByteArray timedPacket(bool big, quint32 type, const QByteArray &interfaceField, quint64 units, const QByteArray &data,
                              qint64 claimed)
{
    QByteArray body = interfaceField;
    put32(body, quint32(units >> 32), big);
    put32(body, quint32(units), big);
    put32(body, claimed < 0 ? quint32(data.size()) : quint32(claimed), big);
    put32(body, quint32(data.size()), big);
    body.append(data);
    return block(big, type, body);
}

inline QByteArray enhancedPacket(bool big, quint32 iface, quint64 units, const QByteArray &data, qint64 claimed = -1)
{
    QByteArray interfaceField;
    put32(interfaceField, iface, big);
    return timedPacket(big, 6, interfaceField, units, data, claimed);
}

// The obsolete packet block, still written by old tools: a 16-bit interface id and a 16-bit
// drops count where the enhanced block has a 32-bit interface id.
inline QByteArray obsoletePacket(bool big, quint16 iface, quint64 units, const QByteArray &data, qint64 claimed = -1)
{
    QByteArray interfaceField;
    put16(interfaceField, iface, big);
    put16(interfaceField, 0, big);
    return timedPacket(big, 2, interfaceField, units, data, claimed);
}

inline QByteArray simplePacket(bool big, const QByteArray &data)
{
    QByteArray body;
    put32(body, quint32(data.size()), big);
    body.append(data);
    return block(big, 3, body);
}

} // namespace capturebytes
