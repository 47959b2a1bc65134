#include "registertrendpanel.h"

#include "compose/addressfield.h"
#include "common/plotcursor.h"
#include "common/plotexportmenu.h"
#include "common/plotfollower.h"
#include "registers/registertable.h"
#include "registers/registertablemodel.h"

#include "protocol/adubuilder.h"
#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSettings>
#include <QtGui/QAction>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QListWidget>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <iterator>

namespace mbscope {

namespace {

QColor seriesColour(int index)
{
    static const QColor colours[] = {QColor(31, 119, 180), QColor(255, 127, 14), QColor(44, 160, 44),
                                     QColor(214, 39, 40),  QColor(148, 103, 189), QColor(140, 86, 75),
                                     QColor(227, 119, 194), QColor(127, 127, 127), QColor(188, 189, 34),
                                     QColor(23, 190, 207)};
    return colours[index % int(std::size(colours))];
}

// Where the plotted series are kept between runs (issue 14, item 3: trend choices survive a
// restart): one JSON object a series.
const QString kShownKey = QStringLiteral("trends/shown");

} // namespace

RegisterTrendPanel::RegisterTrendPanel(QWidget *parent)
    : QWidget(parent)
    , m_list(new QListWidget(this))
    , m_address(new AddressField(this))
    , m_table(new QComboBox(this))
    , m_format(new QComboBox(this))
    , m_message(new QLabel(this))
    , m_plot(new QCustomPlot(this))
    , m_cursor(new PlotCursor(m_plot))
    , m_export(new PlotExportMenu(m_plot, QStringLiteral("register-trends")))
    , m_follower(new PlotFollower(m_plot, kRedrawMs, this))
    , m_addSelected(new QAction(tr("Add &selected register"), this))
{
    m_watchChoice = new QComboBox(this);
    m_watchValueChoice = new QComboBox(this);
    m_list->setObjectName(QStringLiteral("trendRegisters"));
    m_list->setToolTip(tr("Checked registers are plotted against time"));
    m_table->addItem(tr("Holding registers"), int(ModbusTable::HoldingRegisters));
    m_table->addItem(tr("Input registers"), int(ModbusTable::InputRegisters));
    m_table->addItem(tr("Coils"), int(ModbusTable::Coils));
    m_table->addItem(tr("Discrete inputs"), int(ModbusTable::DiscreteInputs));
    connect(m_table, &QComboBox::currentIndexChanged, this,
            [this]() { m_address->setTable(ModbusTable(m_table->currentData().toInt())); });
    for (const RegisterFormat &format : RegisterFormat::all()) {
        if (format.type() != RegisterType::Ascii)
            m_format->addItem(format.name());
    }
    auto *add = new QPushButton(tr("&Add"), this);
    add->setToolTip(tr("Plot the register at this address, read with this format"));
    connect(add, &QPushButton::clicked, this, &RegisterTrendPanel::addFromFields);
    m_message->setWordWrap(true);
    m_message->setObjectName(QStringLiteral("trendMessage"));

    auto *left = new QWidget(this);
    auto *fields = new QFormLayout;
    fields->addRow(tr("Table:"), m_table);
    fields->addRow(tr("Address:"), m_address);
    fields->addRow(tr("Format:"), m_format);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_list, 1);
    leftLayout->addLayout(fields);
    leftLayout->addWidget(add);

    // Values of the workspace's watches, by watch and point name, decoded as the watch says.
    auto *watchBox = new QWidget(this);
    watchBox->setObjectName(QStringLiteral("trendWatchBox"));
    m_watchChoice->setObjectName(QStringLiteral("trendWatchChoice"));
    m_watchChoice->setToolTip(tr("A watch of the Watches tab"));
    m_watchValueChoice->setObjectName(QStringLiteral("trendWatchValueChoice"));
    m_watchValueChoice->setToolTip(tr("One of the watch's values, by its point's name or its address"));
    connect(m_watchChoice, &QComboBox::currentIndexChanged, this, &RegisterTrendPanel::refillWatchValues);
    auto *addWatchValue = new QPushButton(tr("Plot watch value"), watchBox);
    addWatchValue->setObjectName(QStringLiteral("trendAddWatchValue"));
    addWatchValue->setToolTip(tr("Plot this value of the watch as the watch polls (Workspace \u2192 Start all)"));
    connect(addWatchValue, &QPushButton::clicked, this, &RegisterTrendPanel::addFromWatchChoice);
    auto *watchFields = new QFormLayout;
    watchFields->setContentsMargins(0, 0, 0, 0);
    watchFields->addRow(tr("Watch:"), m_watchChoice);
    watchFields->addRow(tr("Value:"), m_watchValueChoice);
    auto *watchLayout = new QVBoxLayout(watchBox);
    watchLayout->setContentsMargins(0, 6, 0, 0);
    watchLayout->addLayout(watchFields);
    watchLayout->addWidget(addWatchValue);
    watchBox->setVisible(false); // until there are watches
    leftLayout->addWidget(watchBox);
    leftLayout->addWidget(m_message);

