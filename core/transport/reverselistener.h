#pragma once

#include "linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

// The listening side of a reverse connection (mode=listen, see TcpLink): a TCP server on the
// URL's address that keeps the connections devices open until the link takes one, and applies
// the URL's busy= policy to a connection that comes while another is held (BusyPolicy):
//   replace  every older waiting connection is closed; connectionWaiting() tells the link, which
//            drops the one in use;
//   queue    kept in order of arrival, at most kMaxWaiting; more are closed at once;
//   refuse   closed at once while a connection is in use or waiting.
// The listener keeps listening from its first listen() until it is destroyed, so that a device
// that dials again between two requests is taken by the next one; it closes whatever waits when
// it goes. Descriptors are plain POSIX sockets; a taken one belongs to the caller.
class ReverseListener : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxWaiting = 8;

    explicit ReverseListener(BusyPolicy policy, QObject *parent = nullptr);
    ~ReverseListener() override;

    // Starts listening on host:port (an IP address); does nothing while listening. Returns what
    // went wrong ("address in use: another program listens on 127.0.0.1:5020"), or an empty string.
    [[nodiscard]] QString listen(const QString &host, quint16 port);
    [[nodiscard]] bool isListening() const;

    // The oldest waiting connection whose device has not closed it (closed ones are dropped on
    // the way), or -1. A parked one (park()) first has the bytes that came meanwhile discarded:
    // they answer nothing the next open asks.
    [[nodiscard]] int take();
    // A connection the link lets go of without ending it (close() on request): the first to be
    // taken again. In use no longer.
    void park(int fd);
    // Whether the link holds a connection now (for busy=refuse and replace).
    void setInUse(bool inUse) { m_inUse = inUse; }

    [[nodiscard]] int waitingCount() const { return int(m_waiting.size()); }
    // Connections closed at once by the busy policy, or replaced, since the listener began.
    [[nodiscard]] quint64 turnedAway() const { return m_turnedAway; }

    // "127.0.0.1:40312", "[::1]:40312": the far end of a connection.
    [[nodiscard]] static QString peerOf(int fd);

Q_SIGNALS:
    // A device connected and its connection waits to be taken; peer is where it came from.
    void connectionWaiting(const QString &peer);

private:
    class Server;
    struct Waiting {
        int fd = -1;
        bool parked = false;
    };

    void onIncoming(int fd);
    void closeWaiting();

    BusyPolicy m_policy;
    Server *m_server; // a child
    QList<Waiting> m_waiting;
    bool m_inUse = false;
    quint64 m_turnedAway = 0;
};

} // namespace mbscope
