#include "simulatorpanel.h"

#include "common/lastfolder.h"

#include "simfaultform.h"
#include "simscriptpanel.h"
#include "simregistermodel.h"
#include "simrunlistmodel.h"
#include "simtrafficmodel.h"

#include "json/jsonreader.h"
#include "profile/faultrulereader.h"
#include "profile/faultrulewriter.h"
#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QSettings>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

#include <iterator>

namespace mbscope {

namespace {

const QString kSavedFaultsKey = QStringLiteral("simulator/faultRules");

struct FramingChoice {
    const char *label; // translated in the panel's context
    const char *scheme;
    const char *example; // the URL the choice proposes when the text has another kind of address
};

// QT_TRANSLATE_NOOP: the labels are translated where they are shown.
constexpr FramingChoice kFramings[] = {
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "Modbus TCP"), "tcp", "tcp://127.0.0.1:5020"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "RTU over TCP"), "rtu-tcp", "rtu-tcp://127.0.0.1:5020"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "ASCII over TCP"), "ascii-tcp", "ascii-tcp://127.0.0.1:5020"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "Modbus UDP"), "udp", "udp://127.0.0.1:5020"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "RTU over UDP"), "rtu-udp", "rtu-udp://127.0.0.1:5020"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "Modbus TCP Security (TLS)"), "tls", "tls://127.0.0.1:802"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "Serial RTU"), "rtu", "rtu:///dev/ttyUSB0?baud=19200&parity=E"},
    {QT_TRANSLATE_NOOP("mbscope::SimulatorPanel", "Serial ASCII"), "ascii", "ascii:///dev/ttyUSB0?baud=9600&parity=E&data=7"},
};

bool isSerialScheme(QStringView scheme)
{
    return scheme == QLatin1String("rtu") || scheme == QLatin1String("ascii");
}

} // namespace

SimulatorPanel::SimulatorPanel(QWidget *parent)
    : QWidget(parent)
    , m_runs(new SimRunListModel(this))
    , m_registers(new SimRegisterModel(this))
    , m_traffic(new SimTrafficModel(this))
{
    buildUi();
    updateButtons();
    updateTrafficNote();
}

SimulatorPanel::~SimulatorPanel()
{
    disconnect(m_runs, nullptr, this, nullptr); // no reselection while the panel goes
    for (const QPointer<SimulatorHost> &host : std::as_const(m_owned)) {
        if (host) {
            disconnect(host, nullptr, this, nullptr);
            host->stop();
        }
    }
}

