#pragma once

#include "translationloader.h"

#include "common/theme.h"

#include "session/recordingsettings.h"

#include <QtWidgets/QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace mbscope {

// Tools > Preferences: the window's theme (Theme: the desktop's colours, light or dark, applied
// at once) and language (the system's, English or Bahasa Indonesia), kept in
// QSettings and used from the next start: every panel builds its texts once, so a live switch
// would leave half the window in the old language. And the recording of traffic: on or off, the
// capture folder, the size of a journal part and of the whole folder (RecordingSettings).
class PreferencesDialog : public QDialog
{
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget *parent = nullptr);

    [[nodiscard]] TranslationLoader::Choice languageChoice() const;
    void setLanguageChoice(TranslationLoader::Choice choice);
    [[nodiscard]] QComboBox *languageBox() const { return m_language; }

    // The window's colours (Theme): applied at once when the dialog is accepted.
    [[nodiscard]] Theme::Choice themeChoice() const;
    void setThemeChoice(Theme::Choice choice);
    [[nodiscard]] QComboBox *themeBox() const { return m_theme; }

    // Stores the choices and applies the theme; true when the language differs from what was stored (a restart is needed).
    bool apply();

    // "startup/simulator": every start launches the built-in simulator and connects to it. Off
    // (the default), only the first run does; later starts put back the last session or target.
    static constexpr const char *kStartSimulatorKey = "startup/simulator";
    [[nodiscard]] static bool startsSimulator();
    [[nodiscard]] QCheckBox *simulatorBox() const { return m_simulator; }

    void setRecordingSettings(const RecordingSettings &settings);
    [[nodiscard]] RecordingSettings recordingSettings() const;

private:
    void updateNote();
    void updateRecordingEnabled();

    QComboBox *m_language = nullptr;
    QComboBox *m_theme = nullptr;
    QLabel *m_note = nullptr;
    QCheckBox *m_record = nullptr;
    QCheckBox *m_simulator = nullptr;
    QLineEdit *m_folder = nullptr;
    QToolButton *m_browse = nullptr;
    QSpinBox *m_rotate = nullptr;
    QSpinBox *m_keep = nullptr;
    TranslationLoader::Choice m_stored = TranslationLoader::Choice::System;
};

} // namespace mbscope
