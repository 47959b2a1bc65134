#include "mapscandialog.h"

#include "common/lastfolder.h"

#include "inferdialog.h"
#include "mapresulttree.h"
#include "scanform.h"

#include "discovery/mapscanner.h"
#include "discovery/profiledraft.h"
#include "discovery/scanwatches.h"
#include "job/job.h"
#include "job/jobthread.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>
#include <QtWidgets/QCheckBox>
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

MapScanDialog::MapScanDialog(QWidget *parent)
    : QDialog(parent)
    , m_job(new Job(this))
    , m_jobs(new JobThread(this))
    , m_scanner(new MapScanner)
    , m_tree(new MapResultTree(this))
    , m_target(new QLineEdit(this))
    , m_unit(ScanForm::spinBox(this, "mapUnit", 0, 255, 1))
    , m_first(ScanForm::spinBox(this, "mapFirstAddress", 0, 65535, 0))
    , m_last(ScanForm::spinBox(this, "mapLastAddress", 0, 65535, 999))
    , m_step(ScanForm::spinBox(this, "mapStep", 1, 2000, 1))
    , m_optional(new QCheckBox(tr("&Optional functions (07, 08, 0B, 0C, 11, 14, 17, 18, 2B/0E)"), this))
    , m_timeout(ScanForm::spinBox(this, "mapTimeout", 1, 60000, 500, tr(" ms")))
    , m_gap(ScanForm::spinBox(this, "mapGap", 0, 60000, 0, tr(" ms")))
    , m_maxRequests(ScanForm::spinBox(this, "mapMaxRequests", 1, 1000000, 20000))
    , m_start(new QPushButton(tr("&Start"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_save(new QPushButton(tr("Save profile &draft\u2026"), this))
    , m_add(new QPushButton(tr("&Add as watches"), this))
    , m_infer(new QPushButton(tr("I&nfer types\u2026"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("mapScanDialog"));
    setWindowTitle(tr("Map a unit's registers"));
    m_target->setObjectName(QStringLiteral("mapTarget"));
    m_target->setToolTip(tr("The link of the unit. The scan opens a connection of its own."));
    m_step->setToolTip(tr("Between blocks, ask one address in this many: 1 finds every address, 16 every block of "
                          "16 addresses or more in about a sixteenth of the requests. A block found is mapped whole."));
    m_optional->setObjectName(QStringLiteral("mapOptional"));
    m_optional->setChecked(true);
    m_maxRequests->setToolTip(tr("The scan stops after this many requests."));
    m_maxRequests->setGroupSeparatorShown(true);

    auto *addresses = new QHBoxLayout;
    addresses->addWidget(m_first);
    addresses->addWidget(new QLabel(tr("to"), this));
    addresses->addWidget(m_last);
    addresses->addWidget(new QLabel(tr("step"), this));
    addresses->addWidget(m_step);
    addresses->addStretch();
    auto *tables = new QHBoxLayout;
    const QStringList tableTexts{tr("0&1 Coils"), tr("0&2 Discrete inputs"), tr("0&3 Holding"), tr("0&4 Input")};
    for (int i = 0; i < tableTexts.size(); ++i) {
        auto *box = new QCheckBox(tableTexts.at(i), this);
        box->setObjectName(QStringLiteral("mapTable%1").arg(i + 1));
        box->setChecked(true);
        tables->addWidget(box);
        m_tables.append(box);
    }
    tables->addStretch();
    auto *timing = new QHBoxLayout;
    timing->addWidget(m_timeout);
    timing->addWidget(new QLabel(tr("gap"), this));
    timing->addWidget(m_gap);
    timing->addWidget(new QLabel(tr("at most"), this));
    timing->addWidget(m_maxRequests);
    timing->addWidget(new QLabel(tr("requests"), this));
    timing->addStretch();

    auto *form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    auto *unitRow = new QHBoxLayout;
    unitRow->addWidget(m_unit);
    unitRow->addStretch();
    ScanForm::addRow(this, form, tr("&Unit:"), m_unit, unitRow);
    ScanForm::addRow(this, form, tr("Add&resses:"), m_first, addresses);
    form->addRow(tr("Tables:"), tables);
    form->addRow(QString(), m_optional);
    ScanForm::addRow(this, form, tr("T&imeout:"), m_timeout, timing);

    m_start->setObjectName(QStringLiteral("mapStart"));
    m_stop->setObjectName(QStringLiteral("mapStop"));
    m_progress->setObjectName(QStringLiteral("mapProgress"));
    m_status->setObjectName(QStringLiteral("mapStatus"));
    m_status->setWordWrap(true);

    m_save->setObjectName(QStringLiteral("mapSaveDraft"));
    m_save->setToolTip(tr("Save the map as a device profile that mbscope simulate --profile serves: "
                          "the unit cloned into the simulator, to test against without the hardware."));
    m_add->setObjectName(QStringLiteral("mapAddWatches"));
    m_add->setToolTip(tr("Add a watch per block found to the window's watches."));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_save, QDialogButtonBox::ActionRole);
    buttons->addButton(m_add, QDialogButtonBox::ActionRole);
    m_infer->setObjectName(QStringLiteral("mapInfer"));
    m_infer->setToolTip(tr("Read the blocks found again and again and propose each value's type, order, scale, unit "
                           "and kind, to confirm or correct row by row (mbscope infer)."));
    buttons->addButton(m_infer, QDialogButtonBox::ActionRole);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_tree, 1);
    layout->addWidget(buttons);
    resize(720, 560);

    connect(m_start, &QPushButton::clicked, this, &MapScanDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &MapScanDialog::stop);
    connect(m_save, &QPushButton::clicked, this, &MapScanDialog::chooseDraftFile);
    connect(m_add, &QPushButton::clicked, this, [this] { Q_EMIT watchesRequested(watches()); });
    connect(m_infer, &QPushButton::clicked, this, [this] {
        InferDialog *dialog = inferTypes();
        dialog->show();
        dialog->raise();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &MapScanDialog::reject);
    // The scanner lives in the job's thread: its progress and the job's cancel cross by queued signals.
    m_jobs->adopt(m_scanner);
    connect(m_scanner, &MapScanner::progressChanged, m_job, &Job::report);
    connect(m_job, &Job::cancelRequested, m_scanner, &MapScanner::stop);
    connect(m_job, &Job::progressChanged, this, &MapScanDialog::onProgress);
    connect(m_job, &Job::finished, this, &MapScanDialog::onFinished);
    m_status->setText(tr("Reads every table's addresses (exception 02 says an address is missing). Never writes."));
    updateButtons();
}

MapScanDialog::~MapScanDialog()
{
    delete m_jobs; // cancels the scan, ends its thread and deletes the scanner there
}

bool MapScanDialog::isRunning() const
{
    return m_job->isActive();
}

void MapScanDialog::setTarget(const LinkUrl &url, quint8 unit)
{
    m_target->setText(url.toString());
    m_unit->setValue(unit);
}

std::optional<MapScanSettings> MapScanDialog::settings()
{
    const std::optional<LinkUrl> url = ScanForm::target(m_target, m_status, tr("Give the link of the unit, e.g. tcp://192.168.1.10:502."));
    if (!url)
        return std::nullopt;
    MapScanSettings s;
    s.url = *url;
    s.unit = quint8(m_unit->value());
    s.firstAddress = m_first->value();
    s.lastAddress = m_last->value();
    s.step = m_step->value();
    s.functions.clear();
    for (int i = 0; i < m_tables.size(); ++i) {
        if (m_tables.at(i)->isChecked())
            s.functions.append(quint8(i + 1));
    }
    s.optionalFunctions = m_optional->isChecked();
    s.timeoutMs = m_timeout->value();
    s.gapMs = m_gap->value();
    s.maxRequests = m_maxRequests->value();
    if (s.functions.isEmpty() && !s.optionalFunctions) {
        ScanForm::showProblem(m_status, tr("Choose a table or the optional functions: there is nothing to scan."));
        return std::nullopt;
    }
    if (const QString problem = s.problem(); !problem.isEmpty()) {
        ScanForm::showProblem(m_status, problem);
        return std::nullopt;
    }
    return s;
}

void MapScanDialog::start()
{
    if (isRunning())
        return;
    const std::optional<MapScanSettings> s = settings();
    if (!s)
        return;
    m_runSettings = s;
    m_map.reset();
    m_tree->clear();
    m_progress->setRange(0, 0);
    m_status->setText(tr("Mapping unit %1\u2026").arg(s->unit));
    MapScanner *scanner = m_scanner;
    const MapScanSettings settings = *s;
    m_jobs->run(m_job, [this, scanner, settings]() -> JobThread::Outcome {
        // In the job's thread: only the scanner is touched here; the map comes back by value.
        const std::optional<RegisterMap> map = scanner->run(settings);
        return {scanner->end(), [this, map] { m_map = map; }};
    });
    updateButtons();
}

void MapScanDialog::onFinished(JobEnd end)
{
    const MapScanSettings s = m_runSettings.value_or(MapScanSettings{});
    const std::optional<RegisterMap> &map = m_map;
    if (map) {
        m_mapTarget = s.url.toString();
        m_mapUrl = s.url;
        m_tree->showMap(*map);
    }
    const int found = map ? MapResultTree::addressCount(*map) : 0;
    m_progress->setRange(0, 1);
    m_progress->setValue(1);
    QString how;
    switch (end) {
    case JobEnd::Completed: how = tr("Map complete"); break;
    case JobEnd::Stopped: how = tr("Stopped"); break;
    case JobEnd::TimeLimit: how = tr("Time limit reached"); break;
    case JobEnd::RequestLimit: how = tr("Request limit reached"); break;
    case JobEnd::LinkError: how = tr("The link failed"); break;
    }
    if (end == JobEnd::LinkError && found == 0)
        ScanForm::showProblem(m_status, tr("The link failed: %1 cannot be reached.").arg(s.url.toString()));
    else
        m_status->setText(tr("%1: %n address(es) found in %2 requests.", nullptr, found)
                              .arg(how)
                              .arg(map ? map->requests : 0));
    updateButtons();
    Q_EMIT scanFinished(end);
}

void MapScanDialog::stop()
{
    m_job->cancel();
}

void MapScanDialog::reject()
{
    m_job->cancel();
    QDialog::reject();
}

void MapScanDialog::onProgress(const JobProgress &p)
{
    if (m_job->state() != JobState::Running)
        return;
    ScanForm::showProgress(m_progress, m_status, p, tr("%1 of %2 addresses searched").arg(p.done).arg(p.total));
}

QList<WatchDefinition> MapScanDialog::watches() const
{
    return m_map ? ScanWatches::fromMap(m_mapTarget, *m_map) : QList<WatchDefinition>{};
}

bool MapScanDialog::saveDraft(const QString &path)
{
    if (!m_map)
        return false;
    QSaveFile file(path);
    const QByteArray json = ProfileDraft::toJson(*m_map, QFileInfo(path).completeBaseName(), m_mapTarget);
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit()) {
        ScanForm::showProblem(m_status, tr("Cannot save %1: %2").arg(QDir::toNativeSeparators(path), file.errorString()));
        return false;
    }
    m_status->setText(tr("Saved %1: mbscope simulate --profile %1 serves this unit.").arg(QDir::toNativeSeparators(path)));
    return true;
}

InferDialog *MapScanDialog::inferTypes()
{
    if (!m_inferDialog)
        m_inferDialog = new InferDialog(this);
    if (m_map)
        m_inferDialog->setSource(m_mapUrl, m_map->unit, *m_map);
    return m_inferDialog;
}

void MapScanDialog::chooseDraftFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save profile draft"),
                                                      LastFolder::start(QStringLiteral("unit-%1.json").arg(m_map ? m_map->unit : 1)),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        saveDraft(path);
}

void MapScanDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    const bool blocks = m_map && MapResultTree::addressCount(*m_map) > 0;
    m_save->setEnabled(m_map.has_value() && !running);
    m_add->setEnabled(blocks && !running);
    m_infer->setEnabled(blocks && !running);
    QList<QWidget *> fields{m_target, m_unit, m_first, m_last, m_step, m_optional, m_timeout, m_gap, m_maxRequests};
    for (QCheckBox *box : std::as_const(m_tables))
        fields.append(box);
    for (QWidget *w : std::as_const(fields))
        w->setEnabled(!running);
}

} // namespace mbscope
