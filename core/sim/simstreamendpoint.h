#pragma once

#include "sim/simendpoint.h"

#include <QtCore/QList>

class QTcpServer;

namespace mbscope {

class SimConnection;

// tcp:// (MBAP), rtu-tcp:// and ascii-tcp:// (RTU or ASCII frames over a TCP stream) and
// tls:// (MBAP over mutual TLS, MODBUS/TCP Security): a QTcpServer (QSslServer for tls) taking
// many clients at once, one SimConnection each. Binds the URL's host, 127.0.0.1 by default.
//
// tls:// needs cert= and key= (the server's certificate and private key, PEM); with ca= every
// client must present a certificate signed by that CA (mutual TLS), without it clients are not
// asked for one.
class SimStreamEndpoint final : public SimEndpoint
{
    Q_OBJECT
public:
    SimStreamEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options);
    ~SimStreamEndpoint() override;

    bool start(QString *error) override;
    void stop() override;
    [[nodiscard]] int connectionCount() const override { return int(m_connections.size()); }

private:
    void onNewConnection();
    bool configureTls(QString *error);

    QTcpServer *m_server = nullptr;
    QList<SimConnection *> m_connections;
};

} // namespace mbscope
