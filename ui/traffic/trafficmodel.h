#pragma once

#include "common/frameexchange.h"
#include "trafficfilter.h"
#include "trafficlinks.h"

#include "exchange/trafficentry.h"
#include "exchange/transaction.h"
#include "traffic/trafficarchive.h"
#include "traffic/trafficlog.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtGui/QFont>

#include <functional>
#include <memory>
#include <vector>

namespace mbscope {

// Every frame in and out, as a table that stays smooth with millions of rows. The frames are the
// engine's traffic log, kept in a TrafficLog of the list's own (the engine's lives in the engine
// thread): the same frames, verdicts and transaction ids, about 32 bytes a small frame, appended
// in one beginInsertRows per batch; cell text is made only in data(). An answer's request is the
// latest frame out of its link with the answer's transaction id (the engine's pairing), looked up
// when needed. Filtering keeps a vector of the shown rows' indexes (none while everything is
// shown). Pausing holds new rows back from the views, never drops them.
//
// Memory stays bounded however long a poll runs (issue 31): at most rowLimit frames are kept in
// memory. With an archive folder (setArchiveFolder: the window's cache folder) the oldest tenth
// beyond that goes to a TrafficArchive, a journal on disk, and stays in the list: scrolling,
// selecting, pairing and searching read it back from there. Without one (or when the disk
// refuses), the oldest tenth is dropped from the list instead, and counted.
//
// Feeds: appendLinkFrames() takes TransactionEngine::framesLogged's batches, appendFrames() a
// traffic log's frames with its link ids (TrafficLog::copy, a journal read back). Engines that do
// not publish their frames (a test plan's, a replay's) feed appendTransactions(): each
// transaction becomes the frames its engine's log holds (the request out, then the answer in, or
// an empty frame in with the verdict; a late answer only its answer). Feed an engine's frames or
// its transactions, not both, or frames show twice.
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
    // An answer's request is looked for this many frames back at most (deep pipelining, many
    // links), so a lost request never costs a scan of the whole list.
    static constexpr int kPairWindow = 4096;
    static constexpr qsizetype kPairCacheSize = 8192;

    explicit TrafficModel(QObject *parent = nullptr);
    ~TrafficModel() override;

    // Names the engine's link ids (TrafficLog::links) for frames fed by appendFrames.
    void setLinkName(quint16 link, const QString &url);
    // The link appendTransactions' frames travelled on.
    void setCurrentLink(const QString &url);

    void setFilter(const TrafficFilter &filter);
    [[nodiscard]] const TrafficFilter &filter() const { return m_filter; }

    void setPaused(bool paused);
    [[nodiscard]] bool isPaused() const { return m_paused; }
    // Rows stored but not shown yet because the model is paused.
    [[nodiscard]] qsizetype heldCount() const { return qsizetype(m_log->appended() - m_publishedEnd); }

    // At most this many frames (default 200,000) and bytes of frames and their records (default
    // 32 MiB) are kept in memory; beyond either the oldest tenth goes to the archive, or is
    // dropped without one.
    void setRowLimit(qsizetype limit);
    [[nodiscard]] qsizetype rowLimit() const { return m_rowLimit; }
    void setByteLimit(quint64 bytes);
    [[nodiscard]] quint64 byteLimit() const { return m_byteLimit; }
    // Where frames beyond the memory limits go (a journal made in folder, removed with the
    // model or by clear()); empty: they are dropped. Applies from the next clear() when frames
    // were dropped already.
    void setArchiveFolder(const QString &folder);
    // Why the archive stopped taking frames (the folder could not be written), or empty.
    [[nodiscard]] const QString &archiveProblem() const { return m_archiveProblem; }
    // Frames kept on disk only, in the archive (part of frameCount()).
    [[nodiscard]] quint64 archivedCount() const { return m_archive ? m_log->firstSequence() : 0; }
    // Oldest rows dropped for the limits since the last clear.
    [[nodiscard]] quint64 droppedCount() const { return firstKept(); }

