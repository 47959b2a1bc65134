#pragma once

#include "protocol/registerformat.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace mbscope {

// Named bits inside one register of a watch: "bit 3: door open" (firstBit 3, bitCount 1) or
// "bits 8-11: mode" (firstBit 8, bitCount 4). Bit 0 is the register's least significant bit.
struct WatchBitField {
    QString name;
    int firstBit = 0;   // 0..15
    int bitCount = 1;   // 1..16, firstBit + bitCount <= 16
    QStringList states; // optional names of the field's values ("off", "on"); index = value

    friend bool operator==(const WatchBitField &, const WatchBitField &) = default;
};

// One value a watch reads: a register (or a group of registers for a wide format), or a bit of
// the coil and discrete input tables. Addresses not named by a point are still shown, as u16 (or
// 0/1), with no name.
struct WatchPoint {
    quint16 address = 0;          // the first address of the value (0-based protocol address)
    QString name;                 // unique within the watch when not empty
    QString description;
    RegisterFormat format;        // registers only; a 32-bit register (Enron) watch uses its type's width
    double scale = 1;             // value = raw * scale + offset
    double offset = 0;
    QString unit;                 // engineering unit ("V", "hPa", "cps")
    bool writable = false;        // only written from MQTT or the window when set (holding registers, coils)
    QList<WatchBitField> bitFields;

    friend bool operator==(const WatchPoint &, const WatchPoint &) = default;
};

enum class WatchSeverity : quint8 { Info, Warning, Alarm };

// A condition on a point's value that sets a colour and a severity and writes a message once it
// has held for forPolls consecutive polls (and clears when it stops holding).
//   above:   value > high          below:  value < low
//   outside: value < low or > high  inside: low <= value <= high
//   equal:   value == low           notEqual: value != low
//   bits:    (raw & mask) != 0  (low holds the mask)
struct WatchRule {
    enum class Condition : quint8 { Above, Below, Outside, Inside, Equal, NotEqual, Bits };
    QString point;                // the point's name, or its address as a number ("0x0079", "121")
    Condition condition = Condition::Above;
    double low = 0;
    double high = 0;
    int forPolls = 1;             // >= 1
    WatchSeverity severity = WatchSeverity::Warning;
    QString colour;               // "#RRGGBB", empty: the severity's colour in the current theme
    QString message;              // "pressure above 1100 hPa"; empty: a message is made from the rule

    friend bool operator==(const WatchRule &, const WatchRule &) = default;
};

// One block of one device polled at its own interval: what Modbus Poll calls a poll window.
// Functions 01-04 read a table; 0x18 reads the FIFO whose pointer is at address (quantity is
// then the most values expected, up to 31). 0x17 is not a watch function: it writes every time.
struct WatchDefinition {
    QString name;                 // unique in the session; used in CSV file names, metrics labels, MQTT topics
    QString target;               // link URL: "tcp://127.0.0.1:5020", "rtu-tcp://host:4001", "rtu:///dev/ttyUSB0?baud=19200"
    quint8 unit = 1;
    quint8 function = 3;          // 1, 2, 3, 4 or 0x18
    quint16 address = 0;
    quint16 quantity = 1;         // addresses (Enron: 32-bit values)
    qint64 intervalMs = 1000;     // start to start; 0: as fast as the link allows
    bool enron32 = false;         // each address holds one 32-bit value (Enron/Daniel 5000-5999, 7000-7999)
    QString profileBlock;         // where it came from, "rosrao-gamma/unit 1/holding 0x0079"; informative
    QList<WatchPoint> points;     // in address order, not overlapping
    QList<WatchRule> rules;
    bool enabled = true;

    friend bool operator==(const WatchDefinition &, const WatchDefinition &) = default;
};

// Settings of one link that the watches naming it share (matched by URL).
struct WatchLinkSettings {
    QString target;
    int gapMs = 0;                // idle line between the end of one exchange and the next request
    int warmUpMs = 0;             // after the link opens, before its first request (a device's warm-up)
    int timeoutMs = -1;           // -1: the URL's timeout=, else 1000 ms
    int retries = 0;
    int reconnectMinMs = 500;     // backoff after a link error: doubles from min to max
    int reconnectMaxMs = 30000;

    friend bool operator==(const WatchLinkSettings &, const WatchLinkSettings &) = default;
};

// Values logged to CSV: one file per watch in directory, a row per poll or per change,
// a new file when the current one passes rollBytes or rollSeconds (0: never).
struct WatchLogSettings {
    enum class Mode : quint8 { EveryPoll, OnChange };
    QString directory;            // relative to the session document when not absolute
    Mode mode = Mode::EveryPoll;
    qint64 rollBytes = 0;
    qint64 rollSeconds = 0;
    bool enabled = false;

    friend bool operator==(const WatchLogSettings &, const WatchLogSettings &) = default;
};

// The watches of a session (the "watches" section of a session document, version 2).
struct SessionWatches {
    QList<WatchDefinition> watches;
    QList<WatchLinkSettings> links;
    std::optional<WatchLogSettings> log;

    [[nodiscard]] bool isEmpty() const { return watches.isEmpty(); }
    friend bool operator==(const SessionWatches &, const SessionWatches &) = default;
};

} // namespace mbscope
