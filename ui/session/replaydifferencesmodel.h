#pragma once

#include "protocol/framing.h"
#include "replay/replayoutcome.h"

#include <QtCore/QAbstractTableModel>

#include <array>
#include <memory>
#include <vector>

namespace mbscope {

class ReplayScript;

// The answers of a replay against a live target, each beside the recorded one: which request,
// the recorded answer, the new answer, what differs and how (AnswerComparison's differences),
// latency recorded and now. Lists the differences only, or every answer (setShowMatches); the
// counts cover every answer either way. Outcomes are appended as the replay goes.
class ReplayDifferencesModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { IndexColumn, RequestColumn, RecordedColumn, NowColumn, KindColumn, DifferencesColumn,
                  RecordedLatencyColumn, NowLatencyColumn, ColumnCount };
    // What differs, as a user sorts it out: the answer's values, its bytes alone (every field
    // alike, the PDU not), an exception against a normal answer (or another code), another
    // outcome (a CRC error, a malformed answer), an answer against a timeout either way, or
    // only the time it took (see isLatencyChange).
    enum class Kind : quint8 { Same, Values, Bytes, Exception, Outcome, Timeout, Latency };
    static constexpr std::size_t kKindCount = 7;

    explicit ReplayDifferencesModel(QObject *parent = nullptr);
    ~ReplayDifferencesModel() override;

    // A new replay of script to a link with targetFraming: clears the rows.
    void reset(std::shared_ptr<const ReplayScript> script, Framing targetFraming);
    void appendOutcome(const ReplayOutcome &outcome);
    void setShowMatches(bool show);
    [[nodiscard]] bool showMatches() const { return m_showMatches; }

    [[nodiscard]] qsizetype replayed() const { return qsizetype(m_rows.size()); }
    [[nodiscard]] qsizetype count(Kind kind) const { return m_counts[std::size_t(kind)]; }
    [[nodiscard]] qsizetype differed() const { return replayed() - count(Kind::Same); }
    [[nodiscard]] Kind kindAt(int row) const;
    // "12 answers replayed: 10 the same, 1 with other values, 1 timeout"
    [[nodiscard]] QString countsText() const;
    [[nodiscard]] static QString kindName(Kind kind);
    [[nodiscard]] static Kind classify(const ReplayOutcome &outcome, const Transaction &recorded, Framing recordedFraming,
                                       Framing nowFraming);
    // An answer whose values match but which came more than twice as fast or as slow as
    // recorded, and at least 10 ms apart (a device's jitter on a loaded bench mostly stays within that).
    [[nodiscard]] static bool isLatencyChange(qint64 recordedNs, qint64 nowNs);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Row {
        ReplayOutcome outcome;
        Kind kind = Kind::Same;
    };
    void rebuildShown();
    [[nodiscard]] const Row &shownRow(int row) const { return m_rows[std::size_t(m_shown[std::size_t(row)])]; }

    std::shared_ptr<const ReplayScript> m_script;
    Framing m_targetFraming = Framing::Tcp;
    std::vector<Row> m_rows;
    std::vector<qsizetype> m_shown; // indexes into m_rows
    std::array<qsizetype, kKindCount> m_counts{};
    bool m_showMatches = false;
};

} // namespace mbscope
