#include "addressfield.h"

#include "common/severitystyle.h"

#include <QtWidgets/QComboBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>

namespace mbscope {

namespace {

constexpr int kMaxAddress = 65535;

} // namespace

AddressField::AddressField(QWidget *parent)
    : QWidget(parent)
    , m_edit(new QLineEdit(QStringLiteral("0"), this))
    , m_notationCombo(new QComboBox(this))
    , m_baseLabel(new QLabel(this))
{
    m_edit->setObjectName(QStringLiteral("addressEdit"));
    m_notationCombo->setObjectName(QStringLiteral("notationCombo"));
    m_notationCombo->addItem(tr("Decimal (0-based)"), int(Notation::Decimal));
    m_notationCombo->addItem(tr("Hex (0-based)"), int(Notation::Hex));
    m_notationCombo->addItem(tr("Modicon (1-based)"), int(Notation::Modicon));
    m_baseLabel->setObjectName(QStringLiteral("addressBaseLabel"));
    m_baseLabel->setWordWrap(true);
    QFont small = m_baseLabel->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    m_baseLabel->setFont(small);

    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setVerticalSpacing(1);
    layout->addWidget(m_edit, 0, 0);
    layout->addWidget(m_notationCombo, 0, 1);
    layout->addWidget(m_baseLabel, 1, 0, 1, 2);
    layout->setColumnStretch(0, 1);

    connect(m_edit, &QLineEdit::textChanged, this, [this] {
        updateBase();
        Q_EMIT changed();
    });
    connect(m_notationCombo, &QComboBox::currentIndexChanged, this, &AddressField::onNotationChanged);
    updateBase();
}

void AddressField::setTable(std::optional<ModbusTable> table)
{
    const std::optional<int> before = address();
    m_table = table;
    // Without a table there is no Modicon reference: fall back to decimal, keeping the address.
    if (!table && notation() == Notation::Modicon)
        setNotation(Notation::Decimal);
    else if (before && m_shown == Notation::Modicon)
        m_edit->setText(format(*before)); // the table digit changes with the table
    updateBase();
}

void AddressField::setNotation(Notation notation)
{
    m_notationCombo->setCurrentIndex(m_notationCombo->findData(int(notation)));
}

AddressField::Notation AddressField::notation() const
{
    return Notation(m_notationCombo->currentData().toInt());
}

void AddressField::onNotationChanged()
{
    // Parse in the old notation, write in the new one: the address stays, only its spelling changes.
    const std::optional<int> value = address();
    m_shown = notation();
    if (value)
        m_edit->setText(format(*value));
    updateBase();
    Q_EMIT changed();
}

std::optional<int> AddressField::address() const
{
    return parse(nullptr);
}

QString AddressField::error() const
{
    QString why;
    if (parse(&why))
        return {};
    return why;
}

void AddressField::setAddress(int address)
{
    m_edit->setText(format(address));
}

void AddressField::setText(const QString &text)
{
    m_edit->setText(text);
}

QString AddressField::text() const
{
    return m_edit->text();
}

QString AddressField::baseText() const
{
    return m_baseLabel->text();
}

QString AddressField::format(int address) const
{
    switch (m_shown) {
    case Notation::Decimal: return QString::number(address);
    case Notation::Hex: return QStringLiteral("0x") + QStringLiteral("%1").arg(address, 4, 16, QLatin1Char('0')).toUpper();
    case Notation::Modicon:
        if (!m_table)
            return QString::number(address);
        {
            const ModiconReference ref(*m_table, quint16(address));
            return ref.hasFiveDigitForm() ? ref.fiveDigit() : ref.sixDigit();
        }
    }
    return QString::number(address);
}

std::optional<int> AddressField::parse(QString *error) const
{
    const QString text = m_edit->text().trimmed();
    auto fail = [error](const QString &why) -> std::optional<int> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (text.isEmpty())
        return fail(tr("type an address"));
    bool ok = false;
    switch (m_shown) {
    case Notation::Decimal: {
        const qlonglong value = text.toLongLong(&ok, 10);
        if (!ok)
            return fail(tr("'%1' is not a decimal number (switch the notation to Hex for 0x... addresses)").arg(text));
        if (value < 0 || value > kMaxAddress)
            return fail(tr("address %1 is out of range: PDU addresses are 0-65535").arg(value));
        return int(value);
    }
    case Notation::Hex: {
        QString digits = text;
        if (digits.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
            digits = digits.mid(2);
        const qlonglong value = digits.toLongLong(&ok, 16);
        if (!ok || digits.isEmpty())
            return fail(tr("'%1' is not a hex number (0x0079 or 79)").arg(text));
        if (value > kMaxAddress)
            return fail(tr("address 0x%1 is out of range: PDU addresses are 0x0000-0xFFFF").arg(value, 0, 16));
        return int(value);
    }
    case Notation::Modicon: {
        const ModiconReferenceResult ref = ModiconReference::parse(text);
        if (!ref.ok)
            return fail(ref.error);
        if (m_table && ref.reference.table() != *m_table)
            return fail(tr("%1 is a reference to %2, but this function addresses %3 (%4xxxx)")
                            .arg(text, QLatin1String(ModiconReference::tableName(ref.reference.table())),
                                 QLatin1String(ModiconReference::tableName(*m_table)))
                            .arg(ModiconReference::tableDigit(*m_table)));
        return int(ref.reference.address());
    }
    }
    return std::nullopt;
}

QString AddressField::referenceHint() const
{
    // The mistake the guide describes: a manual's 40122 typed as a PDU address (the device then
    // answers exception 02, or the address is out of range).
    if (m_shown != Notation::Decimal || !m_table)
        return {};
    bool ok = false;
    const qlonglong value = m_edit->text().trimmed().toLongLong(&ok, 10);
    if (!ok || ModiconReference::addressHint(value).isEmpty())
        return {};
    const ModiconReferenceResult ref = ModiconReference::parse(m_edit->text().trimmed());
    return tr("%1 looks like a Modicon reference; its PDU address is %2 (0x%3): choose Modicon (1-based) to type it as one")
        .arg(value)
        .arg(ref.reference.address())
        .arg(ref.reference.address(), 4, 16, QLatin1Char('0'));
}

void AddressField::updateBase()
{
    QString why;
    const std::optional<int> value = parse(&why);
    const QString hint = referenceHint();
    QPalette p = m_baseLabel->palette();
    if (!value) {
        m_baseLabel->setText(hint.isEmpty() ? why : why + QLatin1Char('\n') + hint);
        p.setColor(QPalette::WindowText, SeverityStyle::textColor(Severity::Error));
        m_baseLabel->setPalette(p);
        return;
    }
    p.setColor(QPalette::WindowText, hint.isEmpty() ? palette().color(QPalette::PlaceholderText)
                                                    : SeverityStyle::textColor(Severity::Warning));
    m_baseLabel->setPalette(p);
    QString base;
    if (m_table)
        base = ModiconReference(*m_table, quint16(*value)).describe();
    else
        base = tr("PDU address %1 (0x%2), 0-based").arg(*value).arg(*value, 4, 16, QLatin1Char('0'));
    m_baseLabel->setText(hint.isEmpty() ? base : base + QLatin1Char('\n') + hint);
}

} // namespace mbscope
