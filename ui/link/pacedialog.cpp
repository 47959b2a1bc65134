#include "pacedialog.h"

#include "common/lastfolder.h"
#include "profile/profileloader.h"

#include <QtCore/QFileInfo>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

QSpinBox *msBox(QWidget *parent, const char *objectName, int high, qint64 value)
{
    auto *box = new QSpinBox(parent);
    box->setObjectName(QLatin1String(objectName));
    box->setRange(0, high);
    box->setSingleStep(10);
    box->setSuffix(PaceDialog::tr(" ms"));
    box->setSpecialValueText(PaceDialog::tr("none"));
    box->setValue(int(value));
    return box;
}

} // namespace

PaceDialog::PaceDialog(const Pace &pace, bool streamLink, QWidget *parent)
    : QDialog(parent)
    , m_streamLink(streamLink)
{
    setObjectName(QStringLiteral("paceDialog"));
    setWindowTitle(tr("Device pace"));
    auto *intro = new QLabel(tr("How fast this device may be asked. Every request the window sends on the target keeps it "
                                "(Send, Poll, sweeps), as gap=, warmup= and close=each of its URL do on the command line."),
                             this);
    intro->setWordWrap(true);
    m_gap = msBox(this, "paceGap", 600000, pace.gap.count());
    m_gap->setToolTip(tr("No request sooner than this after the one before it was sent or its exchange ended"));
    m_warmUp = msBox(this, "paceWarmUp", 600000, pace.warmUp.count());
    m_warmUp->setToolTip(tr("Nothing is sent sooner than this after the link opens (every time it opens)"));
    m_close = new QCheckBox(tr("A new connection for each request (the device hangs up after each answer)"), this);
    m_close->setObjectName(QStringLiteral("paceClose"));
    m_close->setChecked(streamLink && pace.closeAfterAnswer);
    m_close->setEnabled(streamLink);
    if (!streamLink)
        m_close->setToolTip(tr("Only a stream link (TCP, RTU or ASCII over TCP, TLS) has a connection to hang up"));
    auto *fromProfile = new QPushButton(tr("From &profile…"), this);
    fromProfile->setObjectName(QStringLiteral("paceFromProfile"));
    fromProfile->setToolTip(tr("Take minGapMs, warmUpMs and closesAfterAnswer from a device profile's limits (as scan --timing "
                               "--profile-out records them), with some to spare, as poll --profile keeps them"));
    connect(fromProfile, &QPushButton::clicked, this, &PaceDialog::chooseProfile);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("paceStatus"));
    m_status->setWordWrap(true);

    auto *form = new QFormLayout;
    form->addRow(tr("&Gap between requests:"), m_gap);
    form->addRow(tr("&Warm-up after connecting:"), m_warmUp);
    form->addRow(QString(), m_close);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->addButton(fromProfile, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    resize(qMax(sizeHint().width(), 520), sizeHint().height());
}

PaceDialog::Pace PaceDialog::pace() const
{
    return Pace{std::chrono::milliseconds(m_gap->value()), std::chrono::milliseconds(m_warmUp->value()),
                m_streamLink && m_close->isChecked()};
}

bool PaceDialog::takeProfile(const QString &path)
{
    const ProfileLoadResult loaded = ProfileLoader::loadFile(path);
    if (!loaded.ok) {
        m_status->setText(tr("Nothing taken: %1").arg(loaded.errorText()));
        resize(width(), qMax(height(), sizeHint().height()));
        return false;
    }
    const DeviceLimits &limits = loaded.profile.limits;
    m_gap->setValue(int(limits.clientGap().count()));
    m_warmUp->setValue(int(limits.clientWarmUp().count()));
    m_close->setChecked(m_streamLink && limits.closesAfterAnswer);
    QStringList taken;
    if (limits.minGapMs > 0)
        taken.append(tr("minGapMs %1 (%2 ms, 1 ms to spare)").arg(limits.minGapMs).arg(limits.clientGap().count()));
    if (limits.warmUpMs > 0)
        taken.append(tr("warmUpMs %1 (%2 ms, a tenth to spare)").arg(limits.warmUpMs).arg(limits.clientWarmUp().count()));
    if (limits.closesAfterAnswer)
        taken.append(m_streamLink ? tr("closesAfterAnswer") : tr("not closesAfterAnswer (this link has no connection to hang up)"));
    QString text = taken.isEmpty() ? tr("%1 has no minGapMs, warmUpMs or closesAfterAnswer: no pace.").arg(QFileInfo(path).fileName())
                                   : tr("From %1: %2.").arg(QFileInfo(path).fileName(), taken.join(QStringLiteral(", ")));
    if (!limits.maxQuantity.isEmpty()) {
        QStringList largest;
        for (auto it = limits.maxQuantity.cbegin(); it != limits.maxQuantity.cend(); ++it)
            largest.append(QStringLiteral("%1 %2").arg(DeviceLimits::functionKey(it.key())).arg(it.value()));
        text += QLatin1Char(' ')
              + tr("Its maxQuantity (%1) is not applied: the window sends the request you build as it is; keep reads within it.")
                    .arg(largest.join(QStringLiteral(", ")));
    }
    m_status->setText(text);
    m_status->setToolTip(path);
    // The note takes lines of its own: the dialog grows for them rather than squeezing the fields.
    resize(width(), qMax(height(), sizeHint().height()));
    return true;
}

void PaceDialog::chooseProfile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Device pace from a profile"), LastFolder::start(QString()),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        takeProfile(path);
}

} // namespace mbscope
