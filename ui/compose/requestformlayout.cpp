// RequestForm's fields and their layout (the rest of the class is requestform.cpp).
#include "requestform.h"

#include "addressfield.h"
#include "common/coretext.h"
#include "common/severitystyle.h"

#include "protocol/functioncode.h"

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

// A spin box refuses a keystroke that would take it past its maximum: with the specification's
// limit as maximum, 126 typed became 12 without a word. The quantity fields take any number
// typed; build() refuses the ones the specification forbids and says why.
constexpr int kTypeableMax = 99999999;

QSpinBox *quantitySpinBox(const QString &name, QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setObjectName(name);
    spin->setRange(0, kTypeableMax);
    spin->setValue(1);
    spin->setAccelerated(true);
    return spin;
}

} // namespace

void RequestForm::buildUi()
{
    m_function = new QComboBox(this);
    m_function->setObjectName(QStringLiteral("functionCombo"));
    for (int code : functionCodes()) {
        const QString name = code == 0x2B ? tr("Read Device Identification") : fieldText(functionName(quint8(code)));
        // Hex and decimal both: "0x10 (16)" beside "0x16 (22)" cannot be misread.
        const QString hex = QStringLiteral("%1").arg(code, 2, 16, QLatin1Char('0')).toUpper();
        m_function->addItem(QStringLiteral("0x%1 (%2)  %3").arg(hex).arg(code).arg(name), code);
    }

    m_address = new AddressField(this);
    m_address->setObjectName(QStringLiteral("addressField"));
    m_quantity = quantitySpinBox(QStringLiteral("quantitySpin"), this);
    m_quantityLimit = new QLabel(this);
    m_quantityLimit->setForegroundRole(QPalette::PlaceholderText);
    m_quantityRow = new QWidget(this);
    auto *quantityLayout = new QHBoxLayout(m_quantityRow);
    quantityLayout->setContentsMargins(0, 0, 0, 0);
    quantityLayout->addWidget(m_quantity);
    quantityLayout->addWidget(m_quantityLimit, 1);

    m_coil = new QCheckBox(tr("ON (FF 00); unchecked: OFF (00 00)"), this);
    m_coil->setObjectName(QStringLiteral("coilCheck"));
    m_value = new QLineEdit(QStringLiteral("0"), this);
    m_value->setObjectName(QStringLiteral("valueEdit"));
    m_value->setToolTip(tr("Register value: decimal (0-65535 or -32768..-1) or hex (0x1234)"));
    m_andMask = new QLineEdit(QStringLiteral("0xFFFF"), this);
    m_andMask->setObjectName(QStringLiteral("andMaskEdit"));
    m_orMask = new QLineEdit(QStringLiteral("0x0000"), this);
    m_orMask->setObjectName(QStringLiteral("orMaskEdit"));
    m_writeAddress = new AddressField(this);
    m_writeAddress->setObjectName(QStringLiteral("writeAddressField"));
    m_writeQuantity = quantitySpinBox(QStringLiteral("writeQuantitySpin"), this);
    m_writeQuantity->setSuffix(tr(" registers (1-121)"));

    m_values = new QTableWidget(0, 2, this);
    m_values->setObjectName(QStringLiteral("valueTable"));
    m_values->setHorizontalHeaderLabels({tr("Address"), tr("Value")});
    m_values->horizontalHeader()->setStretchLastSection(true);
    m_values->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_values->verticalHeader()->setDefaultSectionSize(m_values->fontMetrics().height() + 6);
    m_values->setMinimumHeight(120);
    m_values->setToolTip(tr("Register values: decimal (0-65535 or -32768..-1) or hex (0x1234); coils: tick for ON"));

    m_deviceIdCode = new QComboBox(this);
    m_deviceIdCode->setObjectName(QStringLiteral("deviceIdCodeCombo"));
    m_deviceIdCode->addItem(tr("01 basic (stream)"), 1);
    m_deviceIdCode->addItem(tr("02 regular (stream)"), 2);
    m_deviceIdCode->addItem(tr("03 extended (stream)"), 3);
    m_deviceIdCode->addItem(tr("04 one object"), 4);
    m_objectId = new QSpinBox(this);
    m_objectId->setObjectName(QStringLiteral("objectIdSpin"));
    m_objectId->setRange(0, 0xFFFF); // refused past 0xFF by build(), not cut at the third digit
    m_objectId->setDisplayIntegerBase(16);
    m_objectId->setPrefix(QStringLiteral("0x"));

    m_errorLabel = new QLabel(this);
    m_errorLabel->setObjectName(QStringLiteral("formErrorLabel"));
    m_errorLabel->setWordWrap(true);
    QPalette errorPalette = m_errorLabel->palette();
    errorPalette.setColor(QPalette::WindowText, SeverityStyle::textColor(Severity::Error));
    m_errorLabel->setPalette(errorPalette);

    m_previewLabel = new QLabel(this);
    m_previewLabel->setObjectName(QStringLiteral("formPreviewLabel"));
    m_previewLabel->setWordWrap(true);
    m_previewLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_form = new QFormLayout;
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_form->addRow(tr("&Function:"), m_function);
    m_form->addRow(tr("&Address:"), m_address);
    m_form->addRow(tr("&Quantity:"), m_quantityRow);
    m_form->addRow(tr("Coil &value:"), m_coil);
    m_form->addRow(tr("&Value:"), m_value);
    m_form->addRow(tr("AND mask:"), m_andMask);
    m_form->addRow(tr("OR mask:"), m_orMask);
    m_form->addRow(tr("&Write address:"), m_writeAddress);
    m_form->addRow(tr("Write q&uantity:"), m_writeQuantity);
    m_form->addRow(tr("Read &code:"), m_deviceIdCode);
    m_form->addRow(tr("&Object id:"), m_objectId);
    m_form->addRow(tr("Values:"), m_values);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(m_form);
    layout->addWidget(m_errorLabel);
    layout->addWidget(m_previewLabel);
    layout->addStretch(1);

    connect(m_function, &QComboBox::currentIndexChanged, this, &RequestForm::onFunctionChanged);
    connect(m_address, &AddressField::changed, this, [this] {
        updateTableAddresses();
        onChanged();
    });
    connect(m_writeAddress, &AddressField::changed, this, [this] {
        updateTableAddresses();
        onChanged();
    });
    connect(m_quantity, &QSpinBox::valueChanged, this, [this] {
        resizeValueTable();
        onChanged();
    });
    connect(m_writeQuantity, &QSpinBox::valueChanged, this, [this] {
        resizeValueTable();
        onChanged();
    });
    connect(m_coil, &QCheckBox::toggled, this, &RequestForm::onChanged);
    connect(m_value, &QLineEdit::textChanged, this, &RequestForm::onChanged);
    connect(m_andMask, &QLineEdit::textChanged, this, &RequestForm::onChanged);
    connect(m_orMask, &QLineEdit::textChanged, this, &RequestForm::onChanged);
    connect(m_deviceIdCode, &QComboBox::currentIndexChanged, this, &RequestForm::onChanged);
    connect(m_objectId, &QSpinBox::valueChanged, this, &RequestForm::onChanged);
    connect(m_values, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (isCoilTable() && item->column() == 1) {
            const QString text = item->checkState() == Qt::Checked ? tr("ON") : tr("OFF");
            if (item->text() != text)
                item->setText(text); // re-enters with the same text
        }
        onChanged();
    });
}

} // namespace mbscope
