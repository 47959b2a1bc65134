#pragma once

#include <QtCore/QList>

namespace mbscope {

// Which traffic in a capture is Modbus, and how to pair it.
struct CaptureOptions {
    // Server ports carrying MBAP: Modbus TCP over TCP, Modbus UDP over UDP (Messaging on TCP/IP
    // V1.0b, 4.1: 502).
    QList<quint16> mbapPorts{502};
    // Server ports carrying RTU frames over TCP or UDP (a serial device server: 4001, 950...).
    // A port in both lists is taken as RTU.
    QList<quint16> rtuPorts;
    // A request unanswered this long (capture time) is a timeout, as in the engine, whose
    // default this is; an answer after it is late.
    qint64 timeoutNs = 1'000'000'000;
    // RTU over TCP has no length for codes without a length rule: a pause this long in one
    // direction ends a frame (what the engine waits on an RTU-over-TCP link).
    qint64 rtuSilenceNs = 50'000'000;
};

} // namespace mbscope