void SimulatorPanel::buildUi()
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    auto *startRow = new QHBoxLayout;
    startRow->addWidget(new QLabel(tr("Profile:"), this));
    m_profile = new QComboBox(this);
    m_profile->setObjectName(QStringLiteral("simProfile"));
    m_profile->setEditable(true);
    m_profile->setInsertPolicy(QComboBox::NoInsert);
    m_profile->setMinimumContentsLength(14);
    m_profile->setToolTip(tr("A built-in profile, or the path of a profile file (docs/profiles.md)."));
    for (const ShippedProfile &shipped : ProfileLoader::shippedProfiles()) {
        m_profile->addItem(shipped.name);
        m_profile->setItemData(m_profile->count() - 1, shipped.description, Qt::ToolTipRole);
    }
    m_profile->setCurrentIndex(qMax(0, m_profile->findText(QStringLiteral("rosrao-gamma"))));
    startRow->addWidget(m_profile);
    m_browse = new QToolButton(this);
    m_browse->setText(tr("..."));
    m_browse->setToolTip(tr("Choose a profile file"));
    startRow->addWidget(m_browse);
    startRow->addWidget(new QLabel(tr("Listen on:"), this));
    m_framing = new QComboBox(this);
    m_framing->setObjectName(QStringLiteral("simFraming"));
    for (const FramingChoice &choice : kFramings)
        m_framing->addItem(tr(choice.label), QString::fromLatin1(choice.scheme));
    startRow->addWidget(m_framing);
    m_url = new QLineEdit(QString::fromLatin1(kFramings[0].example), this);
    m_url->setObjectName(QStringLiteral("simUrl"));
    m_url->setToolTip(tr("Where the simulator listens, as a URL: port 0 lets the system choose a free port."));
    startRow->addWidget(m_url, 1);
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("simStart"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("simStop"));
    m_stop->setToolTip(tr("Stops the simulator selected in the list."));
    startRow->addWidget(m_start);
    startRow->addWidget(m_stop);
    layout->addLayout(startRow);

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("simMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();
    layout->addWidget(m_message);

    auto *splitter = new QSplitter(Qt::Vertical, this);
    m_runsView = new QTableView(splitter);
    m_runsView->setObjectName(QStringLiteral("simRuns"));
    m_runsView->setModel(m_runs);
    m_runsView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_runsView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_runsView->verticalHeader()->hide();
    m_runsView->verticalHeader()->setDefaultSectionSize(m_runsView->fontMetrics().height() + 6);
    m_runsView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_runsView->horizontalHeader()->setSectionResizeMode(SimRunListModel::EndpointColumn, QHeaderView::Stretch);
    splitter->addWidget(m_runsView);

    m_tabs = new QTabWidget(splitter);
    m_tabs->setObjectName(QStringLiteral("simTabs"));
    m_tabs->setDocumentMode(true);

    auto *registersPage = new QWidget(m_tabs);
    auto *registersLayout = new QVBoxLayout(registersPage);
    registersLayout->setContentsMargins(0, 4, 0, 0);
    auto *unitRow = new QHBoxLayout;
    unitRow->addWidget(new QLabel(tr("Unit:"), registersPage));
    m_unit = new QComboBox(registersPage);
    m_unit->setObjectName(QStringLiteral("simUnit"));
    unitRow->addWidget(m_unit);
    auto *hint = new QLabel(tr("Double-click a value to set it in the simulator (decimal, or hex with 0x)."), registersPage);
    hint->setEnabled(false);
    unitRow->addWidget(hint, 1);
    registersLayout->addLayout(unitRow);
    m_registersView = new QTableView(registersPage);
    m_registersView->setObjectName(QStringLiteral("simRegisters"));
    m_registersView->setModel(m_registers);
    m_registersView->verticalHeader()->hide();
    m_registersView->verticalHeader()->setDefaultSectionSize(m_registersView->fontMetrics().height() + 6);
    m_registersView->horizontalHeader()->setSectionResizeMode(SimRegisterModel::NameColumn, QHeaderView::Stretch);
    m_registersView->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                     | QAbstractItemView::AnyKeyPressed);
    registersLayout->addWidget(m_registersView, 1);
    m_editMessage = new QLabel(registersPage);
    m_editMessage->setObjectName(QStringLiteral("simEditMessage"));
    m_editMessage->setWordWrap(true);
    registersLayout->addWidget(m_editMessage);
    m_tabs->addTab(registersPage, tr("Registers"));

    m_faults = new SimFaultForm(m_tabs);
    m_faults->setObjectName(QStringLiteral("simFaults"));
    m_tabs->addTab(m_faults, tr("Faults"));

    m_scripts = new SimScriptPanel(m_tabs);
    m_scripts->setObjectName(QStringLiteral("simScriptPanel"));

    auto *trafficPage = new QWidget(m_tabs);
    auto *trafficLayout = new QVBoxLayout(trafficPage);
    trafficLayout->setContentsMargins(0, 4, 0, 0);
    m_trafficView = new QTableView(trafficPage);
    m_trafficView->setObjectName(QStringLiteral("simTraffic"));
    m_trafficView->setModel(m_traffic);
    m_trafficView->verticalHeader()->hide();
    m_trafficView->verticalHeader()->setDefaultSectionSize(m_trafficView->fontMetrics().height() + 6);
    m_trafficView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_trafficView->setWordWrap(false);
    m_trafficView->horizontalHeader()->setStretchLastSection(true);
    // Widths for what the columns hold: a time, a URL, a peer address, a function's name, the
    // outcome's sentence (its whole text in the tooltip) and two frames.
    const int digit = m_trafficView->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    const int widths[] = {8, 20, 14, 5, 22, 50, 30};
    for (int column = 0; column < int(std::size(widths)); ++column)
        m_trafficView->setColumnWidth(column, widths[column] * digit);
    trafficLayout->addWidget(m_trafficView, 1);
    auto *trafficRow = new QHBoxLayout;
    m_trafficNote = new QLabel(trafficPage);
    m_trafficNote->setObjectName(QStringLiteral("simTrafficNote"));
    trafficRow->addWidget(m_trafficNote, 1);
    auto *clear = new QPushButton(tr("&Clear"), trafficPage);
    trafficRow->addWidget(clear);
    trafficLayout->addLayout(trafficRow);
    m_tabs->addTab(trafficPage, tr("Traffic"));
    m_tabs->addTab(m_scripts, tr("Script"));

    splitter->addWidget(m_tabs);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({90, 400});
    layout->addWidget(splitter, 1);

    connect(m_start, &QPushButton::clicked, this, &SimulatorPanel::onStartClicked);
    connect(m_url, &QLineEdit::returnPressed, this, &SimulatorPanel::onStartClicked);
    connect(m_stop, &QPushButton::clicked, this, [this] { stopSimulator(m_current); });
    connect(m_browse, &QToolButton::clicked, this, &SimulatorPanel::chooseProfileFile);
    connect(m_framing, &QComboBox::activated, this, &SimulatorPanel::onFramingChosen);
    connect(m_url, &QLineEdit::textEdited, this, &SimulatorPanel::onUrlEdited);
    connect(m_runsView->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) { selectHost(m_runs->hostAt(current.row())); });
    connect(m_runs, &QAbstractItemModel::rowsRemoved, this, [this] {
        if (!m_current || m_runs->rowOf(m_current) < 0)
            selectHost(m_runs->hostAt(0));
    });
    connect(m_unit, &QComboBox::activated, this, [this] { selectUnit(quint8(m_unit->currentData().toInt())); });
    connect(m_registers, &SimRegisterModel::valueEdited, this, [this](quint8 unit, SimTable table, int address, quint16 value) {
        if (m_current) {
            m_current->setValue(unit, table, address, value);
            m_editMessage->setText(tr("Set %1 %2 of unit %3 to %4.")
                                       .arg(QLatin1String(simTableName(table)))
                                       .arg(address)
                                       .arg(unit)
                                       .arg(value));
        }
    });
    connect(m_registers, &SimRegisterModel::editRefused, m_editMessage, &QLabel::setText);
    connect(m_faults, &SimFaultForm::rulesChanged, this, [this](const FaultRuleSet &rules) {
        if (!m_current)
            return;
        m_current->setFaultRules(rules);
        // The built-in simulator's rules are kept for the next start (issue 14, item 3).
        if (m_runs->isBuiltIn(m_runs->rowOf(m_current)))
            QSettings().setValue(kSavedFaultsKey,
                                 QString::fromUtf8(QJsonDocument(FaultRuleWriter::toJson(rules)).toJson(QJsonDocument::Compact)));
    });
    connect(clear, &QPushButton::clicked, this, [this] {
        m_traffic->clear();
        updateTrafficNote();
    });
}

