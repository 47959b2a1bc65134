#include "exchangesource.h"

#include "capture/journalexchangereader.h"

#include <QtCore/QFile>

#include <algorithm>

namespace mbscope {

namespace {

ExchangeSourceReport readPackets(const QString &path, const std::function<CaptureFileReader::Result(const CaptureFileReader::Sink &)> &reader,
                                 const CaptureOptions &options, const ExchangeSource::Sink &sink,
                                 const ExchangeSource::ConversationSink &onConversation)
{
    ExchangeSourceReport report;
    report.path = path;
    ExchangePairer pairer(options.timeoutNs, sink);
    ModbusFrameExtractor extractor(options, [&pairer](const CapturedFrame &frame) { pairer.add(frame); });
    if (onConversation)
        extractor.setConversationSink(onConversation);
    extractor.setGapSink([&pairer](quint32 conversation, Direction direction) {
        if (direction == Direction::Response)
            pairer.answersLost(conversation);
    });
    qint64 endNs = -1; // the capture's last packet: requests whose timeout reaches past it are unanswered at its end
    report.file = reader([&extractor, &endNs](const CapturePacket &packet) {
        endNs = std::max(endNs, packet.timeNs);
        extractor.add(packet);
    });
    extractor.finish();
    pairer.finish(std::max<qint64>(endNs, 0));
    report.kind = report.file.format == TrafficFormat::Unknown ? ExchangeSourceReport::Kind::Unreadable
                                                                             : ExchangeSourceReport::Kind::Capture;
    report.error = report.file.error;
    report.frames = extractor.counters();
    report.pairs = pairer.counters();
    report.unansweredAtEnd = report.pairs.unansweredAtEnd;
    report.conversations = extractor.conversations();
    report.otherModbusPorts = extractor.otherModbusPorts();
    report.problems = extractor.problems() + pairer.problems();
    report.problemCount = extractor.problemCount() + pairer.problemCount();
    return report;
}

} // namespace

QString ExchangeSourceReport::kindName() const
{
    switch (kind) {
    case Kind::Capture: return trafficformat::name(file.format);
    case Kind::Journal: return QStringLiteral("journal");
    case Kind::Unreadable: break;
    }
    return QStringLiteral("unreadable");
}

ExchangeSourceReport ExchangeSource::read(const QString &path, const CaptureOptions &options, const Sink &sink,
                                          const ConversationSink &onConversation)
{
    QByteArray first;
    {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            ExchangeSourceReport report;
            report.path = path;
            report.error = QStringLiteral("cannot open: %1").arg(file.errorString());
            return report;
        }
        first = file.read(8);
    }
    if (JournalExchangeReader::isJournal(first)) {
        ExchangeSourceReport report;
        report.path = path;
        const JournalExchangeReader::Result journal = JournalExchangeReader::read(path, sink, onConversation);
        report.kind = ExchangeSourceReport::Kind::Journal;
        report.journal = journal.recovery;
        report.journalGarbage = journal.garbageFrames;
        report.journalDuplicates = journal.duplicateResponses;
        report.unansweredAtEnd = journal.noOutcome;
        report.conversations = journal.conversations;
        report.pairs.unmatchedResponses = journal.unmatchedResponses;
        report.pairs.lateResponses = journal.lateResponses;
        if (!journal.recovery.isClean())
            report.error = journal.recovery.message;
        if (journal.recovery.ending == TrafficJournalRecovery::Ending::NotAJournal
            || journal.recovery.ending == TrafficJournalRecovery::Ending::Unreadable)
            report.kind = ExchangeSourceReport::Kind::Unreadable;
        return report;
    }
    return readPackets(path, [&path](const CaptureFileReader::Sink &s) { return CaptureFileReader::readFile(path, s); }, options, sink,
                       onConversation);
}

ExchangeSourceReport ExchangeSource::readCapture(QByteArrayView bytes, const CaptureOptions &options, const Sink &sink,
                                                 const ConversationSink &onConversation)
{
    return readPackets(QStringLiteral("(memory)"), [bytes](const CaptureFileReader::Sink &s) { return CaptureFileReader::readBytes(bytes, s); },
                       options, sink, onConversation);
}

} // namespace mbscope
