#pragma once

#include "inference/blocksamples.h"
#include "inference/readingalternatives.h"
#include "inference/valueguess.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>

namespace mbscope {

// The window's Infer draft, a row per guessed value, to confirm or correct row by row: whether it
// is confirmed, its address, a name and unit to type, its kind and how sure the type is, then its
// readings side by side (ReadingAlternatives: the guess first, then u32 ABCD / CDAB, f32 ABCD /
// CDAB, i16 x0.1 ...), each showing the value the last read gives under it. Checking a reading
// chooses it and confirms the row. confirmedGuesses() gives the guesses as the person left them.
class InferDraftModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { ConfirmedColumn, AddressColumn, NameColumn, UnitColumn, KindColumn, ConfidenceColumn, FirstReadingColumn };
    static constexpr int kColumns = FirstReadingColumn + ReadingAlternatives::kMost;

    explicit InferDraftModel(QObject *parent = nullptr);

    void setGuesses(const QList<ValueGuess> &guesses);
    // The last sample of each block read again: every row's words, and so every reading's value.
    void updateLive(const QList<BlockSamples> &blocks);
    [[nodiscard]] QList<ValueGuess> confirmedGuesses() const;
    [[nodiscard]] int confirmedCount() const;
    // The reading a row has chosen (0: the guess).
    [[nodiscard]] int chosenReading(int row) const { return m_rows.value(row).chosen; }
    [[nodiscard]] QList<Reading> readings(int row) const { return m_rows.value(row).readings; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

Q_SIGNALS:
    void confirmedChanged(int confirmed);

private:
    struct Row {
        ValueGuess guess;
        QList<Reading> readings;
        int chosen = 0;
        bool confirmed = false;
        QString name;
        QString unit;
        QList<quint16> words; // the last read, wire order
    };
    [[nodiscard]] QString readingText(const Row &row, int reading) const;

    QList<Row> m_rows;
};

} // namespace mbscope
