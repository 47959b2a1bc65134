#pragma once

#include "capture/captureexchange.h"
#include "capture/capturedframe.h"
#include "capture/capturefilereader.h"
#include "capture/captureoptions.h"
#include "capture/exchangepairer.h"
#include "capture/modbusframeextractor.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>
#include <vector>

namespace mbscope {

// What reading a source of exchanges found, whatever the source was.
struct ExchangeSourceReport {
    enum class Kind : quint8 { Unreadable, Capture, Journal };
    Kind kind = Kind::Unreadable;
    QString path;
    // Unreadable: why nothing could be read ("not a capture file: ..."). Otherwise the damage
    // that stopped the reading early, where it is, with everything before it read; empty when
    // the whole source was read.
    QString error;
    CaptureFileReader::Result file;           // Capture
    ModbusFrameExtractor::Counters frames;    // Capture
    ExchangePairer::Counters pairs;           // Capture
    TrafficJournalRecovery journal;           // Journal
    quint64 journalGarbage = 0;
    quint64 journalDuplicates = 0; // Journal: of the unmatched answers, second answers to one request (a server's duplicates)
    quint64 unansweredAtEnd = 0; // requests cut by the end of the journal or capture (CaptureExchange::Kind::Unanswered)
    std::vector<CaptureConversation> conversations;
    // Capture: other ports whose traffic looks like Modbus (most packets first).
    std::vector<ModbusPortFinder::Found> otherModbusPorts;
    QStringList problems;  // the first few, with packet numbers
    quint64 problemCount = 0;

    [[nodiscard]] bool isReadable() const { return kind != Kind::Unreadable; }
    [[nodiscard]] bool isComplete() const { return isReadable() && error.isEmpty(); }
    [[nodiscard]] QString kindName() const; // "pcap", "pcapng", "journal", "unreadable"
};

// Opens a capture file (pcap, pcapng) or a traffic journal, tells which by its first bytes, and
// hands every exchange to the sink in request order (CaptureExchange).
class ExchangeSource
{
public:
    using Sink = std::function<void(const CaptureExchange &)>;
    // Called once per conversation (a capture's client/server pair, a journal's link) before
    // any of its exchanges: exports need its addresses as they go.
    using ConversationSink = std::function<void(const CaptureConversation &)>;
    [[nodiscard]] static ExchangeSourceReport read(const QString &path, const CaptureOptions &options, const Sink &sink,
                                                   const ConversationSink &onConversation = {});
    // The same over capture bytes in memory (tests).
    [[nodiscard]] static ExchangeSourceReport readCapture(QByteArrayView bytes, const CaptureOptions &options, const Sink &sink,
                                                          const ConversationSink &onConversation = {});
};

} // namespace mbscope
