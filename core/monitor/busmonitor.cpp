#include "busmonitor.h"

#include "protocol/checksum.h"
#include "traffic/trafficlog.h"
#include "transport/link.h"
#include "transport/monotonicclock.h"

#include <chrono>

namespace mbscope {

namespace {

qint64 answerTimeout(const LinkUrl &url, const BusMonitor::Options &options)
{
    return url.responseTimeoutMs > 0 ? qint64(url.responseTimeoutMs) * 1'000'000 : options.answerTimeoutNs;
}

} // namespace

BusMonitor::BusMonitor(const LinkUrl &url, const Options &options, QObject *parent)
    : QObject(parent)
    , m_url(url)
    , m_framer(url.kind == LinkKind::Ascii || url.kind == LinkKind::AsciiTcp ? Framing::Ascii : Framing::Rtu, answerTimeout(url, options),
               [this](const CapturedFrame &frame) {
                   if (frame.direction == Direction::Response && frame.status == FrameStatus::Truncated)
                       m_truncatedAnswers.insert(frame.packet);
                   m_pairer.add(frame);
               })
    , m_pairer(answerTimeout(url, options), [this](const CaptureExchange &exchange) { onExchange(exchange); })
{
    m_link = Link::create(url, this);
    m_link->setListenOnly(true);
    m_statistics.setMeasuredOnTheLine(true);
    m_silenceNs = options.silenceNs;
    if (m_silenceNs <= 0)
        m_silenceNs = m_link->t35Ns() > 0 ? qMax(m_link->t35Ns(), kMinSilenceNs) : kNetworkSilenceNs;
    m_framer.setGarbageSink([this](const SkippedBytes &run, qint64 timeNs) { onGarbage(run, timeNs); });

    // Children, so that moveToThread() takes them along (the window runs a monitor on a thread of its own).
    m_silenceTimer.setParent(this);
    m_tick.setParent(this);
    m_silenceTimer.setSingleShot(true);
    m_silenceTimer.setTimerType(Qt::PreciseTimer);
    m_silenceTimer.setInterval(std::chrono::nanoseconds(m_silenceNs) < std::chrono::milliseconds(1)
                                   ? std::chrono::milliseconds(1)
                                   : std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::nanoseconds(m_silenceNs + 999'999)));
    connect(&m_silenceTimer, &QTimer::timeout, this, &BusMonitor::onSilence);
    m_tick.setInterval(std::chrono::milliseconds(50));
    connect(&m_tick, &QTimer::timeout, this, &BusMonitor::onTick);

    connect(m_link, &Link::bytesReceived, this, &BusMonitor::onBytes);
    connect(m_link, &Link::opened, this, [this] {
        m_tick.start();
        Q_EMIT opened();
    });
    connect(m_link, &Link::errorOccurred, this, [this](const LinkError &error) {
        if (!m_stopped && m_link->state() == Link::State::Closed)
            Q_EMIT linkFailed(error.message);
    });
}

BusMonitor::~BusMonitor() = default;

QString BusMonitor::unsupportedReason(const LinkUrl &url)
{
    switch (url.kind) {
    case LinkKind::Rtu:
    case LinkKind::Ascii:
    case LinkKind::RtuTcp:
    case LinkKind::AsciiTcp:
        if (url.delimited.enabled)
            return QStringLiteral("a delimited framing has no requests and answers to pair: a monitor listens to Modbus RTU or ASCII");
        return {};
    case LinkKind::Tcp:
    case LinkKind::Tls:
    case LinkKind::Udp:
        return QStringLiteral("%1:// carries Modbus between one client and this program, not a bus another master drives: "
                              "listen with rtu:// or ascii:// on the line's serial port, or rtu-tcp:// on a serial device "
                              "server's port (to see Modbus TCP traffic, capture it with Wireshark or tcpdump and use "
                              "mbscope analyze)")
            .arg(LinkUrl::schemeName(url.kind));
    case LinkKind::RtuUdp:
        return QStringLiteral("rtu-udp:// is not a stream a monitor can listen to: use rtu:// on the line's serial port, "
                              "or rtu-tcp:// on a serial device server's port");
    }
    return {};
}

void BusMonitor::setTrafficLog(TrafficLog *log)
{
    m_log = log;
    if (m_log)
        m_logLink = m_log->addLink(m_url.toString());
}

void BusMonitor::start()
{
    m_stopped = false;
    m_link->open();
}

void BusMonitor::stop()
{
    if (m_stopped)
        return;
    m_stopped = true;
    m_silenceTimer.stop();
    m_tick.stop();
    m_framer.silence();
    m_pairer.finish();
    m_link->close();
    if (m_log)
        m_log->flush();
}

void BusMonitor::onBytes(const QByteArray &bytes, qint64, qint64 lastByteNs)
{
    if (m_stopped)
        return;
    m_bytes += quint64(bytes.size());
    m_framer.feed(bytes, lastByteNs);
    if (m_framer.pendingSize() > 0)
        m_silenceTimer.start();
}

void BusMonitor::onSilence()
{
    m_framer.silence();
}

void BusMonitor::onTick()
{
    const qint64 now = monotonicNowNs();
    m_pairer.advance(now);
    if (m_log)
        m_log->flushIfDue(now);
}

void BusMonitor::onExchange(const CaptureExchange &exchange)
{
    CaptureExchange seen = exchange;
    Transaction &t = seen.transaction;
    // An answer the framer could not delimit for its CRC is a CRC error, as the engine counts it.
    if (seen.framing == Framing::Rtu && !t.response.isEmpty() && t.status == TransactionStatus::Malformed
        && checksum::crc16Modbus(t.response) != 0) {
        t.status = TransactionStatus::CrcError;
        t.problem = QStringLiteral("the answer's CRC is wrong (the line damaged it)");
    }
    // An answer cut short fails its CRC too, but what the line did to it is lose its end.
    if (seen.responsePacket != 0 && m_truncatedAnswers.remove(seen.responsePacket) && t.status == TransactionStatus::CrcError) {
        t.status = TransactionStatus::Malformed;
        t.problem = QStringLiteral("the answer was cut short: %1 bytes before the silence, and its CRC does not match")
                        .arg(t.response.size());
    }
    if (seen.kind == CaptureExchange::Kind::Transaction)
        m_statistics.add(t);
    if (m_log) {
        const TrafficVerdict verdict = seen.kind == CaptureExchange::Kind::UnmatchedResponse ? TrafficVerdict::Unsolicited
                                                                                          : trafficVerdict(t.status);
        if (!t.request.isEmpty() && t.status != TransactionStatus::Late)
            m_log->append(t.sentNs, TrafficDirection::Out, m_logLink, verdict, t.id, t.request);
        if (!t.response.isEmpty())
            m_log->append(t.firstByteNs, TrafficDirection::In, m_logLink, verdict,
                          seen.kind == CaptureExchange::Kind::UnmatchedResponse ? 0 : t.id, t.response);
    }
    Q_EMIT exchangeObserved(seen);
}

void BusMonitor::onGarbage(const SkippedBytes &run, qint64 timeNs)
{
    if (m_log)
        m_log->append(timeNs, TrafficDirection::In, m_logLink, TrafficVerdict::Garbage, 0, run.bytes);
}

} // namespace mbscope

#include "moc_busmonitor.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
