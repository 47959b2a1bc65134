#include "captureanalysis.h"

#include "protocol/hexnumber.h"
#include "traffic/trafficmetadata.h"

#include "exchange/responsematcher.h"
#include "protocol/functioncode.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

namespace mbscope {

namespace {

QString padded(const QString &label)
{
    return label.leftJustified(14);
}

} // namespace

CaptureAnalysis::CaptureAnalysis(const HistogramSpec &histogram) : m_spec(histogram), m_overall(histogram) {}

CaptureAnalysis::~CaptureAnalysis() = default;

void CaptureAnalysis::add(const CaptureExchange &exchange)
{
    const Transaction &t = exchange.transaction;
    const qint64 first = t.sentNs != 0 ? t.sentNs : t.doneNs;
    const qint64 last = std::max(t.sentNs, t.doneNs);
    if (first != 0 && (m_firstNs == 0 || first < m_firstNs))
        m_firstNs = first;
    m_lastNs = std::max(m_lastNs, last);
    if (m_conversations.size() <= exchange.conversation)
        m_conversations.resize(exchange.conversation + 1);
    ConversationCounts &c = m_conversations[exchange.conversation];
    if (exchange.kind == CaptureExchange::Kind::UnmatchedResponse) {
        ++m_unmatched;
        ++c.unmatched;
        return;
    }
    if (exchange.kind == CaptureExchange::Kind::Unanswered) {
        ++m_unansweredAtEnd;
        return;
    }
    // The function code and the unit id alone (ExchangeFields would also format the values: not needed here).
    FrameKeys keys = ResponseMatcher::keysOf(t.request, exchange.framing);
    if (!keys.valid)
        keys = ResponseMatcher::keysOf(t.response, exchange.framing);
    // While every exchange has had the same function code (unit id), its table's figures are the
    // overall ones (a null entry): kept apart only from the first exchange that differs, as a
    // copy of the overall figures then. A capture of one kind of request keeps its samples once.
    std::unique_ptr<Statistics> *entries[2] = {nullptr, nullptr};
    const quint8 tableKeys[2] = {quint8(keys.functionCode & 0x7f), keys.unit};
    std::map<quint8, std::unique_ptr<Statistics>> *tables[2] = {&m_byFunction, &m_byUnit};
    for (int i = 0; i < 2; ++i) {
        auto &table = *tables[i];
        if (table.empty() && m_overallAdded == 0 && keys.valid) {
            table.emplace(tableKeys[i], nullptr);
            continue;
        }
        if (table.size() == 1 && !table.begin()->second) {
            if (keys.valid && table.begin()->first == tableKeys[i])
                continue;
            table.begin()->second = std::make_unique<Statistics>(m_overall);
        }
        if (keys.valid) {
            entries[i] = &table[tableKeys[i]];
            if (!*entries[i])
                *entries[i] = std::make_unique<Statistics>(m_spec);
        }
    }
    m_overall.add(t);
    ++m_overallAdded;
    for (std::unique_ptr<Statistics> *entry : entries) {
        if (entry)
            (*entry)->add(t);
    }
    if (exchange.recordedAs != CaptureExchange::RecordedAs::Unknown) {
        std::unique_ptr<Statistics> &leg = exchange.recordedAs == CaptureExchange::RecordedAs::Server ? m_answered : m_sent;
        if (!leg)
            leg = std::make_unique<Statistics>(m_spec);
        leg->add(t);
    }
    if (t.status != TransactionStatus::Late) {
        ++c.transactions;
        if (t.status == TransactionStatus::Ok)
            ++c.ok;
        else if (t.status != TransactionStatus::Broadcast)
            ++c.failed;
    }
}

const Statistics &CaptureAnalysis::tableStatistics(const std::unique_ptr<Statistics> &entry) const
{
    return entry ? *entry : m_overall;
}

QJsonObject CaptureAnalysis::toJson(const ExchangeSourceReport &report) const
{
    QJsonObject o = m_overall.toJson();
    QJsonObject source{
        {QStringLiteral("path"), report.path},
        {QStringLiteral("format"), report.kindName()},
        {QStringLiteral("complete"), report.isComplete()},
        {QStringLiteral("error"), report.error.isEmpty() ? QJsonValue() : QJsonValue(report.error)},
        {QStringLiteral("unmatched_responses"), double(m_unmatched)},
        {QStringLiteral("unanswered_at_end"), double(m_unansweredAtEnd)},
    };
    if (report.kind == ExchangeSourceReport::Kind::Capture) {
        const auto &f = report.frames;
        source.insert(QStringLiteral("packets"), double(report.file.packets));
        source.insert(QStringLiteral("good_bytes"), double(report.file.goodBytes));
        source.insert(QStringLiteral("file_bytes"), double(report.file.fileBytes));
        source.insert(QStringLiteral("modbus_packets"), double(f.modbusPackets));
        source.insert(QStringLiteral("other_packets"), double(f.otherPackets + f.notIp));
        source.insert(QStringLiteral("fragments"), double(f.fragments));
        source.insert(QStringLiteral("malformed_packets"), double(f.malformedPackets));
        source.insert(QStringLiteral("cut_by_snap_length"), double(f.cutBySnapLength));
        source.insert(QStringLiteral("frames"), double(f.frames));
        source.insert(QStringLiteral("requests"), double(report.pairs.requests));
        source.insert(QStringLiteral("responses"), double(report.pairs.responses));
        source.insert(QStringLiteral("malformed_requests"), double(report.pairs.malformedRequests));
        source.insert(QStringLiteral("retransmitted_bytes"), double(f.retransmittedBytes));
        source.insert(QStringLiteral("lost_bytes"), double(f.lostBytes));
        source.insert(QStringLiteral("gaps"), double(f.gaps));
        source.insert(QStringLiteral("joined_mid_stream"), double(f.joinedMidStream));
        source.insert(QStringLiteral("cut_by_gap_bytes"), double(f.cutByGapBytes));
        source.insert(QStringLiteral("skipped_bytes"), double(f.skippedBytes));
        source.insert(QStringLiteral("skipped_runs"), double(f.skippedRuns));
    } else if (report.kind == ExchangeSourceReport::Kind::Journal) {
        source.insert(QStringLiteral("frames"), double(report.journal.frames));
        source.insert(QStringLiteral("batches"), double(report.journal.batches));
        source.insert(QStringLiteral("garbage_frames"), double(report.journalGarbage));
        source.insert(QStringLiteral("duplicate_responses"), double(report.journalDuplicates));
        source.insert(QStringLiteral("recovery"), report.journal.message);
        source.insert(QStringLiteral("version"), double(report.journal.version));
        source.insert(QStringLiteral("notes"), double(report.journal.notes));
        // What the journal says it recorded (trafficmetadata.h), as written; null when it says nothing.
        const QJsonDocument metadata = QJsonDocument::fromJson(report.journal.metadata);
        source.insert(QStringLiteral("metadata"), metadata.isObject() ? QJsonValue(metadata.object()) : QJsonValue());
    }
    o.insert(QStringLiteral("source"), source);
    o.insert(QStringLiteral("span_ms"), double(m_lastNs - m_firstNs) / 1e6);

    QJsonArray conversations;
    for (const CaptureConversation &c : report.conversations) {
        const ConversationCounts counts = c.id < m_conversations.size() ? m_conversations[c.id] : ConversationCounts{};
        QJsonObject conversation{
            // A client the journal does not give, or a serial line's: null.
            {QStringLiteral("client"), c.clientText().isEmpty() ? QJsonValue() : QJsonValue(c.clientText())},
            {QStringLiteral("server"), c.serverText()},
            {QStringLiteral("transport"), c.isSerial() ? QStringLiteral("serial") : c.udp ? QStringLiteral("udp") : QStringLiteral("tcp")},
            {QStringLiteral("framing"), framingName(c.framing)},
            {QStringLiteral("requests"), double(c.requests)},
            {QStringLiteral("responses"), double(c.responses)},
            {QStringLiteral("transactions"), double(counts.transactions)},
            {QStringLiteral("ok"), double(counts.ok)},
            {QStringLiteral("failed"), double(counts.failed)},
            {QStringLiteral("unmatched_responses"), double(counts.unmatched)},
        };
        if (!c.udp && !c.isSerial()) {
            conversation.insert(QStringLiteral("request_gaps"), double(c.requestGaps));
            conversation.insert(QStringLiteral("request_bytes_lost"), double(c.requestBytesLost));
            conversation.insert(QStringLiteral("response_gaps"), double(c.responseGaps));
            conversation.insert(QStringLiteral("response_bytes_lost"), double(c.responseBytesLost));
            conversation.insert(QStringLiteral("joined_mid_stream"), c.joinedMidStream);
        }
        conversations.append(conversation);
    }
    o.insert(QStringLiteral("conversations"), conversations);
    if (hasTwoLegs()) {
        QJsonArray legs;
        for (const auto &[name, statistics] : {std::pair{"answered", m_answered.get()}, std::pair{"sent", m_sent.get()}}) {
            QJsonObject leg = statistics->toJson();
            leg.insert(QStringLiteral("leg"), QString::fromLatin1(name));
            legs.append(leg);
        }
        o.insert(QStringLiteral("legs"), legs);
    }
    QJsonArray functions;
    for (const auto &[code, statistics] : m_byFunction) {
        QJsonObject f = tableStatistics(statistics).toJson();
        f.insert(QStringLiteral("function"), QStringLiteral("0x%1").arg(hexNumber(code, 2)));
        f.insert(QStringLiteral("name"), QString::fromLatin1(functionName(code)));
        functions.append(f);
    }
    o.insert(QStringLiteral("functions"), functions);
    QJsonArray units;
    for (const auto &[id, statistics] : m_byUnit) {
        QJsonObject u = tableStatistics(statistics).toJson();
        u.insert(QStringLiteral("unit"), int(id));
        units.append(u);
    }
    o.insert(QStringLiteral("units"), units);
    o.insert(QStringLiteral("problems"), QJsonArray::fromStringList(report.problems));
    o.insert(QStringLiteral("problem_count"), double(report.problemCount));
    return o;
}

QString CaptureAnalysis::summary(const ExchangeSourceReport &report) const
{
    QString out = QStringLiteral("ANALYZE %1  (%2").arg(report.path, report.kindName());
    if (report.kind == ExchangeSourceReport::Kind::Capture)
        out += QStringLiteral(", %1 packets, %2 Modbus frames").arg(report.file.packets).arg(report.frames.frames);
    else
        out += QStringLiteral(", %1 frames").arg(report.journal.frames);
    out += QStringLiteral(", %1 s of traffic)\n").arg(QString::number(double(m_lastNs - m_firstNs) / 1e9, 'f', 3));
    if (!report.error.isEmpty())
        out += padded(report.journal.ending == TrafficJournalRecovery::Ending::NotClosed ? QStringLiteral("truncated")
                                                                                          : QStringLiteral("damaged"))
               + report.error + QStringLiteral("; everything before it is analysed\n");
    if (m_unansweredAtEnd > 0)
        out += padded(QStringLiteral("unanswered")) + QStringLiteral("%1 request(s) at the end of the recording, cut by its end before "
                                                                     "their outcome: counted in no figure below (not as timeouts)\n")
                                                          .arg(m_unansweredAtEnd);
    if (report.kind == ExchangeSourceReport::Kind::Journal && !report.journal.metadata.isEmpty()) {
        TrafficMetadata metadata;
        QString problem;
        if (TrafficMetadata::fromJson(report.journal.metadata, &metadata, &problem)) {
            for (const QString &line : metadata.summaryLines())
                out += line + QLatin1Char('\n');
        } else {
            out += padded(QStringLiteral("metadata")) + problem + QLatin1Char('\n');
        }
    }

    for (const CaptureConversation &c : report.conversations) {
        const ConversationCounts counts = c.id < m_conversations.size() ? m_conversations[c.id] : ConversationCounts{};
        out += padded(QStringLiteral("conversation")) + c.description()
               + QStringLiteral(": %1 transactions, %2 ok, %3 failed").arg(counts.transactions).arg(counts.ok).arg(counts.failed);
        if (counts.unmatched > 0)
            out += QStringLiteral(", %1 answers matching no request").arg(counts.unmatched);
        if (c.requestGaps > 0)
            out += QStringLiteral("; %1 gap(s) to the server, %2 byte(s) never captured").arg(c.requestGaps).arg(c.requestBytesLost);
        if (c.responseGaps > 0)
            out += QStringLiteral("; %1 gap(s) to the client, %2 byte(s) never captured").arg(c.responseGaps).arg(c.responseBytesLost);
        if (c.joinedMidStream)
            out += QStringLiteral("; joined mid-stream");
        out += QLatin1Char('\n');
    }
    if (report.conversations.empty())
        out += padded(QStringLiteral("conversation")) + QStringLiteral("none: no traffic on the Modbus ports (--port, --rtu-port)\n");

    if (!m_byFunction.empty() || !m_byUnit.empty()) {
        // Both tables in one unit, the one the overall latency line below chooses, and with the same
        // column widths, so a column reads down through both. "-": nothing answered, no latency.
        const LatencyUnit unit = LatencyUnit::forTypical(m_overall.latency().medianNs());
        const auto row = [&unit](const QString &label, const Statistics &s) {
            const LatencySamples &l = s.latency();
            const bool any = !l.isEmpty();
            const auto figure = [&](double ns) { return any ? unit.format(ns) : QStringLiteral("-"); };
            return QStringList{label, QString::number(s.count()), QString::number(s.ok()), QString::number(s.exceptions()),
                               QString::number(s.timeouts()), QString::number(s.failed() - s.exceptions() - s.timeouts()),
                               figure(double(l.minNs())), figure(l.meanNs()), figure(double(l.medianNs())),
                               figure(double(l.percentileNs(95))), figure(double(l.percentileNs(99))), figure(double(l.maxNs()))};
        };
        const auto header = [](const QString &first) {
            return QStringList{first, QStringLiteral("COUNT"), QStringLiteral("OK"), QStringLiteral("EXCEPTIONS"),
                               QStringLiteral("TIMEOUTS"), QStringLiteral("OTHER"), QStringLiteral("MIN"), QStringLiteral("MEAN"),
                               QStringLiteral("MEDIAN"), QStringLiteral("P95"), QStringLiteral("P99"), QStringLiteral("MAX")};
        };
        constexpr qsizetype firstLatencyColumn = 6;
        QList<QList<QStringList>> tables(2);
        tables[0].append(header(QStringLiteral("FUNCTION")));
        for (const auto &[code, s] : m_byFunction)
            tables[0].append(row(QStringLiteral("0x%1 %2").arg(hexNumber(code, 2)).arg(QString::fromLatin1(functionName(code))), tableStatistics(s)));
        tables[1].append(header(QStringLiteral("UNIT")));
        for (const auto &[id, s] : m_byUnit)
            tables[1].append(row(QString::number(id), tableStatistics(s)));
        if (hasTwoLegs()) {
            // The tap's two legs: what its masters saw (their requests it answered) and what the
            // devices took (the requests it sent them); the difference is the tap's own time.
            tables.append(QList<QStringList>{header(QStringLiteral("LEG"))});
            tables[2].append(row(QStringLiteral("answered (masters)"), *m_answered));
            tables[2].append(row(QStringLiteral("sent (devices)"), *m_sent));
        }
        QList<int> widths(tables[0].constFirst().size(), 0);
        for (const QList<QStringList> &table : tables) {
            for (const QStringList &cells : table) {
                for (qsizetype i = 0; i < cells.size(); ++i)
                    widths[i] = std::max(widths.at(i), int(cells.at(i).size()));
            }
        }
        // Above the latency columns, once, their unit.
        int latencyStart = 0;
        for (qsizetype i = 0; i < firstLatencyColumn; ++i)
            latencyStart += widths.at(i) + 2;
        for (const QList<QStringList> &table : tables) {
            out += QLatin1Char('\n') + QString(latencyStart, QLatin1Char(' ')) + QStringLiteral("LATENCY ")
                   + QString::fromUtf8(unit.name) + QLatin1Char('\n');
            for (const QStringList &cells : table) {
                QString line = cells.at(0).leftJustified(widths.at(0));
                for (qsizetype i = 1; i < cells.size(); ++i)
                    line += QStringLiteral("  ") + cells.at(i).rightJustified(widths.at(i));
                out += line + QLatin1Char('\n');
            }
        }
        out += QLatin1Char('\n');
    }
    // Where a recording's times were taken (README, "analyze"): not where a live poll takes them.
    QString from;
    QString to;
    if (report.kind == ExchangeSourceReport::Kind::Capture) {
        from = QStringLiteral("the capture time of the packet that completed the request");
        to = QStringLiteral("that of the packet that completed the answer");
    } else if (report.kind == ExchangeSourceReport::Kind::Journal) {
        TrafficMetadata metadata;
        QString ignored;
        const bool server = TrafficMetadata::fromJson(report.journal.metadata, &metadata, &ignored)
                            && metadata.role == TrafficMetadata::Role::Server;
        from = server ? QStringLiteral("the request's arrival (as the server read it)") : QStringLiteral("the start of the request's write");
        to = server ? QStringLiteral("the write of the answer's last piece") : QStringLiteral("the read that brought the answer's first byte");
        if (hasTwoLegs()) {
            from = QStringLiteral("answered: the request's arrival (as the tap read it) to the write of the answer's last piece; "
                                  "sent: the start of the request's write");
            to = QStringLiteral("the read that brought the answer's first byte");
        }
    }
    out += m_overall.summary(from, to);
    if (m_unmatched > 0)
        out += padded(QStringLiteral("unmatched")) + QStringLiteral("%1 answer(s) matching no request").arg(m_unmatched)
               + (report.journalDuplicates > 0
                      ? QStringLiteral(", %1 of them duplicates (a second answer to a request answered already)").arg(report.journalDuplicates)
                      : QString())
               + QLatin1Char('\n');
    if (report.kind == ExchangeSourceReport::Kind::Capture) {
        const auto &f = report.frames;
        if (f.lostBytes > 0 || f.retransmittedBytes > 0 || f.skippedBytes > 0 || report.pairs.malformedRequests > 0)
            out += padded(QStringLiteral("streams")) + QStringLiteral("%1 byte(s) lost in %2 gap(s), %3 retransmitted, %4 skipped by the framers, "
                                                                      "%5 malformed request(s)\n")
                                                            .arg(f.lostBytes).arg(f.gaps).arg(f.retransmittedBytes).arg(f.skippedBytes)
                                                            .arg(report.pairs.malformedRequests);
        if (f.gaps > 0 || f.joinedMidStream > 0)
            out += padded(QStringLiteral("gaps")) + QStringLiteral("%1 hole(s) in the capture (%2 byte(s) never captured, %3 byte(s) of frames they "
                                                                   "cut passed over), %4 stream(s) joined mid-way: framing resumed at the "
                                                                   "next frame, so only exchanges whose packets were lost are timeouts or "
                                                                   "unmatched answers\n")
                                                        .arg(f.gaps).arg(f.lostBytes).arg(f.cutByGapBytes).arg(f.joinedMidStream);
    }
    if (!report.problems.isEmpty()) {
        out += padded(QStringLiteral("problems")) + QStringLiteral("%1 found%2\n")
                                                       .arg(report.problemCount)
                                                       .arg(report.problemCount > quint64(report.problems.size())
                                                                ? QStringLiteral(", the first %1:").arg(report.problems.size())
                                                                : QStringLiteral(":"));
        for (const QString &p : report.problems)
            out += padded(QString()) + p + QLatin1Char('\n');
    }
    return out;
}

} // namespace mbscope
