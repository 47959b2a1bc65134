#include "inferdialog.h"

#include "common/lastfolder.h"

#include "inferdraftmodel.h"
#include "scanform.h"

#include "inference/blockinferrer.h"
#include "inference/inferencedraft.h"
#include "job/job.h"
#include "job/jobthread.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <utility>

namespace mbscope {

InferDialog::InferDialog(QWidget *parent)
    : QDialog(parent)
    , m_job(new Job(this))
    , m_jobs(new JobThread(this))
    , m_sampler(new BlockSampler)
    , m_model(new InferDraftModel(this))
    , m_table(new QTableView(this))
    , m_samples(ScanForm::spinBox(this, "inferSamples", 2, 100000, 20))
    , m_interval(ScanForm::spinBox(this, "inferInterval", 10, 3600000, 500, tr(" ms")))
    , m_start(new QPushButton(tr("&Sample and infer"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_again(new QPushButton(tr("&Read again"), this))
    , m_save(new QPushButton(tr("Sa&ve profile\u2026"), this))
    , m_progress(new QProgressBar(this))
    , m_source(new QLabel(this))
    , m_status(new QLabel(this))
{
    setWindowTitle(tr("Infer types"));
    m_samples->setToolTip(tr("How many times every block is read: the more, the surer the kinds and relations."));
    m_interval->setToolTip(tr("From the start of one round of reads to the start of the next."));
    auto *form = new QFormLayout;
    form->addRow(tr("Unit:"), m_source);
    auto *timing = new QHBoxLayout;
    timing->addWidget(m_samples);
    timing->addWidget(new QLabel(tr("every"), this));
    timing->addWidget(m_interval);
    timing->addStretch(1);
    ScanForm::addRow(this, form, tr("Sa&mples:"), m_samples, timing);

    m_start->setObjectName(QStringLiteral("inferStart"));
    m_stop->setObjectName(QStringLiteral("inferStop"));
    m_again->setObjectName(QStringLiteral("inferReadAgain"));
    m_again->setToolTip(tr("Read every block once more and show the values under every reading."));
    m_save->setObjectName(QStringLiteral("inferSave"));
    m_save->setToolTip(tr("Save the draft as a device profile that mbscope simulate --profile serves and "
                          "mbscope export-map exports: the rows checked OK are confirmed, the others stay guesses."));
    m_progress->setObjectName(QStringLiteral("inferProgress"));
    m_status->setObjectName(QStringLiteral("inferStatus"));
    m_status->setWordWrap(true);
    m_table->setObjectName(QStringLiteral("inferTable"));
    m_table->setModel(m_model);
    m_table->setWordWrap(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_again, QDialogButtonBox::ActionRole);
    buttons->addButton(m_save, QDialogButtonBox::ActionRole);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(1100, 640);

    connect(m_start, &QPushButton::clicked, this, &InferDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &InferDialog::stop);
    connect(m_again, &QPushButton::clicked, this, &InferDialog::readAgain);
    connect(m_save, &QPushButton::clicked, this, &InferDialog::chooseFile);
    connect(buttons, &QDialogButtonBox::rejected, this, &InferDialog::reject);
    // The sampler lives in the job's thread: its rounds and the job's cancel cross by queued signals.
    m_jobs->adopt(m_sampler);
    connect(m_sampler, &BlockSampler::roundDone, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_job, &Job::cancelRequested, m_sampler, &BlockSampler::stop);
    connect(m_job, &Job::finished, this, &InferDialog::onFinished);
    connect(m_model, &InferDraftModel::confirmedChanged, this, [this](int confirmed) {
        if (m_haveDraft)
            m_status->setText(tr("%1 of %2 values confirmed. Check the reading whose numbers you recognise, "
                                 "or OK to keep the guess; then save the profile.")
                                  .arg(confirmed)
                                  .arg(m_model->rowCount()));
    });
    m_status->setText(tr("Reads the blocks of the map again and again, then proposes each value's type, order, "
                         "scale, unit and kind. Never writes."));
    updateButtons();
}

void InferDialog::setSource(const LinkUrl &url, quint8 unit, const RegisterMap &map)
{
    m_url = url;
    m_unit = unit;
    SampleSettings s;
    s.takeBlocks(map);
    m_blocks = s.blocks;
    m_maxQuantity = s.maxQuantity;
    int addresses = 0;
    for (const BlockRequest &b : std::as_const(m_blocks))
        addresses += b.count;
    m_source->setText(tr("%1, unit %2: %n block(s) of the map", nullptr, int(m_blocks.size())).arg(url.toString()).arg(int(unit))
                      + tr(", %n address(es)", nullptr, addresses));
    updateButtons();
}

SampleSettings InferDialog::settings(int samples) const
{
    SampleSettings s;
    s.url = m_url;
    s.unit = m_unit;
    s.blocks = m_blocks;
    s.samples = samples;
    s.intervalMs = m_interval->value();
    s.maxQuantity = m_maxQuantity;
    return s;
}

InferDialog::~InferDialog()
{
    delete m_jobs; // cancels the sampling, ends its thread and deletes the sampler there
}

bool InferDialog::isRunning() const
{
    return m_job->isActive();
}

void InferDialog::start()
{
    if (isRunning() || m_blocks.isEmpty())
        return;
    m_progress->setRange(0, m_samples->value());
    m_progress->setValue(0);
    m_status->setText(tr("Reading the blocks %n time(s)\u2026", nullptr, m_samples->value()));
    run(Run::Sample, m_samples->value());
}

void InferDialog::readAgain()
{
    if (isRunning() || !m_haveDraft)
        return;
    run(Run::ReadAgain, 1);
}

void InferDialog::run(Run what, int samples)
{
    m_run = what;
    BlockSampler *sampler = m_sampler;
    const SampleSettings s = settings(samples);
    Job *job = m_job;
    m_jobs->run(m_job, [this, sampler, s, job]() -> JobThread::Outcome {
        // In the job's thread: only the sampler is touched here; what it read comes back by value,
        // the first failure as the job's problem.
        const QList<BlockSamples> read = sampler->run(s);
        if (!sampler->problem().isEmpty())
            job->addProblem(sampler->problem());
        const JobEnd end = job->isCancelRequested() ? JobEnd::Stopped : sampler->linkFailed() ? JobEnd::LinkError : JobEnd::Completed;
        return {end, [this, read] { m_read = read; }};
    });
    updateButtons();
}

void InferDialog::onFinished()
{
    const Run what = std::exchange(m_run, Run::None);
    if (what == Run::ReadAgain) {
        m_model->updateLive(m_read);
        updateButtons();
        Q_EMIT readDone();
        return;
    }
    showInference();
}

void InferDialog::showInference()
{
    int samples = 0;
    for (const BlockSamples &b : std::as_const(m_read))
        samples = std::max(samples, int(b.samples.size()));
    if (samples < 2) {
        m_haveDraft = false;
        const QStringList problems = m_job->problems();
        ScanForm::showProblem(m_status, problems.isEmpty() ? tr("Too few reads answered to infer anything.")
                                                           : tr("Nothing could be read: %1").arg(problems.constFirst()));
        updateButtons();
        return;
    }
    QList<ValueGuess> guesses;
    for (const QList<ValueGuess> &block : BlockInferrer::inferUnit(m_read))
        guesses += block;
    m_haveDraft = true;
    m_model->setGuesses(guesses);
    m_table->resizeColumnsToContents();
    updateButtons();
    Q_EMIT inferred(int(guesses.size()));
}

void InferDialog::stop()
{
    m_job->cancel();
}

void InferDialog::reject()
{
    m_job->cancel();
    QDialog::reject();
}

bool InferDialog::saveProfile(const QString &path)
{
    if (!m_haveDraft)
        return false;
    QSaveFile file(path);
    const QByteArray json = InferenceDraft::toJson(m_model->confirmedGuesses(), m_unit, QFileInfo(path).completeBaseName(),
                                                   m_url.toString(), m_interval->value());
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit()) {
        ScanForm::showProblem(m_status, tr("Cannot save %1: %2").arg(QDir::toNativeSeparators(path), file.errorString()));
        return false;
    }
    m_status->setText(tr("Saved %1 (%2 of %3 values confirmed): mbscope simulate --profile %1 serves it, "
                         "mbscope export-map %1 --to FORMAT exports it.")
                          .arg(QDir::toNativeSeparators(path))
                          .arg(m_model->confirmedCount())
                          .arg(m_model->rowCount()));
    return true;
}

void InferDialog::chooseFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save profile"), LastFolder::start(QStringLiteral("unit-%1-inferred.json").arg(int(m_unit))),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        saveProfile(path);
}

void InferDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running && !m_blocks.isEmpty());
    m_stop->setEnabled(running);
    m_again->setEnabled(!running && m_haveDraft);
    m_save->setEnabled(!running && m_haveDraft);
    m_samples->setEnabled(!running);
    m_interval->setEnabled(!running);
}

} // namespace mbscope
