#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"

namespace mbscope {

// One request and what became of it, read back from a capture or a traffic journal, in the
// engine's own terms so that Statistics, exports and plots treat both alike. Times are capture
// times in ns since 1970-01-01 UTC: transaction.sentNs when the request's last byte was seen,
// transaction.doneNs (and firstByteNs) when the answer's last byte was seen, 0 when none.
//
// An answer that matches no request is a record of its own (UnmatchedResponse: the request is
// empty, sentNs 0); Statistics are not fed those, as the engine counts them apart. A request
// whose outcome the recording does not hold because the recording ends first (a journal whose
// writer was killed with the request in flight; a capture that ends before the request's timeout
// ran out) is Unanswered: "unanswered at the end of the recording", not a timeout; Statistics
// are not fed those either, and replay leaves them out.
struct CaptureExchange {
    enum class Kind : quint8 { Transaction, UnmatchedResponse, Unanswered };
    // Journals: whether the recorder sent the request (a client: poll, read...) or answered it
    // (a server: simulate). The inline tap's journal holds both: its masters' requests, which it
    // answered, and its own to the devices. Captures: Unknown (the capture was not a party).
    enum class RecordedAs : quint8 { Unknown, Client, Server };
    Kind kind = Kind::Transaction;
    RecordedAs recordedAs = RecordedAs::Unknown;
    quint32 conversation = 0;   // CaptureConversation::id, or the journal's link id
    Framing framing = Framing::Tcp;
    quint64 requestPacket = 0;  // packet number in the capture (journal: sequence + 1); 0 when none
    quint64 responsePacket = 0;
    Transaction transaction;    // id: 1, 2, 3... in request order
};

} // namespace mbscope
