#pragma once

#include "common/frameexchange.h"
#include "trafficfilter.h"
#include "trafficstore.h"

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtGui/QFont>

#include <vector>

namespace mbscope {

// Every frame in and out, as a table that stays smooth with millions of rows: frames are kept in
// a TrafficStore (48 bytes a row plus the bytes), appended in one beginInsertRows per batch, and
// cell text is made only in data(). Filtering keeps a vector of the shown rows' indexes (none
// while everything is shown). Pausing holds new rows back from the views, never drops them.
//
// Feeds: appendFrames() takes the traffic log's frames (TrafficLog::copy, a journal read back),
// which carry every frame, unsolicited and garbage ones included; appendTransactions() takes
// TransactionEngine::transactionsFinished's batches and makes the request and answer rows of each
// (a late answer adds only its answer row), and appendLinkFrames() the frames of no transaction
// (TransactionEngine::unmatchedFrames), so the two make every frame. Feed the log's frames or
// the engine's batches, not both, or frames show twice.
class TrafficModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        NumberColumn,
        TimeColumn,
        DirectionColumn,
        LinkColumn,
        UnitColumn,
        FunctionColumn,
        LengthColumn,
        LatencyColumn,
        VerdictColumn,
        BytesColumn,
        ColumnCount
    };
    Q_ENUM(Column)

    enum Role {
        DirectionRole = Qt::UserRole + 1, // int: TrafficDirection
        VerdictRole,                      // int: TrafficVerdict
        TransactionIdRole,                // qulonglong
        LatencyNsRole,                    // qlonglong, -1 none
        TimeNsRole,                       // qlonglong: monotonic ns
        StoreRowRole,                     // qlonglong: the row's index in store()
        BytesRole,                        // QByteArray: the frame
    };
    Q_ENUM(Role)

    // Bytes shown in the Bytes column before "…"; the tooltip has them all.
    static constexpr int kBytesShown = 24;

    explicit TrafficModel(QObject *parent = nullptr);

    // Names the engine's link ids (TrafficLog::links) for frames fed by appendFrames.
    void setLinkName(quint16 link, const QString &url);
    // The link appendTransactions' frames travelled on.
    void setCurrentLink(const QString &url);

    void setFilter(const TrafficFilter &filter);
    [[nodiscard]] const TrafficFilter &filter() const { return m_filter; }

    void setPaused(bool paused);
    [[nodiscard]] bool isPaused() const { return m_paused; }
    // Rows stored but not shown yet because the model is paused.
    [[nodiscard]] qsizetype heldCount() const { return m_store.size() - m_published; }

    // At most this many frames are kept (default 5 million); beyond it the oldest tenth goes.
    void setRowLimit(qsizetype limit);
    [[nodiscard]] qsizetype rowLimit() const { return m_rowLimit; }
    // Oldest rows dropped for the limit since the last clear.
    [[nodiscard]] quint64 droppedCount() const { return m_dropped; }

    [[nodiscard]] const TrafficStore &store() const { return m_store; }
    [[nodiscard]] qsizetype storeRow(int row) const; // -1 for an invalid row
    [[nodiscard]] int rowOfStoreRow(qsizetype storeRow) const; // -1 when filtered out or held
    // The frame of a row with the frame it pairs with, for the decode view.
    [[nodiscard]] FrameExchange exchangeAt(int row) const;
    // The next (or previous) shown row after fromRow matching query (TrafficSearch), wrapping
    // around; -1 when none does. fromRow -1 starts at the top (or the bottom backwards).
    [[nodiscard]] int findNext(const QString &query, int fromRow, bool forward = true) const;

    // Heap bytes held: the store plus the index of shown rows.
    [[nodiscard]] std::size_t memoryBytes() const;

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

public Q_SLOTS:
    void appendFrames(const QList<mbscope::TrafficFrame> &frames);
    void appendTransactions(const QList<mbscope::Transaction> &transactions);
    // Frames of one link named by its URL (TransactionEngine::unmatchedFrames): unsolicited,
    // duplicate and garbage frames with their verdicts.
    void appendLinkFrames(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void clear();

Q_SIGNALS:
    // Rows were appended, held, dropped or cleared: for status lines.
    void countsChanged();

private:
    void publish();
    void rebuildShown();
    void enforceLimit();
    [[nodiscard]] QVariant displayText(qsizetype storeRow, int column) const;
    [[nodiscard]] QVariant foreground(qsizetype storeRow, int column) const;
    [[nodiscard]] QVariant background(qsizetype storeRow) const;
    [[nodiscard]] QString toolTip(qsizetype storeRow, int column) const;

    TrafficStore m_store;
    TrafficFilter m_filter;
    std::vector<quint32> m_shown; // store rows shown, when the filter does not accept all
    bool m_filtered = false;
    bool m_paused = false;
    qsizetype m_published = 0; // store rows the views have been told about
    qsizetype m_rowLimit = 5'000'000;
    quint64 m_dropped = 0;     // rows dropped for the limit since the last clear: numbers go on
    qint64 m_originNs = 0;     // the Time column counts from the first frame
    bool m_hasOrigin = false;
    QFont m_monoFont;          // for the Bytes column
    quint16 m_currentLink = 0;
    bool m_hasCurrentLink = false;
};

} // namespace mbscope
