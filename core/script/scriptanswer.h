#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// What a device script's onRequest(request) (or onFrame(bytes)) returned, read by ScriptHost:
//   undefined (or no onRequest)  -> Normal: the profile's answer
//   null or {silent: true}       -> Silence: no answer at all
//   [1, 2, 3] or {values: [...]} -> Values: the answer to a read (01-04, 17) made of these values
//   {exception: 4}               -> Exception: that exception code (1-255)
//   {pdu: [0x03, 2, 0, 7]}       -> Pdu: this PDU, framed like any answer (MBAP, CRC, LRC)
//   {adu: [...]} or {adu: "hex"} -> Adu: exactly these bytes, framing and all
//   {delay: 2.5}                 -> the answer (any of the above, Normal when alone) after 2.5 ms
// A call that threw, ran past the time limit or returned something else is Failed, with a note.
struct ScriptAnswer {
    enum class Kind : quint8 {
        Normal,
        Silence,
        Values,
        Exception,
        Pdu,
        Adu,
        Failed,
    };
    Kind kind = Kind::Normal;
    QList<quint16> values;
    int exceptionCode = 0;
    QByteArray bytes;        // Pdu, Adu; onFrame: the answer's body
    qint64 delayNs = -1;     // -1: the unit's response delay
    bool timedOut = false;   // Failed because the time limit interrupted the call
    QString note;            // Failed: the error, located ("gamma.js:12: TypeError: ...")

    [[nodiscard]] static ScriptAnswer failed(const QString &note, bool timedOut = false)
    {
        ScriptAnswer a;
        a.kind = Kind::Failed;
        a.note = note;
        a.timedOut = timedOut;
        return a;
    }
};

} // namespace mbscope
