#include "sim/simserialendpoint.h"

#include <QtCore/QPointer>

#include "protocol/asciiframer.h"
#include "protocol/delimitedframer.h"
#include "protocol/rtuframer.h"
#include "sim/simulator.h"
#include "transport/monotonicclock.h"
#include "transport/rtsdirection.h"
#include "transport/seriallinecontrol.h"
#include "transport/seriallink.h"

#include <QtSerialPort/QSerialPort>

#include <algorithm>

namespace mbscope {

namespace {

constexpr int kAsciiSilenceMs = 1000; // Serial Line V1.02, 2.5.2.1: up to 1 s between characters

} // namespace

SimSerialEndpoint::SimSerialEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options)
    : SimEndpoint(simulator, url, options)
    , m_responder(true, this)
    , m_silence(this)
{
    m_silence.setSingleShot(true);
    m_silence.setTimerType(Qt::PreciseTimer);
    connect(&m_silence, &QTimer::timeout, this, &SimSerialEndpoint::onSilence);
    if (url.serial.rs485.enabled()) {
        m_rts = new RtsDirection(url.serial.rs485, url.serial.device, [this](const QByteArray &answer) { return writeAnswer(answer); },
                                 this);
        connect(m_rts, &RtsDirection::failed, this, [this](const QString &what) {
            this->simulator()->noteConnection(this, this->url().serial.device, SimLogEntry::Verdict::ConnectionClosed, what);
        });
    }
}

SimSerialEndpoint::~SimSerialEndpoint()
{
    stop();
}

bool SimSerialEndpoint::start(QString *error)
{
    const SerialSettings &s = url().serial;
    m_port = new QSerialPort(s.device, this);
    m_port->setBaudRate(s.baud);
    m_port->setDataBits(QSerialPort::DataBits(s.dataBits));
    m_port->setParity(s.parity == 'E' ? QSerialPort::EvenParity
                      : s.parity == 'O' ? QSerialPort::OddParity
                                        : QSerialPort::NoParity);
    m_port->setStopBits(s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port->open(QIODevice::ReadWrite)) {
        *error = url().toString() + QStringLiteral(": cannot open %1: %2").arg(s.device, m_port->errorString());
        delete m_port;
        m_port = nullptr;
        return false;
    }
    if (m_rts) {
        const QString why = m_rts->start(std::make_unique<SerialLineControl>(int(m_port->handle())));
        if (!why.isEmpty()) {
            *error = url().toString() + QStringLiteral(": ") + why;
            m_port->close();
            delete m_port;
            m_port = nullptr;
            return false;
        }
    }
    m_lineFreeNs = 0;
    if (url().delimited.enabled) {
        m_framer = std::make_unique<DelimitedFramer>(url().delimited);
    } else if (url().kind == LinkKind::Rtu) {
        auto rtu = std::make_unique<RtuFramer>(Direction::Request);
        rtu->setBaudRate(s.baud);
        rtu->setDropsBadFrames(true); // a request whose CRC fails is dropped whole, the next read at once
        m_framer = std::move(rtu);
    } else {
        m_framer = std::make_unique<AsciiFramer>();
    }
    connect(m_port, &QSerialPort::readyRead, this, &SimSerialEndpoint::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        if (e == QSerialPort::NoError || e == QSerialPort::TimeoutError)
            return;
        simulator()->noteConnection(this, url().serial.device, SimLogEntry::Verdict::ConnectionClosed,
                                    QStringLiteral("serial port error: %1").arg(m_port->errorString()));
        if (e == QSerialPort::ResourceError) // the device is gone (the pty's other end closed)
            stop();
    });
    setBound(url(), true);
    return true;
}

void SimSerialEndpoint::stop()
{
    m_silence.stop();
    m_responder.clear();
    if (m_rts)
        m_rts->stop(); // while the port is open: RTS back to rest, the driver's settings back
    if (m_port && m_port->isOpen())
        m_port->close();
    setBound(boundUrl(), false);
}

