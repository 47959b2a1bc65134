#pragma once

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>

#include <functional>
#include <optional>

namespace mbscope {

class Link;
class TrafficLog;
class TransactionEngine;

// One request at a time to a device, for the scans: a PDU completed for the link's framing and
// unit, sent by a TransactionEngine of its own (so its verdicts are the engine's), with a quiet
// gap kept between the end of one exchange and the next request. answered() carries the record
// and every byte read while it was in flight (frames, garbage and unsolicited bytes alike), so an
// echo or junk can be told from silence.
class ProbeChannel : public QObject
{
    Q_OBJECT
public:
    using LinkFactory = std::function<Link *(const LinkUrl &url, QObject *parent)>;

    explicit ProbeChannel(QObject *parent = nullptr);
    ~ProbeChannel() override;

    // The device; closes a link open to another one.
    void setTarget(const LinkUrl &url);
    void setLinkFactory(const LinkFactory &factory);
    [[nodiscard]] const LinkUrl &target() const { return m_url; }
    void setGapMs(int gapMs) { m_gapMs = gapMs; }
    // On every connection the channel opens from now on, the first request waits this long after
    // it opened (EngineOptions::warmUp). Closes the link open now.
    void setWarmUpMs(int warmUpMs);
    // Every frame in and out goes to log (a command's --record, the window's recording) until
    // setTrafficLog(nullptr), which writes the last ones to its journal; log must outlive that,
    // and be shared (TrafficLog::setShared) when another engine writes it too. Callable from
    // another thread than the channel's (it waits for the channel's thread to set it).
    void setTrafficLog(TrafficLog *log);
    [[nodiscard]] int gapMs() const { return m_gapMs; }

    // Sends pdu to unit after the gap; answered() follows once. One at a time: a call while a
    // probe is in flight is refused (false).
    bool probe(quint8 unit, const QByteArray &pdu, int timeoutMs);
    // Sends bytes exactly as given (a frame built by the caller: a PDU too long on purpose).
    bool probeRaw(const QByteArray &adu, int timeoutMs);
    [[nodiscard]] bool isBusy() const { return m_pendingId != 0 || m_waiting; }
    // probe(), then a local event loop until its answer: nullopt when the channel was busy or
    // cancel() came first. For the scans that decide each request from the last answer.
    struct Answer {
        Transaction transaction;
        QByteArray bytesRead;
    };
    [[nodiscard]] std::optional<Answer> ask(quint8 unit, const QByteArray &pdu, int timeoutMs);
    // probeRaw(), then the same wait: bytes exactly as given (the conformance battery's frames).
    [[nodiscard]] std::optional<Answer> askRaw(const QByteArray &adu, int timeoutMs);
    // Abandons the probe in flight (no answered() for it) and closes the link.
    void cancel();
    // Closes the link (a TCP client's connection: the next probe opens a new one).
    void closeLink();

    // The ADU for pdu to unit in the link's framing (MBAP transaction ids counting up).
    [[nodiscard]] QByteArray frame(quint8 unit, const QByteArray &pdu);

Q_SIGNALS:
    void answered(const mbscope::Transaction &transaction, const QByteArray &bytesRead);
    // Every frame in and out as the engine logs it (TransactionEngine::framesLogged): for a
    // traffic view.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void cancelled();
    // The engine opened the link (the first probe, and each after the link closed).
    void linkOpened();

private:
    void sendNow();
    void onTransactions(const QList<mbscope::Transaction> &transactions);
    void onFrames(const QList<mbscope::TrafficFrame> &frames);
    void deliver();
    [[nodiscard]] std::optional<Answer> waitForAnswer();

    TransactionEngine *m_engine;
    LinkUrl m_url;
    int m_warmUpMs = 0;
    int m_gapMs = 0;
    quint16 m_transactionId = 0;
    QByteArray m_nextAdu;
    int m_nextTimeoutMs = 0;
    bool m_waiting = false; // in the gap before sendNow
    quint64 m_pendingId = 0;
    quint64 m_generation = 0;
    Transaction m_done;
    bool m_haveDone = false;
    QByteArray m_bytesRead;
    QElapsedTimer m_sinceEnd;
};

} // namespace mbscope
