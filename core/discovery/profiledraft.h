#pragma once

#include "registermap.h"
#include "unitprobe.h"

#include <QtCore/QList>
#include <QtCore/QMap>

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {

// A register map as a device profile (docs/profiles.md) that `mbscope simulate --profile FILE`
// serves: one unit with the scanned id, a table entry per block with the values read, the function
// codes the device knew (read functions that were accepted and optional ones answered or refused
// with anything but 01; the write functions, never tried, are left out), and the exception status
// read, and the device's limits the scan measured ("limits": {"maxQuantity"} for a read function
// that takes fewer than the specification allows). A draft: names, types and scaling are for a
// person to add.
class ProfileDraft
{
public:
    [[nodiscard]] static QByteArray toJson(const RegisterMap &map, const QString &name, const QString &source);
    // profile (a profile's JSON text) with limits merged into its "limits": each member given
    // replaces the profile's, maxQuantity function by function; a member given as null (measured:
    // the device has no such limit) removes the profile's, minGapMs with its tooSoon and maxClients
    // with its extraClients; everything else is kept. answered holds reads the device answered
    // (function code -> quantity): a profile's maxQuantity below one is disproved and removed. *said
    // is one line for a person (describeLimits, and what was removed). Empty and *error set when
    // profile is not a JSON object.
    [[nodiscard]] static QByteArray mergeLimits(const QByteArray &profile, const QJsonObject &limits, const QMap<int, int> &answered,
                                                QString *said, QString *error);
    // profile with what a unit scan found: each id that answered (with data or an exception of
    // its own) and is not among the profile's units is added as a unit of its own ({"id": N},
    // its tables for a map scan to fill); "unknownUnit" says what the ids that were not there got
    // when they all got the same: "silent" (no answer), "exception" (0B); "first" when every id
    // asked (16 or more) answered, as a device that ignores the unit id does (then no unit is
    // added). Ids 0 and 248-255 (broadcast, reserved, the MBAP server's own) are left out.
    // *said is one line for a person. Empty and *error set when profile is not a JSON object.
    [[nodiscard]] static QByteArray mergeUnits(const QByteArray &profile, const QList<UnitProbe> &probes, QString *said,
                                               QString *error);
    // What limits (as mergeLimits takes them) says, for a person: "minGapMs 50, maxQuantity 0x03 16;
    // no limit seen: warmUpMs", or "nothing measured".
    [[nodiscard]] static QString describeLimits(const QJsonObject &limits);
};

} // namespace mbscope
