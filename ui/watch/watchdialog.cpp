#include "watchdialog.h"

#include "watchpointtable.h"
#include "watchruletable.h"

#include "compose/addressfield.h"

#include "transport/linkurl.h"
#include "protocol/quantitylimits.h"
#include "watch/watchblock.h"

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

std::optional<ModbusTable> tableOf(int function)
{
    switch (function) {
    case 1: return ModbusTable::Coils;
    case 2: return ModbusTable::DiscreteInputs;
    case 3: return ModbusTable::HoldingRegisters;
    case 4: return ModbusTable::InputRegisters;
    default: break;
    }
    return std::nullopt;
}

} // namespace

WatchDialog::WatchDialog(QWidget *parent)
    : QDialog(parent)
    , m_name(new QLineEdit(this))
    , m_target(new QLineEdit(this))
    , m_unit(new QSpinBox(this))
    , m_function(new QComboBox(this))
    , m_address(new AddressField(this))
    , m_quantity(new QSpinBox(this))
    , m_interval(new QSpinBox(this))
    , m_enron(new QCheckBox(tr("Each address holds a 32-bit value (&Enron/Daniel)"), this))
    , m_enabled(new QCheckBox(tr("Poll this watch (&on)"), this))
    , m_points(new WatchPointTable(this))
    , m_rules(new WatchRuleTable(this))
    , m_problems(new QLabel(this))
{
    setObjectName(QStringLiteral("watchDialog"));
    setWindowTitle(tr("Watch"));
    m_name->setObjectName(QStringLiteral("watchName"));
    m_target->setObjectName(QStringLiteral("watchTarget"));
    m_target->setPlaceholderText(QStringLiteral("tcp://127.0.0.1:502"));
    m_target->setToolTip(tr("The link URL: tcp://host:port, rtu-tcp://host:port, udp://host:port, "
                            "rtu:///dev/ttyUSB0?baud=19200"));
    m_unit->setRange(0, 255);
    m_unit->setValue(1);
    m_function->addItem(tr("01 Read coils"), 1);
    m_function->addItem(tr("02 Read discrete inputs"), 2);
    m_function->addItem(tr("03 Read holding registers"), 3);
    m_function->addItem(tr("04 Read input registers"), 4);
    m_function->addItem(tr("18 Read FIFO queue"), 0x18);
    m_function->setCurrentIndex(2);
    m_quantity->setRange(1, QuantityLimits::kReadBits);
    m_quantity->setValue(10);
    m_interval->setRange(0, 24 * 3600 * 1000);
    m_interval->setSuffix(tr(" ms"));
    m_interval->setValue(1000);
    m_interval->setToolTip(tr("Start to start; 0: as fast as the link allows"));
    m_enabled->setChecked(true);

    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("Tar&get:"), m_target);
    form->addRow(tr("&Unit:"), m_unit);
    form->addRow(tr("&Function:"), m_function);
    auto *addressLabel = new QLabel(tr("&Address:"), this);
    addressLabel->setBuddy(m_address->lineEdit());
    form->addRow(addressLabel, m_address);
    form->addRow(tr("&Quantity:"), m_quantity);
    form->addRow(tr("&Interval:"), m_interval);
    form->addRow(m_enron);
    form->addRow(m_enabled);

    auto *pointsPage = new QWidget(this);
    auto *pointsLayout = new QVBoxLayout(pointsPage);
    pointsLayout->addWidget(m_points);
    auto *pointButtons = new QHBoxLayout;
    auto *addPoint = new QPushButton(tr("Add &point"), pointsPage);
    auto *removePoint = new QPushButton(tr("Remo&ve point"), pointsPage);
    pointButtons->addWidget(addPoint);
    pointButtons->addWidget(removePoint);
    pointButtons->addStretch(1);
    pointsLayout->addLayout(pointButtons);
    connect(addPoint, &QPushButton::clicked, this, [this] {
        quint16 next = quint16(m_address->address().value_or(0));
        QStringList ignored;
        for (const WatchPoint &point : m_points->points(&ignored))
            next = quint16(qMax<int>(next, point.address + point.format.registerCount()));
        m_points->addPoint(next);
    });
    connect(removePoint, &QPushButton::clicked, m_points, &WatchPointTable::removeCurrent);

    auto *rulesPage = new QWidget(this);
    auto *rulesLayout = new QVBoxLayout(rulesPage);
    rulesLayout->addWidget(m_rules);
    auto *ruleButtons = new QHBoxLayout;
    auto *addRule = new QPushButton(tr("Add &rule"), rulesPage);
    auto *removeRule = new QPushButton(tr("Remove ru&le"), rulesPage);
    ruleButtons->addWidget(addRule);
    ruleButtons->addWidget(removeRule);
    ruleButtons->addStretch(1);
    rulesLayout->addLayout(ruleButtons);
    connect(addRule, &QPushButton::clicked, this, [this] {
        const int row = m_points->currentRow();
        const QTableWidgetItem *name = row >= 0 ? m_points->item(row, WatchPointTable::NameColumn) : nullptr;
        m_rules->addRule(name ? name->text() : QString());
    });
    connect(removeRule, &QPushButton::clicked, m_rules, &WatchRuleTable::removeCurrent);

    auto *tabs = new QTabWidget(this);
    tabs->addTab(pointsPage, tr("Poin&ts"));
    tabs->addTab(rulesPage, tr("Rule&s"));

    m_problems->setObjectName(QStringLiteral("watchProblems"));
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color: palette(bright-text);"));
    m_problems->hide();

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(tabs, 1);
    layout->addWidget(m_problems);
    layout->addWidget(buttons);
    connect(m_function, &QComboBox::currentIndexChanged, this, &WatchDialog::onFunctionChanged);
    connect(m_enron, &QCheckBox::toggled, this, &WatchDialog::onFunctionChanged);
    onFunctionChanged();
    resize(760, 600);
}

