#pragma once

#include "linkurl.h"

#include <QtCore/QByteArray>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

// What went wrong on a link, said for a person: which link, which address, and what the
// operating system answered ("tcp://192.168.127.254:4001: connection refused (the host answered,
// nothing listens on port 4001)"; "rtu:///dev/ttyUSB0: permission denied: add yourself to the
// 'dialout' group").
struct LinkError {
    enum class Kind : quint8 { None, Config, NotFound, Permission, Refused, Timeout, Closed, Io };
    Kind kind = Kind::None;
    QString message;
};

// One connection to a device: bytes out, bytes in, with monotonic nanosecond timestamps. Links
// know nothing of Modbus; framing, matching and timing verdicts belong to the engine.
// A link lives in the engine's thread; all calls come from that thread.
class Link : public QObject
{
    Q_OBJECT
public:
    enum class State : quint8 { Closed, Opening, Open };

    ~Link() override;

    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] virtual bool isDatagram() const { return false; }

    // Starts opening; opened() or errorOccurred() follows (connect timeout from the URL).
    virtual void open() = 0;
    virtual void close() = 0;
    // Writes the bytes exactly as given. Returns false (and emits errorOccurred) when the link
    // cannot take them. bytesWritten(tNs) follows once the last byte has left for the wire as
    // far as the operating system lets us know (TCP: accepted by the kernel; serial: drained).
    virtual bool write(const QByteArray &bytes) = 0;

    // Creates the link a URL names (TcpLink, UdpLink, SerialLink, TlsLink).
    [[nodiscard]] static Link *create(const LinkUrl &url, QObject *parent = nullptr);

signals:
    void opened();
    void closed(const QString &reason);
    void bytesWritten(qint64 lastByteNs);
    // One read's worth of bytes; a datagram link emits exactly one datagram per signal.
    // firstByteNs/lastByteNs: when the first and the last byte of this chunk were seen.
    void bytesReceived(const QByteArray &bytes, qint64 firstByteNs, qint64 lastByteNs);
    void errorOccurred(const mbscope::LinkError &error);

protected:
    explicit Link(const LinkUrl &url, QObject *parent = nullptr);
    void setState(State state) { m_state = state; }

private:
    LinkUrl m_url;
    State m_state = State::Closed;
};

} // namespace mbscope