    m_plot->setObjectName(QStringLiteral("registerTrendPlot"));
    m_plot->setMinimumSize(300, 200);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->xAxis->setLabel(tr("time since the first answer (s)"));
    m_plot->yAxis->setLabel(tr("scaled value"));
    m_plot->legend->setVisible(true);
    // Top left and see-through: the newest values arrive at the right edge and stay visible.
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    m_plot->legend->setBrush(QColor(255, 255, 255, 150));
    m_plot->legend->setBorderPen(QPen(QColor(0, 0, 0, 60)));
    m_cursor->setXFormatter([](double x) { return tr("t = %1 s").arg(x, 0, 'f', 3); });

    m_follower->setFit([this] { fitAxes(); });
    m_follower->setRedraw([this] { redraw(); });
    m_follower->followAction()->setToolTip(tr("Keep every value in view as new answers arrive"));
    m_follower->clearAction()->setToolTip(tr("Forget the values plotted; the registers stay chosen"));
    connect(m_follower->clearAction(), &QAction::triggered, this, &RegisterTrendPanel::clear);
    m_addSelected->setToolTip(tr("Plot the register selected in the Registers table, in the format of its column"));
    m_addSelected->setEnabled(false);
    connect(m_addSelected, &QAction::triggered, this, &RegisterTrendPanel::addSelectedFromTable);

    auto *tools = new QToolBar(this);
    tools->addAction(m_follower->followAction());
    tools->addAction(m_follower->clearAction());
    tools->addAction(m_addSelected);
    tools->addSeparator();
    tools->addAction(m_export->saveAction());
    tools->addAction(m_export->copyAction());
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addWidget(tools);
    rightLayout->addWidget(m_plot, 1);

    auto *split = new QSplitter(this);
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    split->setSizes({220, 600});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);

    connect(m_list, &QListWidget::itemChanged, this, &RegisterTrendPanel::onItemChanged);
    restoreChoices();
}

void RegisterTrendPanel::setProfile(const UnitProfile &unit, const QString &profileName)
{
    // Series of the previous profile that are plotted stay, and the watches' values; the others leave the list.
    QList<Row> kept;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.graph || row.series.isWatchValue())
            kept.append(row);
    }
    m_rows = kept;
    m_filling = true;
    m_list->clear();
    for (const Row &row : std::as_const(m_rows)) {
        auto *item = new QListWidgetItem(row.series.label(), m_list);
        item->setToolTip(row.series.description());
        item->setCheckState(row.graph && row.graph->visible() ? Qt::Checked : Qt::Unchecked);
    }
    m_filling = false;
    for (const TrendSeries &series : TrendSeries::fromProfile(unit, profileName)) {
        const bool known = std::any_of(m_rows.cbegin(), m_rows.cend(),
                                       [&](const Row &row) { return row.series.sameRegister(series); });
        if (known)
            continue;
        m_filling = true;
        auto *item = new QListWidgetItem(series.label(), m_list);
        item->setToolTip(series.description());
        item->setCheckState(Qt::Unchecked);
        m_filling = false;
        m_rows.append(Row{series, nullptr});
    }
    restoreChoices();
}

void RegisterTrendPanel::saveChoices() const
{
    if (m_restoring)
        return;
    QJsonArray shown;
    for (const Row &row : m_rows) {
        if (row.graph && row.graph->visible())
            shown.append(row.series.toJson());
    }
    QSettings().setValue(kShownKey, QString::fromUtf8(QJsonDocument(shown).toJson(QJsonDocument::Compact)));
}

