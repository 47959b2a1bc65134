#pragma once

#include "protocol/streamframe.h"
#include "sim/simresponder.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QTimer>

#include <memory>

class QTcpSocket;

namespace mbscope {

class SimEndpoint;
class SimTcpStream;
class Simulator;
class StreamFramer;

// One client of a stream endpoint (tcp, rtu-tcp, ascii-tcp, tls): its own framer (MBAP, RTU in
// the request direction, or ASCII), its own responder (answers in request order), an idle timer
// and a silence timer that ends unfinished frames. Plain TCP is read and written on the
// descriptor (SimTcpStream), TLS through its QSslSocket.
class SimConnection : public QObject
{
    Q_OBJECT
public:
    SimConnection(Simulator *simulator, SimEndpoint *endpoint, QTcpSocket *socket, QObject *parent = nullptr);
    ~SimConnection() override;

    [[nodiscard]] const QString &peer() const { return m_peer; }
    // Closes after what is already written has left; logged once with the reason.
    void close(const QString &reason);

Q_SIGNALS:
    void finished(mbscope::SimConnection *connection);

private:
    void onReadyRead();
    void onSilence();
    void onDisconnected();
    void drain();
    // The plan for one answer, to the responder (ordered: after the answers before it).
    void enqueue(const FaultPlan &plan, qint64 receivedNs);
    [[nodiscard]] bool isConnected() const;

    Simulator *m_simulator;
    SimEndpoint *m_endpoint;
    QTcpSocket *m_socket = nullptr;  // TLS
    SimTcpStream *m_stream = nullptr; // plain TCP
    std::unique_ptr<StreamFramer> m_framer;
    QList<StreamFrame> m_frames;   // drain()'s lists, kept between reads
    QList<SkippedBytes> m_skipped;
    SimResponder m_responder;
    QTimer m_idle;
    QTimer m_silence;
    QString m_peer;
    qint64 m_connectedNs = 0;
    bool m_closing = false;
    bool m_finished = false;
};

} // namespace mbscope
