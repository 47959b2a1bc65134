#pragma once

#include "profile/simtable.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <array>
#include <optional>

namespace mbscope {

struct DeviceProfile;

// A block of one table, "holding:10" or "coils:0-7": what --writable, --readable and --missing
// name. Table keys as profiles spell them (coils, discrete, input, holding).
struct TableRange {
    SimTable table = SimTable::HoldingRegisters;
    int first = 0;
    int last = 0;

    [[nodiscard]] int count() const { return last - first + 1; }
    // "holding:10-19" read; on error nullopt and *error says what is wrong and where.
    [[nodiscard]] static std::optional<TableRange> parse(const QString &text, QString *error);
    [[nodiscard]] QString toString() const;
};

// What the battery runs against and what it may assume. Safe by default: only reads, unless
// writable names addresses the user allows it to write (every value it writes is put back).
struct ConformanceSettings {
    LinkUrl url;
    quint8 unit = 1;
    int timeoutMs = 1000;
    // Per table (SimTable order): an address the device has (-1: none known, the battery tries 0),
    // and an address it does not have (-1: none known; 65535 is tried, and a device that answers
    // it may implement the whole address space).
    std::array<int, SimTableCount> readable{-1, -1, -1, -1};
    std::array<int, SimTableCount> missing{-1, -1, -1, -1};
    QList<TableRange> writable;
    // The function codes the device promises (a profile's unit): checked against what it does.
    // Empty with promised false: nothing declared, support is read from the answers.
    QList<quint8> promisedFunctions;
    bool promised = false;
    QString promiseSource; // "profile conformance (unit 1)"
    int timingSamples = 20;  // requests timed for the response-time check
    int maxClients = 8;      // tcp.clients: connections opened beside the battery's own, at most
    QStringList only;        // run only checks whose id starts with one of these (empty: all)

    // Readable and missing addresses and the functions from a profile's unit (the one whose id is
    // unit, else the first). False with *error when the profile has no such unit.
    bool applyProfile(const DeviceProfile &profile, QString *error);
    // The writable range of table, if the user named one.
    [[nodiscard]] const TableRange *writableIn(SimTable table) const;
    [[nodiscard]] bool selected(const QString &checkId) const;
};

} // namespace mbscope
