#pragma once

#include "profile/faultrule.h"
#include "tap/tapsettings.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QMetaType>
#include <QtCore/QStringList>

#include <optional>

namespace mbscope {

// The window's inline tap (the connection bar's Tap): where masters connect, and how their
// requests are forwarded (core/tap's TapSettings: the routes, the bar's target last, taking every
// unit the others leave; timeout, retries, read-only, what a master gets instead of an answer).
// What `mbscope tap` takes on its command line, as one value.
struct TapSetup {
    QList<LinkUrl> listen; // LinkUse::Listen URLs (port 0: any free port)
    TapSettings settings;
    // Fault rules applied to the devices' answers on their way back (--faults), read from faultsFile.
    std::optional<FaultRuleSet> faults;
    QString faultsFile;

    // "tap --listen tcp://127.0.0.1:5020 --target rtu-tcp://127.0.0.1:4001 --read-only": the
    // command line that runs the same tap (for the status bar, the journal and the guide).
    [[nodiscard]] QStringList arguments() const
    {
        QStringList out;
        for (const LinkUrl &url : listen)
            out << QStringLiteral("--listen") << url.toString();
        for (const TapRoute &route : settings.routes) {
            // The bar's target is the last route, for every unit the others leave (--target).
            const bool last = &route == &settings.routes.constLast();
            if (last && route.firstUnit == 0 && route.lastUnit == 255 && !route.renumbers()) {
                out << QStringLiteral("--target") << route.target.toString();
                continue;
            }
            QString units = QString::number(route.firstUnit);
            if (route.lastUnit != route.firstUnit)
                units += QLatin1Char('-') + QString::number(route.lastUnit);
            if (route.renumbers())
                units += QLatin1Char(':') + QString::number(route.deviceUnit);
            out << QStringLiteral("--route") << units + QLatin1Char('=') + route.target.toString();
        }
        out << QStringLiteral("--timeout") << QStringLiteral("%1ms").arg(settings.timeoutMs);
        if (settings.retries > 0)
            out << QStringLiteral("--retries") << QString::number(settings.retries);
        if (settings.noAnswer != TapSettings::NoAnswer::Auto)
            out << QStringLiteral("--no-answer")
                << (settings.noAnswer == TapSettings::NoAnswer::Exception ? QStringLiteral("exception") : QStringLiteral("silence"));
        if (!faultsFile.isEmpty())
            out << QStringLiteral("--faults") << faultsFile;
        if (settings.readOnly) {
            out << QStringLiteral("--read-only");
            if (settings.refusal == TapSettings::Refusal::Silence)
                out << QStringLiteral("--refuse") << QStringLiteral("silence");
        }
        return out;
    }
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::TapSetup)
Q_DECLARE_METATYPE(mbscope::TapCounters) // the tap's counters, queued from its thread