void SimSerialEndpoint::onReadyRead()
{
    const QByteArray bytes = m_port->readAll();
    if (bytes.isEmpty())
        return;
    m_framer->feed(bytes, monotonicNowNs());
    drain();
    if (m_framer->pendingSize() + m_framer->openSkippedRunSize() == 0) {
        m_silence.stop();
        return;
    }
    if (url().kind == LinkKind::Rtu && !url().delimited.enabled) {
        // t3.5 after the last byte, rounded up to whole milliseconds (timers have no finer grain).
        const qint64 t35 = RtuFramer::t35Ns(url().serial.baud);
        m_silence.start(int(std::max<qint64>(1, (t35 + 999'999) / 1'000'000)));
    } else {
        m_silence.start(kAsciiSilenceMs);
    }
}

void SimSerialEndpoint::onSilence()
{
    if (!m_framer->onSilence(monotonicNowNs())) {
        m_silence.start(1); // the timer fired a little early
        return;
    }
    drain();
}

void SimSerialEndpoint::drain()
{
    const QString &device = url().serial.device;
    const QList<StreamFrame> frames = m_framer->takeFrames();
    const QList<SkippedBytes> skipped = m_framer->takeSkipped();
    qsizetype f = 0;
    qsizetype s = 0;
    while (f < frames.size() || s < skipped.size()) {
        if (s < skipped.size() && (f >= frames.size() || skipped.at(s).offset < frames.at(f).offset)) {
            simulator()->noteSkipped(this, skipped.at(s++), device);
            continue;
        }
        const StreamFrame &frame = frames.at(f++);
        const qint64 received = frame.lastByteNs != 0 ? frame.lastByteNs : monotonicNowNs();
        QPointer<SimSerialEndpoint> self(this);
        simulator()->takeFrame(this, frame.bytes, frame.status, device, received, 0, [self, received](const FaultPlan &plan) {
            if (!self)
                return;
            self->m_responder.enqueue(self->keepFrameGap(plan), received, [endpoint = self.data(), id = plan.trafficId](const QByteArray &answer) {
                if (!endpoint->m_port || !endpoint->m_port->isOpen())
                    return;
                if (endpoint->m_rts)
                    endpoint->m_rts->send(answer); // now, or once RTS has been up rts_before
                else
                    endpoint->m_port->write(answer);
                endpoint->simulator()->noteSent(endpoint, answer, id);
            });
        });
    }
}

FaultPlan SimSerialEndpoint::keepFrameGap(const FaultPlan &plan) const
{
    if (url().kind != LinkKind::Rtu || url().delimited.enabled || plan.chunks.isEmpty())
        return plan;
    // A frame is cut as soon as its length is in, so without this the answer could start sooner
    // than t3.5 after the request's last byte, and a slave on the bus that frames by silence would
    // take the request and the answer for one frame (Serial Line V1.02, 2.5.1.1). A delay longer
    // than t3.5 (the unit's, a fault's) already keeps it.
    FaultPlan kept = plan;
    qint64 &first = kept.chunks.first().delayNs;
    first = std::max(first, RtuFramer::t35Ns(url().serial.baud));
    return kept;
}

bool SimSerialEndpoint::writeAnswer(const QByteArray &answer)
{
    if (!m_port || !m_port->isOpen() || m_port->write(answer) != answer.size())
        return false;
    m_port->flush(); // to the kernel now: the line time counts from here
    // SerialLink's line model: characters back to back from the moment the kernel has them.
    const qint64 start = qMax(monotonicNowNs(), m_lineFreeNs);
    m_lineFreeNs = start + answer.size() * SerialLink::lineCharacterNs(url().serial);
    m_rts->drained(m_lineFreeNs);
    return true;
}

} // namespace mbscope

#include "moc_simserialendpoint.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
