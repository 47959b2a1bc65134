#include "preferencesdialog.h"

#include <QtCore/QSettings>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

PreferencesDialog::PreferencesDialog(QWidget *parent)
    : QDialog(parent)
    , m_language(new QComboBox(this))
    , m_theme(new QComboBox(this))
    , m_note(new QLabel(this))
    , m_record(new QCheckBox(tr("&Record all traffic of the window's connections"), this))
    , m_folder(new QLineEdit(this))
    , m_rotate(new QSpinBox(this))
    , m_keep(new QSpinBox(this))
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

    m_theme->setObjectName(QStringLiteral("themeBox"));
    for (Theme::Choice choice : {Theme::Choice::System, Theme::Choice::Light, Theme::Choice::Dark})
        m_theme->addItem(Theme::displayName(choice), QVariant::fromValue(int(choice)));
    m_theme->setToolTip(tr("The window's colours: the desktop's, or light or dark whatever the desktop uses. "
                           "Rule colours in the watches stay readable in both."));
    setThemeChoice(Theme::storedChoice());

    auto *form = new QFormLayout;
    form->addRow(tr("&Language:"), m_language);
    form->addRow(tr("T&heme:"), m_theme);
    m_simulator = new QCheckBox(tr("Start the built-in &simulator and connect to it at every start"), this);
    m_simulator->setObjectName(QStringLiteral("startSimulatorBox"));
    m_simulator->setToolTip(tr("Off: only the first run does; later starts open the last session (or put back the "
                               "last target, disconnected) and the last layout."));
    m_simulator->setChecked(startsSimulator());
    form->addRow(m_simulator);

    m_record->setObjectName(QStringLiteral("recordBox"));
    m_record->setToolTip(tr("Every frame in and out is written to a traffic journal as it happens, one per connection; "
                            "a saved session keeps its journal beside it. analyze, export and replay read journals."));
    m_folder->setObjectName(QStringLiteral("captureFolder"));
    m_folder->setPlaceholderText(RecordingSettings::defaultFolder());
    m_folder->setToolTip(tr("Where journals are written until a session is saved (empty: the default shown)"));
    m_browse = new QToolButton(this);
    m_browse->setText(tr("&Browse\u2026"));
    connect(m_browse, &QToolButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Capture folder"), m_folder->text());
        if (!dir.isEmpty())
            m_folder->setText(dir);
    });
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_browse);
    m_rotate->setObjectName(QStringLiteral("rotateMiB"));
    m_rotate->setRange(1, 4096);
    m_rotate->setToolTip(tr("A journal that reaches this size is closed and the recording goes on in a new part"));
    m_keep->setObjectName(QStringLiteral("keepMiB"));
    m_keep->setRange(16, 1 << 20);
    m_keep->setSingleStep(256);
    m_keep->setToolTip(tr("The oldest journals in the capture folder are deleted to stay under this size "
                          "(never one being written, never one beside a saved session)"));
    auto *recordingForm = new QFormLayout;
    recordingForm->addRow(m_record);
    // A row made of a layout has no buddy of its own: the label is given the line edit, so that
    // its Alt+F works and the & is not shown.
    auto *folderLabel = new QLabel(tr("Capture &folder:"), this);
    folderLabel->setBuddy(m_folder);
    recordingForm->addRow(folderLabel, folderRow);
    recordingForm->addRow(tr("New journal &part every (MiB):"), m_rotate);
    recordingForm->addRow(tr("&Keep at most (MiB):"), m_keep);
    auto *recording = new QGroupBox(tr("Recording"), this);
    recording->setLayout(recordingForm);
    connect(m_record, &QCheckBox::toggled, this, &PreferencesDialog::updateRecordingEnabled);
    setRecordingSettings(RecordingSettings::load());
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
    layout->addWidget(recording);
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

Theme::Choice PreferencesDialog::themeChoice() const
{
    return Theme::Choice(m_theme->currentData().toInt());
}

void PreferencesDialog::setThemeChoice(Theme::Choice choice)
{
    const int row = m_theme->findData(QVariant::fromValue(int(choice)));
    m_theme->setCurrentIndex(row < 0 ? 0 : row);
}

bool PreferencesDialog::startsSimulator()
{
    return QSettings().value(QLatin1String(kStartSimulatorKey), false).toBool();
}

bool PreferencesDialog::apply()
{
    QSettings().setValue(QLatin1String(kStartSimulatorKey), m_simulator->isChecked());
    if (themeChoice() != Theme::storedChoice() || themeChoice() != Theme::current()) {
        Theme::storeChoice(themeChoice());
        Theme::apply(themeChoice());
    }
    const TranslationLoader::Choice chosen = languageChoice();
    if (chosen == m_stored)
        return false;
    TranslationLoader::storeChoice(chosen);
    m_stored = chosen;
    return true;
}

void PreferencesDialog::setRecordingSettings(const RecordingSettings &settings)
{
    m_record->setChecked(settings.enabled);
    m_folder->setText(settings.folder);
    m_rotate->setValue(settings.rotateMiB);
    m_keep->setValue(settings.keepMiB);
    updateRecordingEnabled();
}

void PreferencesDialog::updateRecordingEnabled()
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_folder, m_browse, m_rotate, m_keep})
        w->setEnabled(m_record->isChecked());
}

RecordingSettings PreferencesDialog::recordingSettings() const
{
    RecordingSettings s;
    s.enabled = m_record->isChecked();
    s.folder = m_folder->text().trimmed();
    s.rotateMiB = m_rotate->value();
    s.keepMiB = m_keep->value();
    return s;
}

void PreferencesDialog::updateNote()
{
    m_note->setText(languageChoice() == m_stored
                        ? tr("mbscope --lang id (or en) chooses the language for one run.")
                        : tr("The new language is used when mbscope is started again."));
}

} // namespace mbscope