void RegisterTrendPanel::restoreChoices()
{
    const QJsonArray saved = QJsonDocument::fromJson(QSettings().value(kShownKey).toString().toUtf8()).array();
    m_restoring = true;
    for (const QJsonValue &value : saved) {
        const std::optional<TrendSeries> series = TrendSeries::fromJson(value.toObject());
        if (!series)
            continue;
        const auto row = std::find_if(m_rows.cbegin(), m_rows.cend(),
                                      [&](const Row &r) { return r.series.sameRegister(*series); });
        // A profile's register comes back when its profile is listed; one added by address at once.
        if (row != m_rows.cend())
            setSeriesShown(int(std::distance(m_rows.cbegin(), row)), true);
        else if (series->name.isEmpty() || series->isWatchValue())
            addSeries(*series);
    }
    m_restoring = false;
}

void RegisterTrendPanel::setRegisterTable(RegisterTable *table)
{
    m_registerTable = table;
    m_addSelected->setEnabled(table != nullptr);
}

int RegisterTrendPanel::addSeries(const TrendSeries &series)
{
    for (int i = 0; i < m_rows.size(); ++i) {
        if (m_rows.at(i).series.sameRegister(series)) {
            setSeriesShown(i, true);
            return i;
        }
    }
    m_filling = true;
    auto *item = new QListWidgetItem(series.label(), m_list);
    item->setToolTip(series.description());
    item->setCheckState(Qt::Unchecked);
    m_filling = false;
    m_rows.append(Row{series, nullptr});
    const int index = int(m_rows.size()) - 1;
    setSeriesShown(index, true);
    return index;
}

void RegisterTrendPanel::setSeriesShown(int index, bool shown)
{
    m_list->item(index)->setCheckState(shown ? Qt::Checked : Qt::Unchecked); // onItemChanged does the rest
}

void RegisterTrendPanel::onItemChanged(QListWidgetItem *item)
{
    if (m_filling)
        return;
    const int index = m_list->row(item);
    if (index < 0 || index >= m_rows.size())
        return;
    const bool shown = item->checkState() == Qt::Checked;
    QCPGraph *graph = shown ? graphFor(index) : m_rows.at(index).graph;
    if (!graph)
        return;
    graph->setVisible(shown);
    if (shown)
        graph->addToLegend();
    else
        graph->removeFromLegend();
    saveChoices();
    redraw();
}

QCPGraph *RegisterTrendPanel::graphFor(int index)
{
    Row &row = m_rows[index];
    if (row.graph)
        return row.graph;
    row.graph = m_plot->addGraph();
    const QColor colour = seriesColour(m_plot->graphCount() - 1); // in the order they were chosen
    row.graph->setPen(QPen(colour, 1.5));
    row.graph->setLineStyle(QCPGraph::lsStepLeft); // a polled value holds until the next answer
    row.graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour, colour, 3));
    row.graph->setName(row.series.label());
    // The register's history so far: ticking a box shows what was already read, not only what comes.
    if (row.series.isWatchValue()) {
        for (const WatchAnswer &answer : std::as_const(m_watchHistory)) {
            if (answer.watchName != row.series.watchName)
                continue;
            if (const qsizetype at = answer.addresses.indexOf(quint16(row.series.address)); at >= 0)
                row.graph->addData(answer.seconds, answer.values.at(at));
        }
    }
    for (const Answer &answer : std::as_const(m_history)) {
        if (row.series.isWatchValue())
            break;
        if (row.series.unitId >= 0 && row.series.unitId != answer.unitId)
            continue;
        if (const std::optional<double> value = row.series.valueIn(answer.read))
            row.graph->addData(answer.seconds, *value);
    }
    const QString unit = row.series.unit;
    m_cursor->setValueFormatter(row.graph, [unit](double value) {
        return unit.isEmpty() ? QString::number(value, 'g', 7) : tr("%1 %2").arg(QString::number(value, 'g', 7), unit);
    });
    return row.graph;
}

bool RegisterTrendPanel::addSelectedFromTable()
{
    if (!m_registerTable) {
        showMessage(tr("No register table to take a register from"));
        return false;
    }
    const RegisterTableModel *model = m_registerTable->model();
    const QModelIndex current = m_registerTable->view()->currentIndex();
    if (!model->hasAnswer() || !current.isValid()) {
        showMessage(tr("Select a register in the Registers table first"));
        return false;
    }
    TrendSeries series;
    series.table = model->answer().table;
    series.address = current.data(RegisterTableModel::AddressRole).toInt();
    const int valueIndex = model->valueIndexOf(current.column());
    series.format = valueIndex >= 0 ? model->formatOfColumn(current.column()) : RegisterFormat();
    // The profile's meaning when the register is one of its entries in that format.
    for (const Row &row : std::as_const(m_rows)) {
        if (!row.series.isWatchValue() && row.series.table == series.table && row.series.address == series.address
            && (valueIndex < 0 || row.series.format == series.format)) {
            series = row.series;
            break;
        }
    }
    const int index = addSeries(series);
    showMessage(tr("Plotting %1").arg(m_rows.at(index).series.label()));
    return true;
}

