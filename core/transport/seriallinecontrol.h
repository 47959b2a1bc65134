#pragma once

#include "linecontrol.h"

namespace mbscope {

// LineControl on an open serial port's file descriptor, by ioctl: TIOCMBIS / TIOCMBIC for RTS,
// TIOCGRS485 / TIOCSRS485 for the driver's RS-485 mode (Linux; elsewhere those answer ENOTSUP).
// A pseudo terminal has no modem lines (ENOTTY); a driver without an RS-485 mode refuses
// TIOCSRS485 with ENOTTY too. The descriptor stays the port's.
class SerialLineControl final : public LineControl
{
public:
    explicit SerialLineControl(int fd)
        : m_fd(fd)
    {
    }

    int setRts(bool asserted) override;
    int kernelRs485(KernelRs485 *settings) override;
    int setKernelRs485(const KernelRs485 &settings) override;

private:
    int m_fd;
};

} // namespace mbscope
