#pragma once

#include "link.h"

#include <QtCore/QList>
#include <QtCore/QTimer>
#include <QtSerialPort/QSerialPort>

#include <functional>
#include <memory>

namespace mbscope {

class LineControl;
class RtsDirection;

// A serial port: rtu:// and ascii:// (QSerialPort; baud, parity, data and stop bits from the URL,
// no flow control).
//
// When the bytes left: the link never blocks its thread, so it does not call tcdrain(). It
// computes the drain time from the line settings instead: the line is modelled as sending
// characters back to back, each lineCharacterNs() long (start bit, data bits, parity bit, stop
// bits at the baud rate), from the moment the kernel accepts them or the line frees up, whichever
// is later. bytesWritten(t) is emitted once that time has come, carrying the computed time. The
// kernel's output queue (TIOCOUTQ) is not used: it does not count the bytes already in the UART's
// FIFO. USB adapters add their own latency, which no host-side figure can see. On a pseudo
// terminal (socat) the bytes leave at once and the baud rate is only nominal; the computed time
// is then later than the truth.
// So a fast device's answer can arrive before bytesWritten is emitted: the engine must go by the
// timestamps, not the order of the signals. lineFreeNs() gives the computed time at once.
//
// RS-485 direction control (the URL's rts=, rts_before=, rts_after=, rs485=kernel; see
// RtsDirection): at open RTS goes to its resting level, or the driver's RS-485 mode is turned on,
// and a port that cannot do it (a pseudo terminal has no modem lines, a driver without
// TIOCSRS485) fails to open with a Config error that names the device and the OS's answer. Each
// write raises RTS first; after rts_before the bytes go (write() has returned true by then, and
// lineFreeNs() still gives the previous write's time, which is in the past), and RTS goes back
// rts_after after the computed drain time of the last byte.
class SerialLink final : public Link
{
    Q_OBJECT
public:
    explicit SerialLink(const LinkUrl &url, QObject *parent = nullptr);
    ~SerialLink() override;

    void open() override;
    void close() override;
    bool write(const QByteArray &bytes) override;

    [[nodiscard]] qint64 t15Ns() const override;
    [[nodiscard]] qint64 t35Ns() const override;
    [[nodiscard]] qint64 turnaroundNs() const override { return qint64(url().serial.turnaroundUs) * 1000; }

    // When the last byte written so far will have left the line, by the model above (0 before
    // any write); known as soon as write() returns.
    [[nodiscard]] qint64 lineFreeNs() const { return m_lineFreeNs; }
    // One character on the line with these settings: (1 + data + parity + stop) bits at the baud rate.
    [[nodiscard]] static qint64 lineCharacterNs(const SerialSettings &settings);

    // Why a device cannot be opened, from the operating system's error number (errno): missing
    // device, permission denied (naming the group that owns the device file and how to join it),
    // busy, not a serial port. Public so that tests can check it for EACCES as root, where the
    // kernel grants every access.
    [[nodiscard]] static QString openFailureMessage(const QString &device, int osError);
    // The group that owns a file ("dialout"), empty when it cannot be told.
    [[nodiscard]] static QString owningGroup(const QString &path);

    // Tests: what switches RTS and the driver's RS-485 mode on the open port's descriptor (by
    // default SerialLineControl, by ioctl). Set before open().
    using LineControlFactory = std::function<std::unique_ptr<LineControl>(int fd)>;
    void setLineControlFactory(LineControlFactory factory) { m_lineControlFactory = std::move(factory); }

private:
    void startOpen();
    void teardown();
    bool writeNow(const QByteArray &bytes);
    void onReadyRead();
    void onPortError(QSerialPort::SerialPortError error);
    [[nodiscard]] bool hungUp() const;
    void account();
    void scheduleDrain();
    void onDrainTimer();

    QSerialPort *m_port = nullptr;
    QTimer m_drainTimer;
    RtsDirection *m_rts = nullptr; // with the URL's RS-485 direction control only
    LineControlFactory m_lineControlFactory;
    QList<qint64> m_marks;  // m_submitted at the end of each write the kernel has not fully taken
    QList<qint64> m_drains; // computed drain times of the writes taken, not yet reported
    qint64 m_submitted = 0;
    qint64 m_accepted = 0;
    qint64 m_lineFreeNs = 0;
    int m_readErrors = 0; // read errors since the last bytes read
    bool m_inWrite = false;
};

} // namespace mbscope
