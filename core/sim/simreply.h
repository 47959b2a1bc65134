#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// What a unit made of one request (SimProcessor::process).
struct SimReply {
    enum class Kind : quint8 {
        Normal,     // a normal response
        Exception,  // an exception response (exceptionCode says which)
        Silent,     // processed, no answer: broadcast, 08/04 (listen-only), 08/01 in listen-only
        ListenOnly, // not processed: the unit is in listen-only mode (V1.1b3 6.8.1, sub-function 04)
    };
    Kind kind = Kind::Silent;
    QByteArray pdu;          // the response PDU, function code first; empty when there is no answer
    quint8 exceptionCode = 0;
    QString note;            // why: "address 0x0100 is outside the holding registers", ...

    [[nodiscard]] bool hasAnswer() const { return !pdu.isEmpty(); }

    [[nodiscard]] static SimReply normal(const QByteArray &pdu)
    {
        return SimReply{Kind::Normal, pdu, 0, {}};
    }
    // Exception codes: V1.1b3 section 7 (01 illegal function, 02 illegal data address, 03 illegal
    // data value, 04 server device failure, 06 server busy, 07 NAK, 0B gateway target failed).
    [[nodiscard]] static SimReply exception(quint8 functionCode, quint8 code, const QString &note)
    {
        QByteArray bytes(2, 0);
        bytes[0] = char(functionCode | 0x80);
        bytes[1] = char(code);
        return SimReply{Kind::Exception, bytes, code, note};
    }
    [[nodiscard]] static SimReply silent(const QString &note)
    {
        return SimReply{Kind::Silent, {}, 0, note};
    }
};

} // namespace mbscope
