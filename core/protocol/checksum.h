#pragma once

#include <QtCore/QByteArrayView>
#include <QtCore/qglobal.h>

namespace mbscope::checksum {

// CRC-16/MODBUS: polynomial 0x8005 reflected (0xA001), initial value 0xFFFF, no final XOR
// (MODBUS over Serial Line v1.02, 6.2.2). The value is returned as a number; on the wire it
// travels low byte first, so "01 03 00 79 00 16" is followed by 15 DD for a CRC of 0xDD15.
[[nodiscard]] quint16 crc16Modbus(QByteArrayView bytes);

// LRC: the two's complement of the 8-bit sum of the bytes, without carries
// (Serial Line v1.02, 6.2.1). Computed over the binary values, not over the hex characters.
[[nodiscard]] quint8 lrc(QByteArrayView bytes);

} // namespace mbscope::checksum
