#include "watchprofiledialog.h"

#include "common/lastfolder.h"

#include "profile/profileloader.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

WatchProfileDialog::WatchProfileDialog(QWidget *parent)
    : QDialog(parent)
    , m_profile(new QComboBox(this))
    , m_unit(new QSpinBox(this))
    , m_target(new QLineEdit(this))
    , m_interval(new QSpinBox(this))
{
    setObjectName(QStringLiteral("watchProfileDialog"));
    setWindowTitle(tr("Watches from a device profile"));
    m_profile->setEditable(true);
    for (const ShippedProfile &shipped : ProfileLoader::shippedProfiles())
        m_profile->addItem(shipped.name);
    m_profile->setToolTip(tr("A shipped profile's name, or the path of a profile file"));
    auto *browse = new QToolButton(this);
    browse->setText(tr("&Browse\u2026"));
    connect(browse, &QToolButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Device profile"), LastFolder::start(), tr("Profiles (*.json)"));
        LastFolder::remember(path);
        if (!path.isEmpty())
            m_profile->setCurrentText(path);
    });
    auto *profileRow = new QHBoxLayout;
    profileRow->addWidget(m_profile, 1);
    profileRow->addWidget(browse);
    m_unit->setRange(0, 255);
    m_unit->setValue(1);
    m_target->setPlaceholderText(QStringLiteral("tcp://127.0.0.1:502"));
    m_interval->setRange(0, 24 * 3600 * 1000);
    m_interval->setSuffix(tr(" ms"));
    m_interval->setValue(1000);

    auto *form = new QFormLayout;
    // A row that is a layout gets no buddy from the form: the label would show "&Profile:".
    auto *profileLabel = new QLabel(tr("&Profile:"), this);
    profileLabel->setBuddy(m_profile);
    form->addRow(profileLabel, profileRow);
    form->addRow(tr("&Unit:"), m_unit);
    form->addRow(tr("&Target:"), m_target);
    form->addRow(tr("&Interval:"), m_interval);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void WatchProfileDialog::setTarget(const QString &target)
{
    m_target->setText(target);
}

void WatchProfileDialog::setProfile(const QString &nameOrPath)
{
    m_profile->setCurrentText(nameOrPath);
}

QString WatchProfileDialog::profile() const
{
    return m_profile->currentText().trimmed();
}

int WatchProfileDialog::unit() const
{
    return m_unit->value();
}

QString WatchProfileDialog::target() const
{
    return m_target->text().trimmed();
}

int WatchProfileDialog::intervalMs() const
{
    return m_interval->value();
}

} // namespace mbscope
