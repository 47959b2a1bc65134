#pragma once

#include "sim/simendpointoptions.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtCore/QString>

namespace mbscope {

class Simulator;

// One place the simulator listens on (tcp://, rtu-tcp://, ascii-tcp://, tls://, udp://,
// rtu-udp://, rtu://, ascii://). Endpoints cut frames out of what they receive and hand them to
// the Simulator, which answers with a FaultPlan they execute (SimResponder).
class SimEndpoint : public QObject
{
    Q_OBJECT
public:
    ~SimEndpoint() override;

    [[nodiscard]] const LinkUrl &url() const { return m_url; } // as asked for (port 0 stays 0)
    // As bound: the port the OS chose for port 0; serial endpoints: url().
    [[nodiscard]] const LinkUrl &boundUrl() const { return m_boundUrl; }
    [[nodiscard]] const QString &name() const { return m_name; } // boundUrl().toString()
    [[nodiscard]] const SimEndpointOptions &options() const { return m_options; }
    [[nodiscard]] Framing framing() const { return m_url.framing(); }
    [[nodiscard]] bool isListening() const { return m_listening; }
    // monotonicNowNs() when the endpoint started listening (a serial port: when it opened).
    [[nodiscard]] qint64 startedNs() const { return m_startedNs; }
    [[nodiscard]] virtual int connectionCount() const { return 0; }

    // Binds / opens; false with *error set ("rtu-tcp://127.0.0.1:4001: address in use").
    virtual bool start(QString *error) = 0;
    // Closes the listening socket or port and every connection.
    virtual void stop() = 0;

protected:
    SimEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options);
    [[nodiscard]] Simulator *simulator() const { return m_simulator; }
    void setBound(const LinkUrl &bound, bool listening);

private:
    Simulator *m_simulator;
    LinkUrl m_url;
    LinkUrl m_boundUrl;
    QString m_name;
    SimEndpointOptions m_options;
    bool m_listening = false;
    qint64 m_startedNs = 0;
};

} // namespace mbscope
