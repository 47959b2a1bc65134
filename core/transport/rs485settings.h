#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// RS-485 direction control of a serial link: who switches the adapter's transmitter on around a
// send, by the RTS line. A half-duplex RS-485 transceiver whose driver enable (DE) is wired to RTS
// must drive the bus while the frame leaves and release it at once after the last byte, or the
// device's answer collides with it. URL options rts=up|down, rts_before=, rts_after=, rs485=kernel
// (see LinkUrl); the link's RtsDirection does the switching.
struct Rs485Settings {
    // The RTS level while sending (libmodbus's MODBUS_RTU_RTS_UP / MODBUS_RTU_RTS_DOWN): Up asserts
    // RTS for the send and deasserts it after; Down the other way round. None: RTS is left alone
    // (an adapter that switches direction by itself, or an RS-232 line).
    enum class Rts : quint8 { None, Up, Down };

    Rts rts = Rts::None;
    // The driver switches RTS itself (Linux's RS-485 mode, ioctl TIOCSRS485), at the bit and
    // without mbscope's timers; rts then gives the level while sending (Up when not given).
    bool kernel = false;
    int beforeUs = 0; // RTS at its sending level this long before the first byte leaves
    int afterUs = 0;  // and kept there this long after the last byte left the line

    [[nodiscard]] bool enabled() const { return rts != Rts::None; }
    [[nodiscard]] bool sendLevel() const { return rts == Rts::Up; }

    friend bool operator==(const Rs485Settings &, const Rs485Settings &) = default;
};

} // namespace mbscope
