#pragma once

#include "capture/captureexchange.h"
#include "capture/capturedframe.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QString>

#include <functional>
#include <vector>

namespace mbscope {

// The exchanges of a traffic journal (trafficjournal.h) in the same shape as a capture's, so
// that one analysis and one set of exports serve both. The journal already knows which answer
// belongs to which request (the transaction id) and what the engine made of it (the verdict):
// both are kept, not worked out again; ResponseVerdict only adds the exception code and the
// problem text. Retries share their transaction's id: only the last attempt is an exchange, as
// in the engine's statistics. Unsolicited frames are unmatched answers; garbage is counted.
//
// Times: the journal's monotonic ns turned into wall-clock ns through its header. A request is
// stamped when it was written, an answer when its first byte was read (what the journal keeps),
// so latencies from a journal can be a frame's transmission time shorter than the engine's.
//
// A server's journal (its metadata's role, trafficmetadata.h) is read as its clients saw it:
// requests are what came in, answers what went out. An answer a server sent in pieces (the
// simulator's chunks and trickle rules) is one frame per piece in its journal, each with the
// time it left: the pieces are joined into the answer the client's framer made of them (by the
// framing's length rule), stamped from its first piece to its last, so that its latency runs to
// its last byte; a second answer to one request (the duplicate rule) is an answer matching no
// request, counted among the duplicates, as the engine counts it.
class JournalExchangeReader
{
public:
    using Sink = std::function<void(const CaptureExchange &)>;

    struct Result {
        TrafficJournalRecovery recovery;
        quint64 garbageFrames = 0;
        quint64 unmatchedResponses = 0;
        // Of those, second answers to a request a server's journal shows answered already (the
        // simulator's duplicate rule): the engine's duplicate frames.
        quint64 duplicateResponses = 0;
        quint64 lateResponses = 0;
        // Requests whose outcome the journal does not hold, as it ends first: CaptureExchange::Kind::Unanswered.
        quint64 noOutcome = 0;
        // One per link id (its id), then one per further connection an endpoints note
        // (journalendpoints.h) starts on a link. Framing and serial port from the link's URL;
        // server from the URL when it names an address, or from the note; client from the note
        // only (clientKnown, serverKnown: capturedframe.h).
        std::vector<CaptureConversation> conversations;
    };

    // onConversation is called for a conversation just before its first exchange.
    [[nodiscard]] static Result read(const QString &path, const Sink &sink,
                                     const std::function<void(const CaptureConversation &)> &onConversation = {});
    // Whether a file starts with the journal's magic ("MBSCTLOG").
    [[nodiscard]] static bool isJournal(QByteArrayView firstBytes);
};

} // namespace mbscope
