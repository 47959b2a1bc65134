#include "inferdraftmodel.h"

#include "profile/valuekind.h"

#include <QtGui/QFont>

#include <algorithm>

namespace mbscope {

InferDraftModel::InferDraftModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void InferDraftModel::setGuesses(const QList<ValueGuess> &guesses)
{
    beginResetModel();
    m_rows.clear();
    for (const ValueGuess &g : guesses) {
        Row r;
        r.guess = g;
        r.readings = ReadingAlternatives::of(g);
        r.unit = g.unit;
        r.words = g.lastWords;
        m_rows.append(r);
    }
    endResetModel();
    Q_EMIT confirmedChanged(0);
}

void InferDraftModel::updateLive(const QList<BlockSamples> &blocks)
{
    for (qsizetype i = 0; i < m_rows.size(); ++i) {
        Row &r = m_rows[i];
        for (const BlockSamples &b : blocks) {
            if (b.function != r.guess.function || b.samples.isEmpty() || r.guess.address < b.address
                || r.guess.address + r.guess.registers > b.address + b.registerCount)
                continue;
            r.words = b.samples.constLast().mid(r.guess.address - b.address, r.guess.registers);
        }
    }
    if (!m_rows.isEmpty())
        Q_EMIT dataChanged(index(0, FirstReadingColumn), index(int(m_rows.size()) - 1, kColumns - 1));
}

QList<ValueGuess> InferDraftModel::confirmedGuesses() const
{
    QList<ValueGuess> out;
    for (const Row &r : m_rows) {
        ValueGuess g = r.guess;
        const Reading &chosen = r.readings.at(r.chosen);
        if (r.chosen != 0) {
            g.format = chosen.format;
            g.scale = chosen.scale;
            g.scaleRegister = -1;
        }
        g.lastWords = r.words;
        g.name = r.name.trimmed();
        g.unit = r.unit.trimmed();
        g.confirmed = r.confirmed;
        out.append(g);
    }
    return out;
}

int InferDraftModel::confirmedCount() const
{
    return int(std::count_if(m_rows.cbegin(), m_rows.cend(), [](const Row &r) { return r.confirmed; }));
}

int InferDraftModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int InferDraftModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : kColumns;
}

QString InferDraftModel::readingText(const Row &row, int reading) const
{
    if (row.guess.bit)
        return row.words.value(0) ? QStringLiteral("1") : QStringLiteral("0");
    if (row.guess.text)
        return QLatin1Char('"') + row.guess.lastText + QLatin1Char('"');
    return row.readings.at(reading).valueText(row.words);
}

QVariant InferDraftModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &r = m_rows.at(index.row());
    const int column = index.column();
    const int reading = column - FirstReadingColumn;
    if (column >= FirstReadingColumn) {
        if (reading >= r.readings.size())
            return {};
        switch (role) {
        case Qt::DisplayRole:
            // The reading's name, and the value it gives under it.
            return QStringLiteral("%1\n%2").arg(r.guess.text ? r.guess.typeName() : r.readings.at(reading).label(),
                                                readingText(r, reading));
        case Qt::CheckStateRole:
            return r.chosen == reading ? Qt::Checked : Qt::Unchecked;
        case Qt::FontRole:
            if (r.chosen == reading) {
                QFont bold;
                bold.setBold(true);
                return bold;
            }
            return {};
        case Qt::ToolTipRole:
            return reading == 0 ? tr("The guess: %1").arg(r.guess.evidence)
                                : tr("Check to read the value as %1 instead").arg(r.readings.at(reading).label());
        default:
            return {};
        }
    }
    if (role == Qt::CheckStateRole && column == ConfirmedColumn)
        return r.confirmed ? Qt::Checked : Qt::Unchecked;
    if (role == Qt::ToolTipRole) {
        QString tip = r.guess.evidence;
        if (!r.guess.scaleEvidence.isEmpty())
            tip += QLatin1Char('\n') + tr("Scale (%1 %): %2").arg(qRound(r.guess.scaleConfidence * 100)).arg(r.guess.scaleEvidence);
        return tip;
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole)
        return {};
    switch (column) {
    case ConfirmedColumn: return {};
    case AddressColumn:
        return r.guess.registers > 1 ? QStringLiteral("%1-%2").arg(r.guess.address).arg(r.guess.address + r.guess.registers - 1)
                                     : QString::number(r.guess.address);
    case NameColumn: return r.name;
    case UnitColumn: return r.unit;
    case KindColumn: return valueKindName(r.guess.kind);
    case ConfidenceColumn: return QStringLiteral("%1 %").arg(qRound(r.guess.confidence * 100));
    default: return {};
    }
}

bool InferDraftModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return false;
    Row &r = m_rows[index.row()];
    const int column = index.column();
    const int before = confirmedCount();
    if (role == Qt::CheckStateRole && column >= FirstReadingColumn) {
        const int reading = column - FirstReadingColumn;
        if (reading >= r.readings.size() || Qt::CheckState(value.toInt()) != Qt::Checked)
            return false; // a reading is unchosen by choosing another
        r.chosen = reading;
        r.confirmed = true;
        Q_EMIT dataChanged(this->index(index.row(), 0), this->index(index.row(), kColumns - 1));
    } else if (role == Qt::CheckStateRole && column == ConfirmedColumn) {
        r.confirmed = Qt::CheckState(value.toInt()) == Qt::Checked;
        Q_EMIT dataChanged(index, index);
    } else if (role == Qt::EditRole && (column == NameColumn || column == UnitColumn)) {
        (column == NameColumn ? r.name : r.unit) = value.toString();
        Q_EMIT dataChanged(index, index);
    } else {
        return false;
    }
    if (confirmedCount() != before)
        Q_EMIT confirmedChanged(confirmedCount());
    return true;
}

Qt::ItemFlags InferDraftModel::flags(const QModelIndex &index) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const int column = index.column();
    if (column == ConfirmedColumn)
        f |= Qt::ItemIsUserCheckable;
    else if (column == NameColumn || column == UnitColumn)
        f |= Qt::ItemIsEditable;
    else if (column >= FirstReadingColumn && column - FirstReadingColumn < m_rows.at(index.row()).readings.size())
        f |= Qt::ItemIsUserCheckable;
    return f;
}

QVariant InferDraftModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case ConfirmedColumn: return tr("OK");
    case AddressColumn: return tr("Address");
    case NameColumn: return tr("Name");
    case UnitColumn: return tr("Unit");
    case KindColumn: return tr("Kind");
    case ConfidenceColumn: return tr("Sure");
    case FirstReadingColumn: return tr("Guess");
    default: return tr("Reading %1").arg(section - FirstReadingColumn + 1);
    }
}

} // namespace mbscope
