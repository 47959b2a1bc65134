#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QCoreApplication>
#include <QtGui/QColor>

namespace mbscope {

// The colours of a rule that holds: its cell's background (the rule's own "#RRGGBB", or its
// severity's hue, blended into the palette's Base) and a text colour that reads on it. Computed
// from the application palette when asked, so the light and dark themes both get readable cells:
// the text keeps a WCAG contrast of at least 4.5:1 against the background.
class RulePalette
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::RulePalette)

public:
    [[nodiscard]] static QColor hue(WatchSeverity severity);
    // colour: a rule's "#RRGGBB" (empty or invalid: the severity's hue).
    [[nodiscard]] static QColor background(WatchSeverity severity, const QString &colour = {});
    [[nodiscard]] static QColor foreground(WatchSeverity severity, const QString &colour = {});
    // "info", "warning", "alarm" in the window's language.
    [[nodiscard]] static QString severityName(WatchSeverity severity);
    // WCAG 2.x contrast ratio of two colours (1 to 21).
    [[nodiscard]] static double contrast(const QColor &a, const QColor &b);
    static constexpr double kMinimumContrast = 4.5;
};

} // namespace mbscope
