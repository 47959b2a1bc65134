#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// The window's colours: the desktop's (System, the default), or a light or dark scheme chosen
// in Preferences and kept in QSettings ("appearance/theme"). Light and Dark use the Fusion style
// with a palette of their own, so they look the same on every desktop; System puts back the
// style and palette the platform gave at start, so a dark desktop gives a dark window. Views
// that colour data (SeverityStyle, RulePalette) read the application palette each time they
// paint, so they follow a change at once.
class Theme
{
    Q_DECLARE_TR_FUNCTIONS(mbscope::Theme)

public:
    enum class Choice { System, Light, Dark };

    static constexpr const char *kSettingsKey = "appearance/theme";

    [[nodiscard]] static Choice storedChoice();
    static void storeChoice(Choice choice);
    // "system", "light", "dark" (the --theme option and QSettings), case ignored.
    [[nodiscard]] static std::optional<Choice> parse(const QString &text);
    [[nodiscard]] static QString key(Choice choice);
    // The name shown in Preferences.
    [[nodiscard]] static QString displayName(Choice choice);

    // Applies choice to the whole application (every window, dialogs opened later too).
    static void apply(Choice choice);
    [[nodiscard]] static Choice current();
    // True when the application palette's window colour is dark (whatever chose it).
    [[nodiscard]] static bool isDark();
};

} // namespace mbscope
