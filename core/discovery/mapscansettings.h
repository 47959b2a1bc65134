#pragma once

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// What a register-map scan searches, and its bounds.
struct MapScanSettings {
    LinkUrl url;
    quint8 unit = 1;
    int firstAddress = 0;           // the addresses searched in every table
    int lastAddress = 999;
    // Between blocks, one address in `step` is asked: 1 finds every address; 16 finds every block of
    // 16 addresses or more (and shorter ones that a probe happens to hit) in about a sixteenth of
    // the requests. A block found is always mapped whole.
    int step = 1;
    QList<quint8> functions{1, 2, 3, 4}; // the tables mapped
    bool optionalFunctions = true;  // ask 07, 08, 0B, 0C, 11, 14, 17, 18, 2B/0E too
    int timeoutMs = 500;            // per request
    int gapMs = 0;
    int maxRequests = 20000;        // the whole scan stops after this many requests
    qint64 maxDurationMs = 600000;  // or after this long

    [[nodiscard]] QString problem() const;
};

} // namespace mbscope
