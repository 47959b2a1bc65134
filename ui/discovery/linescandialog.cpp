#include "linescandialog.h"

#include "scanform.h"

#include "job/job.h"
#include "job/jobthread.h"

#include <QtCore/QSet>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTreeWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

enum Column { SettingColumn, UnitColumn, ResultColumn };
constexpr int TrialRole = Qt::UserRole + 1; // index into m_trials

// "9600, 19200" as numbers within [low, high]; nullopt names the first bad part in *bad.
std::optional<QList<int>> numberList(const QString &text, int low, int high, QString *bad)
{
    QList<int> out;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int n = part.trimmed().toInt(&ok);
        if (!ok || n < low || n > high) {
            *bad = part.trimmed();
            return std::nullopt;
        }
        out.append(n);
    }
    return out;
}

} // namespace

LineScanDialog::LineScanDialog(QWidget *parent)
    : QDialog(parent)
    , m_job(new Job(this))
    , m_jobs(new JobThread(this))
    , m_scanner(new LineScanner)
    , m_list(new QTreeWidget(this))
    , m_target(new QLineEdit(this))
    , m_bauds(new QLineEdit(QStringLiteral("9600, 19200, 38400, 57600, 115200, 4800, 2400, 1200"), this))
    , m_units(new QLineEdit(this))
    , m_timeout(ScanForm::spinBox(this, "lineTimeout", 1, 60000, 200, tr(" ms")))
    , m_first(new QCheckBox(tr("Stop at the &first setting that answers"), this))
    , m_start(new QPushButton(tr("&Start"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_use(new QPushButton(tr("&Use this setting"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("lineScanDialog"));
    setWindowTitle(tr("Find a serial line's settings"));
    m_target->setObjectName(QStringLiteral("lineTarget"));
    m_target->setToolTip(tr("The serial port, as rtu:///dev/ttyUSB0 or ascii:///dev/ttyUSB0: its line settings are the ones tried."));
    m_bauds->setObjectName(QStringLiteral("lineBauds"));
    m_bauds->setToolTip(tr("Baud rates to try, in this order."));
    m_units->setObjectName(QStringLiteral("lineUnits"));
    m_units->setPlaceholderText(tr("empty: 1 on every setting, then 2-247"));
    m_units->setToolTip(tr("Unit ids asked on every setting, e.g. 1 or 1, 17. Give the id when you know it: without one the scan is long."));
    m_timeout->setToolTip(tr("How long each request waits, plus the time the request and a long answer take on the line at each rate."));
    m_first->setObjectName(QStringLiteral("lineFirst"));

    auto *parities = new QHBoxLayout;
    const QList<QPair<QString, char>> parityTexts{{tr("&Even"), 'E'}, {tr("&None"), 'N'}, {tr("&Odd"), 'O'}};
    for (const auto &[text, letter] : parityTexts) {
        auto *box = new QCheckBox(text, this);
        box->setObjectName(QStringLiteral("lineParity%1").arg(QLatin1Char(letter)));
        box->setChecked(true);
        parities->addWidget(box);
        m_parities.append(box);
    }
    parities->addSpacing(24);
    for (const int bits : {1, 2}) {
        auto *box = new QCheckBox(bits == 1 ? tr("1 stop bit") : tr("2 stop bits"), this);
        box->setObjectName(QStringLiteral("lineStop%1").arg(bits));
        box->setChecked(true);
        parities->addWidget(box);
        m_stopBits.append(box);
    }
    parities->addStretch();

    auto *form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    form->addRow(tr("&Baud rates:"), m_bauds);
    form->addRow(tr("Parity, stop bits:"), parities);
    form->addRow(tr("Unit i&ds:"), m_units);
    form->addRow(tr("T&imeout:"), m_timeout);
    form->addRow(QString(), m_first);

    m_start->setObjectName(QStringLiteral("lineStart"));
    m_stop->setObjectName(QStringLiteral("lineStop"));
    m_progress->setObjectName(QStringLiteral("lineProgress"));
    m_status->setObjectName(QStringLiteral("lineStatus"));
    m_status->setWordWrap(true);

    m_list->setObjectName(QStringLiteral("lineTrials"));
    m_list->setColumnCount(3);
    m_list->setHeaderLabels({tr("Setting"), tr("Unit"), tr("Result")});
    m_list->setRootIsDecorated(false);
    m_list->setUniformRowHeights(true);
    m_list->header()->setStretchLastSection(true);
    m_list->setColumnWidth(SettingColumn, 120);
    m_list->setColumnWidth(UnitColumn, 60);

    m_use->setObjectName(QStringLiteral("lineUseSetting"));
    m_use->setToolTip(tr("Put the port with the selected setting that worked (or the first) in the unit scan's target."));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_use, QDialogButtonBox::ActionRole);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_list, 1);
    layout->addWidget(buttons);
    resize(680, 560);

    connect(m_start, &QPushButton::clicked, this, &LineScanDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &LineScanDialog::stop);
    connect(m_use, &QPushButton::clicked, this, [this] {
        if (const std::optional<LinkUrl> url = workingUrl()) {
            Q_EMIT settingChosen(*url);
            m_status->setText(tr("The unit scan's target is now %1.").arg(url->toString()));
        }
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &LineScanDialog::reject);
    connect(m_scanner, &LineScanner::tried, this, &LineScanDialog::onTried);
    // The scanner lives in the job's thread: its signals and the job's cancel cross by queued connections.
    m_jobs->adopt(m_scanner);
    connect(m_scanner, &LineScanner::progressChanged, m_job, &Job::report);
    connect(m_job, &Job::cancelRequested, m_scanner, &LineScanner::stop);
    connect(m_job, &Job::finished, this, &LineScanDialog::onFinished);
    connect(m_job, &Job::progressChanged, this, [this](const JobProgress &p) {
        if (m_job->state() == JobState::Running)
            ScanForm::showProgress(m_progress, m_status, p, tr("%1 of %2 tried, %3 answered").arg(p.done).arg(p.total).arg(p.found));
    });
    m_status->setText(tr("Asks the read on every setting until CRC-valid answers come back. Never writes."));
    updateButtons();
}

LineScanDialog::~LineScanDialog()
{
    delete m_jobs; // cancels the scan, ends its thread and deletes the scanner there
}

bool LineScanDialog::isRunning() const
{
    return m_job->isActive();
}

void LineScanDialog::setTarget(const LinkUrl &url, quint8 function, quint16 address)
{
    m_target->setText(url.toString());
    m_ran.function = function;
    m_ran.address = address;
}

std::optional<LineScanSettings> LineScanDialog::settings()
{
    const std::optional<LinkUrl> url = ScanForm::target(m_target, m_status, tr("Give the serial port, e.g. rtu:///dev/ttyUSB0."));
    if (!url)
        return std::nullopt;
    LineScanSettings s;
    s.url = *url;
    s.function = m_ran.function;
    s.address = m_ran.address;
    QString bad;
    const std::optional<QList<int>> bauds = numberList(m_bauds->text(), 50, 4000000, &bad);
    if (!bauds || bauds->isEmpty()) {
        ScanForm::showProblem(m_status, bauds ? tr("Baud rates: give at least one, e.g. 9600, 19200.")
                          : tr("Baud rates: \"%1\" is not a baud rate.").arg(bad));
        return std::nullopt;
    }
    s.bauds = *bauds;
    const std::optional<QList<int>> units = numberList(m_units->text(), 1, 247, &bad);
    if (!units) {
        ScanForm::showProblem(m_status, tr("Unit ids: \"%1\" is not an id from 1 to 247.").arg(bad));
        return std::nullopt;
    }
    s.units.clear();
    for (const int unit : *units)
        s.units.append(quint8(unit));
    s.parities.clear();
    for (QCheckBox *box : std::as_const(m_parities)) {
        if (box->isChecked())
            s.parities.append(box->objectName().back().toLatin1());
    }
    s.stopBits.clear();
    for (int i = 0; i < m_stopBits.size(); ++i) {
        if (m_stopBits.at(i)->isChecked())
            s.stopBits.append(i + 1);
    }
    if (s.parities.isEmpty() || s.stopBits.isEmpty()) {
        ScanForm::showProblem(m_status, tr("Choose at least one parity and one stop-bit count."));
        return std::nullopt;
    }
    s.timeoutMs = m_timeout->value();
    s.stopAtFirst = m_first->isChecked();
    if (const QString problem = s.problem(); !problem.isEmpty()) {
        ScanForm::showProblem(m_status, problem);
        return std::nullopt;
    }
    return s;
}

void LineScanDialog::start()
{
    if (isRunning())
        return;
    const std::optional<LineScanSettings> s = settings();
    if (!s)
        return;
    m_ran = *s;
    m_trials.clear();
    m_list->clear();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    LineScanner *scanner = m_scanner;
    const LineScanSettings settings = *s;
    m_jobs->run(m_job, [this, scanner, settings]() -> JobThread::Outcome {
        // In the job's thread: only the scanner is touched here; the trials come back by value.
        const std::optional<QList<LineTrial>> trials = scanner->run(settings);
        return {scanner->end(), [this, trials] {
                    if (trials)
                        m_trials = *trials;
                }};
    });
    updateButtons();
}

void LineScanDialog::onFinished(JobEnd end)
{
    summarise(end);
    updateButtons();
    Q_EMIT scanFinished(end);
}

void LineScanDialog::onTried(const LineTrial &trial)
{
    auto *item = new QTreeWidgetItem(m_list);
    item->setText(SettingColumn, trial.settingText());
    item->setText(UnitColumn, QString::number(trial.unit));
    item->setText(ResultColumn, trial.works() ? tr("works: %1").arg(trial.probe.summary()) : trial.probe.summary());
    item->setData(SettingColumn, TrialRole, m_list->topLevelItemCount() - 1);
    if (trial.works()) {
        QFont bold = item->font(SettingColumn);
        bold.setBold(true);
        for (int c = 0; c < 3; ++c)
            item->setFont(c, bold);
    }
    m_list->scrollToItem(item);
}

void LineScanDialog::summarise(JobEnd end)
{
    QStringList working;
    QSet<char> parities;
    for (const LineTrial &t : std::as_const(m_trials)) {
        if (t.works()) {
            working.append(tr("%1 (unit %2)").arg(t.settingText()).arg(t.unit));
            parities.insert(t.parity);
        }
    }
    if (end == JobEnd::LinkError && working.isEmpty()) {
        ScanForm::showProblem(m_status, tr("The port failed: %1").arg(m_trials.isEmpty() ? m_ran.url.toString() : m_trials.constLast().probe.summary()));
        return;
    }
    QString text = working.isEmpty() ? tr("No setting answered (%n tried).", nullptr, int(m_trials.size()))
                                     : tr("Answered: %1.").arg(working.join(QStringLiteral(", ")));
    if (end == JobEnd::Stopped)
        text = tr("Stopped. %1").arg(text);
    else if (end == JobEnd::TimeLimit)
        text = tr("Time limit reached. %1").arg(text);
    if (parities.size() > 1)
        text += QLatin1Char(' ')
                + tr("Several parities answered: this line does not carry the parity bit (a pseudo terminal, or a converter "
                     "that ignores it), so the device's parity cannot be told here.");
    m_status->setText(text);
}

std::optional<LinkUrl> LineScanDialog::workingUrl() const
{
    int index = -1;
    if (QTreeWidgetItem *item = m_list->currentItem(); item && item->isSelected())
        index = item->data(SettingColumn, TrialRole).toInt();
    if (index < 0 || index >= m_trials.size() || !m_trials.at(index).works()) {
        index = -1;
        for (int i = 0; i < m_trials.size() && index < 0; ++i) {
            if (m_trials.at(i).works())
                index = i;
        }
    }
    if (index < 0)
        return std::nullopt;
    const LineTrial &t = m_trials.at(index);
    LinkUrl url = m_ran.url;
    url.serial.baud = t.baud;
    url.serial.parity = t.parity;
    url.serial.stopBits = t.stopBits;
    return url;
}

void LineScanDialog::stop()
{
    m_job->cancel();
}

void LineScanDialog::reject()
{
    m_job->cancel();
    QDialog::reject();
}

void LineScanDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    bool works = false;
    for (const LineTrial &t : std::as_const(m_trials))
        works = works || t.works();
    m_use->setEnabled(works && !running);
    QList<QWidget *> fields{m_target, m_bauds, m_units, m_timeout, m_first};
    for (QCheckBox *box : std::as_const(m_parities))
        fields.append(box);
    for (QCheckBox *box : std::as_const(m_stopBits))
        fields.append(box);
    for (QWidget *w : std::as_const(fields))
        w->setEnabled(!running);
}

} // namespace mbscope
