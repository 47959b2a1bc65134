#include "scandialog.h"

#include "common/lastfolder.h"

#include "discovery/profiledraft.h"
#include "protocol/framingtraits.h"

#include "inferdialog.h"
#include "linescandialog.h"
#include "mapscandialog.h"
#include "scanresultmodel.h"
#include "scanform.h"
#include "timingscandialog.h"

#include "discovery/linescanner.h"
#include "discovery/mapscanner.h"
#include "discovery/scanwatches.h"
#include "discovery/unitscanner.h"

#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

ScanDialog::ScanDialog(QWidget *parent)
    : QDialog(parent)
    , m_scanner(new UnitScanner(this))
    , m_model(new ScanResultModel(this))
    , m_target(new QLineEdit(this))
    , m_first(ScanForm::spinBox(this, "scanFirstUnit", 0, 255, 1))
    , m_last(ScanForm::spinBox(this, "scanLastUnit", 0, 255, 247))
    , m_function(new QComboBox(this))
    , m_address(ScanForm::spinBox(this, "scanAddress", 0, 65535, 0))
    , m_quantity(ScanForm::spinBox(this, "scanQuantity", 1, 125, 1))
    , m_timeout(ScanForm::spinBox(this, "scanTimeout", 1, 60000, 200, tr(" ms")))
    , m_gap(ScanForm::spinBox(this, "scanGap", 0, 60000, 20, tr(" ms")))
    , m_start(new QPushButton(tr("&Start"), this))
    , m_stop(new QPushButton(tr("Sto&p"), this))
    , m_copy(new QPushButton(tr("&Copy as watches (JSON)"), this))
    , m_add(new QPushButton(tr("&Add as watches"), this))
    , m_map(new QPushButton(tr("&Map unit\u2026"), this))
    , m_timing(new QPushButton(tr("Timi&ng\u2026"), this))
    , m_line(new QPushButton(tr("Seria&l settings\u2026"), this))
    , m_recordUnits(new QPushButton(tr("Record in pr&ofile\u2026"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_table(new QTableView(this))
{
    setObjectName(QStringLiteral("scanDialog"));
    setWindowTitle(tr("Scan for units"));
    m_target->setObjectName(QStringLiteral("scanTarget"));
    m_target->setPlaceholderText(QStringLiteral("tcp://192.168.1.10:502, rtu-tcp://host:4001, rtu:///dev/ttyUSB0?baud=9600"));
    m_target->setToolTip(tr("The link to scan. The scan opens a connection of its own; the window's connection is left alone."));
    m_function->setObjectName(QStringLiteral("scanFunction"));
    ScanForm::addReadFunctions(m_function);
    m_function->setToolTip(tr("Every id is asked this read: a scan never writes."));
    m_first->setToolTip(tr("1-247 on a serial line or a serial device server; 0 and 248-255 only over Modbus TCP."));
    m_timeout->setToolTip(tr("How long each id may take to answer."));
    m_gap->setToolTip(tr("Quiet time between one answer (or timeout) and the next request."));

    auto *ids = new QHBoxLayout;
    ids->addWidget(m_first);
    ids->addWidget(new QLabel(tr("to"), this));
    ids->addWidget(m_last);
    ids->addStretch();
    auto *read = new QHBoxLayout;
    read->addWidget(m_function);
    read->addWidget(new QLabel(tr("address"), this));
    read->addWidget(m_address);
    read->addWidget(new QLabel(tr("quantity"), this));
    read->addWidget(m_quantity);
    read->addStretch();
    auto *timing = new QHBoxLayout;
    timing->addWidget(m_timeout);
    timing->addWidget(new QLabel(tr("gap"), this));
    timing->addWidget(m_gap);
    timing->addStretch();
    auto *form = new QFormLayout;
    form->addRow(tr("&Target:"), m_target);
    // A row of several fields: the label's mnemonic goes to the first of them.
    ScanForm::addRow(this, form, tr("&Unit ids:"), m_first, ids);
    ScanForm::addRow(this, form, tr("&Read:"), m_function, read);
    ScanForm::addRow(this, form, tr("T&imeout:"), m_timeout, timing);

    m_start->setObjectName(QStringLiteral("scanStart"));
    m_stop->setObjectName(QStringLiteral("scanStop"));
    m_progress->setObjectName(QStringLiteral("scanProgress"));
    m_status->setObjectName(QStringLiteral("scanStatus"));
    m_status->setWordWrap(true);
    // Two lines of room: a wrapped status (what was recorded where) is read whole, not cut.
    m_status->setMinimumHeight(2 * m_status->fontMetrics().lineSpacing() + 4);

    m_table->setObjectName(QStringLiteral("scanResults"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setColumnWidth(ScanResultModel::UnitColumn, 50);
    m_table->setColumnWidth(ScanResultModel::ResultColumn, 220);
    m_table->setColumnWidth(ScanResultModel::LatencyColumn, 80);

    m_copy->setObjectName(QStringLiteral("scanCopyWatches"));
    m_copy->setToolTip(tr("Watch definitions of the selected found units (or of every found unit) as JSON on the clipboard."));
    m_add->setObjectName(QStringLiteral("scanAddWatches"));
    m_add->setToolTip(tr("Add watches of the selected found units (or of every found unit) to the window's watches."));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_copy, QDialogButtonBox::ActionRole);
    buttons->addButton(m_add, QDialogButtonBox::ActionRole);
    m_map->setObjectName(QStringLiteral("scanMapUnit"));
    m_map->setToolTip(tr("Find which addresses the selected unit has, the largest read it takes and its optional functions; "
                         "save the map as a profile the simulator serves."));
    buttons->addButton(m_map, QDialogButtonBox::ActionRole);
    m_timing->setObjectName(QStringLiteral("scanTimeUnit"));
    m_timing->setToolTip(tr("Measure how the selected unit copes with being asked: the shortest gap between requests, "
                            "pipelining, clients at once, the largest read; with the settings that follow."));
    buttons->addButton(m_timing, QDialogButtonBox::ActionRole);
    m_line->setObjectName(QStringLiteral("scanLineSettings"));
    m_line->setToolTip(tr("On a serial port: try baud rates, parities and stop bits with the read above until a unit answers."));
    buttons->addButton(m_line, QDialogButtonBox::ActionRole);
    m_recordUnits->setObjectName(QStringLiteral("scanRecordUnits"));
    m_recordUnits->setToolTip(tr("Add the units that answered to an existing device profile, and its unknownUnit from what "
                                 "the other ids got (as scan --units --profile-out)."));
    buttons->addButton(m_recordUnits, QDialogButtonBox::ActionRole);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(ScanForm::runRow(m_start, m_stop, m_progress));
    layout->addWidget(m_status);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(640, 520);

    connect(m_start, &QPushButton::clicked, this, &ScanDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &ScanDialog::stop);
    connect(m_copy, &QPushButton::clicked, this, &ScanDialog::copyWatches);
    connect(m_add, &QPushButton::clicked, this, [this] { Q_EMIT watchesRequested(watches()); });
    connect(m_map, &QPushButton::clicked, this, &ScanDialog::mapSelectedUnit);
    connect(m_timing, &QPushButton::clicked, this, &ScanDialog::timeSelectedUnit);
    connect(m_line, &QPushButton::clicked, this, &ScanDialog::findLineSettings);
    connect(m_recordUnits, &QPushButton::clicked, this, &ScanDialog::recordUnits);
    connect(m_target, &QLineEdit::textChanged, this, &ScanDialog::updateButtons);
    connect(buttons, &QDialogButtonBox::rejected, this, &ScanDialog::reject);
    connect(m_scanner, &UnitScanner::probed, m_model, &ScanResultModel::append);
    connect(m_scanner, &UnitScanner::progressChanged, this, &ScanDialog::onProgress);
    connect(m_scanner, &UnitScanner::finished, this, &ScanDialog::onFinished);
    adopt(m_scanner->channel());
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &ScanDialog::updateButtons);
    connect(m_model, &QAbstractItemModel::modelReset, this, &ScanDialog::updateButtons);
    m_status->setText(tr("Asks every id the read above, one at a time, and says what each did."));
    updateButtons();
}

ScanDialog::~ScanDialog()
{
    m_scanner->stop();
}

void ScanDialog::setTarget(const LinkUrl &url)
{
    m_target->setText(url.toString());
    if (url.isSerial() || isSerialLine(url.framing())) {
        m_first->setValue(qMax(1, m_first->value()));
        m_last->setValue(qMin(247, m_last->value()));
    }
}

bool ScanDialog::isRunning() const
{
    return m_scanner->isRunning();
}

std::optional<UnitScanSettings> ScanDialog::settings()
{
    const std::optional<LinkUrl> url = ScanForm::target(m_target, m_status, tr("Give the link to scan, e.g. tcp://192.168.1.10:502."));
    if (!url)
        return std::nullopt;
    UnitScanSettings s;
    s.url = *url;
    s.firstUnit = m_first->value();
    s.lastUnit = m_last->value();
    s.function = quint8(m_function->currentData().toInt());
    s.address = quint16(m_address->value());
    s.quantity = quint16(m_quantity->value());
    s.timeoutMs = m_timeout->value();
    s.gapMs = m_gap->value();
    if (const QString problem = s.problem(); !problem.isEmpty()) {
        ScanForm::showProblem(m_status, problem);
        return std::nullopt;
    }
    return s;
}

void ScanDialog::start()
{
    if (isRunning())
        return;
    std::optional<UnitScanSettings> s = settings();
    if (!s)
        return;
    s->keepTargetPace(); // the target's gap= holds: the list says the gap kept
    m_running = *s;
    m_model->clear();
    m_progress->setRange(0, s->idCount());
    m_progress->setValue(0);
    m_scanner->start(*s);
    updateButtons();
}

void ScanDialog::stop()
{
    m_scanner->stop();
}

void ScanDialog::reject()
{
    m_scanner->stop();
    QDialog::reject();
}

void ScanDialog::onProgress(const JobProgress &p)
{
    if (!isRunning()) {
        m_progress->setValue(p.done);
        return;
    }
    ScanForm::showProgress(m_progress, m_status, p, tr("%1 of %2 ids asked, %3 found").arg(p.done).arg(p.total).arg(p.found));
}

void ScanDialog::onFinished(JobEnd end)
{
    const JobProgress p = m_scanner->progress();
    QString how;
    switch (end) {
    case JobEnd::Completed: how = tr("Scan complete"); break;
    case JobEnd::Stopped: how = tr("Stopped"); break;
    case JobEnd::TimeLimit: how = tr("Time limit reached"); break;
    case JobEnd::RequestLimit: how = tr("Request limit reached"); break;
    case JobEnd::LinkError:
        how = tr("The link failed: %1").arg(m_scanner->results().isEmpty() ? QString() : m_scanner->results().constLast().problem);
        break;
    }
    m_status->setText(tr("%1: %2 of %3 ids asked in %4, %5 found.")
                          .arg(how)
                          .arg(p.done)
                          .arg(p.total)
                          .arg(ScanForm::duration(p.elapsedMs))
                          .arg(p.found));
    updateButtons();
    Q_EMIT scanFinished(end);
}

void ScanDialog::updateButtons()
{
    const bool running = isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    bool found = false;
    for (const UnitProbe &p : m_model->probes())
        found = found || p.kind == UnitProbeKind::Answers;
    m_copy->setEnabled(found);
    m_add->setEnabled(found);
    m_map->setEnabled(found && !running);
    m_timing->setEnabled(found && !running);
    m_recordUnits->setEnabled(!running && !m_model->probes().isEmpty());
    const LinkUrl::Result target = LinkUrl::parse(m_target->text().trimmed());
    m_line->setEnabled(!running && target.url && target.url->isSerial());
    for (QWidget *w : {static_cast<QWidget *>(m_target), static_cast<QWidget *>(m_first), static_cast<QWidget *>(m_last),
                       static_cast<QWidget *>(m_function), static_cast<QWidget *>(m_address), static_cast<QWidget *>(m_quantity),
                       static_cast<QWidget *>(m_timeout), static_cast<QWidget *>(m_gap)})
        w->setEnabled(!running);
}

QList<WatchDefinition> ScanDialog::watches() const
{
    QList<int> rows;
    for (const QModelIndex &index : m_table->selectionModel()->selectedRows())
        rows.append(index.row());
    std::sort(rows.begin(), rows.end());
    QList<WatchDefinition> out;
    const QList<UnitProbe> &probes = m_model->probes();
    if (rows.isEmpty()) {
        for (int i = 0; i < probes.size(); ++i)
            rows.append(i);
    }
    for (const int row : std::as_const(rows))
        out += ScanWatches::fromProbe(m_running, probes.at(row));
    return out;
}

int ScanDialog::chosenFoundRow() const
{
    const QList<UnitProbe> &probes = m_model->probes();
    for (const QModelIndex &index : m_table->selectionModel()->selectedRows()) {
        if (probes.at(index.row()).kind == UnitProbeKind::Answers)
            return index.row();
    }
    for (int i = 0; i < probes.size(); ++i) {
        if (probes.at(i).kind == UnitProbeKind::Answers)
            return i;
    }
    return -1;
}

MapScanDialog *ScanDialog::mapSelectedUnit()
{
    const int row = chosenFoundRow();
    if (row < 0)
        return nullptr;
    if (!m_mapDialog) {
        m_mapDialog = new MapScanDialog(this);
        adopt(m_mapDialog->scanner()->channel());
        adopt(m_mapDialog->inferTypes()->sampler()->channel()); // Infer types' reads: traffic and recording too
        connect(m_mapDialog, &MapScanDialog::watchesRequested, this, &ScanDialog::watchesRequested);
    }
    if (!m_mapDialog->isRunning())
        m_mapDialog->setTarget(m_running.url, quint8(m_model->probes().at(row).unit));
    m_mapDialog->show();
    m_mapDialog->raise();
    m_mapDialog->activateWindow();
    return m_mapDialog;
}

TimingScanDialog *ScanDialog::timeSelectedUnit()
{
    const int row = chosenFoundRow();
    if (row < 0)
        return nullptr;
    if (!m_timingDialog) {
        m_timingDialog = new TimingScanDialog(this);
        adopt(m_timingDialog->scanner()->channel());
        m_timingDialog->scanner()->setTrafficLog(m_trafficLog); // its clients' engines too
    }
    if (!m_timingDialog->isRunning())
        m_timingDialog->setTarget(m_running.url, quint8(m_model->probes().at(row).unit), m_running.function, m_running.address);
    m_timingDialog->show();
    m_timingDialog->raise();
    m_timingDialog->activateWindow();
    return m_timingDialog;
}

LineScanDialog *ScanDialog::findLineSettings()
{
    const LinkUrl::Result target = LinkUrl::parse(m_target->text().trimmed());
    if (!target.url || !target.url->isSerial())
        return nullptr;
    if (!m_lineDialog) {
        m_lineDialog = new LineScanDialog(this);
        adopt(m_lineDialog->scanner()->channel());
        connect(m_lineDialog, &LineScanDialog::settingChosen, this, [this](const LinkUrl &url) { m_target->setText(url.toString()); });
    }
    if (!m_lineDialog->isRunning())
        m_lineDialog->setTarget(*target.url, quint8(m_function->currentData().toInt()), quint16(m_address->value()));
    m_lineDialog->show();
    m_lineDialog->raise();
    m_lineDialog->activateWindow();
    return m_lineDialog;
}

void ScanDialog::adopt(ProbeChannel *channel)
{
    channel->setTrafficLog(m_trafficLog);
    connect(channel, &ProbeChannel::framesLogged, this, &ScanDialog::framesLogged);
}

void ScanDialog::setTrafficLog(TrafficLog *log)
{
    m_trafficLog = log;
    m_scanner->channel()->setTrafficLog(log);
    if (m_mapDialog) {
        m_mapDialog->scanner()->channel()->setTrafficLog(log);
        m_mapDialog->inferTypes()->sampler()->channel()->setTrafficLog(log);
    }
    if (m_timingDialog)
        m_timingDialog->scanner()->setTrafficLog(log);
    if (m_lineDialog)
        m_lineDialog->scanner()->channel()->setTrafficLog(log);
}

void ScanDialog::copyWatches()
{
    const QList<WatchDefinition> list = watches();
    QGuiApplication::clipboard()->setText(QString::fromUtf8(ScanWatches::toJson(list)));
    m_status->setText(tr("%n watch definition(s) copied to the clipboard.", nullptr, int(list.size())));
}

void ScanDialog::recordUnits()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Record units in profile"), LastFolder::start(QString()),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (path.isEmpty())
        return;
    const QList<UnitProbe> probes = m_model->probes();
    ScanForm::mergeIntoProfile(path, [&probes](const QByteArray &profile, QString *said, QString *problem) {
        return ProfileDraft::mergeUnits(profile, probes, said, problem);
    }, m_status);
}

} // namespace mbscope
