#pragma once

#include <QtCore/QSize>
#include <QtCore/QString>

class QMainWindow;
class QWidget;

namespace mbscope {

// The window's geometry and dock layout in QSettings, per screen size ("window/1920x1080/geometry",
// ".../state"): the layout made on a laptop and the one made on the office monitor each come back
// on their own screen. A screen with nothing saved yet gets the last layout saved on any screen
// ("window/geometry", "window/state").
class WindowLayout
{
public:
    struct Restored {
        bool geometry = false;
        bool state = false;
    };

    // "window/1920x1080"; "window" for an unknown (empty) size.
    [[nodiscard]] static QString group(const QSize &screen);
    // The size of the screen window is on (empty when it has none).
    [[nodiscard]] static QSize screenSize(const QWidget &window);

    static void save(const QMainWindow &window, const QSize &screen);
    static Restored restore(QMainWindow &window, const QSize &screen);
};

} // namespace mbscope
