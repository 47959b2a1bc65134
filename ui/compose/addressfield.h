#pragma once

#include "protocol/modiconreference.h"

#include <QtWidgets/QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace mbscope {

// A data address typed the way the user's documentation writes it: decimal or hex PDU addresses
// (0-based, what goes on the wire) or a Modicon reference (40122: 1-based, table digit first). The
// base is always shown below in words ("PDU address 121 (0x0079), register number 122, Modicon
// 40122 / 400122"), so a 1-based number from a manual is not sent one register off.
class AddressField : public QWidget
{
    Q_OBJECT
public:
    enum class Notation : quint8 {
        Decimal,
        Hex,
        Modicon,
    };
    Q_ENUM(Notation)

    explicit AddressField(QWidget *parent = nullptr);

    // The table the function code addresses (Modicon references need one); none for FIFO pointers.
    void setTable(std::optional<ModbusTable> table);
    void setNotation(Notation notation);
    [[nodiscard]] Notation notation() const;
    // The 0-based PDU address, or nullopt with error() saying what is wrong.
    [[nodiscard]] std::optional<int> address() const;
    [[nodiscard]] QString error() const;
    void setAddress(int address);
    void setText(const QString &text);
    [[nodiscard]] QString text() const;
    [[nodiscard]] QString baseText() const;
    [[nodiscard]] QLineEdit *lineEdit() const { return m_edit; }

Q_SIGNALS:
    void changed();

private:
    [[nodiscard]] std::optional<int> parse(QString *error) const;
    [[nodiscard]] QString format(int address) const;
    void onNotationChanged();
    void updateBase();
    // Decimal text of 10001 or more that reads as a Modicon reference: what it would be as one.
    [[nodiscard]] QString referenceHint() const;

    QLineEdit *m_edit = nullptr;
    QComboBox *m_notationCombo = nullptr;
    QLabel *m_baseLabel = nullptr;
    std::optional<ModbusTable> m_table = ModbusTable::HoldingRegisters;
    Notation m_shown = Notation::Decimal; // the notation the text is written in
};

} // namespace mbscope
