#include "scanform.h"

#include "profile/profileloader.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>

#include <QtWidgets/QComboBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>

namespace mbscope {

QSpinBox *ScanForm::spinBox(QWidget *parent, const char *objectName, int low, int high, int value, const QString &suffix)
{
    auto *box = new QSpinBox(parent);
    box->setObjectName(QLatin1String(objectName));
    box->setRange(low, high);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

void ScanForm::addReadFunctions(QComboBox *box)
{
    box->addItem(tr("01 Read Coils"), 1);
    box->addItem(tr("02 Read Discrete Inputs"), 2);
    box->addItem(tr("03 Read Holding Registers"), 3);
    box->addItem(tr("04 Read Input Registers"), 4);
    box->setCurrentIndex(2);
}

void ScanForm::addRow(QWidget *parent, QFormLayout *form, const QString &label, QWidget *buddy, QLayout *fields)
{
    auto *text = new QLabel(label, parent);
    text->setBuddy(buddy);
    form->addRow(text, fields);
}

QHBoxLayout *ScanForm::runRow(QPushButton *start, QPushButton *stop, QProgressBar *progress)
{
    auto *row = new QHBoxLayout;
    row->addWidget(start);
    row->addWidget(stop);
    row->addWidget(progress, 1);
    return row;
}

void ScanForm::showProblem(QLabel *status, const QString &text)
{
    // Rich text: a line break of the text is a <br>.
    status->setText(QStringLiteral("<span style=\"color:#c0392b\">%1</span>")
                        .arg(text.toHtmlEscaped().replace(QLatin1Char('\n'), QLatin1String("<br>"))));
}

std::optional<LinkUrl> ScanForm::target(const QLineEdit *target, QLabel *status, const QString &emptyHint)
{
    const QString text = target->text().trimmed();
    const LinkUrl::Result parsed = LinkUrl::parse(text);
    if (!parsed.url)
        showProblem(status, text.isEmpty() ? emptyHint : parsed.error);
    return parsed.url;
}

void ScanForm::showProgress(QProgressBar *bar, QLabel *status, const JobProgress &progress, const QString &counts)
{
    bar->setRange(0, qMax(1, progress.total));
    bar->setValue(qBound(0, progress.done, qMax(1, progress.total)));
    status->setText(tr("%1, about %2 left").arg(counts, duration(progress.remainingMs)));
}

QString ScanForm::duration(qint64 ms)
{
    return ms < 60000 ? tr("%1 s").arg(QString::number(double(ms) / 1000.0, 'f', 1))
                      : tr("%1 min %2 s").arg(ms / 60000).arg((ms / 1000) % 60);
}

bool ScanForm::mergeIntoProfile(const QString &path, const ProfileMerge &merge, QLabel *status)
{
    const QString shown = QDir::toNativeSeparators(path);
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly)) {
        showProblem(status, tr("Cannot read %1: %2").arg(shown, in.errorString()));
        return false;
    }
    const QByteArray profile = in.readAll();
    in.close();
    if (const ProfileLoadResult loaded = ProfileLoader::parse(profile, shown); !loaded.ok) {
        showProblem(status, tr("%1 is not a profile the simulator loads, so nothing was recorded in it: %2")
                                .arg(shown, loaded.errorText()));
        return false;
    }
    QString said;
    QString problem;
    const QByteArray merged = merge(profile, &said, &problem);
    if (problem.isEmpty()) {
        if (const ProfileLoadResult loaded = ProfileLoader::parse(merged, shown); !loaded.ok)
            problem = loaded.errorText();
    }
    if (!problem.isEmpty()) {
        showProblem(status, tr("Cannot record it in %1: %2").arg(shown, problem));
        return false;
    }
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(merged) != merged.size() || !out.commit()) {
        showProblem(status, tr("Cannot save %1: %2").arg(shown, out.errorString()));
        return false;
    }
    status->setText(tr("Recorded in %1: %2.").arg(QFileInfo(path).fileName(), said));
    status->setToolTip(shown);
    return true;
}

} // namespace mbscope
