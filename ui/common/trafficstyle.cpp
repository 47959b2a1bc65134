#include "trafficstyle.h"

#include <QtCore/QCoreApplication>
#include <QtGui/QGuiApplication>
#include <QtGui/QPalette>

namespace mbscope {

Severity TrafficStyle::severity(TrafficVerdict verdict)
{
    switch (verdict) {
    case TrafficVerdict::Ok:
    case TrafficVerdict::Sent:
        return Severity::Ok;
    case TrafficVerdict::Broadcast:
        return Severity::Info;
    case TrafficVerdict::Exception:
    case TrafficVerdict::Late:
    case TrafficVerdict::Unsolicited:
        return Severity::Warning;
    case TrafficVerdict::Timeout:
    case TrafficVerdict::CrcError:
    case TrafficVerdict::Malformed:
    case TrafficVerdict::Unexpected:
    case TrafficVerdict::LinkError:
    case TrafficVerdict::Garbage:
        return Severity::Error;
    }
    return Severity::Error;
}

QString TrafficStyle::verdictText(TrafficVerdict verdict)
{
    // trafficVerdictName with spaces, in the window's language (the names are keys in JSON and
    // journals, so the core keeps them as they are). In TrafficVerdict's order.
    static constexpr const char *kWords[kTrafficVerdictCount] = {
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "ok"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "exception"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "timeout"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "crc error"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "malformed"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "unexpected"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "link error"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "broadcast"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "late"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "sent"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "unsolicited"),
        QT_TRANSLATE_NOOP("mbscope::TrafficStyle", "garbage"),
    };
    const auto index = std::size_t(verdict);
    if (index >= std::size(kWords))
        return QLatin1String(trafficVerdictName(verdict)).toString().replace(QLatin1Char('_'), QLatin1Char(' '));
    return QCoreApplication::translate("mbscope::TrafficStyle", kWords[index]);
}

QString TrafficStyle::directionText(TrafficDirection direction)
{
    return direction == TrafficDirection::Out
               ? QStringLiteral("\u2192 ") + QCoreApplication::translate("mbscope::TrafficStyle", "out")
               : QStringLiteral("\u2190 ") + QCoreApplication::translate("mbscope::TrafficStyle", "in");
}

QColor TrafficStyle::directionColor(TrafficDirection direction)
{
    const bool dark = QGuiApplication::palette().color(QPalette::Base).lightness() < 128;
    if (direction == TrafficDirection::Out)
        return dark ? QColor(0x8A, 0xB4, 0xF8) : QColor(0x1A, 0x5F, 0xB4);
    return dark ? QColor(0x81, 0xC9, 0x95) : QColor(0x1B, 0x7F, 0x3B);
}

} // namespace mbscope
