#pragma once

#include <QtCore/QLocale>
#include <QtCore/QString>

#include <optional>

class QCoreApplication;

namespace mbscope {

// Which language the window speaks and the translators that make it so. The choice lives in
// QSettings ("ui/language"); `mbscope --lang` overrides it for one run. The translations are
// compiled into mbscope (:/translations/mbscope_<lang>.qm), so an installed copy is never needed.
// The command line and JSON output never go through these translators: they stay English.
class TranslationLoader
{
public:
    enum class Choice { System, English, Indonesian };

    static constexpr const char *kSettingsKey = "ui/language";
    static constexpr const char *kResourceDir = ":/translations";

    // "system", "en", "id" (also "english", "indonesian", "id_ID"...); nullopt for anything else.
    [[nodiscard]] static std::optional<Choice> parse(const QString &code);
    [[nodiscard]] static QString code(Choice choice);

    [[nodiscard]] static Choice storedChoice();
    static void storeChoice(Choice choice);

    // The locale a choice stands for: the system's for System.
    [[nodiscard]] static QLocale localeFor(Choice choice);

    // Installs mbscope's translation for locale (and Qt's own where the system has one) on app,
    // replacing what an earlier call installed. True when the window will speak a translated
    // language; false for English, or when mbscope has no translation for locale.
    static bool install(QCoreApplication &app, const QLocale &locale);
};

} // namespace mbscope
