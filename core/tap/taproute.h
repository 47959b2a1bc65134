#pragma once

#include "transport/linkurl.h"

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// Where the inline tap sends the requests for a range of unit ids, and which unit id the device
// has there. Written on the command line (`mbscope tap --route`) as
//
//     UNITS[:DEVICE_UNIT]=TARGET_URL
//
// UNITS is one id (5) or a range (1-10), ids 0-255; DEVICE_UNIT renumbers them: the first unit of
// the range becomes DEVICE_UNIT and the others keep their distance (`1-4:17=...`: 1 is sent as
// 17, 2 as 18...). `--target URL` is the route `0-255=URL`. Examples:
//
//     1:17=rtu-tcp://10.0.0.5:4001     master asks unit 1, the device behind the server is unit 17
//     10-19=rtu:///dev/ttyUSB0?baud=19200&parity=N
//
// The target URL's timeout= option is the response timeout of this route's requests, and
// retries=N (the tap's own, taken off the URL before the link reads it) the further attempts of a
// read on this route (a unit behind a flaky radio link gets 3, an absent one 0 so that it does
// not hold the line for the others):
//
//     5=rtu:///dev/ttyUSB0?baud=9600&timeout=300ms&retries=3
struct TapRoute {
    int firstUnit = 0;
    int lastUnit = 255;
    int deviceUnit = -1; // -1: ids are sent as they came
    LinkUrl target;
    int retries = -1;    // -1: the tap's (TapSettings::retries)

    [[nodiscard]] bool serves(int unit) const { return unit >= firstUnit && unit <= lastUnit; }
    [[nodiscard]] bool renumbers() const { return deviceUnit >= 0 && deviceUnit != firstUnit; }
    // The id the device has for the master's unit (serves(unit) must hold).
    [[nodiscard]] quint8 deviceUnitFor(int unit) const;
    // "units 1-4 as 17-20 -> rtu-tcp://127.0.0.1:4001", "every unit -> tcp://..."
    [[nodiscard]] QString describe() const;

    struct Result;
    [[nodiscard]] static Result parse(QStringView text);
    // A target URL that may give retries=N: the route to every unit (`--target URL`).
    [[nodiscard]] static Result parseTarget(QStringView url);
};

struct TapRoute::Result {
    std::optional<TapRoute> route;
    QString error; // "'1-300=tcp://...': unit 300 is above 255"
};

} // namespace mbscope
