#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "protocol/readanswer.h"
#include "protocol/registerformat.h"
#include "protocol/tablewrite.h"
#include "profile/deviceprofile.h"
#include "profile/readanswerrows.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QTimer>


namespace mbscope {

// The values of one table (coils, discrete inputs, input or holding registers) as the latest
// read answer gave them: one row per PDU address, a thin adapter over the core's ReadAnswerRows,
// which decodes; this model words it, marks changes and turns edits into writes. Columns:
//   Address | Modicon reference | Name (from a profile) | one column per value format | Scaled
// Each value column has its own RegisterFormat (u16, i16, hex, bin, ascii, 32/64-bit integers and
// floats in the four orders). A value wider than one register stands on the row of its first
// register with SpanRole saying how many rows it covers; the rows it covers say which value they
// belong to. Where the profile has a multi-register value the column's values start at its
// address (WideValueLayout), elsewhere from the first register of the answer. Bit tables have one
// value column.
//
// Values that changed since the previous answer are marked (ChangedRole, a background colour)
// until the next answer or until the highlight duration has passed.
//
// Editing a value in a writable table (coils, holding registers) never changes the model: it
// builds the write request (RegisterWrite) with the function the user chose (setWriteChoice) and emits
// writeRequested; the next answer shows what the device made of it. Bad input is refused with
// editRefused saying what and where.
class RegisterTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Role {
        AddressRole = Qt::UserRole + 1, // int: the row's PDU address
        ChangedRole,                    // bool: the value changed with the latest answer
        SpanRole,                       // int: rows the value of this cell covers; 0 on the rows
                                        // after its first (for a view's setSpan)
        RawRole,                        // int: the row's register (0-65535) or bit (0/1)
        FormatRole,                     // QString: the column's format name ("f32-cdab")
    };
    Q_ENUM(Role)

    // Fixed columns; value columns follow, then the scaled column.
    enum Column { AddressColumn, ReferenceColumn, NameColumn, FirstValueColumn };
    Q_ENUM(Column)

    explicit RegisterTableModel(QObject *parent = nullptr);

    // Updates from a read (01, 02, 03, 04 or 17): the request gives the table and the start
    // address, the response the values. A refused answer (an exception, a byte count that does
    // not fit) leaves the values as they were and is reported through answerRefused and
    // lastProblem(). A new table or address range resets the rows; the same range updates them.
    bool update(const QByteArray &requestPdu, const QByteArray &responsePdu);
    // The same from an engine transaction whose bytes are ADUs in framing.
    bool updateFromTransaction(const Transaction &transaction, Framing framing);
    void setAnswer(const ReadAnswer &answer);
    void clear();
    [[nodiscard]] bool hasAnswer() const { return m_hasAnswer; }
    [[nodiscard]] const ReadAnswer &answer() const { return m_rows.answer(); }
    [[nodiscard]] QString lastProblem() const { return m_lastProblem; }

    // Value columns, one format each (bit tables ignore them and show one value column).
    void setValueFormats(const QList<RegisterFormat> &formats);
    [[nodiscard]] QList<RegisterFormat> valueFormats() const { return m_formats; }
    void setValueFormat(int valueIndex, RegisterFormat format);
    void addValueColumn(RegisterFormat format);
    void removeValueColumn(int valueIndex);
    // Sets the order of every multi-register value column (16-bit ones take the byte order of
    // BADC/DCBA as BA): the toolbar's word order.
    void setOrder(RegisterOrder order);
    [[nodiscard]] int valueColumnCount() const;
    [[nodiscard]] int scaledColumn() const { return FirstValueColumn + valueColumnCount(); }
    // The value index of a column, or -1 for the other columns.
    [[nodiscard]] int valueIndexOf(int column) const;
    [[nodiscard]] RegisterFormat formatOfColumn(int column) const;

    // Names, formats, scaling and units of the unit's entries for this table.
    void setProfile(const UnitProfile &unit, const QString &profileName);
    void clearProfile();
    [[nodiscard]] QString profileName() const { return m_profileName; }
    [[nodiscard]] bool hasProfile() const { return m_rows.profile().has_value(); }

    void setWriteChoice(WriteChoice choice) { m_writeChoice = choice; }
    [[nodiscard]] WriteChoice writeChoice() const { return m_writeChoice; }
    // The write request an edit of this cell would produce from text, without emitting it.
    [[nodiscard]] TableWriteResult writeFor(const QModelIndex &index, const QString &text) const;

    // How long a change stays marked when no new answer comes; 0 keeps it until the next answer.
    void setHighlightDuration(int ms);
    [[nodiscard]] int highlightDuration() const { return m_highlightMs; }
    void clearHighlights();

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

Q_SIGNALS:
    // A write request PDU (function code first) for the window to complete and send.
    void writeRequested(const QByteArray &pdu, const QString &description);
    // An edit that was refused: "register 40122 (PDU address 121), u16: '70000' is out of range
    // for u16 (0 to 65535)".
    void editRefused(const QString &message);
    void answerRefused(const QString &message);
    // Formats, profile or table changed: views re-apply spans and header menus.
    void layoutOfValuesChanged();

private:
    [[nodiscard]] RowValue valueAt(int row, int valueIndex) const;
    [[nodiscard]] QString valueText(int row, const RowValue &value) const;
    [[nodiscard]] QString valueToolTip(int row, const RowValue &value) const;
    [[nodiscard]] QString nameText(int row) const;
    [[nodiscard]] QString scaledText(int row) const;
    [[nodiscard]] bool isChanged(int row, int column) const;
    [[nodiscard]] QVariant toolTip(int row, int column) const;
    [[nodiscard]] bool isEditableCell(int row, int column) const;
    void refuse(const QString &message);
    void valueColumnsChanged();

    ReadAnswerRows m_rows; // the answer and the profile
    bool m_hasAnswer = false;
    QList<bool> m_changed;           // per row, from the latest answer
    QList<RegisterFormat> m_formats; // value columns
    QString m_profileName;
    WriteChoice m_writeChoice = WriteChoice::Automatic;
    QString m_lastProblem;
    int m_highlightMs = 3000;
    QTimer m_highlightTimer;
};

} // namespace mbscope
