#include "conformancedialog.h"

#include "conformancepdf.h"
#include "conformanceresultmodel.h"

#include "conformance/conformancehtml.h"
#include "conformance/conformancerunner.h"
#include "discovery/scanform.h"
#include "job/job.h"
#include "job/jobthread.h"
#include "profile/profileloader.h"
#include "session/junitreport.h"

#include <QtCore/QFileInfo>
#include <QtCore/QJsonDocument>
#include <QtCore/QSaveFile>
#include <QtCore/QTimer>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

ConformanceDialog::ConformanceDialog(QWidget *parent)
    : QDialog(parent)
    , m_model(new ConformanceResultModel(this))
    , m_target(new QLineEdit(this))
    , m_unit(ScanForm::spinBox(this, "conformUnit", 1, 247, 1))
    , m_timeout(ScanForm::spinBox(this, "conformTimeout", 10, 60000, 1000, tr(" ms")))
    , m_profile(new QLineEdit(this))
    , m_writable(new QLineEdit(this))
    , m_only(new QLineEdit(this))
    , m_start(new QPushButton(tr("&Run"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_save(new QPushButton(tr("&Save report\u2026"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_table(new QTableView(this))
    , m_job(new Job(this))
    , m_jobs(new JobThread(this))
{
    setObjectName(QStringLiteral("conformanceDialog"));
    setWindowTitle(tr("Conformance"));
    m_target->setObjectName(QStringLiteral("conformTarget"));
    m_target->setToolTip(tr("The link of the slave under test. The battery opens a connection of its own."));
    m_unit->setToolTip(tr("The unit id under test, 1-247."));
    m_timeout->setToolTip(tr("How long each request waits for its answer."));
    m_profile->setObjectName(QStringLiteral("conformProfile"));
    m_profile->setPlaceholderText(tr("none: what the device supports is read from its answers"));
    m_profile->setToolTip(tr("A device profile (shipped name or JSON file) that declares what the device promises: "
                             "its functions, and its tables' readable and missing addresses."));
    m_writable->setObjectName(QStringLiteral("conformWritable"));
    m_writable->setPlaceholderText(tr("none: the battery only reads"));
    m_writable->setToolTip(tr("Addresses the write checks may use, each value found is put back: holding:10-13, coils:10-17. "
                              "Empty: nothing is written."));
    m_only->setObjectName(QStringLiteral("conformOnly"));
    m_only->setPlaceholderText(tr("every check"));
    m_only->setToolTip(tr("Run only the checks whose id starts with one of these, comma-separated: read.03, mbap"));
    m_start->setObjectName(QStringLiteral("conformStart"));
    m_stop->setObjectName(QStringLiteral("conformStop"));
    m_save->setObjectName(QStringLiteral("conformSave"));
    m_save->setToolTip(tr("Save the scorecard as an HTML page, a PDF, JSON or JUnit XML"));
    m_progress->setObjectName(QStringLiteral("conformProgress"));
    m_status->setObjectName(QStringLiteral("conformStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setObjectName(QStringLiteral("conformResults"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setColumnWidth(ConformanceResultModel::VerdictColumn, 60);
    m_table->setColumnWidth(ConformanceResultModel::CheckColumn, 300);
    m_table->setColumnWidth(ConformanceResultModel::ClauseColumn, 190);
    m_table->setColumnWidth(ConformanceResultModel::SentenceColumn, 380);
    m_table->setColumnWidth(ConformanceResultModel::RequestColumn, 180);

    auto *form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    auto *unitRow = new QHBoxLayout;
    unitRow->addWidget(m_unit);
    unitRow->addWidget(new QLabel(tr("timeout"), this));
    unitRow->addWidget(m_timeout);
    unitRow->addStretch();
    ScanForm::addRow(this, form, tr("&Unit:"), m_unit, unitRow);
    form->addRow(tr("&Profile:"), m_profile);
    form->addRow(tr("&Writable:"), m_writable);
    form->addRow(tr("&Only:"), m_only);

    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_save);
    bottom->addStretch();
    auto *close = new QPushButton(tr("&Close"), this);
    connect(close, &QPushButton::clicked, this, &QDialog::reject);
    bottom->addWidget(close);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_table, 1);
    layout->addLayout(bottom);

    connect(m_start, &QPushButton::clicked, this, &ConformanceDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &ConformanceDialog::stop);
    connect(m_save, &QPushButton::clicked, this, &ConformanceDialog::save);
    connect(m_job, &Job::finished, this, &ConformanceDialog::onFinished);
    m_status->setText(tr("Reads only, unless Writable names addresses. A failure says what was sent, what came back and "
                         "what the clause requires."));
    resize(1200, 700);
    updateButtons();
}

ConformanceDialog::~ConformanceDialog()
{
    if (m_runner)
        m_runner->stop();
    delete m_jobs; // ends the job's thread: the check in flight returns at once, the rest are not run
}

bool ConformanceDialog::isRunning() const
{
    return m_job->isActive();
}

void ConformanceDialog::setTarget(const LinkUrl &url)
{
    m_target->setText(url.toString());
}

std::optional<ConformanceSettings> ConformanceDialog::settings()
{
    const std::optional<LinkUrl> url = ScanForm::target(m_target, m_status, tr("Type the link of the slave under test."));
    if (!url)
        return std::nullopt;
    ConformanceSettings s;
    s.url = *url;
    s.unit = quint8(m_unit->value());
    s.timeoutMs = m_timeout->value();
    for (const QString &item : m_writable->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        QString error;
        const std::optional<TableRange> range = TableRange::parse(item.trimmed(), &error);
        if (!range) {
            ScanForm::showProblem(m_status, tr("Writable: %1").arg(error));
            return std::nullopt;
        }
        s.writable.append(*range);
    }
    for (const QString &prefix : m_only->text().split(QLatin1Char(','), Qt::SkipEmptyParts))
        s.only.append(prefix.trimmed());
    if (!s.only.isEmpty()) {
        bool any = false;
        for (const ConformanceCheck &c : ConformanceRunner::battery())
            any = any || s.selected(c.id);
        if (!any) {
            ScanForm::showProblem(m_status, tr("Only: %1 selects no check.").arg(m_only->text()));
            return std::nullopt;
        }
    }
    if (const QString profile = m_profile->text().trimmed(); !profile.isEmpty()) {
        const ProfileLoadResult loaded = ProfileLoader::load(profile);
        if (!loaded.ok) {
            ScanForm::showProblem(m_status, tr("Profile %1: %2").arg(profile, loaded.errorText()));
            return std::nullopt;
        }
        QString error;
        if (!s.applyProfile(loaded.profile, &error)) {
            ScanForm::showProblem(m_status, tr("Profile %1: %2").arg(profile, error));
            return std::nullopt;
        }
    }
    return s;
}

void ConformanceDialog::start()
{
    if (isRunning())
        return;
    const std::optional<ConformanceSettings> s = settings();
    if (!s)
        return;
    m_result.reset();
    m_model->clear();
    int total = 0;
    for (const ConformanceCheck &c : ConformanceRunner::battery())
        total += s->selected(c.id) ? 1 : 0;
    m_progress->setRange(0, total);
    m_progress->setValue(0);
    m_status->setText(s->writable.isEmpty() ? tr("Running: reads only\u2026") : tr("Running: writes allowed on %1\u2026").arg(m_writable->text()));
    run(*s);
    updateButtons();
}

void ConformanceDialog::run(const ConformanceSettings &settings)
{
    m_runner = std::make_unique<ConformanceRunner>(settings);
    m_runner->setTrafficLog(m_trafficLog); // the shared, locked log: written from the job's thread
    // Called in the job's thread: each crosses to this one by a queued call.
    m_runner->setFramesLogged([this](const QList<TrafficFrame> &frames, const QString &link) {
        QMetaObject::invokeMethod(this, [this, frames, link] { Q_EMIT framesLogged(frames, link); }, Qt::QueuedConnection);
    });
    m_delivered.reset();
    ConformanceRunner *runner = m_runner.get();
    m_jobs->run(m_job, [this, runner]() -> JobThread::Outcome {
        const ConformanceResult result = runner->run([this](const CheckResult &r) {
            QMetaObject::invokeMethod(this, [this, r] {
                m_model->append(r);
                m_progress->setValue(m_progress->value() + 1);
                m_table->scrollToBottom();
                Q_EMIT checkDecided(m_progress->value(), m_progress->maximum());
            }, Qt::QueuedConnection);
        });
        return {result.linkFailed ? JobEnd::LinkError : JobEnd::Completed, [this, result] { m_delivered = result; }};
    });
}

void ConformanceDialog::onFinished()
{
    m_runner.reset();
    if (!m_delivered)
        return;
    const ConformanceResult result = *m_delivered;
    m_result = result;
    if (!result.linkLostAt.isEmpty()) {
        // The check the device died under is re-judged once the next request finds it gone: the
        // rows shown as they came give way to the scorecard.
        m_model->clear();
        for (const CheckResult &c : result.checks)
            m_model->append(c);
    }
    if (result.linkFailed) {
        ScanForm::showProblem(m_status, tr("Not tested: %1").arg(result.linkMessage));
    } else {
        QString verdict = result.verdictSentence();
        verdict[0] = verdict.at(0).toUpper();
        const QString text = QStringLiteral("%1. %2 in %3.")
                                 .arg(verdict, result.countsSentence(), ScanForm::duration(result.elapsedNs / 1000000));
        if (result.passed())
            m_status->setText(text);
        else
            ScanForm::showProblem(m_status, text);
    }
    updateButtons();
    Q_EMIT finished(result.passed());
}

void ConformanceDialog::stop()
{
    if (m_runner)
        m_runner->stop();
    m_status->setText(tr("Stopping after the check that runs now\u2026"));
}

void ConformanceDialog::reject()
{
    stop();
    QDialog::reject();
}

bool ConformanceDialog::saveReport(const QString &path, QString *error)
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!m_result || m_result->linkFailed)
        return fail(tr("There is no scorecard to save: run the battery first."));
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("html") || suffix == QLatin1String("htm"))
        return ConformanceHtml::write(*m_result, path, error);
    if (suffix == QLatin1String("pdf"))
        return ConformancePdf::write(*m_result, path, error);
    if (suffix == QLatin1String("xml"))
        return JUnitReport::write(m_result->toJUnit(), path, error);
    if (suffix != QLatin1String("json"))
        return fail(tr("%1: name the file .html, .pdf, .json or .xml (JUnit) to say which report to save.").arg(path));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(tr("cannot write %1: %2").arg(path, file.errorString()));
    file.write(QJsonDocument(m_result->toJson()).toJson(QJsonDocument::Indented));
    if (!file.commit())
        return fail(tr("cannot write %1: %2").arg(path, file.errorString()));
    return true;
}

void ConformanceDialog::save()
{
    QString filter;
    QString path = QFileDialog::getSaveFileName(this, tr("Save the scorecard"), QStringLiteral("conform.html"),
                                                      tr("HTML page (*.html);;PDF (*.pdf);;JSON (*.json);;JUnit XML (*.xml)"), &filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty()) // the filter chosen says the format
        path += filter.contains(QLatin1String("*.json")) ? QStringLiteral(".json")
              : filter.contains(QLatin1String("*.pdf"))  ? QStringLiteral(".pdf")
              : filter.contains(QLatin1String("*.xml"))  ? QStringLiteral(".xml")
                                                          : QStringLiteral(".html");
    QString error;
    if (saveReport(path, &error))
        m_status->setText(tr("Saved %1.").arg(path));
    else
        ScanForm::showProblem(m_status, error);
}

void ConformanceDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    m_save->setEnabled(!running && m_result.has_value() && !m_result->linkFailed);
    for (QWidget *w : std::initializer_list<QWidget *>{m_target, m_unit, m_timeout, m_profile, m_writable, m_only})
        w->setEnabled(!running);
}

} // namespace mbscope
