#pragma once

#include "registermap.h"

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
    // with its extraClients; everything else is kept. Empty and *error set when profile is not a
    // JSON object.
    [[nodiscard]] static QByteArray mergeLimits(const QByteArray &profile, const QJsonObject &limits, QString *error);
    // What limits (as mergeLimits takes them) says, for a person: "minGapMs 50, maxQuantity 0x03 16;
    // no limit seen: warmUpMs", or "nothing measured".
    [[nodiscard]] static QString describeLimits(const QJsonObject &limits);
};

} // namespace mbscope
