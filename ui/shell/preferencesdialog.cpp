#include "preferencesdialog.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

PreferencesDialog::PreferencesDialog(QWidget *parent)
    : QDialog(parent)
    , m_language(new QComboBox(this))
    , m_note(new QLabel(this))
    , m_stored(TranslationLoader::storedChoice())
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    m_language->setObjectName(QStringLiteral("languageBox"));
    // Each language is named in its own words, as language pickers do: whoever cannot read the
    // current one still finds theirs.
    // The language System gives here: Indonesian for an Indonesian locale, English otherwise (the
    // sources; also for the C locale, which has no language name).
    const QString systemGives = TranslationLoader::localeFor(TranslationLoader::Choice::System).language() == QLocale::Indonesian
        ? QStringLiteral("Bahasa Indonesia")
        : QStringLiteral("English");
    const QString system = tr("System language (%1)").arg(systemGives);
    m_language->addItem(system, QVariant::fromValue(int(TranslationLoader::Choice::System)));
    m_language->addItem(QStringLiteral("English"), QVariant::fromValue(int(TranslationLoader::Choice::English)));
    m_language->addItem(QStringLiteral("Bahasa Indonesia"), QVariant::fromValue(int(TranslationLoader::Choice::Indonesian)));
    m_language->setToolTip(tr("The language of menus, panels and messages. The command line and JSON output stay English."));
    setLanguageChoice(m_stored);

    m_note->setObjectName(QStringLiteral("languageNote"));
    m_note->setWordWrap(true);

    auto *form = new QFormLayout;
    form->addRow(tr("&Language:"), m_language);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        apply();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_language, &QComboBox::currentIndexChanged, this, &PreferencesDialog::updateNote);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_note);
    layout->addStretch(1);
    layout->addWidget(buttons);
    updateNote();
}

TranslationLoader::Choice PreferencesDialog::languageChoice() const
{
    return TranslationLoader::Choice(m_language->currentData().toInt());
}

void PreferencesDialog::setLanguageChoice(TranslationLoader::Choice choice)
{
    const int row = m_language->findData(QVariant::fromValue(int(choice)));
    m_language->setCurrentIndex(row < 0 ? 0 : row);
}

bool PreferencesDialog::apply()
{
    const TranslationLoader::Choice chosen = languageChoice();
    if (chosen == m_stored)
        return false;
    TranslationLoader::storeChoice(chosen);
    m_stored = chosen;
    return true;
}

void PreferencesDialog::updateNote()
{
    m_note->setText(languageChoice() == m_stored
                        ? tr("mbscope --lang id (or en) chooses the language for one run.")
                        : tr("The new language is used when mbscope is started again."));
}

} // namespace mbscope
