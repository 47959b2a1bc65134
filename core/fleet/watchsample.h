#pragma once

#include "watch/watchpointvalue.h"

#include <QtCore/QList>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// One poll of one watch as the runner saw it.
struct WatchSample {
    enum class Status : quint8 {
        Ok,        // an answer with the values
        Exception, // an exception answer (exceptionCode)
        Timeout,   // no answer within the timeout, after every retry
        CrcError,  // an answer with a wrong CRC or LRC
        Error,     // any other failure: a malformed or unexpected answer, a link error (error says)
    };

    int watch = -1;           // index in SessionWatches::watches
    QString watchName;
    qint64 timeMs = 0;        // when the answer came (or the poll failed), ms since the epoch, UTC
    Status status = Status::Timeout;
    quint8 exceptionCode = 0;
    QString error;            // what went wrong, for every status but Ok
    bool linkError = false;   // Error because the link failed: its WatchLinkState says so too
    QList<quint16> words;     // registers in wire order (Enron: two per address)
    QList<bool> bits;         // coils and discrete inputs
    QList<WatchPointValue> values; // the answer decoded (WatchDecoder); empty unless Ok
    qint64 latencyNs = -1;    // request sent to answer complete; -1 without an answer
    quint64 poll = 0;         // the watch's poll number, from 1
    // Bytes of the exchange that ended the poll, as written to and read from the link (the
    // window's status bar counts the watches' traffic with them); 0 when nothing was sent.
    qint64 requestBytes = 0;
    qint64 answerBytes = 0;

    [[nodiscard]] bool isOk() const { return status == Status::Ok; }
};

[[nodiscard]] QString watchSampleStatusName(WatchSample::Status status); // "ok", "exception", "timeout"...

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::WatchSample)
