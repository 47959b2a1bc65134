#pragma once

#include "sim/simendpoint.h"
#include "sim/simresponder.h"

#include <QtCore/QTimer>

#include <memory>

class QSerialPort;

namespace mbscope {

class RtsDirection;
class StreamFramer;

// rtu:// and ascii:// on a serial port (a pty in tests): the units on a bus. RTU frames are cut
// by their predicted length and ended by the t3.5 silence (Serial Line V1.02, 2.5.1.1; the
// framer's t35Ns for the URL's baud rate); ASCII frames by ':' and CR LF, an unfinished frame
// dropped after a second of silence (2.5.2.1). Answers leave one at a time, in request order; an
// RTU answer never starts sooner than t3.5 after its request's last byte was read.
// With the URL's RS-485 options (rts=, rts_before=, rts_after=, rs485=kernel) the slave drives its
// transmitter as a link does (RtsDirection): RTS to rest at start, raised around each answer and
// put back after the answer's computed line time; a port that cannot do it is refused at start.
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
    bool writeAnswer(const QByteArray &answer);
    // RTU: the plan with its first chunk no sooner than t3.5 after the request (ASCII unchanged).
    [[nodiscard]] FaultPlan keepFrameGap(const FaultPlan &plan) const;

    QSerialPort *m_port = nullptr;
    std::unique_ptr<StreamFramer> m_framer;
    SimResponder m_responder;
    QTimer m_silence;
    RtsDirection *m_rts = nullptr; // with the URL's RS-485 direction control only
    qint64 m_lineFreeNs = 0;       // when the last answer will have left the line
};

} // namespace mbscope
