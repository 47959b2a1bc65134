#pragma once

#include "busframer.h"

#include "capture/captureexchange.h"
#include "capture/exchangepairer.h"
#include "exchange/statistics.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QStringList>
#include <QtCore/QTimer>

#include <memory>

namespace mbscope {

class Link;
class TrafficLog;

// A listen-only tap on a bus another master drives: an RS485 line through a serial port (rtu://,
// ascii://) or a serial device server's port (rtu-tcp://, ascii-tcp://). The link is opened
// listen-only (Link::setListenOnly: a serial port for reading only, and no write ever made), its
// bytes are framed both ways at once (BusFramer), the frames paired into exchanges as a capture's
// are (ExchangePairer: order, unit and function code) and judged as the engine judges an answer
// (ResponseVerdict); a damaged answer is a CRC error. Statistics are the engine's, over the
// exchanges seen. Latency is the time from the request's last byte to the answer's last byte
// as the tap read them (poll's measure).
class BusMonitor : public QObject
{
    Q_OBJECT
public:
    struct Options {
        // How long a request waits for its answer before it counts as a timeout. The URL's
        // timeout= when it has one, else this.
        qint64 answerTimeoutNs = 1'000'000'000;
        // The quiet time that ends a frame: 0 for the link's t3.5 (Serial Line V1.02, 2.5.1.1),
        // at least kMinSilenceNs; on a network link (no character timing) kNetworkSilenceNs.
        qint64 silenceNs = 0;
    };
    // A timer cannot be trusted below a couple of milliseconds, and a serial driver (a USB
    // adapter's latency timer, a device server's packets) delivers bytes in bursts.
    static constexpr qint64 kMinSilenceNs = 2'000'000;
    static constexpr qint64 kNetworkSilenceNs = 20'000'000;

    BusMonitor(const LinkUrl &url, const Options &options, QObject *parent = nullptr);
    ~BusMonitor() override;

    // Empty when the URL names a link a monitor can listen on; else why not ("tcp:// carries
    // MBAP between one client and one server: there is no bus to listen to ...").
    [[nodiscard]] static QString unsupportedReason(const LinkUrl &url);

    // Every frame seen goes into the log (requests as Out, answers as In with their exchange's
    // verdict, unmatched answers as Unsolicited, skipped bytes as Garbage). Set before start().
    void setTrafficLog(TrafficLog *log);

    // Opens the link (listen-only); opened() or linkFailed() follows.
    void start();
    // Ends what is pending (a frame waiting for its silence, requests waiting for an answer: those
    // are timeouts) and closes the link. The statistics are final then.
    void stop();

    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] Link *link() const { return m_link; }
    [[nodiscard]] qint64 silenceNs() const { return m_silenceNs; }
    [[nodiscard]] const Statistics &statistics() const { return m_statistics; }
    [[nodiscard]] const BusCounters &bus() const { return m_framer.counters(); }
    [[nodiscard]] const ExchangePairer::Counters &pairing() const { return m_pairer.counters(); }
    [[nodiscard]] quint64 unmatchedResponses() const { return m_pairer.counters().unmatchedResponses; }
    [[nodiscard]] QStringList problems() const { return m_pairer.problems(); }
    [[nodiscard]] quint64 problemCount() const { return m_pairer.problemCount(); }
    [[nodiscard]] quint64 bytesSeen() const { return m_bytes; }

Q_SIGNALS:
    void opened();
    // One exchange, as soon as its outcome is known (answered, damaged, timed out), in request order.
    void exchangeObserved(const mbscope::CaptureExchange &exchange);
    // The link could not be opened, or was lost: what the operating system said.
    void linkFailed(const QString &message);

private:
    void onBytes(const QByteArray &bytes, qint64 firstByteNs, qint64 lastByteNs);
    void onSilence();
    void onTick();
    void onExchange(const CaptureExchange &exchange);
    void onGarbage(const SkippedBytes &run, qint64 timeNs);

    LinkUrl m_url;
    Link *m_link = nullptr;
    qint64 m_silenceNs = 0;
    BusFramer m_framer;
    ExchangePairer m_pairer;
    Statistics m_statistics;
    QSet<quint64> m_truncatedAnswers; // frame numbers of answers a silence cut short
    TrafficLog *m_log = nullptr;
    quint16 m_logLink = 0;
    QTimer m_silenceTimer;
    QTimer m_tick;
    quint64 m_bytes = 0;
    bool m_stopped = false;
};

} // namespace mbscope