    // The frames kept, in memory or archived, shown or not (held, filtered out).
    [[nodiscard]] qsizetype frameCount() const { return qsizetype(m_log->appended() - firstKept()); }
    // The frames kept in memory, the newest.
    [[nodiscard]] const TrafficLog &log() const { return *m_log; }
    // Every frame kept, archived ones first, from the frame numbered from (0: the first ever
    // appended) on (forward) or back, until visitor returns false; as TrafficLog::visit.
    void visitFrames(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const;
    // The number of the oldest frame kept (in the archive or in memory).
    [[nodiscard]] quint64 firstKept() const { return m_archive ? 0 : m_log->firstSequence(); }
    [[nodiscard]] const TrafficLinks &links() const { return m_links; }
    // A row's frame by its index among the frames kept (0: the oldest kept).
    [[nodiscard]] qsizetype storeRow(int row) const; // -1 for an invalid row
    [[nodiscard]] int rowOfStoreRow(qsizetype storeRow) const; // -1 when filtered out or held
    [[nodiscard]] TrafficEntry frameAt(qsizetype storeRow) const;
    // The request an answer belongs to, or the answer a request got (-1: none known), and an
    // answer's latency: its first byte read minus its request written (-1: none).
    [[nodiscard]] qsizetype pairedRow(qsizetype storeRow) const;
    [[nodiscard]] qint64 latencyNs(qsizetype storeRow) const;
    // Unit and function code of a frame; an empty frame in (timeout, link error) has its request's.
    [[nodiscard]] FrameKeys keysAt(qsizetype storeRow) const;
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
    // Transactions timed by the wall clock (an analysed capture, a journal read back) put on the
    // monotonic clock live frames use, then appended: Time (s) stays one time line (the list
    // showed about -1.8e9 s for live frames after an analysed capture, issue 25).
    void appendRecordedTransactions(const QList<mbscope::Transaction> &transactions);
    // Frames of one link named by its URL (TransactionEngine::framesLogged).
    void appendLinkFrames(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    // Frames of several links in one batch, each frame's link an index into links (the names of
    // the log they come from: the window's tap, TapRunner::framesLogged), kept in their order.
    void appendNamedFrames(const QList<mbscope::TrafficFrame> &frames, const QStringList &links);
    void clear();

Q_SIGNALS:
    // Rows were appended, held, dropped or cleared: for status lines.
    void countsChanged();

private:
    // A frame kept by the log (TrafficLog's own limits are off: the model drops whole tenths).
    void keep(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict, quint64 transactionId,
              QByteArrayView bytes);
    void appended();
    void publish();
    void rebuildShown();
    void enforceLimit();
    // Moves the oldest count frames of memory to the archive; false when there is none (or it
    // failed: then its frames are gone from the list too).
    bool archiveOldest(quint64 count);
    // Drops the oldest count frames kept (from the archive first) and tells the views.
    void dropOldest(quint64 count);
    [[nodiscard]] quint64 sequenceOf(qsizetype storeRow) const { return firstKept() + quint64(storeRow); }
    [[nodiscard]] QVariant displayText(qsizetype storeRow, int column) const;
    [[nodiscard]] QVariant foreground(qsizetype storeRow, int column) const;
    [[nodiscard]] QVariant background(qsizetype storeRow) const;
    [[nodiscard]] QString toolTip(qsizetype storeRow, int column) const;

    std::unique_ptr<TrafficLog> m_log;
    QString m_archiveFolder;
    QString m_archiveProblem;
    std::unique_ptr<TrafficArchive> m_archive; // frames 0 .. m_log->firstSequence() - 1, when made
    TrafficLinks m_links;
    // Pairs found, so painting does not look them up again: a slot per frame sequence modulo
    // the size (sequence + 1, 0: empty; the pair's sequence). Fixed size: it never grows.
    struct PairSlot {
        quint64 key = 0;
        quint64 paired = 0;
    };
    mutable std::vector<PairSlot> m_pairs;
    TrafficFilter m_filter;
    std::vector<quint32> m_shown; // store rows shown, when the filter does not accept all
    bool m_filtered = false;
    bool m_paused = false;
    quint64 m_publishedEnd = 0; // the sequence after the last frame the views have been told about
    qsizetype m_rowLimit = 200'000;
    quint64 m_byteLimit = quint64(32) << 20;
    qint64 m_originNs = 0;     // the Time column counts from the first frame
    bool m_hasOrigin = false;
    QFont m_monoFont;          // for the Bytes column
    quint16 m_currentLink = 0;
    bool m_hasCurrentLink = false;
};

} // namespace mbscope
