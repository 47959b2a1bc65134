#include "appicon.h"

#include <QtCore/QFile>
#include <QtGui/QPainter>
#include <QtGui/QPixmap>

#ifdef MBSCOPE_HAVE_SVG
#include <QtSvg/QSvgRenderer>
#endif

namespace mbscope {

QIcon applicationIcon()
{
    const QString path = QStringLiteral(":/icons/mbscope.svg");
    if (!QFile::exists(path))
        return {};
#ifdef MBSCOPE_HAVE_SVG
    QSvgRenderer renderer(path);
    if (renderer.isValid()) {
        QIcon icon;
        // The hicolor sizes packaging/icons installs as PNG.
        for (const int size : {16, 22, 24, 32, 48, 64, 128, 256}) {
            QPixmap pixmap(size, size);
            pixmap.fill(Qt::transparent);
            QPainter painter(&pixmap);
            painter.setRenderHint(QPainter::Antialiasing);
            renderer.render(&painter);
            painter.end();
            icon.addPixmap(pixmap);
        }
        return icon;
    }
#endif
    return QIcon(path); // Qt's SVG icon engine, when installed
}

} // namespace mbscope