void RegisterTrendPanel::addFromFields()
{
    const std::optional<int> address = m_address->address();
    if (!address) {
        showMessage(tr("Not added: the address is wrong: %1").arg(m_address->error()));
        return;
    }
    const RegisterFormatResult format = RegisterFormat::parse(m_format->currentText());
    if (!format.ok) {
        showMessage(tr("Not added: %1").arg(format.error));
        return;
    }
    TrendSeries series;
    series.table = ModbusTable(m_table->currentData().toInt());
    series.address = *address;
    series.format = format.format;
    if (series.address + series.format.registerCount() > 0x10000) {
        showMessage(tr("Not added: a %1 at PDU address %2 would go past the last address (65535)")
                        .arg(series.format.name())
                        .arg(series.address));
        return;
    }
    const int index = addSeries(series);
    showMessage(tr("Plotting %1").arg(m_rows.at(index).series.label()));
}

void RegisterTrendPanel::addTransactions(const QList<Transaction> &transactions)
{
    bool added = false;
    for (const Transaction &t : transactions) {
        if (!t.isOk())
            continue;
        const AduParts request = AduBuilder::parse(t.request, m_framing);
        const AduParts response = AduBuilder::parse(t.response, m_framing);
        const ReadAnswerResult read = ReadAnswer::fromPdus(request.pdu, response.pdu);
        if (!read.ok)
            continue; // not a read, or an answer the register table reports
        if (m_startNs == 0)
            m_startNs = t.sentNs; // the first answer starts the time axis
        const double seconds = secondsOf(t.doneNs);
        m_history.append(Answer{seconds, request.unitId, read.answer});
        m_lastSeconds = std::max(m_lastSeconds, seconds);
        for (Row &row : m_rows) {
            if (!row.graph || row.series.isWatchValue() || (row.series.unitId >= 0 && row.series.unitId != request.unitId))
                continue;
            if (const std::optional<double> value = row.series.valueIn(read.answer)) {
                row.graph->addData(seconds, *value);
                m_lastSeconds = std::max(m_lastSeconds, seconds);
                added = true;
            }
        }
    }
    if (m_history.size() > kHistoryAnswers)
        m_history.remove(0, m_history.size() - kHistoryAnswers);
    if (added)
        m_follower->scheduleRedraw();
}

double RegisterTrendPanel::secondsOf(qint64 ns)
{
    if (m_startNs == 0)
        m_startNs = ns;
    return double(ns - m_startNs) / 1e9;
}

void RegisterTrendPanel::setWatches(const SessionWatches &watches)
{
    m_watches = watches;
    const QString chosen = m_watchChoice->currentText();
    {
        const QSignalBlocker blocker(m_watchChoice);
        m_watchChoice->clear();
        for (const WatchDefinition &watch : watches.watches)
            m_watchChoice->addItem(watch.name);
        m_watchChoice->setCurrentIndex(std::max(0, m_watchChoice->findText(chosen)));
    }
    refillWatchValues();
    if (QWidget *box = findChild<QWidget *>(QStringLiteral("trendWatchBox")))
        box->setVisible(!watches.watches.isEmpty());
}

void RegisterTrendPanel::refillWatchValues()
{
    m_watchValueChoice->clear();
    const int index = m_watchChoice->currentIndex();
    if (index < 0 || index >= m_watches.watches.size())
        return;
    const WatchDefinition &watch = m_watches.watches.at(index);
    // Its named points, then the addresses of its block that no point names (a FIFO has none).
    QList<quint16> named;
    for (const WatchPoint &point : watch.points) {
        if (point.name.isEmpty())
            continue;
        named << point.address;
        m_watchValueChoice->addItem(point.unit.isEmpty() ? point.name : tr("%1 (%2)").arg(point.name, point.unit), int(point.address));
    }
    if (watch.function < 1 || watch.function > 4)
        return;
    for (int address = watch.address; address < int(watch.address) + watch.quantity && address <= 0xFFFF; ++address) {
        if (!named.contains(quint16(address)))
            m_watchValueChoice->addItem(tr("address %1").arg(ReadAnswer::addressText(address)), address);
    }
}

