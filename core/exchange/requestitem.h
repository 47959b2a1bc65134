#pragma once

#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

class LinkUrl;

// What the engine needs to know to match an answer to the bytes it sends. Read from the framing
// of the link the bytes go to, never by changing them.
enum class MatchRule : quint8 {
    Mbap,         // Modbus TCP/UDP: transaction id, unit id, function code (Messaging on TCP/IP V1.0b, 4.2)
    UnitFunction, // RTU and ASCII (also over TCP/UDP): unit id and function code (Serial Line V1.02, 2.1)
    NextFrame,    // delimited framing, or request bytes too short to carry keys: the next frame
};

// One request as the user gave it: a name, the exact bytes to send, and how long to wait.
// The keys (unit, function code, transaction id) come from the bytes through the link's framing.
struct RequestItem {
    QString name;
    QByteArray bytes;              // sent exactly as given, but for the MBAP transaction id (engineNumbered, pipelining)
    Framing framing = Framing::Tcp;
    MatchRule rule = MatchRule::Mbap;
    quint8 unit = 0;
    quint8 functionCode = 0;
    quint16 transactionId = 0;     // Mbap only
    // Mbap: the engine writes the connection's next transaction id into the bytes when it sends
    // them (each attempt, each repeat of a poll), so that every request on one connection has an
    // id of its own whoever made it (Messaging on TCP/IP V1.0b, 3.1.3: the id pairs an answer
    // with its request). False: the id is sent as given and the connection's ids go on after it.
    bool engineNumbered = false;
    int timeoutMs = 1000;
    int retries = 0;               // further attempts after a timeout or an unusable answer
    // Unit 0 on a serial framing (RTU, ASCII, whatever carries them): every server acts, none
    // answers (Serial Line V1.02, 2.1). Unit 0 over MBAP addresses the gateway or server itself.
    bool broadcast = false;

    // Keys read from bytes in the given framing. Bytes too short for the keys match the next
    // frame (the user may send a broken frame on purpose; the engine still times the answer).
    [[nodiscard]] static RequestItem fromBytes(const QByteArray &bytes, Framing framing,
                                               bool delimited = false, const QString &name = {});
    // The framing and delimited flag of the link's URL, and its response timeout (?timeout=) when
    // it gives one.
    [[nodiscard]] static RequestItem forLink(const QByteArray &bytes, const LinkUrl &url,
                                             const QString &name = {});
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::RequestItem)
