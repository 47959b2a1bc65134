#pragma once

#include "linkreceiver.h"
#include "linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

// What went wrong on a link, said for a person: which link, which address, and what the
// operating system answered ("tcp://192.168.127.254:4001: connection refused (the host answered,
// nothing listens on port 4001)"; "rtu:///dev/ttyUSB0: permission denied: add yourself to the
// 'dialout' group").
struct LinkError {
    enum class Kind : quint8 {
        None,
        Config,     // the URL's settings cannot be used (unreadable certificate, unsupported baud rate)
        NotFound,   // no such host or device
        Permission, // the operating system refused access (serial device permissions)
        Refused,    // the host answered: nothing listens there (TCP RST, ICMP port unreachable)
        Timeout,    // no connection within the connect timeout
        Closed,     // the peer closed the connection, or the link was not open
        Io,         // any other failure the operating system reported
        Handshake,  // TLS: the handshake failed (certificate, CA, protocol)
    };
    Kind kind = Kind::None;
    QString message; // begins with the link's URL
};

// One connection to a device: bytes out, bytes in, with monotonic nanosecond timestamps. Links
// know nothing of Modbus; framing, matching and timing verdicts belong to the engine.
// A link lives in the engine's thread; all calls come from that thread, and no call blocks it
// (no waitFor*: everything is signalled).
//
// Life cycle: open() -> opened() or errorOccurred() (state back to Closed). While open, a lost
// connection emits errorOccurred() then closed(reason). close() emits closed() when the link was
// open or opening. open() after close() or after a loss opens again: the engine reconnects on its
// next request by calling open() when state() is Closed. close() is immediate and never fails.
// Some errors leave the link open (a serial write error, a UDP "port unreachable" should Qt
// report one): check state() after errorOccurred().
class Link : public QObject
{
    Q_OBJECT
public:
    enum class State : quint8 { Closed, Opening, Open };

    ~Link() override;

    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] bool isOpen() const { return m_state == State::Open; }
    [[nodiscard]] virtual bool isDatagram() const { return false; }
    // The last error reported (kind None before any).
    [[nodiscard]] const LinkError &lastError() const { return m_lastError; }

    // Serial timing for the engine, 0 on links without it (network links carry no silences).
    // t1.5 and t3.5 follow RtuFramer's rule (Serial Line V1.02, 2.5.1.1: 11-bit characters, fixed
    // 750 us and 1750 us above 19200 baud); turnaround is the URL's RS485 turnaround delay, the
    // wait after a broadcast (Serial Line V1.02, 2.4.1) and before expecting an answer.
    [[nodiscard]] virtual qint64 t15Ns() const { return 0; }
    [[nodiscard]] virtual qint64 t35Ns() const { return 0; }
    [[nodiscard]] virtual qint64 turnaroundNs() const { return 0; }

    // Starts opening; opened() or errorOccurred() follows, always after open() has returned
    // (connect timeout from the URL). Does nothing while opening or open.
    virtual void open() = 0;
    virtual void close() = 0;
    // Writes the bytes exactly as given. Returns false (and emits errorOccurred) when the link
    // cannot take them. bytesWritten(tNs) follows once per write, in order, once the last byte has
    // left for the wire as far as the operating system lets us know (TCP: the clock read just
    // before the send() that handed the kernel the last byte, see TcpLink; TLS: accepted by the
    // kernel; UDP: sent; serial: drained, see SerialLink). It may be emitted before write() returns.
    virtual bool write(const QByteArray &bytes) = 0;

    // While a receiver is set, received bytes and write times go to it by a direct call and
    // bytesReceived() / bytesWritten() are not emitted (links that emit those signals themselves,
    // as test doubles may, still reach whoever is connected). Same thread only; nullptr: signals.
    void setReceiver(LinkReceiver *receiver) { m_receiver = receiver; }

    // A listen-only link (the bus monitor) never sends a byte: a serial port is opened for reading
    // only, and write() refuses (errorOccurred with Kind::Config) on every link. Set before open().
    void setListenOnly(bool listenOnly) { m_listenOnly = listenOnly; }
    [[nodiscard]] bool isListenOnly() const { return m_listenOnly; }

    // Creates the link a URL names (TcpLink for tcp, rtu-tcp and ascii-tcp; UdpLink for udp and
    // rtu-udp; SerialLink for rtu and ascii; TlsLink for tls), closed. The caller owns it.
    [[nodiscard]] static Link *create(const LinkUrl &url, QObject *parent = nullptr);

Q_SIGNALS:
    void opened();
    void closed(const QString &reason);
    void bytesWritten(qint64 lastByteNs);
    // One read's worth of bytes; a datagram link emits exactly one datagram per signal.
    // firstByteNs/lastByteNs: when the first and the last byte of this chunk were seen. Links take
    // one monotonicNowNs() in their read handler, so the bytes of a chunk share one time (the
    // operating system does not say when each byte came): firstByteNs == lastByteNs.
    void bytesReceived(const QByteArray &bytes, qint64 firstByteNs, qint64 lastByteNs);
    void errorOccurred(const mbscope::LinkError &error);

protected:
    explicit Link(const LinkUrl &url, QObject *parent = nullptr);
    void setState(State state) { m_state = state; }
    // What subclasses call instead of emitting bytesReceived() / bytesWritten(): the receiver, or
    // the signal when there is none.
    void deliverReceived(const QByteArray &bytes, qint64 firstByteNs, qint64 lastByteNs)
    {
        if (m_receiver)
            m_receiver->linkBytesReceived(bytes, firstByteNs, lastByteNs);
        else
            Q_EMIT bytesReceived(bytes, firstByteNs, lastByteNs);
    }
    void deliverWritten(qint64 lastByteNs)
    {
        if (m_receiver)
            m_receiver->linkBytesWritten(lastByteNs);
        else
            Q_EMIT bytesWritten(lastByteNs);
    }
    // Records and emits an error; the message is prefixed with the URL ("tcp://h:502: ...").
    void reportError(LinkError::Kind kind, const QString &what);
    // Closed from Open or Opening: sets the state and emits closed(reason) once.
    void setClosed(const QString &reason);
    // write() on a listen-only link: reports why nothing is sent. True when the write must stop.
    [[nodiscard]] bool refuseWriteWhenListening(qsizetype byteCount);
    // The open link was lost: state Closed, errorOccurred, then closed(message).
    void reportLoss(LinkError::Kind kind, const QString &what);
    // The operating system's answer as Qt words it ("Connection refused"), made to read inside a
    // sentence ("connection refused").
    [[nodiscard]] static QString osAnswer(const QString &errorString);

private:
    LinkUrl m_url;
    State m_state = State::Closed;
    LinkError m_lastError;
    LinkReceiver *m_receiver = nullptr;
    bool m_listenOnly = false;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::LinkError)
