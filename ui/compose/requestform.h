#pragma once

#include "protocol/buildresult.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtWidgets/QWidget>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;

namespace mbscope {

class AddressField;

// The composer's Form tab: a function code, then only the fields that code has, with the
// specification's limits (V1.1b3, 6): addresses in decimal, hex or Modicon notation (AddressField),
// quantities bounded per code, a value table for multiple writes (checkboxes for coils). It builds
// the PDU with RequestBuilder, so a value out of range is named with its limit instead of wrapped,
// and completes it for the link's framing and unit: the same bytes the Raw tab would send.
class RequestForm : public QWidget
{
    Q_OBJECT
public:
    explicit RequestForm(QWidget *parent = nullptr);

    // Function codes the form has fields for, in the order of the list.
    [[nodiscard]] static QList<int> functionCodes();

    void setFunctionCode(int code);
    [[nodiscard]] int functionCode() const;
    void setFraming(Framing framing);
    void setUnitId(int unit);

    // The PDU the fields describe (errors when a field is out of range or unreadable).
    [[nodiscard]] BuildResult build() const;
    // The PDU completed for the framing and unit; empty when build() has errors.
    [[nodiscard]] QByteArray bytes() const;
    [[nodiscard]] QString errorText() const;
    // "Bytes: 01 03 00 79 00 16 15 DD (RTU, unit 1)" under the fields; empty with errors.
    [[nodiscard]] QString previewText() const;

    // Fills the fields from a request PDU (function code first). False when the form has no
    // fields for that code or the PDU is not a well-formed request of it (the fields keep theirs).
    bool setFromPdu(const QByteArray &pdu);

    // Fields, for tests and keyboard users.
    [[nodiscard]] AddressField *addressField() const { return m_address; }
    [[nodiscard]] AddressField *writeAddressField() const { return m_writeAddress; }
    [[nodiscard]] QSpinBox *quantitySpin() const { return m_quantity; }
    [[nodiscard]] QSpinBox *writeQuantitySpin() const { return m_writeQuantity; }
    [[nodiscard]] QCheckBox *coilCheck() const { return m_coil; }
    [[nodiscard]] QLineEdit *valueEdit() const { return m_value; }
    [[nodiscard]] QLineEdit *andMaskEdit() const { return m_andMask; }
    [[nodiscard]] QLineEdit *orMaskEdit() const { return m_orMask; }
    [[nodiscard]] QTableWidget *valueTable() const { return m_values; }
    [[nodiscard]] QComboBox *deviceIdCodeCombo() const { return m_deviceIdCode; }
    [[nodiscard]] QSpinBox *objectIdSpin() const { return m_objectId; }
    // Sets the value table's rows (the write quantity follows).
    void setRegisterValues(const QList<quint16> &values);
    void setCoilValues(const QList<bool> &values);
    [[nodiscard]] bool isFieldVisible(QWidget *field) const;

Q_SIGNALS:
    // Any field changed (the composer rewrites the Raw tab from bytes() when it is valid).
    void changed();

private:
    void buildUi();
    void onFunctionChanged();
    void onChanged();
    void resizeValueTable();
    void updateTableAddresses();
    [[nodiscard]] bool isCoilTable() const;
    [[nodiscard]] int writeCount() const;
    // Why a quantity typed is refused (empty when within 1-max): label as the message names it.
    [[nodiscard]] QString quantityError(const QString &label, int quantity, int max, const char *unit) const;
    [[nodiscard]] QList<quint16> registerValues(QStringList *errors) const;
    [[nodiscard]] QList<bool> coilValues() const;

    QComboBox *m_function = nullptr;
    QFormLayout *m_form = nullptr;
    AddressField *m_address = nullptr;
    QSpinBox *m_quantity = nullptr;
    QLabel *m_quantityLimit = nullptr;
    QCheckBox *m_coil = nullptr;
    QLineEdit *m_value = nullptr; // 06's value: typed as the value table's cells are
    QLineEdit *m_andMask = nullptr;
    QLineEdit *m_orMask = nullptr;
    AddressField *m_writeAddress = nullptr;
    QSpinBox *m_writeQuantity = nullptr;
    QTableWidget *m_values = nullptr;
    QComboBox *m_deviceIdCode = nullptr;
    QSpinBox *m_objectId = nullptr;
    QLabel *m_errorLabel = nullptr;
    QLabel *m_previewLabel = nullptr; // the bytes the fields make, as the Raw tab will hold them
    QWidget *m_quantityRow = nullptr;
    Framing m_framing = Framing::Rtu;
    quint8 m_unit = 1;
    bool m_filling = false;
};

} // namespace mbscope
