#include "timingscandialog.h"

#include "common/lastfolder.h"
#include "scanform.h"
#include "timingresulttree.h"

#include "discovery/profiledraft.h"
#include "job/job.h"
#include "job/jobthread.h"

#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

TimingScanDialog::TimingScanDialog(QWidget *parent)
    : QDialog(parent)
    , m_job(new Job(this))
    , m_jobs(new JobThread(this))
    , m_scanner(new TimingScanner)
    , m_tree(new TimingResultTree(this))
    , m_target(new QLineEdit(this))
    , m_unit(ScanForm::spinBox(this, "timingUnit", 0, 255, 1))
    , m_function(new QComboBox(this))
    , m_address(ScanForm::spinBox(this, "timingAddress", 0, 65535, 0))
    , m_timeout(ScanForm::spinBox(this, "timingTimeout", 1, 60000, 1000, tr(" ms")))
    , m_gaps(new QLineEdit(QStringLiteral("200, 100, 50, 20, 10, 5, 2, 1, 0"), this))
    , m_perGap(ScanForm::spinBox(this, "timingPerGap", 1, 10000, 20))
    , m_pipeline(ScanForm::spinBox(this, "timingPipeline", 1, 64, 8))
    , m_clients(ScanForm::spinBox(this, "timingClients", 1, 256, 16))
    , m_start(new QPushButton(tr("&Start"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_copy(new QPushButton(tr("&Copy settings"), this))
    , m_saveLimits(new QPushButton(tr("Record &limits in profile\u2026"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("timingScanDialog"));
    setWindowTitle(tr("Time a unit"));
    m_target->setObjectName(QStringLiteral("timingTarget"));
    m_target->setToolTip(tr("The link of the unit. The scan opens connections of its own."));
    m_function->setObjectName(QStringLiteral("timingFunction"));
    ScanForm::addReadFunctions(m_function);
    m_function->setToolTip(tr("The read asked throughout: a timing scan never writes."));
    m_gaps->setObjectName(QStringLiteral("timingGaps"));
    m_gaps->setToolTip(tr("Quiet times between requests to try, in milliseconds, from the longest down; "
                          "the scan stops going shorter once errors start."));
    m_perGap->setToolTip(tr("Requests asked at each gap."));
    m_pipeline->setToolTip(tr("Modbus TCP: requests sent without waiting for answers."));
    m_clients->setToolTip(tr("TCP links: connections held open at once, each asked in turn."));

    auto *unitRow = new QHBoxLayout;
    unitRow->addWidget(m_unit);
    unitRow->addWidget(m_function);
    unitRow->addWidget(new QLabel(tr("address"), this));
    unitRow->addWidget(m_address);
    unitRow->addStretch();
    auto *gapRow = new QHBoxLayout;
    gapRow->addWidget(m_gaps, 1);
    gapRow->addWidget(new QLabel(tr("ms, asked"), this));
    gapRow->addWidget(m_perGap);
    gapRow->addWidget(new QLabel(tr("times each"), this));
    auto *linkRow = new QHBoxLayout;
    linkRow->addWidget(m_pipeline);
    linkRow->addWidget(new QLabel(tr("pipelined, up to"), this));
    linkRow->addWidget(m_clients);
    linkRow->addWidget(new QLabel(tr("clients at once"), this));
    linkRow->addStretch();
    auto *timeoutRow = new QHBoxLayout;
    timeoutRow->addWidget(m_timeout);
    timeoutRow->addStretch();

    auto *form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    ScanForm::addRow(this, form, tr("&Unit:"), m_unit, unitRow);
    ScanForm::addRow(this, form, tr("&Gaps:"), m_gaps, gapRow);
    ScanForm::addRow(this, form, tr("TCP &requests:"), m_pipeline, linkRow);
    ScanForm::addRow(this, form, tr("T&imeout:"), m_timeout, timeoutRow);

    m_start->setObjectName(QStringLiteral("timingStart"));
    m_stop->setObjectName(QStringLiteral("timingStop"));
    m_progress->setObjectName(QStringLiteral("timingProgress"));
    m_progress->setRange(0, 1);
    m_status->setObjectName(QStringLiteral("timingStatus"));
    m_status->setWordWrap(true);

    m_copy->setObjectName(QStringLiteral("timingCopySettings"));
    m_copy->setToolTip(tr("The recommended settings as text: a watch link's gapMs and timeoutMs, mbscope's --timeout "
                          "and Telegraf's modbus input."));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_copy, QDialogButtonBox::ActionRole);
    m_saveLimits->setObjectName(QStringLiteral("timingSaveLimits"));
    m_saveLimits->setToolTip(tr("Merge what was measured (minGapMs, warmUpMs, maxClients, maxQuantity) into an existing "
                                "device profile's limits, such as the map scan's draft; its other contents stay."));
    buttons->addButton(m_saveLimits, QDialogButtonBox::ActionRole);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_tree, 1);
    layout->addWidget(buttons);
    resize(720, 560);

    connect(m_start, &QPushButton::clicked, this, &TimingScanDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &TimingScanDialog::stop);
    connect(m_copy, &QPushButton::clicked, this, &TimingScanDialog::copySettings);
    connect(m_saveLimits, &QPushButton::clicked, this, &TimingScanDialog::chooseProfileFile);
    connect(buttons, &QDialogButtonBox::rejected, this, &TimingScanDialog::reject);
    connect(m_scanner, &TimingScanner::step, this, [this](const QString &what) { m_part = what; });
    // The scanner lives in the job's thread: its signals and the job's cancel cross by queued connections.
    m_jobs->adopt(m_scanner);
    connect(m_scanner, &TimingScanner::progressChanged, m_job, &Job::report);
    connect(m_job, &Job::cancelRequested, m_scanner, &TimingScanner::stop);
    connect(m_job, &Job::finished, this, &TimingScanDialog::onFinished);
    connect(m_job, &Job::progressChanged, this, [this](const JobProgress &p) {
        if (m_job->state() == JobState::Running)
            ScanForm::showProgress(m_progress, m_status, p, tr("Measuring %1: %2 of %3 steps").arg(m_part).arg(p.done).arg(p.total));
    });
    m_status->setText(tr("Asks the read again and again, at shorter and shorter gaps, and says what the unit stood. Never writes."));
    updateButtons();
}

TimingScanDialog::~TimingScanDialog()
{
    delete m_jobs; // cancels the scan, ends its thread and deletes the scanner there
}

bool TimingScanDialog::isRunning() const
{
    return m_job->isActive();
}

void TimingScanDialog::setTarget(const LinkUrl &url, quint8 unit, quint8 function, quint16 address)
{
    m_target->setText(url.toString());
    m_unit->setValue(unit);
    m_function->setCurrentIndex(qMax(0, m_function->findData(int(function))));
    m_address->setValue(address);
}

std::optional<TimingScanSettings> TimingScanDialog::settings()
{
    const std::optional<LinkUrl> url = ScanForm::target(m_target, m_status, tr("Give the link of the unit, e.g. tcp://192.168.1.10:502."));
    if (!url)
        return std::nullopt;
    TimingScanSettings s;
    s.url = *url;
    s.unit = quint8(m_unit->value());
    s.function = quint8(m_function->currentData().toInt());
    s.address = quint16(m_address->value());
    s.timeoutMs = m_timeout->value();
    s.requestsPerGap = m_perGap->value();
    s.pipelineDepth = m_pipeline->value();
    s.maxClients = m_clients->value();
    s.gapsMs.clear();
    const QStringList parts = m_gaps->text().split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &part : parts) {
        bool ok = false;
        const int gap = part.trimmed().toInt(&ok);
        if (!ok || gap < 0 || gap > 60000) {
            ScanForm::showProblem(m_status, tr("Gaps: \"%1\" is not a number of milliseconds from 0 to 60000.").arg(part.trimmed()));
            return std::nullopt;
        }
        s.gapsMs.append(gap);
    }
    if (s.gapsMs.isEmpty()) {
        ScanForm::showProblem(m_status, tr("Gaps: give at least one, e.g. 100, 20, 0."));
        return std::nullopt;
    }
    std::sort(s.gapsMs.begin(), s.gapsMs.end(), std::greater<int>());
    if (const QString problem = s.problem(); !problem.isEmpty()) {
        ScanForm::showProblem(m_status, problem);
        return std::nullopt;
    }
    return s;
}

void TimingScanDialog::start()
{
    if (isRunning())
        return;
    const std::optional<TimingScanSettings> s = settings();
    if (!s)
        return;
    m_runSettings = s;
    m_scannedFunction = s->function;
    m_part.clear();
    m_report.reset();
    m_tree->clear();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    TimingScanner *scanner = m_scanner;
    const TimingScanSettings settings = *s;
    m_jobs->run(m_job, [this, scanner, settings]() -> JobThread::Outcome {
        // In the job's thread: only the scanner is touched here; the report comes back by value.
        const std::optional<TimingReport> report = scanner->run(settings);
        return {scanner->end(), [this, report] { m_report = report; }};
    });
    updateButtons();
}

void TimingScanDialog::onFinished(JobEnd end)
{
    const std::optional<TimingScanSettings> s = m_runSettings;
    const std::optional<TimingReport> report = m_report;
    const bool stopped = end == JobEnd::Stopped;
    const bool timeLimit = end == JobEnd::TimeLimit;
    if (report && s)
        m_tree->showReport(*s, *report);
    if (stopped && (!report || report->firstAnswerMs < 0))
        m_status->setText(tr("Stopped before the first answer: nothing was measured."));
    else if (timeLimit && (!report || report->firstAnswerMs < 0))
        ScanForm::showProblem(m_status, tr("The time limit of %1 came before the first answer: nothing was measured.")
                                            .arg(ScanForm::duration(s->maxDurationMs)));
    else if (!report || report->firstAnswerMs < 0)
        ScanForm::showProblem(m_status, tr("No good answer from unit %1 on %2: nothing to time.").arg(s->unit).arg(s->url.toString()));
    else if (stopped)
        m_status->setText(tr("Stopped: the measurements after it were not made."));
    else if (timeLimit)
        m_status->setText(tr("Time limit of %1 reached: the measurements after it were not made.").arg(ScanForm::duration(s->maxDurationMs)));
    else
        m_status->setText(tr("Done: a gap of %1 ms and a timeout of %2 ms are recommended.")
                              .arg(report->recommendedGapMs())
                              .arg(report->recommendedTimeoutMs()));
    updateButtons();
    Q_EMIT scanFinished(stopped);
}

void TimingScanDialog::stop()
{
    m_job->cancel();
}

void TimingScanDialog::reject()
{
    m_job->cancel();
    QDialog::reject();
}

void TimingScanDialog::copySettings()
{
    if (!m_report)
        return;
    QGuiApplication::clipboard()->setText(TimingResultTree::settingsText(*m_report));
    m_status->setText(tr("The recommended settings are on the clipboard."));
}

bool TimingScanDialog::saveLimits(const QString &path)
{
    if (!m_report || m_report->firstAnswerMs < 0)
        return false;
    const QJsonObject limits = m_report->profileLimits(m_scannedFunction);
    return ScanForm::mergeIntoProfile(path, [&limits, this](const QByteArray &profile, QString *said, QString *problem) {
        return ProfileDraft::mergeLimits(profile, limits, m_report->answeredReads(m_scannedFunction), said, problem);
    }, m_status);
}

void TimingScanDialog::chooseProfileFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Record limits in profile"), LastFolder::start(QString()),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        saveLimits(path);
}

void TimingScanDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    m_copy->setEnabled(m_report.has_value() && m_report->firstAnswerMs >= 0 && !running);
    m_saveLimits->setEnabled(m_copy->isEnabled());
    for (QWidget *w : std::initializer_list<QWidget *>{m_target, m_unit, m_function, m_address, m_timeout, m_gaps, m_perGap,
                                                       m_pipeline, m_clients})
        w->setEnabled(!running);
}

} // namespace mbscope
