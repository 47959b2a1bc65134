#pragma once

#include "protocol/dissection.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace mbscope {

// Dissection::summary in the window's language: "RTU permintaan, unit 1: Baca Holding Register,
// 22 mulai alamat 121 (0x0079)". The core's summary stays English for the command line; this one
// says the same from the same fields.
class DissectionSummary
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::DissectionSummary)

public:
    [[nodiscard]] static QString text(const Dissection &dissection);
};

} // namespace mbscope
