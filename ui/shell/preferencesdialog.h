#pragma once

#include "translationloader.h"

#include <QtWidgets/QDialog>

class QComboBox;
class QLabel;

namespace mbscope {

// Edit > Preferences: the window's language (the system's, English or Bahasa Indonesia), kept in
// QSettings and used from the next start: every panel builds its texts once, so a live switch
// would leave half the window in the old language.
class PreferencesDialog : public QDialog
{
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget *parent = nullptr);

    [[nodiscard]] TranslationLoader::Choice languageChoice() const;
    void setLanguageChoice(TranslationLoader::Choice choice);
    [[nodiscard]] QComboBox *languageBox() const { return m_language; }

    // Stores the choice; true when it differs from what was stored (a restart is needed).
    bool apply();

private:
    void updateNote();

    QComboBox *m_language = nullptr;
    QLabel *m_note = nullptr;
    TranslationLoader::Choice m_stored = TranslationLoader::Choice::System;
};

} // namespace mbscope
