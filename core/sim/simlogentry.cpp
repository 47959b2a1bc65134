#include "sim/simlogentry.h"

namespace mbscope {

const char *SimLogEntry::verdictName(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Answered: return "answered";
    case Verdict::Exception: return "exception";
    case Verdict::NoAnswer: return "no_answer";
    case Verdict::UnknownUnit: return "unknown_unit";
    case Verdict::ChecksumError: return "checksum_error";
    case Verdict::Malformed: return "malformed";
    case Verdict::Garbage: return "garbage";
    case Verdict::ConnectionOpened: return "connection_opened";
    case Verdict::ConnectionRefused: return "connection_refused";
    case Verdict::ConnectionClosed: return "connection_closed";
    }
    return "?";
}

} // namespace mbscope
