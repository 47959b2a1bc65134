#pragma once

#include "exchange/trafficentry.h"
#include "protocol/framingtraits.h"
#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QPair>

#include <functional>

namespace mbscope {

class ProbeChannel;
class TrafficLog;

// One request and everything it brought back.
struct ConformanceExchange {
    QByteArray request;
    Transaction transaction; // the engine's record: its status, exception code, matched answer and times
    QByteArray answer;       // every byte read while the request was in flight (empty: silence)
    int timeoutMs = 0;       // how long it waited
    // Timed out, and its own answer (by transaction id) came just after the timeout, among the
    // bytes read: a late answer, not bytes that answer nothing (answer.late counts it).
    bool late = false;

    [[nodiscard]] bool silent() const { return answer.isEmpty(); }
    [[nodiscard]] bool linkFailed() const { return transaction.status == TransactionStatus::LinkError; }
    // The link failed before the request was written (no connection could be opened, the port is
    // gone): the device was not asked at all.
    [[nodiscard]] bool unreachable() const { return linkFailed() && transaction.writeNs == 0; }
};

// The battery's way to the device: frames sent exactly as built, through the engine (a
// discovery ProbeChannel: one request at a time, every byte read while it was in flight), and
// every frame read kept, so that a check can ask what came after an answer (a duplicate) or
// during a silence it waits out (a broadcast).
class ConformanceLink
{
public:
    ConformanceLink(const LinkUrl &url, int timeoutMs);
    ~ConformanceLink();
    ConformanceLink(const ConformanceLink &) = delete;
    ConformanceLink &operator=(const ConformanceLink &) = delete;

    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] Framing framing() const { return m_url.framing(); }
    [[nodiscard]] bool isMbap() const { return framing() == Framing::Tcp || framing() == Framing::Udp; }
    [[nodiscard]] bool isSerialFraming() const { return isSerialLine(framing()); }
    [[nodiscard]] bool isStream() const { return !m_url.isSerial() && !m_url.isDatagram(); }
    [[nodiscard]] int timeoutMs() const { return m_timeoutMs; }

    // pdu to unit in the link's framing; MBAP transaction ids count up from 1.
    [[nodiscard]] QByteArray frame(quint8 unit, const QByteArray &pdu);
    // The ADU's transaction id, in MBAP framings (0 otherwise).
    [[nodiscard]] static quint16 transactionId(const QByteArray &adu);

    // Sends adu exactly and waits for its answer or its timeout (the link's when timeoutMs < 0).
    [[nodiscard]] ConformanceExchange exchange(const QByteArray &adu, int timeoutMs = -1);
    [[nodiscard]] ConformanceExchange ask(quint8 unit, const QByteArray &pdu) { return exchange(frame(unit, pdu)); }
    // Waits ms and returns every byte read in that time (answers nobody asked for).
    [[nodiscard]] QByteArray listen(int ms);
    // Frames read so far (In), for a check that looks back.
    [[nodiscard]] qsizetype framesRead() const { return m_in.size(); }
    [[nodiscard]] QByteArray bytesReadSince(qsizetype frame) const;
    // Every frame read, with the engine's verdict (late, unsolicited...) and transaction id.
    [[nodiscard]] const QList<TrafficFrame> &framesIn() const { return m_in; }
    // Frames from..to (indexes of framesIn) were expected by the check that read them (the
    // answers to pipelined requests after the first): not counted as unsolicited.
    void excuse(qsizetype from, qsizetype to) { m_excused.append({from, to}); }
    [[nodiscard]] bool isExcused(qsizetype frame) const;
    // Whether a late answer to the transaction came (after its timeout).
    [[nodiscard]] bool answeredLate(quint64 transactionId) const;
    // Closes the connection: the next exchange opens a new one.
    void closeLink();
    // Connections (or ports) opened so far: a device that closes after each answer makes one per request.
    [[nodiscard]] int opens() const { return m_opens; }
    // Exchanges whose request could not be written (ConformanceExchange::unreachable), and the
    // last one's problem: the runner's sign that the device is gone.
    [[nodiscard]] int unreachableCount() const { return m_unreachable; }
    // Exchanges the link dropped under after the request was written (the connection closed).
    [[nodiscard]] int droppedCount() const { return m_dropped; }
    [[nodiscard]] const QString &lastProblem() const { return m_lastProblem; }
    void setTrafficLog(TrafficLog *log);
    // Calls each with the frames the engine logs (ProbeChannel::framesLogged).
    void onFramesLogged(const std::function<void(const QList<TrafficFrame> &, const QString &)> &each);

private:
    LinkUrl m_url;
    int m_timeoutMs;
    quint16 m_transactionId = 0;
    ProbeChannel *m_channel;
    QList<TrafficFrame> m_in;
    int m_opens = 0;
    int m_unreachable = 0;
    int m_dropped = 0;
    QString m_lastProblem;
    QList<QPair<qsizetype, qsizetype>> m_excused;
};

} // namespace mbscope
