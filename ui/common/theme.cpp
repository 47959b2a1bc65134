#include "theme.h"

#include <QtCore/QSettings>
#include <QtGui/QPalette>
#include <QtWidgets/QApplication>
#include <QtWidgets/QStyle>
#include <QtWidgets/QStyleFactory>

namespace mbscope {

namespace {

struct PlatformLook {
    bool saved = false;
    QString styleName;
    QPalette palette;
};

PlatformLook &platformLook()
{
    static PlatformLook look;
    return look;
}

Theme::Choice &currentChoice()
{
    static Theme::Choice choice = Theme::Choice::System;
    return choice;
}

// What the platform gave before any theme was applied: System goes back to it.
void rememberPlatformLook()
{
    PlatformLook &look = platformLook();
    if (look.saved)
        return;
    look.saved = true;
    look.styleName = QApplication::style() ? QApplication::style()->name() : QString();
    look.palette = QApplication::palette();
}

// Dark roles chosen for contrast: text on Base at least 12:1, disabled text still 4.5:1, the
// highlight a blue that white text reads on.
QPalette darkPalette()
{
    QPalette p;
    const QColor window(0x2b, 0x2d, 0x30);
    const QColor base(0x1e, 0x1f, 0x22);
    const QColor text(0xe6, 0xe6, 0xe6);
    const QColor disabled(0x8c, 0x8c, 0x8c);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, QColor(0x26, 0x28, 0x2b));
    p.setColor(QPalette::ToolTipBase, QColor(0x3c, 0x3f, 0x41));
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, disabled);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(0x35, 0x37, 0x3b));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, QColor(0xff, 0x6b, 0x6b));
    p.setColor(QPalette::Light, QColor(0x4a, 0x4d, 0x52));
    p.setColor(QPalette::Midlight, QColor(0x3e, 0x41, 0x45));
    p.setColor(QPalette::Mid, QColor(0x25, 0x26, 0x29));
    p.setColor(QPalette::Dark, QColor(0x18, 0x19, 0x1b));
    p.setColor(QPalette::Shadow, Qt::black);
    p.setColor(QPalette::Highlight, QColor(0x2f, 0x65, 0xca));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Link, QColor(0x8a, 0xb4, 0xf8));
    p.setColor(QPalette::LinkVisited, QColor(0xc5, 0x8a, 0xf9));
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    p.setColor(QPalette::Disabled, QPalette::Base, window);
    return p;
}

} // namespace

Theme::Choice Theme::storedChoice()
{
    return parse(QSettings().value(QLatin1String(kSettingsKey)).toString()).value_or(Choice::System);
}

void Theme::storeChoice(Choice choice)
{
    QSettings().setValue(QLatin1String(kSettingsKey), key(choice));
}

std::optional<Theme::Choice> Theme::parse(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("system"))
        return Choice::System;
    if (t == QLatin1String("light"))
        return Choice::Light;
    if (t == QLatin1String("dark"))
        return Choice::Dark;
    return std::nullopt;
}

QString Theme::key(Choice choice)
{
    switch (choice) {
    case Choice::Light: return QStringLiteral("light");
    case Choice::Dark: return QStringLiteral("dark");
    case Choice::System: break;
    }
    return QStringLiteral("system");
}

QString Theme::displayName(Choice choice)
{
    switch (choice) {
    case Choice::Light: return tr("Light");
    case Choice::Dark: return tr("Dark");
    case Choice::System: break;
    }
    return tr("Follow the desktop");
}

void Theme::apply(Choice choice)
{
    rememberPlatformLook();
    const PlatformLook &look = platformLook();
    currentChoice() = choice;
    if (choice == Choice::System) {
        if (!look.styleName.isEmpty() && QApplication::style()->name() != look.styleName)
            QApplication::setStyle(QStyleFactory::create(look.styleName));
        QApplication::setPalette(look.palette);
        return;
    }
    if (QApplication::style()->name().compare(QLatin1String("fusion"), Qt::CaseInsensitive) != 0)
        QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QApplication::setPalette(choice == Choice::Dark ? darkPalette() : QApplication::style()->standardPalette());
}

Theme::Choice Theme::current()
{
    return currentChoice();
}

bool Theme::isDark()
{
    return QApplication::palette().color(QPalette::Window).lightness() < 128;
}

} // namespace mbscope
