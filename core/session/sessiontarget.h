#pragma once

#include <QtCore/QString>

namespace mbscope {

// Where a session talks to and how the engine waits there. The URL carries the link's own
// settings (serial parameters, TLS files, framing); the rest are engine options.
struct SessionTarget {
    QString url;         // "rtu-tcp://192.168.127.254:4001"; empty: none saved (mbscope run --target gives it)
    int timeoutMs = -1;  // response timeout of every request; -1: the URL's timeout=, else 1000 ms
    int retries = 0;     // further attempts after a timeout or an unusable answer
    int pipelineDepth = 1;

    friend bool operator==(const SessionTarget &, const SessionTarget &) = default;
};

} // namespace mbscope