QString SimulatorPanel::message() const
{
    return m_message->text();
}

void SimulatorPanel::showMessage(const QString &text)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

void SimulatorPanel::updateButtons()
{
    m_stop->setEnabled(m_current != nullptr);
    m_faults->setEnabled(m_current != nullptr);
    m_unit->setEnabled(m_current != nullptr);
}

void SimulatorPanel::updateTrafficNote()
{
    const quint64 dropped = m_traffic->droppedCount();
    if (dropped == 0)
        m_trafficNote->setText(tr("%n line(s), the newest %1 kept.", nullptr, m_traffic->rowCount()).arg(m_traffic->rowLimit()));
    else
        m_trafficNote->setText(tr("%n line(s); %1 older line(s) no longer shown (the newest %2 are kept).", nullptr,
                                  m_traffic->rowCount())
                                   .arg(dropped)
                                   .arg(m_traffic->rowLimit()));
}

void SimulatorPanel::onFramingChosen()
{
    const QString scheme = m_framing->currentData().toString();
    const QString text = m_url->text().trimmed();
    const qsizetype separator = text.indexOf(QLatin1String("://"));
    const QString oldScheme = separator > 0 ? text.left(separator) : QString();
    // The address carries over between network framings; serial and network addresses differ.
    if (separator > 0 && isSerialScheme(oldScheme) == isSerialScheme(scheme))
        m_url->setText(scheme + text.mid(separator));
    else
        m_url->setText(QString::fromLatin1(kFramings[m_framing->currentIndex()].example));
}

void SimulatorPanel::onUrlEdited(const QString &text)
{
    const qsizetype separator = text.indexOf(QLatin1String("://"));
    if (separator <= 0)
        return;
    const int index = m_framing->findData(text.left(separator).trimmed().toLower());
    if (index >= 0)
        m_framing->setCurrentIndex(index);
}

void SimulatorPanel::chooseProfileFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a device profile"), LastFolder::start(),
                                                      tr("Device profiles (*.json);;All files (*)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        m_profile->setEditText(path);
}

void SimulatorPanel::onStartClicked()
{
    startSimulator(m_profile->currentText().trimmed(), m_url->text().trimmed());
}

SimulatorHost *SimulatorPanel::startSimulator(const QString &profile, const QString &url)
{
    if (profile.isEmpty()) {
        showMessage(tr("Choose a profile first: a built-in one from the list, or a profile file."));
        return nullptr;
    }
    const ProfileLoadResult loaded = ProfileLoader::load(profile);
    if (!loaded.ok) {
        showMessage(tr("The profile '%1' cannot be loaded: %2").arg(profile, loaded.errorText()));
        return nullptr;
    }
    auto *host = new SimulatorHost(this);
    QString error;
    if (!host->load(loaded.profile, &error) || !host->listen(url, &error)) {
        delete host;
        showMessage(tr("The simulator was not started on %1: %2").arg(url, error));
        return nullptr;
    }
    watch(host); // before start: the scripts' first log lines are their loads
    host->start();
    m_owned.append(host);
    m_runs->addHost(host, loaded.profile.name);
    showMessage({});
    selectHost(host);
    return host;
}

