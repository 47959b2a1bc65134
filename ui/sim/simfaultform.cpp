#include "simfaultform.h"

#include "profile/profileloader.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QListWidget>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

QString ms(double value)
{
    return QString::number(value, 'g', 6);
}

QString hexByte(int value)
{
    return QString::number(value, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

QDoubleSpinBox *msBox(QWidget *parent, double value, const QString &name)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(0, 600000);
    box->setDecimals(1);
    box->setSingleStep(5);
    box->setValue(value);
    box->setSuffix(SimFaultForm::tr(" ms"));
    return box;
}

} // namespace

SimFaultForm::SimFaultForm(QWidget *parent)
    : QWidget(parent)
{
    buildForm();
    updateFieldVisibility();
    showRules();
}

void SimFaultForm::buildForm()
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    auto *formBox = new QWidget(this);
    m_form = new QFormLayout(formBox);
    m_form->setContentsMargins(0, 0, 0, 0);
    m_kind = new QComboBox(formBox);
    m_kind->setObjectName(QStringLiteral("faultKind"));
    m_kind->addItem(tr("Delay the answer"), int(FaultRule::Kind::Delay));
    m_kind->addItem(tr("Drop the answer"), int(FaultRule::Kind::Drop));
    m_kind->addItem(tr("Wrong CRC or LRC"), int(FaultRule::Kind::WrongChecksum));
    m_kind->addItem(tr("Exception instead of the answer"), int(FaultRule::Kind::Exception));
    m_form->addRow(tr("&Fault:"), m_kind);

    m_unit = new QSpinBox(formBox);
    m_unit->setObjectName(QStringLiteral("faultUnit"));
    m_unit->setRange(0, 255);
    m_unit->setSpecialValueText(tr("any unit"));
    m_form->addRow(tr("&Unit:"), m_unit);

    m_function = new QSpinBox(formBox);
    m_function->setObjectName(QStringLiteral("faultFunction"));
    m_function->setRange(0, 127);
    m_function->setDisplayIntegerBase(16);
    m_function->setPrefix(QStringLiteral("0x"));
    m_function->setSpecialValueText(tr("any function"));
    m_form->addRow(tr("Function &code:"), m_function);

    m_probability = new QDoubleSpinBox(formBox);
    m_probability->setObjectName(QStringLiteral("faultProbability"));
    m_probability->setRange(0, 1);
    m_probability->setDecimals(3);
    m_probability->setSingleStep(0.05);
    m_probability->setValue(1);
    m_probability->setToolTip(tr("The share of matching answers the rule changes: 1 for every one, 0.1 for one in ten."));
    m_form->addRow(tr("&Probability:"), m_probability);

    m_distribution = new QComboBox(formBox);
    m_distribution->setObjectName(QStringLiteral("faultDistribution"));
    m_distribution->addItem(tr("fixed"), int(DelaySpec::Kind::Fixed));
    m_distribution->addItem(tr("uniform"), int(DelaySpec::Kind::Uniform));
    m_distribution->addItem(tr("normal"), int(DelaySpec::Kind::Normal));
    m_distribution->addItem(tr("exponential"), int(DelaySpec::Kind::Exponential));
    m_form->addRow(tr("&Distribution:"), m_distribution);
    m_fixedMs = msBox(formBox, 100, QStringLiteral("faultDelayMs"));
    m_form->addRow(tr("Delay:"), m_fixedMs);
    m_meanMs = msBox(formBox, 100, QStringLiteral("faultMeanMs"));
    m_form->addRow(tr("Mean:"), m_meanMs);
    m_stddevMs = msBox(formBox, 20, QStringLiteral("faultStddevMs"));
    m_form->addRow(tr("Standard deviation:"), m_stddevMs);
    m_minMs = msBox(formBox, 0, QStringLiteral("faultMinMs"));
    m_form->addRow(tr("At least:"), m_minMs);
    m_maxMs = msBox(formBox, 200, QStringLiteral("faultMaxMs"));
    m_form->addRow(tr("At most:"), m_maxMs);

    m_exceptionCode = new QSpinBox(formBox);
    m_exceptionCode->setObjectName(QStringLiteral("faultExceptionCode"));
    m_exceptionCode->setRange(1, 255);
    m_exceptionCode->setDisplayIntegerBase(16);
    m_exceptionCode->setPrefix(QStringLiteral("0x"));
    m_exceptionCode->setValue(0x06);
    m_exceptionCode->setToolTip(tr("01 illegal function, 02 illegal data address, 03 illegal data value, 04 server "
                                   "device failure, 06 server device busy, 0B gateway target failed to respond."));
    m_form->addRow(tr("E&xception code:"), m_exceptionCode);

    m_add = new QPushButton(tr("&Add rule"), formBox);
    m_add->setObjectName(QStringLiteral("faultAdd"));
    m_add->setToolTip(tr("Adds the rule to those in force: the simulator's next request sees it."));
    m_form->addRow(QString(), m_add);
    layout->addWidget(formBox);

    auto *rulesBox = new QWidget(this);
    auto *rulesLayout = new QVBoxLayout(rulesBox);
    rulesLayout->setContentsMargins(0, 0, 0, 0);
    rulesLayout->addWidget(new QLabel(tr("Rules in force:"), rulesBox));
    m_list = new QListWidget(rulesBox);
    m_list->setObjectName(QStringLiteral("faultRules"));
    rulesLayout->addWidget(m_list, 1);
    auto *buttons = new QHBoxLayout;
    m_remove = new QPushButton(tr("&Remove"), rulesBox);
    m_remove->setObjectName(QStringLiteral("faultRemove"));
    m_clear = new QPushButton(tr("&No faults"), rulesBox);
    m_clear->setObjectName(QStringLiteral("faultClear"));
    m_clear->setToolTip(tr("Removes every rule: correct answers from the next request on."));
    m_load = new QPushButton(tr("&Load rules file..."), rulesBox);
    m_load->setObjectName(QStringLiteral("faultLoad"));
    m_load->setToolTip(tr("Replaces the rules by those of a faults file (the format of mbscope simulate --faults)."));
    buttons->addWidget(m_remove);
    buttons->addWidget(m_clear);
    buttons->addStretch(1);
    buttons->addWidget(m_load);
    rulesLayout->addLayout(buttons);
    m_message = new QLabel(rulesBox);
    m_message->setObjectName(QStringLiteral("faultMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    rulesLayout->addWidget(m_message);
    layout->addWidget(rulesBox, 1);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &SimFaultForm::updateFieldVisibility);
    connect(m_distribution, &QComboBox::currentIndexChanged, this, &SimFaultForm::updateFieldVisibility);
    connect(m_add, &QPushButton::clicked, this, &SimFaultForm::addFormRule);
    connect(m_remove, &QPushButton::clicked, this, [this] { removeRule(m_list->currentRow()); });
    connect(m_clear, &QPushButton::clicked, this, &SimFaultForm::clearRules);
    connect(m_load, &QPushButton::clicked, this, &SimFaultForm::chooseRulesFile);
}

