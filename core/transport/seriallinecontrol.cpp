#include "seriallinecontrol.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sys/ioctl.h>
#include <termios.h>

#if defined(__linux__)
#include <linux/serial.h>
#endif

namespace mbscope {

int SerialLineControl::setRts(bool asserted)
{
    const int line = TIOCM_RTS;
    return ::ioctl(m_fd, asserted ? TIOCMBIS : TIOCMBIC, &line) == 0 ? 0 : errno;
}

#if defined(__linux__) && defined(TIOCSRS485)

int SerialLineControl::kernelRs485(KernelRs485 *settings)
{
    serial_rs485 rs485;
    std::memset(&rs485, 0, sizeof rs485);
    if (::ioctl(m_fd, TIOCGRS485, &rs485) != 0)
        return errno;
    settings->enabled = (rs485.flags & SER_RS485_ENABLED) != 0;
    settings->rtsOnSend = (rs485.flags & SER_RS485_RTS_ON_SEND) != 0;
    settings->rtsAfterSend = (rs485.flags & SER_RS485_RTS_AFTER_SEND) != 0;
    settings->delayBeforeMs = int(rs485.delay_rts_before_send);
    settings->delayAfterMs = int(rs485.delay_rts_after_send);
    return 0;
}

int SerialLineControl::setKernelRs485(const KernelRs485 &settings)
{
    serial_rs485 rs485;
    std::memset(&rs485, 0, sizeof rs485);
    // Start from the driver's own settings, so that flags mbscope does not know (bus termination,
    // addressing) stay as they were. Some drivers refuse TIOCGRS485: start from zero then.
    if (::ioctl(m_fd, TIOCGRS485, &rs485) != 0)
        std::memset(&rs485, 0, sizeof rs485);
    auto flag = [&rs485](__u32 bit, bool on) { rs485.flags = on ? (rs485.flags | bit) : (rs485.flags & ~bit); };
    flag(SER_RS485_ENABLED, settings.enabled);
    flag(SER_RS485_RTS_ON_SEND, settings.rtsOnSend);
    flag(SER_RS485_RTS_AFTER_SEND, settings.rtsAfterSend);
    rs485.delay_rts_before_send = __u32(std::max(0, settings.delayBeforeMs));
    rs485.delay_rts_after_send = __u32(std::max(0, settings.delayAfterMs));
    return ::ioctl(m_fd, TIOCSRS485, &rs485) == 0 ? 0 : errno;
}

#else

int SerialLineControl::kernelRs485(KernelRs485 *)
{
    return ENOTSUP;
}

int SerialLineControl::setKernelRs485(const KernelRs485 &)
{
    return ENOTSUP;
}

#endif

} // namespace mbscope
