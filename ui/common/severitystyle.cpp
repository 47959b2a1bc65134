#include "severitystyle.h"

#include <QtGui/QGuiApplication>
#include <QtGui/QPainter>
#include <QtGui/QPainterPath>
#include <QtGui/QPalette>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>

namespace mbscope {

bool SeverityStyle::darkPalette()
{
    return QGuiApplication::palette().color(QPalette::Base).lightness() < 128;
}

QColor SeverityStyle::hue(Severity severity)
{
    switch (severity) {
    case Severity::Error: return QColor(0xd3, 0x2f, 0x2f);
    case Severity::Warning: return QColor(0xf0, 0xa0, 0x00);
    case Severity::Info: return QColor(0x2f, 0x7f, 0xd3);
    case Severity::Ok: break;
    }
    return {};
}

QColor SeverityStyle::textColor(Severity severity)
{
    const bool dark = darkPalette();
    switch (severity) {
    case Severity::Error: return dark ? QColor(0xff, 0x8a, 0x80) : QColor(0xb0, 0x00, 0x20);
    case Severity::Warning: return dark ? QColor(0xff, 0xc8, 0x57) : QColor(0x8a, 0x50, 0x00);
    case Severity::Info: return dark ? QColor(0x8a, 0xc4, 0xff) : QColor(0x1a, 0x5a, 0xa6);
    case Severity::Ok: break;
    }
    return QGuiApplication::palette().color(QPalette::Text);
}

QColor SeverityStyle::goodColor()
{
    return darkPalette() ? QColor(0x81, 0xc9, 0x95) : QColor(0x1b, 0x6e, 0x2a);
}

QColor SeverityStyle::mutedColor()
{
    return darkPalette() ? QColor(0xa0, 0xa0, 0xa0) : QColor(0x66, 0x66, 0x66);
}

void SeverityStyle::setTextColour(QWidget *label, Severity severity)
{
    if (severity == Severity::Ok) {
        label->setPalette(QPalette()); // nothing of its own: the window's palette, whatever it becomes
        return;
    }
    QPalette p = label->palette();
    p.setColor(QPalette::WindowText, textColor(severity));
    label->setPalette(p);
}

QColor SeverityStyle::backgroundColor(Severity severity)
{
    const QColor h = hue(severity);
    if (!h.isValid())
        return {};
    const QColor base = QGuiApplication::palette().color(QPalette::Base);
    const qreal a = darkPalette() ? 0.30 : 0.16;
    return QColor::fromRgbF(float(base.redF() * (1 - a) + h.redF() * a),
                            float(base.greenF() * (1 - a) + h.greenF() * a),
                            float(base.blueF() * (1 - a) + h.blueF() * a));
}

static QPixmap drawMarker(Severity severity, int size)
{
    QPixmap pm(size, size);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    const qreal s = size;
    const QColor h = SeverityStyle::hue(severity);
    QPen glyph(Qt::white, s * 0.14, Qt::SolidLine, Qt::RoundCap);
    switch (severity) {
    case Severity::Error:
        p.setPen(Qt::NoPen);
        p.setBrush(h);
        p.drawEllipse(QRectF(s * 0.06, s * 0.06, s * 0.88, s * 0.88));
        p.setPen(glyph);
        p.drawLine(QPointF(s * 0.32, s * 0.32), QPointF(s * 0.68, s * 0.68));
        p.drawLine(QPointF(s * 0.68, s * 0.32), QPointF(s * 0.32, s * 0.68));
        break;
    case Severity::Warning: {
        QPainterPath triangle;
        triangle.moveTo(s * 0.5, s * 0.06);
        triangle.lineTo(s * 0.96, s * 0.90);
        triangle.lineTo(s * 0.04, s * 0.90);
        triangle.closeSubpath();
        p.setPen(Qt::NoPen);
        p.setBrush(h);
        p.drawPath(triangle);
        glyph.setColor(QColor(0x40, 0x28, 0x00));
        p.setPen(glyph);
        p.drawLine(QPointF(s * 0.5, s * 0.36), QPointF(s * 0.5, s * 0.58));
        p.drawPoint(QPointF(s * 0.5, s * 0.76));
        break;
    }
    case Severity::Info:
        p.setPen(Qt::NoPen);
        p.setBrush(h);
        p.drawEllipse(QRectF(s * 0.06, s * 0.06, s * 0.88, s * 0.88));
        p.setPen(glyph);
        p.drawPoint(QPointF(s * 0.5, s * 0.28));
        p.drawLine(QPointF(s * 0.5, s * 0.46), QPointF(s * 0.5, s * 0.74));
        break;
    case Severity::Ok:
        break;
    }
    return pm;
}

QIcon SeverityStyle::icon(Severity severity)
{
    if (severity == Severity::Ok)
        return {};
    QIcon icon;
    for (int size : {16, 24, 32})
        icon.addPixmap(drawMarker(severity, size));
    return icon;
}

} // namespace mbscope
