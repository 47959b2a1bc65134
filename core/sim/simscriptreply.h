#pragma once

#include "sim/simreply.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

class ScriptHost;
class SimProcessor;

// A unit's answer when its script speaks first (docs/profiles.md, "Scripts"): the request
// goes to onRequest, and what it returns becomes the SimReply (the processor answers when it
// returns undefined, or when it failed and the script's onError says "answer").
struct SimScriptReply {
    SimReply reply;
    qint64 delayNs = -1; // -1: the unit's response delay
    QByteArray adu;      // exact bytes to send instead of reply.pdu framed (the script's "adu")

    struct Request {
        quint8 unitId = 0;
        QByteArray pdu;
        QString endpoint;
        QString peer;
        int transactionId = -1;
    };
    [[nodiscard]] static SimScriptReply make(ScriptHost &script, SimProcessor &processor, const Request &request);
};

} // namespace mbscope