void WatchDialog::onFunctionChanged()
{
    const int function = m_function->currentData().toInt();
    m_address->setTable(tableOf(function));
    m_quantity->setMaximum(WatchBlock::maxQuantity(quint8(function), m_enron->isChecked()));
    m_enron->setEnabled(function == 3 || function == 4);
}

void WatchDialog::setWatch(const WatchDefinition &watch)
{
    m_name->setText(watch.name);
    m_target->setText(watch.target);
    m_unit->setValue(watch.unit);
    m_function->setCurrentIndex(qMax(0, m_function->findData(int(watch.function))));
    m_enron->setChecked(watch.enron32);
    onFunctionChanged();
    m_address->setAddress(watch.address);
    m_quantity->setValue(watch.quantity);
    m_interval->setValue(int(watch.intervalMs));
    m_enabled->setChecked(watch.enabled);
    m_points->setPoints(watch.points);
    m_rules->setRules(watch.rules);
    m_profileBlock = watch.profileBlock;
}

WatchDefinition WatchDialog::watch(QStringList *problems) const
{
    WatchDefinition watch;
    watch.name = m_name->text().trimmed();
    if (watch.name.isEmpty())
        problems->append(tr("Name: give the watch a name (used in CSV file names and logs)"));
    else if (m_taken.contains(watch.name))
        problems->append(tr("Name: another watch is called '%1'").arg(watch.name));
    watch.target = m_target->text().trimmed();
    const LinkUrl::Result url = LinkUrl::parse(watch.target);
    if (!url.url)
        problems->append(tr("Target: %1").arg(url.error));
    watch.unit = quint8(m_unit->value());
    watch.function = quint8(m_function->currentData().toInt());
    if (const std::optional<int> address = m_address->address())
        watch.address = quint16(*address);
    else
        problems->append(tr("Address: %1").arg(m_address->error()));
    watch.quantity = quint16(m_quantity->value());
    watch.intervalMs = m_interval->value();
    watch.enron32 = m_enron->isEnabled() && m_enron->isChecked();
    watch.enabled = m_enabled->isChecked();
    watch.profileBlock = m_profileBlock;
    watch.points = m_points->points(problems);
    for (const WatchPoint &point : std::as_const(watch.points)) {
        if (point.address < watch.address || point.address >= watch.address + watch.quantity)
            problems->append(tr("Point at address %1 lies outside the watch's addresses %2 to %3")
                                 .arg(point.address)
                                 .arg(watch.address)
                                 .arg(watch.address + watch.quantity - 1));
    }
    watch.rules = m_rules->rules(watch, problems);
    return watch;
}

void WatchDialog::done(int result)
{
    if (result == QDialog::Accepted) {
        QStringList problems;
        (void)watch(&problems);
        if (!problems.isEmpty()) {
            m_problems->setText(problems.join(QLatin1Char('\n')));
            m_problems->show();
            return;
        }
    }
    QDialog::done(result);
}

} // namespace mbscope
