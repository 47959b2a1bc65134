#pragma once

#include "exchange/transaction.h"
#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

class QComboBox;
class QWidget;

namespace mbscope {

// What the latency panels of the Analysis dock show: all the bench's traffic (the window's link),
// the polls of one link of the workspace's watches, or those of one watch. The bench's
// transactions and the watch runner's samples (each a poll with its latency, request sent to
// answer complete) come in; the chosen ones go out as transactions, and a new choice clears the
// panels and hands them what was kept of that source so far (the last kKeep of each).
//
// A watch sample becomes a transaction with the sample's status and latency, timed on the
// monotonic clock of the bench's own; on a link, its item is the watch's place among the watches
// of that link ("item 0" the first), so the histogram's item choice tells them apart.
class LatencySource : public QObject
{
    Q_OBJECT

public:
    static constexpr int kKeep = 20000;

    explicit LatencySource(QObject *parent = nullptr);

    // The workspace's watches: a choice for each link they use and for each of them.
    void setWatches(const SessionWatches &watches);
    [[nodiscard]] int choiceCount() const { return int(m_choices.size()); }
    // "All bench traffic", "Link tcp://127.0.0.1:502", "Watch plc words".
    [[nodiscard]] QString choiceText(int index) const;
    [[nodiscard]] int choice() const { return m_choice; }
    // 0 is the bench; a choice no longer there falls back to it.
    void setChoice(int index);
    [[nodiscard]] bool isBench() const { return m_choice == 0; }
    // A combo box that shows and sets the choice (one per panel, all in step).
    [[nodiscard]] QComboBox *makeChoiceBox(QWidget *parent);

    void addBenchTransactions(const QList<mbscope::Transaction> &transactions);
    // A new connection of the bench: its history starts again, so that the time axis starts at
    // this connection's first request, not at the first one the window ever made.
    void restartBench();
    void addWatchSamples(const QList<mbscope::WatchSample> &samples);
    // A watch sample as the latency panels count it (item: -1).
    [[nodiscard]] static Transaction transactionOf(const WatchSample &sample, qint64 nowNs, qint64 nowMs);

Q_SIGNALS:
    // The chosen source changed: the panels clear, then get its history by transactionsChosen().
    void reset();
    void transactionsChosen(const QList<mbscope::Transaction> &transactions);
    void choicesChanged();
    void choiceChanged(int index);

private:
    enum class Kind : quint8 { Bench, Link, Watch };
    struct Choice {
        Kind kind = Kind::Bench;
        QString key; // the link's URL or the watch's name
        friend bool operator==(const Choice &, const Choice &) = default;
    };
    struct Kept {
        QString target;
        QString watchName;
        Transaction transaction;
    };

    [[nodiscard]] bool accepts(const Choice &choice, const QString &target, const QString &watchName) const;
    [[nodiscard]] Transaction forChoice(const Kept &kept) const;
    void fillBox(QComboBox *box) const;

    SessionWatches m_watches;
    QList<Choice> m_choices;
    int m_choice = 0;
    QList<Transaction> m_bench; // newest last, at most kKeep
    QList<Kept> m_polls;        // the watches' polls, newest last, at most kKeep
};

} // namespace mbscope
