#pragma once

#include "sim/simendpoint.h"
#include "sim/simresponder.h"

#include <QtCore/QTimer>

#include <memory>

class QSerialPort;

namespace mbscope {

class StreamFramer;

// rtu:// and ascii:// on a serial port (a pty in tests): the units on a bus. RTU frames are cut
// by their predicted length and ended by the t3.5 silence (Serial Line V1.02, 2.5.1.1; the
// framer's t35Ns for the URL's baud rate); ASCII frames by ':' and CR LF, an unfinished frame
// dropped after a second of silence (2.5.2.1). Answers leave one at a time, in request order.
class SimSerialEndpoint final : public SimEndpoint
{
    Q_OBJECT
public:
    SimSerialEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options);
    ~SimSerialEndpoint() override;

    bool start(QString *error) override;
    void stop() override;

private:
    void onReadyRead();
    void onSilence();
    void drain();

    QSerialPort *m_port = nullptr;
    std::unique_ptr<StreamFramer> m_framer;
    SimResponder m_responder;
    QTimer m_silence;
};

} // namespace mbscope