void SimulatorPanel::addRunning(SimulatorHost *host, const QString &label, bool builtIn)
{
    if (!host || !host->isRunning() || m_runs->rowOf(host) >= 0)
        return;
    watch(host);
    m_runs->addHost(host, label, builtIn);
    if (builtIn)
        restoreSavedFaults(host);
    if (!m_current)
        selectHost(host);
}

// The fault rules the built-in simulator had when mbscope last closed are put back in force,
// and the panel says so: a simulator that drops answers for a reason nobody remembers would be
// worse than one that forgot its rules.
void SimulatorPanel::restoreSavedFaults(SimulatorHost *host)
{
    const QString saved = QSettings().value(kSavedFaultsKey).toString();
    if (saved.isEmpty())
        return;
    QList<ProfileProblem> problems;
    JsonReader reader(&problems, tr("saved fault rules"));
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(saved.toUtf8(), &error);
    const FaultRuleSet rules = FaultRuleReader::readRuleSet(reader, document.object(), QString(), host->faultRules().seed);
    if (error.error != QJsonParseError::NoError || !problems.isEmpty()) {
        QSettings().remove(kSavedFaultsKey);
        showMessage(tr("The fault rules saved at the last run do not read and were dropped: %1")
                        .arg(problems.isEmpty() ? error.errorString() : ProfileProblem::join(problems)));
        return;
    }
    if (rules.rules.isEmpty())
        return;
    host->setFaultRules(rules);
    if (host == m_current)
        m_faults->setRules(rules);
    showMessage(tr("%n fault rule(s) of the last run are in force again (Faults tab: No faults clears them).", nullptr,
                   int(rules.rules.size())));
}

void SimulatorPanel::watch(SimulatorHost *host)
{
    m_scripts->watch(host);
    connect(host, &SimulatorHost::valuesUpdated, this, [this, host](const QList<SimValueUpdate> &updates) {
        if (host == m_current)
            m_registers->applyUpdates(updates);
    });
    connect(host, &SimulatorHost::trafficRecorded, this, [this, host](const QList<SimTrafficRecord> &records, int lost) {
        m_runs->countRecords(host, records);
        m_traffic->appendRecords(records, lost);
        updateTrafficNote();
    });
}

void SimulatorPanel::stopSimulator(SimulatorHost *host)
{
    if (!host)
        return;
    disconnect(host, nullptr, this, nullptr);
    disconnect(host, nullptr, m_scripts, nullptr);
    m_scripts->forget(host);
    const bool owned = m_owned.contains(host);
    m_owned.removeAll(host);
    host->stop(); // the list drops it (stopped)
    if (owned)
        host->deleteLater();
    if (m_current == host)
        selectHost(m_runs->hostAt(0));
}

void SimulatorPanel::selectHost(SimulatorHost *host)
{
    if (host && !host->isRunning())
        host = nullptr;
    if (host == m_current && (host == nullptr || m_registers->hasUnit()))
        return;
    m_current = host;
    m_scripts->setHost(host);
    m_unit->clear();
    m_editMessage->clear();
    if (!host) {
        m_registers->clear();
        m_faults->setRules({});
        updateButtons();
        return;
    }
    const int row = m_runs->rowOf(host);
    if (row >= 0 && m_runsView->currentIndex().row() != row)
        m_runsView->setCurrentIndex(m_runs->index(row, 0));
    for (quint8 id : host->unitIds()) {
        const UnitProfile *unit = host->profile().unit(id);
        m_unit->addItem(unit && !unit->name.isEmpty() ? tr("%1: %2").arg(id).arg(unit->name) : QString::number(id), int(id));
    }
    m_faults->setRules(host->faultRules());
    if (!host->unitIds().isEmpty())
        selectUnit(host->unitIds().first());
    updateButtons();
}

void SimulatorPanel::selectUnit(quint8 unit)
{
    if (!m_current)
        return;
    const int index = m_unit->findData(int(unit));
    if (index >= 0)
        m_unit->setCurrentIndex(index);
    std::optional<UnitProfile> profile;
    if (const UnitProfile *found = m_current->profile().unit(unit))
        profile = *found;
    m_registers->setUnit(unit, m_current->snapshot(unit), profile);
    m_registersView->resizeColumnToContents(SimRegisterModel::TableColumn);
    m_registersView->resizeColumnToContents(SimRegisterModel::AddressColumn);
}

} // namespace mbscope
