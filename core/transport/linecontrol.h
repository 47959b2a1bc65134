#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// The driver's RS-485 mode as Linux's struct serial_rs485 holds it (the parts mbscope sets).
struct KernelRs485 {
    bool enabled = false;     // SER_RS485_ENABLED
    bool rtsOnSend = false;   // SER_RS485_RTS_ON_SEND: RTS asserted while sending
    bool rtsAfterSend = false; // SER_RS485_RTS_AFTER_SEND: RTS asserted after sending
    int delayBeforeMs = 0;    // delay_rts_before_send
    int delayAfterMs = 0;     // delay_rts_after_send

    friend bool operator==(const KernelRs485 &, const KernelRs485 &) = default;
};

// The modem lines and the driver's RS-485 mode of one open serial port. An interface so that
// tests can record the calls (SerialLineControl is the real one, by ioctl on the port's
// descriptor). Each call returns 0, or the operating system's error number (errno).
class LineControl
{
public:
    virtual ~LineControl() = default;

    // RTS asserted (true) or deasserted.
    virtual int setRts(bool asserted) = 0;
    // TIOCGRS485 and TIOCSRS485. setKernelRs485 keeps whatever else the driver had in its settings.
    virtual int kernelRs485(KernelRs485 *settings) = 0;
    virtual int setKernelRs485(const KernelRs485 &settings) = 0;
};

} // namespace mbscope
