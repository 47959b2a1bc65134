#include "simfaultform.h"

#include "common/lastfolder.h"

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
    m_kind->addItem(tr("Wrong transaction id (MBAP)"), int(FaultRule::Kind::WrongTransactionId));
    m_kind->addItem(tr("Wrong unit id"), int(FaultRule::Kind::WrongUnit));
    m_kind->addItem(tr("Fewer registers than asked"), int(FaultRule::Kind::FewerRegisters));
    m_kind->addItem(tr("The answer in chunks"), int(FaultRule::Kind::Chunks));
    m_kind->addItem(tr("The answer a byte at a time"), int(FaultRule::Kind::Trickle));
    m_kind->addItem(tr("Junk bytes around the answer"), int(FaultRule::Kind::Junk));
    m_kind->addItem(tr("The answer more than once"), int(FaultRule::Kind::Duplicate));
    m_kind->addItem(tr("Close the connection"), int(FaultRule::Kind::Close));
    m_kind->addItem(tr("Line noise (flipped bits)"), int(FaultRule::Kind::Noise));
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

    // -1 is "any": a rule for an address range matches requests that touch it.
    auto addressBox = [formBox](const QString &name) {
        auto *box = new QSpinBox(formBox);
        box->setObjectName(name);
        box->setRange(-1, 65535);
        box->setValue(-1);
        box->setSpecialValueText(tr("any"));
        return box;
    };
    m_firstAddress = addressBox(QStringLiteral("faultFirstAddress"));
    m_lastAddress = addressBox(QStringLiteral("faultLastAddress"));
    m_firstAddress->setToolTip(tr("Only requests that touch the addresses from here to 'to' (any: every request)."));
    auto *addresses = new QHBoxLayout;
    addresses->addWidget(m_firstAddress, 1);
    addresses->addWidget(new QLabel(tr("to"), formBox));
    addresses->addWidget(m_lastAddress, 1);
    m_form->addRow(tr("Addresses:"), addresses);

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
    m_distribution->addItem(tr("lognormal"), int(DelaySpec::Kind::LogNormal));
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

    auto countBox = [formBox](const QString &name, int low, int high, int value) {
        auto *box = new QSpinBox(formBox);
        box->setObjectName(name);
        box->setRange(low, high);
        box->setValue(value);
        return box;
    };
    m_delta = countBox(QStringLiteral("faultDelta"), 1, 65535, 1);
    m_delta->setToolTip(tr("Added to the transaction id (modulo 65536) or the unit id (modulo 256)"));
    m_form->addRow(tr("Added to the id:"), m_delta);
    m_fewer = countBox(QStringLiteral("faultFewer"), 1, 125, 1);
    m_fewer->setToolTip(tr("Registers (or bytes of coils) left out of a read's answer"));
    m_form->addRow(tr("Fewer by:"), m_fewer);
    m_chunkBytes = countBox(QStringLiteral("faultChunkBytes"), 1, 260, 4);
    m_form->addRow(tr("Bytes per chunk:"), m_chunkBytes);
    m_gapMs = msBox(formBox, 5, QStringLiteral("faultGapMs"));
    m_gapMs->setToolTip(tr("Between chunks, bytes or copies of the answer"));
    m_form->addRow(tr("Gap:"), m_gapMs);
    m_junkBefore = countBox(QStringLiteral("faultJunkBefore"), 0, 256, 3);
    m_form->addRow(tr("Random bytes before:"), m_junkBefore);
    m_junkAfter = countBox(QStringLiteral("faultJunkAfter"), 0, 256, 0);
    m_form->addRow(tr("Random bytes after:"), m_junkAfter);
    m_copies = countBox(QStringLiteral("faultCopies"), 1, 100, 1);
    m_form->addRow(tr("Extra copies:"), m_copies);
    m_closeWhen = new QComboBox(formBox);
    m_closeWhen->setObjectName(QStringLiteral("faultCloseWhen"));
    m_closeWhen->addItem(tr("before the answer"), int(FaultRule::CloseWhen::Before));
    m_closeWhen->addItem(tr("midway through the answer"), int(FaultRule::CloseWhen::Midway));
    m_closeWhen->addItem(tr("after the answer"), int(FaultRule::CloseWhen::After));
    m_closeWhen->setCurrentIndex(2);
    m_form->addRow(tr("Close:"), m_closeWhen);
    m_bitErrorRate = new QDoubleSpinBox(formBox);
    m_bitErrorRate->setObjectName(QStringLiteral("faultBitErrorRate"));
    m_bitErrorRate->setRange(0, 0.5);
    m_bitErrorRate->setDecimals(6);
    m_bitErrorRate->setSingleStep(0.0001);
    m_bitErrorRate->setValue(0.0001);
    m_bitErrorRate->setToolTip(tr("Each bit of a request or answer flips with this probability: a request hit is lost, "
                                  "an answer hit fails its CRC or LRC."));
    m_form->addRow(tr("Bit error rate:"), m_bitErrorRate);

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
    m_form->setRowVisible(m_meanMs, delay && (distribution == DelaySpec::Kind::Normal || distribution == DelaySpec::Kind::Exponential
                                              || distribution == DelaySpec::Kind::LogNormal));
    m_form->setRowVisible(m_stddevMs, delay && (distribution == DelaySpec::Kind::Normal || distribution == DelaySpec::Kind::LogNormal));
    m_form->setRowVisible(m_minMs, delay && distribution != DelaySpec::Kind::Fixed);
    m_form->setRowVisible(m_maxMs, delay && distribution != DelaySpec::Kind::Fixed);
    m_form->setRowVisible(m_exceptionCode, kind == FaultRule::Kind::Exception);
    m_form->setRowVisible(m_delta, kind == FaultRule::Kind::WrongTransactionId || kind == FaultRule::Kind::WrongUnit);
    m_form->setRowVisible(m_fewer, kind == FaultRule::Kind::FewerRegisters);
    m_form->setRowVisible(m_chunkBytes, kind == FaultRule::Kind::Chunks);
    m_form->setRowVisible(m_gapMs, kind == FaultRule::Kind::Chunks || kind == FaultRule::Kind::Trickle
                                       || kind == FaultRule::Kind::Duplicate);
    m_form->setRowVisible(m_junkBefore, kind == FaultRule::Kind::Junk);
    m_form->setRowVisible(m_junkAfter, kind == FaultRule::Kind::Junk);
    m_form->setRowVisible(m_copies, kind == FaultRule::Kind::Duplicate);
    m_form->setRowVisible(m_bitErrorRate, kind == FaultRule::Kind::Noise);
    m_form->setRowVisible(m_closeWhen, kind == FaultRule::Kind::Close);
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
    if (m_firstAddress->value() >= 0 || m_lastAddress->value() >= 0) {
        rule.firstAddress = m_firstAddress->value() >= 0 ? m_firstAddress->value() : 0;
        rule.lastAddress = m_lastAddress->value() >= 0 ? m_lastAddress->value() : 65535;
    }
    switch (rule.kind) {
    case FaultRule::Kind::WrongTransactionId:
    case FaultRule::Kind::WrongUnit: rule.delta = m_delta->value(); break;
    case FaultRule::Kind::FewerRegisters: rule.fewer = m_fewer->value(); break;
    case FaultRule::Kind::Chunks:
        rule.chunkBytes = m_chunkBytes->value();
        rule.gapMs = m_gapMs->value();
        break;
    case FaultRule::Kind::Trickle: rule.gapMs = m_gapMs->value(); break;
    case FaultRule::Kind::Junk:
        rule.junkBeforeCount = m_junkBefore->value();
        rule.junkAfterCount = m_junkAfter->value();
        break;
    case FaultRule::Kind::Duplicate:
        rule.copies = m_copies->value();
        rule.gapMs = m_gapMs->value();
        break;
    case FaultRule::Kind::Close: rule.closeWhen = FaultRule::CloseWhen(m_closeWhen->currentData().toInt()); break;
    case FaultRule::Kind::Noise: rule.bitErrorRate = m_bitErrorRate->value(); break;
    default: break;
    }
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
    if (rule.hasAddressRange() && rule.lastAddress < rule.firstAddress) {
        m_message->setText(tr("Not added: the address range ends (%1) before it starts (%2).")
                               .arg(rule.lastAddress)
                               .arg(rule.firstAddress));
        return;
    }
    if (rule.kind == FaultRule::Kind::Junk && rule.junkBeforeCount == 0 && rule.junkAfterCount == 0) {
        m_message->setText(tr("Not added: junk needs random bytes before or after the answer."));
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
    const QString path = QFileDialog::getOpenFileName(this, tr("Load fault rules"), LastFolder::start(),
                                                      tr("Fault rules (*.json);;All files (*)"));
    LastFolder::remember(path);
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
        case DelaySpec::Kind::LogNormal:
            what = tr("delay lognormal, mean %1 ms, standard deviation %2 ms").arg(ms(d.meanMs), ms(d.stddevMs));
            break;
        }
        break;
    }
    case FaultRule::Kind::Drop: what = tr("drop the answer"); break;
    case FaultRule::Kind::WrongChecksum: what = tr("wrong CRC or LRC"); break;
    case FaultRule::Kind::Exception: what = tr("exception %1").arg(hexByte(rule.exceptionCode)); break;
    case FaultRule::Kind::WrongTransactionId: what = tr("transaction id + %1").arg(rule.delta); break;
    case FaultRule::Kind::WrongUnit: what = tr("unit id + %1").arg(rule.delta); break;
    case FaultRule::Kind::FewerRegisters: what = tr("%1 fewer registers").arg(rule.fewer); break;
    case FaultRule::Kind::Chunks: what = tr("chunks of %1 bytes, %2 ms apart").arg(rule.chunkBytes).arg(ms(rule.gapMs)); break;
    case FaultRule::Kind::Trickle: what = tr("a byte every %1 ms").arg(ms(rule.gapMs)); break;
    case FaultRule::Kind::Junk: {
        const int before = rule.junkBefore.isEmpty() ? rule.junkBeforeCount : int(rule.junkBefore.size());
        const int after = rule.junkAfter.isEmpty() ? rule.junkAfterCount : int(rule.junkAfter.size());
        what = tr("junk: %1 bytes before, %2 after").arg(before).arg(after);
        break;
    }
    case FaultRule::Kind::Duplicate: what = tr("%1 extra copies, %2 ms apart").arg(rule.copies).arg(ms(rule.gapMs)); break;
    case FaultRule::Kind::Close:
        switch (rule.closeWhen) {
        case FaultRule::CloseWhen::Before: what = tr("close before the answer"); break;
        case FaultRule::CloseWhen::Midway: what = tr("close midway through the answer"); break;
        case FaultRule::CloseWhen::After: what = tr("close after the answer"); break;
        }
        break;
    case FaultRule::Kind::Noise:
        switch (rule.noiseOn) {
        case FaultRule::NoiseOn::Both: what = tr("line noise, bit error rate %1").arg(rule.bitErrorRate); break;
        case FaultRule::NoiseOn::Request: what = tr("line noise on requests, bit error rate %1").arg(rule.bitErrorRate); break;
        case FaultRule::NoiseOn::Answer: what = tr("line noise on answers, bit error rate %1").arg(rule.bitErrorRate); break;
        }
        break;
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
    const auto numbers = [](const QList<int> &list) {
        QStringList out;
        for (int n : list)
            out << QString::number(n);
        return out.join(QStringLiteral(", "));
    };
    if (!rule.starts.isEmpty())
        text = tr("%1, starting at %2").arg(text, numbers(rule.starts));
    if (!rule.quantities.isEmpty())
        text = tr("%1, quantity %2").arg(text, numbers(rule.quantities));
    if (rule.hasValues) {
        QList<int> values;
        for (quint16 v : rule.values)
            values << v;
        text = tr("%1, writing %2").arg(text, numbers(values));
    }
    if (rule.hasTurnaround) {
        text = tr("%1 (when the interval is under a turnaround of %2 ms on average)").arg(text, ms(rule.turnaround.meanMs > 0 ? rule.turnaround.meanMs : rule.turnaround.ms));
    } else if (!rule.byIntervalMs.isEmpty()) {
        QStringList points;
        for (const auto &[intervalMs, chance] : rule.byIntervalMs)
            points << QStringLiteral("%1 ms: %2").arg(ms(intervalMs)).arg(chance);
        text = tr("%1 (probability by interval, %2)").arg(text, points.join(QStringLiteral(", ")));
    } else if (rule.probability < 1) {
        text = tr("%1 (probability %2)").arg(text).arg(rule.probability);
    }
    if (!rule.name.isEmpty())
        text = tr("%1: %2").arg(rule.name, text);
    return text;
}

} // namespace mbscope
