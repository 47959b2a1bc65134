#include "rulepalette.h"

#include "common/theme.h"

#include <QtGui/QGuiApplication>
#include <QtGui/QPalette>

#include <cmath>

namespace mbscope {

namespace {

double channel(double c)
{
    return c <= 0.03928 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double luminance(const QColor &c)
{
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

QColor blend(const QColor &base, const QColor &tint, double amount)
{
    return QColor::fromRgbF(float(base.redF() * (1 - amount) + tint.redF() * amount),
                            float(base.greenF() * (1 - amount) + tint.greenF() * amount),
                            float(base.blueF() * (1 - amount) + tint.blueF() * amount));
}

} // namespace

QColor RulePalette::hue(WatchSeverity severity)
{
    switch (severity) {
    case WatchSeverity::Alarm: return QColor(0xe5, 0x39, 0x35);
    case WatchSeverity::Warning: return QColor(0xf9, 0xa8, 0x25);
    case WatchSeverity::Info: break;
    }
    return QColor(0x1e, 0x88, 0xe5);
}

QColor RulePalette::background(WatchSeverity severity, const QString &colour)
{
    QColor tint(colour);
    if (colour.isEmpty() || !tint.isValid())
        tint = hue(severity);
    const QColor base = QGuiApplication::palette().color(QPalette::Base);
    // A strong tint on light Base; on a dark one a weaker mix keeps the hue without glare.
    const double amount = Theme::isDark() ? 0.45 : 0.35;
    const QColor tinted = blend(base, tint, amount);
    // A rule's own colour that vanishes into Base (white on a light theme, black on a dark one)
    // would hide that the rule holds: the severity's hue shows it instead.
    if (contrast(tinted, base) < 1.1)
        return blend(base, hue(severity), amount);
    return tinted;
}

QColor RulePalette::foreground(WatchSeverity severity, const QString &colour)
{
    const QColor back = background(severity, colour);
    const QColor text = QGuiApplication::palette().color(QPalette::Text);
    if (contrast(text, back) >= kMinimumContrast)
        return text;
    const QColor black(Qt::black);
    const QColor white(Qt::white);
    return contrast(black, back) >= contrast(white, back) ? black : white;
}

QString RulePalette::severityName(WatchSeverity severity)
{
    switch (severity) {
    case WatchSeverity::Alarm: return tr("alarm");
    case WatchSeverity::Warning: return tr("warning");
    case WatchSeverity::Info: break;
    }
    return tr("info");
}

double RulePalette::contrast(const QColor &a, const QColor &b)
{
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

} // namespace mbscope
