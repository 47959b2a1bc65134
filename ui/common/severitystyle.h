#pragma once

#include "protocol/severity.h"

#include <QtGui/QColor>
#include <QtGui/QIcon>

class QWidget;

namespace mbscope {

// How severity looks, in one place, so the field tree, the summary line and later views agree.
// Colours follow the application palette: on a dark Base the hues are lighter and the tints
// stronger, so text stays readable in both schemes.
class SeverityStyle
{
public:
    // The hue of a severity (error red, warning amber, info blue); invalid for Ok.
    [[nodiscard]] static QColor hue(Severity severity);
    // Text colour for a message of this severity on the palette's Base (or on its tint).
    [[nodiscard]] static QColor textColor(Severity severity);
    // Base tinted towards the severity's hue: a row background. Invalid for Ok.
    [[nodiscard]] static QColor backgroundColor(Severity severity);
    // Green of what went well (connected, a passed step), readable on the palette's Base and Window.
    [[nodiscard]] static QColor goodColor();
    // Grey of what is there but says little (a silent unit), readable on Base and Window.
    [[nodiscard]] static QColor mutedColor();
    // Colours a label's text for severity; Ok gives the label back the palette's own colour, so a
    // later change of theme reaches it (a colour copied from the palette would stay, black on dark).
    static void setTextColour(QWidget *label, Severity severity);
    // A small drawn marker (no theme icons: they are missing on many desktops). Null for Ok.
    [[nodiscard]] static QIcon icon(Severity severity);

private:
    [[nodiscard]] static bool darkPalette();
};

} // namespace mbscope