void RegisterTrendPanel::addFromWatchChoice()
{
    const int watch = m_watchChoice->currentIndex();
    if (watch < 0 || watch >= m_watches.watches.size() || m_watchValueChoice->currentIndex() < 0) {
        showMessage(tr("Not added: choose a watch and one of its values"));
        return;
    }
    const int index = addWatchValue(m_watches.watches.at(watch).name, quint16(m_watchValueChoice->currentData().toInt()));
    showMessage(tr("Plotting %1").arg(m_rows.at(index).series.label()));
}

int RegisterTrendPanel::addWatchValue(const QString &watchName, quint16 address, const QString &pointName)
{
    TrendSeries series;
    series.watchName = watchName;
    series.address = address;
    series.name = pointName;
    for (const WatchDefinition &watch : std::as_const(m_watches.watches)) {
        if (watch.name != watchName)
            continue;
        for (const WatchPoint &point : watch.points) {
            if (point.address == address) {
                series.name = point.name;
                series.unit = point.unit;
            }
        }
    }
    return addSeries(series);
}

void RegisterTrendPanel::addWatchSamples(const QList<WatchSample> &samples)
{
    bool added = false;
    const qint64 nowNs = monotonicNowNs();
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    for (const WatchSample &sample : samples) {
        if (!sample.isOk() || sample.values.isEmpty())
            continue;
        // The sample's wall-clock time on the transactions' monotonic axis.
        const double seconds = secondsOf(nowNs - (nowMs - sample.timeMs) * 1000000);
        WatchAnswer answer{seconds, sample.watchName, {}, {}};
        answer.addresses.reserve(sample.values.size());
        answer.values.reserve(sample.values.size());
        for (const WatchPointValue &value : sample.values) {
            answer.addresses << value.address;
            answer.values << value.value;
        }
        m_lastSeconds = std::max(m_lastSeconds, seconds);
        for (Row &row : m_rows) {
            if (!row.graph || row.series.watchName != sample.watchName)
                continue;
            if (const qsizetype at = answer.addresses.indexOf(quint16(row.series.address)); at >= 0) {
                row.graph->addData(seconds, answer.values.at(at));
                added = true;
            }
        }
        m_watchHistory.append(std::move(answer));
    }
    if (m_watchHistory.size() > kHistoryAnswers)
        m_watchHistory.remove(0, m_watchHistory.size() - kHistoryAnswers);
    if (added)
        m_follower->scheduleRedraw();
}

void RegisterTrendPanel::clear()
{
    for (const Row &row : std::as_const(m_rows)) {
        if (row.graph)
            row.graph->data()->clear();
    }
    m_history.clear();
    m_watchHistory.clear();
    m_startNs = 0;
    m_lastSeconds = 0;
    m_cursor->hide();
    m_follower->setFollowing(true);
    redraw();
}

void RegisterTrendPanel::setFollowing(bool following)
{
    m_follower->setFollowing(following);
}

bool RegisterTrendPanel::isFollowing() const
{
    return m_follower->isFollowing();
}

QString RegisterTrendPanel::message() const
{
    return m_message->text();
}

void RegisterTrendPanel::showMessage(const QString &text)
{
    m_message->setText(text);
}

void RegisterTrendPanel::redrawNow()
{
    m_follower->redrawNow();
}

void RegisterTrendPanel::redraw()
{
    m_follower->fitIfFollowing();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void RegisterTrendPanel::fitAxes()
{
    QCPRange values;
    bool any = false;
    double firstSeconds = m_lastSeconds;
    for (const Row &row : std::as_const(m_rows)) {
        if (!row.graph || !row.graph->visible())
            continue;
        bool found = false;
        const QCPRange range = row.graph->getValueRange(found);
        if (!found)
            continue;
        values = any ? QCPRange(std::min(values.lower, range.lower), std::max(values.upper, range.upper)) : range;
        firstSeconds = std::min(firstSeconds, row.graph->getKeyRange(found).lower);
        any = true;
    }
    if (!any)
        values = QCPRange(0, 1);
    const double margin = values.size() > 0 ? values.size() * 0.08 : std::max(std::abs(values.lower) * 0.1, 1.0);
    // From the first point shown, not the session's first answer: a trend begun late fills the width.
    const double from = any ? firstSeconds : 0;
    const double span = std::max(m_lastSeconds - from, 1.0);
    m_plot->xAxis->setRange(from - span * 0.01, from + span * 1.02);
    m_plot->yAxis->setRange(values.lower - margin, values.upper + margin);
}

} // namespace mbscope
