#include "translationloader.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QLibraryInfo>
#include <QtCore/QPointer>
#include <QtCore/QSettings>
#include <QtCore/QTranslator>

namespace mbscope {

namespace {

// Qt ships no Indonesian for its own strings (Debian's qt6-translations-l10n has no qtbase_id),
// so the texts of standard buttons and of the line edits' context menu that the window shows are
// translated in mbscope's file, under Qt's own contexts. Marked here so lupdate keeps them.
[[maybe_unused]] constexpr const char *kQtTextsShownByTheWindow[] = {
    QT_TRANSLATE_NOOP("QPlatformTheme", "OK"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Open"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&Yes"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Yes to &All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&No"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "N&o to All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Abort"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Retry"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Ignore"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Close"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Help"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Apply"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Reset"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Restore Defaults"),
    QT_TRANSLATE_NOOP("QGnomeTheme", "&OK"),
    QT_TRANSLATE_NOOP("QGnomeTheme", "&Save"),
    QT_TRANSLATE_NOOP("QGnomeTheme", "&Cancel"),
    QT_TRANSLATE_NOOP("QGnomeTheme", "&Close"),
    QT_TRANSLATE_NOOP("QGnomeTheme", "Close without Saving"),
    QT_TRANSLATE_NOOP("QLineEdit", "&Undo"),
    QT_TRANSLATE_NOOP("QLineEdit", "&Redo"),
    QT_TRANSLATE_NOOP("QLineEdit", "Cu&t"),
    QT_TRANSLATE_NOOP("QLineEdit", "&Copy"),
    QT_TRANSLATE_NOOP("QLineEdit", "&Paste"),
    QT_TRANSLATE_NOOP("QLineEdit", "Delete"),
    QT_TRANSLATE_NOOP("QLineEdit", "Select All"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "&Undo"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "&Redo"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "Cu&t"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "&Copy"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "Copy &Link Location"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "&Paste"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "Delete"),
    QT_TRANSLATE_NOOP("QWidgetTextControl", "Select All"),
};

// The translators install() put in place, so that a second call replaces them.
QPointer<QTranslator> g_mbscopeTranslator;
QPointer<QTranslator> g_qtTranslator;

void removeInstalled(QPointer<QTranslator> &translator)
{
    if (!translator)
        return;
    QCoreApplication::removeTranslator(translator);
    delete translator;
}

} // namespace

std::optional<TranslationLoader::Choice> TranslationLoader::parse(const QString &code)
{
    const QString c = code.trimmed().toLower();
    if (c == QLatin1String("system") || c == QLatin1String("auto"))
        return Choice::System;
    if (c == QLatin1String("en") || c == QLatin1String("english") || c.startsWith(QLatin1String("en_"))
        || c.startsWith(QLatin1String("en-")) || c == QLatin1String("c"))
        return Choice::English;
    if (c == QLatin1String("id") || c == QLatin1String("indonesian") || c.startsWith(QLatin1String("id_"))
        || c.startsWith(QLatin1String("id-")))
        return Choice::Indonesian;
    return std::nullopt;
}

QString TranslationLoader::code(Choice choice)
{
    switch (choice) {
    case Choice::English: return QStringLiteral("en");
    case Choice::Indonesian: return QStringLiteral("id");
    case Choice::System: break;
    }
    return QStringLiteral("system");
}

TranslationLoader::Choice TranslationLoader::storedChoice()
{
    const QSettings settings;
    return parse(settings.value(QLatin1String(kSettingsKey)).toString()).value_or(Choice::System);
}

void TranslationLoader::storeChoice(Choice choice)
{
    QSettings settings;
    settings.setValue(QLatin1String(kSettingsKey), code(choice));
}

QLocale TranslationLoader::localeFor(Choice choice)
{
    switch (choice) {
    case Choice::English: return QLocale(QLocale::English, QLocale::UnitedStates);
    case Choice::Indonesian: return QLocale(QLocale::Indonesian, QLocale::Indonesia);
    case Choice::System: break;
    }
    return QLocale::system();
}

bool TranslationLoader::install(QCoreApplication &app, const QLocale &locale)
{
    removeInstalled(g_mbscopeTranslator);
    removeInstalled(g_qtTranslator);
    // The source strings are English: nothing to load, and a stray en .qm must not shadow them.
    if (locale.language() == QLocale::English || locale.language() == QLocale::C)
        return false;

    auto *qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        g_qtTranslator = qt;
    } else {
        delete qt;
    }
    // Installed last, so it is asked first: mbscope's words for Qt's buttons win over Qt's.
    // An installed .qm (share/mbscope/translations beside bin/) wins over the embedded one, so a
    // lab can try a corrected translation without rebuilding.
    auto *own = new QTranslator(&app);
    const QString installed = QCoreApplication::applicationDirPath() + QStringLiteral("/../share/mbscope/translations");
    if (!own->load(locale, QStringLiteral("mbscope"), QStringLiteral("_"), installed)
        && !own->load(locale, QStringLiteral("mbscope"), QStringLiteral("_"), QLatin1String(kResourceDir))) {
        delete own;
        return false;
    }
    QCoreApplication::installTranslator(own);
    g_mbscopeTranslator = own;
    return true;
}

} // namespace mbscope
