#pragma once

#include "registermap.h"

#include <QtCore/QByteArray>
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
};

} // namespace mbscope