void SimFaultForm::updateFieldVisibility()
{
    const auto kind = FaultRule::Kind(m_kind->currentData().toInt());
    const auto distribution = DelaySpec::Kind(m_distribution->currentData().toInt());
    const bool delay = kind == FaultRule::Kind::Delay;
    m_form->setRowVisible(m_distribution, delay);
    m_form->setRowVisible(m_fixedMs, delay && distribution == DelaySpec::Kind::Fixed);
    m_form->setRowVisible(m_meanMs, delay && (distribution == DelaySpec::Kind::Normal || distribution == DelaySpec::Kind::Exponential));
    m_form->setRowVisible(m_stddevMs, delay && distribution == DelaySpec::Kind::Normal);
    m_form->setRowVisible(m_minMs, delay && distribution != DelaySpec::Kind::Fixed);
    m_form->setRowVisible(m_maxMs, delay && distribution != DelaySpec::Kind::Fixed);
    m_form->setRowVisible(m_exceptionCode, kind == FaultRule::Kind::Exception);
}

FaultRule SimFaultForm::formRule() const
{
    FaultRule rule;
    rule.kind = FaultRule::Kind(m_kind->currentData().toInt());
    if (m_unit->value() > 0)
        rule.units = {quint8(m_unit->value())};
    if (m_function->value() > 0)
        rule.functions = {quint8(m_function->value())};
    rule.probability = m_probability->value();
    if (rule.kind == FaultRule::Kind::Delay) {
        DelaySpec delay;
        delay.kind = DelaySpec::Kind(m_distribution->currentData().toInt());
        delay.ms = m_fixedMs->value();
        delay.meanMs = m_meanMs->value();
        delay.stddevMs = m_stddevMs->value();
        if (delay.kind != DelaySpec::Kind::Fixed) {
            delay.minMs = m_minMs->value();
            delay.maxMs = m_maxMs->value();
        }
        rule.delay = delay;
    }
    if (rule.kind == FaultRule::Kind::Exception)
        rule.exceptionCode = quint8(m_exceptionCode->value());
    return rule;
}

