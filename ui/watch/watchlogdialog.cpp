#include "watchlogdialog.h"

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

WatchLogDialog::WatchLogDialog(QWidget *parent)
    : QDialog(parent)
    , m_folder(new QLineEdit(this))
    , m_mode(new QComboBox(this))
    , m_rollMiB(new QSpinBox(this))
    , m_rollMinutes(new QSpinBox(this))
    , m_enabled(new QCheckBox(tr("&Log while the watches run"), this))
{
    setObjectName(QStringLiteral("watchLogDialog"));
    setWindowTitle(tr("CSV log of the watches"));
    m_folder->setObjectName(QStringLiteral("watchLogFolder"));
    m_folder->setPlaceholderText(QStringLiteral("watch-logs"));
    m_folder->setToolTip(tr("One CSV file per watch goes here; a folder that is not absolute is beside the session file"));
    auto *browse = new QToolButton(this);
    browse->setText(tr("&Browse\u2026"));
    connect(browse, &QToolButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("CSV log folder"), m_folder->text());
        if (!dir.isEmpty())
            m_folder->setText(dir);
    });
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    m_mode->addItem(tr("A row per poll"), int(WatchLogSettings::Mode::EveryPoll));
    m_mode->addItem(tr("A row when a value changed"), int(WatchLogSettings::Mode::OnChange));
    m_rollMiB->setRange(0, 1 << 20);
    m_rollMiB->setSpecialValueText(tr("never"));
    m_rollMiB->setSuffix(tr(" MiB"));
    m_rollMinutes->setRange(0, 366 * 24 * 60);
    m_rollMinutes->setSpecialValueText(tr("never"));
    m_rollMinutes->setSuffix(tr(" min"));

    auto *form = new QFormLayout;
    form->addRow(m_enabled);
    auto *folderLabel = new QLabel(tr("&Folder:"), this);
    folderLabel->setBuddy(m_folder);
    form->addRow(folderLabel, folderRow);
    form->addRow(tr("&Rows:"), m_mode);
    form->addRow(tr("New file after (&size):"), m_rollMiB);
    form->addRow(tr("New file after (&age):"), m_rollMinutes);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void WatchLogDialog::setSettings(const WatchLogSettings &settings)
{
    m_enabled->setChecked(settings.enabled);
    m_folder->setText(settings.directory);
    m_mode->setCurrentIndex(qMax(0, m_mode->findData(int(settings.mode))));
    m_rollMiB->setValue(int(settings.rollBytes / (1024 * 1024)));
    m_rollMinutes->setValue(int(settings.rollSeconds / 60));
}

WatchLogSettings WatchLogDialog::settings() const
{
    WatchLogSettings s;
    s.enabled = m_enabled->isChecked();
    s.directory = m_folder->text().trimmed();
    s.mode = WatchLogSettings::Mode(m_mode->currentData().toInt());
    s.rollBytes = qint64(m_rollMiB->value()) * 1024 * 1024;
    s.rollSeconds = qint64(m_rollMinutes->value()) * 60;
    return s;
}

} // namespace mbscope
