#include "windowlayout.h"

#include <QtCore/QSettings>
#include <QtGui/QScreen>
#include <QtWidgets/QMainWindow>

namespace mbscope {

QString WindowLayout::group(const QSize &screen)
{
    if (screen.isEmpty())
        return QStringLiteral("window");
    return QStringLiteral("window/%1x%2").arg(screen.width()).arg(screen.height());
}

QSize WindowLayout::screenSize(const QWidget &window)
{
    const QScreen *screen = window.screen();
    return screen ? screen->size() : QSize();
}

void WindowLayout::save(const QMainWindow &window, const QSize &screen)
{
    QSettings settings;
    const QByteArray geometry = window.saveGeometry();
    const QByteArray state = window.saveState();
    for (const QString &group : {group(screen), QStringLiteral("window")}) {
        settings.setValue(group + QStringLiteral("/geometry"), geometry);
        settings.setValue(group + QStringLiteral("/state"), state);
    }
}

WindowLayout::Restored WindowLayout::restore(QMainWindow &window, const QSize &screen)
{
    const QSettings settings;
    QString from = group(screen);
    if (!settings.contains(from + QStringLiteral("/geometry")) && !settings.contains(from + QStringLiteral("/state")))
        from = QStringLiteral("window"); // nothing saved on this screen: the last layout of any
    const QByteArray geometry = settings.value(from + QStringLiteral("/geometry")).toByteArray();
    const QByteArray state = settings.value(from + QStringLiteral("/state")).toByteArray();
    Restored restored;
    restored.geometry = !geometry.isEmpty() && window.restoreGeometry(geometry);
    restored.state = !state.isEmpty() && window.restoreState(state);
    return restored;
}

} // namespace mbscope