void SimFaultForm::addFormRule()
{
    const FaultRule rule = formRule();
    if (rule.kind == FaultRule::Kind::Delay && rule.delay.kind == DelaySpec::Kind::Uniform && rule.delay.maxMs < rule.delay.minMs) {
        m_message->setText(tr("Not added: a uniform delay needs 'At most' (%1 ms) at or above 'At least' (%2 ms).")
                               .arg(ms(rule.delay.maxMs), ms(rule.delay.minMs)));
        return;
    }
    FaultRuleSet rules = m_rules;
    rules.rules.append(rule);
    apply(rules);
    m_message->setText(tr("Added: %1.").arg(describe(rule)));
}

void SimFaultForm::removeRule(int index)
{
    if (index < 0 || index >= m_rules.rules.size())
        return;
    FaultRuleSet rules = m_rules;
    rules.rules.removeAt(index);
    apply(rules);
    m_message->clear();
}

void SimFaultForm::clearRules()
{
    FaultRuleSet rules = m_rules;
    rules.rules.clear();
    apply(rules);
    m_message->setText(tr("No fault rules: the simulator answers correctly from the next request on."));
}

bool SimFaultForm::loadRulesFile(const QString &path)
{
    const FaultRulesLoadResult loaded = ProfileLoader::loadFaults(path);
    if (!loaded.ok) {
        m_message->setText(tr("The rules file does not read; the rules in force stay:\n%1").arg(loaded.errorText()));
        return false;
    }
    apply(loaded.rules);
    m_message->setText(tr("%n rule(s) from %1, seed %2.", nullptr, int(loaded.rules.rules.size()))
                           .arg(path)
                           .arg(loaded.rules.seed));
    return true;
}

QString SimFaultForm::message() const
{
    return m_message->text();
}

void SimFaultForm::chooseRulesFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load fault rules"), QString(),
                                                      tr("Fault rules (*.json);;All files (*)"));
    if (!path.isEmpty())
        loadRulesFile(path);
}

void SimFaultForm::setRules(const FaultRuleSet &rules)
{
    m_rules = rules;
    m_message->clear();
    showRules();
}

void SimFaultForm::apply(const FaultRuleSet &rules)
{
    m_rules = rules;
    showRules();
    Q_EMIT rulesChanged(m_rules);
}

void SimFaultForm::showRules()
{
    m_list->clear();
    for (const FaultRule &rule : std::as_const(m_rules.rules))
        m_list->addItem(describe(rule));
    if (m_rules.rules.isEmpty()) {
        auto *none = new QListWidgetItem(tr("(none: every answer is correct)"), m_list);
        none->setFlags(Qt::NoItemFlags);
    }
    m_remove->setEnabled(!m_rules.rules.isEmpty());
    m_clear->setEnabled(!m_rules.rules.isEmpty());
}

QString SimFaultForm::describe(const FaultRule &rule)
{
    QString what;
    switch (rule.kind) {
    case FaultRule::Kind::Delay: {
        const DelaySpec &d = rule.delay;
        switch (d.kind) {
        case DelaySpec::Kind::Fixed: what = tr("delay %1 ms").arg(ms(d.ms)); break;
        case DelaySpec::Kind::Uniform: what = tr("delay uniform %1 to %2 ms").arg(ms(d.minMs), ms(d.maxMs)); break;
        case DelaySpec::Kind::Normal:
            what = tr("delay normal, mean %1 ms, standard deviation %2 ms").arg(ms(d.meanMs), ms(d.stddevMs));
            break;
        case DelaySpec::Kind::Exponential: what = tr("delay exponential, mean %1 ms").arg(ms(d.meanMs)); break;
        }
        break;
    }
    case FaultRule::Kind::Drop: what = tr("drop the answer"); break;
    case FaultRule::Kind::WrongChecksum: what = tr("wrong CRC or LRC"); break;
    case FaultRule::Kind::Exception: what = tr("exception %1").arg(hexByte(rule.exceptionCode)); break;
    default: what = FaultRule::kindName(rule.kind); break;
    }
    QStringList units;
    for (quint8 unit : rule.units)
        units << QString::number(unit);
    QStringList functions;
    for (quint8 function : rule.functions)
        functions << hexByte(function);
    const QString unitText = units.isEmpty() ? tr("any unit") : tr("unit %1").arg(units.join(QStringLiteral(", ")));
    const QString functionText = functions.isEmpty() ? tr("any function") : tr("function %1").arg(functions.join(QStringLiteral(", ")));
    QString text = tr("%1 for %2, %3").arg(what, unitText, functionText);
    if (rule.hasAddressRange())
        text = tr("%1, addresses %2 to %3").arg(text).arg(rule.firstAddress).arg(rule.lastAddress);
    if (rule.probability < 1)
        text = tr("%1 (probability %2)").arg(text).arg(rule.probability);
    if (!rule.name.isEmpty())
        text = tr("%1: %2").arg(rule.name, text);
    return text;
}

} // namespace mbscope
