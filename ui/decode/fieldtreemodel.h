#pragma once

#include "protocol/dissection.h"

#include <QtCore/QAbstractItemModel>
#include <QtGui/QIcon>

#include <array>
#include <vector>

namespace mbscope {

// A thin read-only adapter that shows a Dissection's FieldTree as a tree. The tree stays the
// single source of truth: the model keeps only the parent/child structure (computed once per
// dissection) and formats every text in data(), so a 125-register response costs nothing until
// its rows are painted. Severity is data on the field; this model only maps it to colours and
// icons through roles, as Wireshark's expert info does.
class FieldTreeModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    enum Column { OffsetColumn, BytesColumn, FieldColumn, ValueColumn, ProblemColumn, ColumnCount };
    Q_ENUM(Column)

    enum Role {
        KeyRole = Qt::UserRole + 1, // QString: the field's stable key, "modbus.function_code"
        SeverityRole,               // int: the field's mbscope::Severity
        FieldIndexRole,             // int: the field's index in the FieldTree
        OffsetRole,                 // int: byte offset in the frame
        LengthRole,                 // int: bytes covered (0 for a field about missing bytes)
    };
    Q_ENUM(Role)

    explicit FieldTreeModel(QObject *parent = nullptr);

    void setDissection(const Dissection &dissection);
    void clear();
    [[nodiscard]] const Dissection &dissection() const { return m_dissection; }

    // The model index of a field of the tree (column 0), or an invalid index.
    [[nodiscard]] QModelIndex indexOfField(int fieldIndex, int column = 0) const;
    // The first field with this key, or an invalid index.
    [[nodiscard]] QModelIndex indexOfKey(const char *key, int column = 0) const;

    [[nodiscard]] QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    [[nodiscard]] QModelIndex parent(const QModelIndex &child) const override;
    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex &index) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

    // Raw bytes longer than this are elided in the Bytes column; the tooltip shows them whole.
    static constexpr int kMaxBytesShown = 8;

private:
    [[nodiscard]] QVariant displayText(int field, int column) const;
    [[nodiscard]] QVariant toolTip(int field, int column) const;
    [[nodiscard]] QIcon severityIcon(Severity severity) const;
    void rebuildStructure();

    Dissection m_dissection;
    std::vector<std::vector<int>> m_children; // [0]: top-level fields, [i + 1]: children of field i
    std::vector<int> m_rowInParent;           // row of field i among its siblings
    mutable std::array<QIcon, 4> m_icons;     // by Severity, made on first use (needs a GUI app)
};

} // namespace mbscope
