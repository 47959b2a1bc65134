#pragma once

#include "duetimer.h"
#include "linecontrol.h"
#include "rs485settings.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <functional>
#include <memory>

namespace mbscope {

// RS-485 direction control around the sends of one serial port, as libmodbus's modbus_rtu_set_rts
// does it (RTS to its sending level, rts_before, the bytes, their line time, rts_after, RTS back),
// but without blocking the thread: libmodbus sleeps (usleep) and waits for the UART (tcdrain);
// here the bytes are held back by a timer and RTS is put back by another, at the time the port's
// owner says the last byte will have left the line (SerialLink's lineFreeNs, from the line
// settings). The timer is a DueTimer (timerfd, to the microsecond, spinning its last 200 us), so
// RTS goes back within tens of microseconds of lineFreeNs + rts_after on an idle machine, not on
// the next millisecond tick; a device that answers sooner than that after the last byte still
// finds the transmitter on (rs485=kernel switches in the driver, at the bit).
//
// With rs485=kernel, start() turns the driver's RS-485 mode on (TIOCSRS485: the level and the
// delays, in whole milliseconds) and sends go straight through; stop() puts the driver's former
// settings back. Used by SerialLink (every command's serial link) and SimSerialEndpoint (a
// simulated slave drives its transmitter too).
class RtsDirection final : public QObject
{
    Q_OBJECT
public:
    // Hands bytes to the port; false when it could not (the writer has said why).
    using Writer = std::function<bool(const QByteArray &bytes)>;
    using Clock = std::function<qint64()>;

    RtsDirection(const Rs485Settings &settings, const QString &device, Writer writer, QObject *parent = nullptr);

    // Tests: a clock of their own instead of monotonicNowNs(), read at every call.
    void setClock(Clock clock) { m_clock = std::move(clock); }

    // At open, before any send: RTS to its resting level (the transmitter off: the kernel asserts
    // RTS when it opens a port), or the driver's RS-485 mode on (kernel). Empty, or what failed,
    // naming the device, the option and the operating system's answer.
    [[nodiscard]] QString start(std::unique_ptr<LineControl> lines);
    // At close, while the port is still open: RTS back to rest at once, or the driver's former
    // RS-485 settings back. Bytes still held back are dropped.
    void stop();
    [[nodiscard]] bool isStarted() const { return m_lines != nullptr; }

    // Sends bytes: RTS to its sending level if it is not there yet, then the bytes, at once when
    // RTS was already there (a send during the previous one or its rts_after) or rts_before is 0,
    // else rts_before later (and every send made meanwhile behind them, in order). False when RTS
    // cannot be switched (failed() says why) or the writer fails at once.
    bool send(const QByteArray &bytes);
    // What was handed to the port will have left the line at lineFreeNs: RTS goes back to rest at
    // lineFreeNs + rts_after, unless a send comes first. Ignored while bytes are held back (their
    // own drain time follows) and while RTS is at rest.
    void drained(qint64 lineFreeNs);

    // When something is due next (held bytes to hand over, RTS to put back), 0 when nothing is.
    [[nodiscard]] qint64 deadlineNs() const;
    // Does what is due by now. The timer calls it; tests call it with their own clock.
    void service();
    // RTS at its sending level.
    [[nodiscard]] bool isSending() const { return m_sending; }

Q_SIGNALS:
    // RTS could not be switched during a send (an adapter unplugged): the message names the device.
    void failed(const QString &what);

private:
    [[nodiscard]] qint64 now() const;
    [[nodiscard]] QString startKernel();
    bool writeNow(const QByteArray &bytes);
    bool switchRts(bool sending, const char *when);
    void arm();

    Rs485Settings m_settings;
    QString m_device;
    Writer m_writer;
    Clock m_clock;
    std::unique_ptr<LineControl> m_lines;
    DueTimer m_timer;
    QList<QByteArray> m_held; // sends waiting for rts_before
    qint64 m_sendAtNs = 0;    // when the held sends go
    qint64 m_restAtNs = 0;    // when RTS goes back to rest (0: not planned)
    bool m_sending = false;
    bool m_kernelSet = false;
    bool m_haveSaved = false;
    KernelRs485 m_saved; // the driver's RS-485 settings before start()
};

} // namespace mbscope
