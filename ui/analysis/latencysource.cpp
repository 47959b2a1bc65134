#include "latencysource.h"

#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>
#include <QtCore/QSignalBlocker>
#include <QtWidgets/QComboBox>

namespace mbscope {

LatencySource::LatencySource(QObject *parent)
    : QObject(parent)
{
    m_choices.append(Choice{});
}

void LatencySource::setWatches(const SessionWatches &watches)
{
    m_watches = watches;
    const Choice chosen = m_choices.value(m_choice);
    QList<Choice> choices{Choice{}};
    for (const WatchDefinition &watch : watches.watches) {
        const Choice link{Kind::Link, watch.target};
        if (!choices.contains(link))
            choices.append(link);
    }
    for (const WatchDefinition &watch : watches.watches)
        choices.append(Choice{Kind::Watch, watch.name});
    if (choices == m_choices)
        return;
    m_choices = choices;
    Q_EMIT choicesChanged();
    const int kept = int(m_choices.indexOf(chosen));
    if (kept >= 0) {
        m_choice = kept;
        Q_EMIT choiceChanged(m_choice);
    } else {
        m_choice = -1; // makes setChoice(0) a change
        setChoice(0);
    }
}

QString LatencySource::choiceText(int index) const
{
    if (index < 0 || index >= m_choices.size())
        return {};
    const Choice &c = m_choices.at(index);
    switch (c.kind) {
    case Kind::Bench: return tr("All bench traffic");
    case Kind::Link: return tr("Watch link %1").arg(c.key);
    case Kind::Watch: return tr("Watch %1").arg(c.key);
    }
    return {};
}

void LatencySource::setChoice(int index)
{
    if (index < 0 || index >= m_choices.size())
        index = 0;
    if (index == m_choice)
        return;
    m_choice = index;
    Q_EMIT choiceChanged(m_choice);
    Q_EMIT reset();
    const Choice &c = m_choices.at(m_choice);
    if (c.kind == Kind::Bench) {
        if (!m_bench.isEmpty())
            Q_EMIT transactionsChosen(m_bench);
        return;
    }
    QList<Transaction> history;
    for (const Kept &kept : std::as_const(m_polls)) {
        if (accepts(c, kept.target, kept.watchName))
            history.append(forChoice(kept));
    }
    if (!history.isEmpty())
        Q_EMIT transactionsChosen(history);
}

QComboBox *LatencySource::makeChoiceBox(QWidget *parent)
{
    auto *box = new QComboBox(parent);
    box->setObjectName(QStringLiteral("latencySourceChoice"));
    box->setToolTip(tr("Whose latency to show: all the bench's traffic, the polls of one link of the "
                       "watches, or those of one watch (Watches tab, while the watches poll)"));
    box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    fillBox(box);
    connect(this, &LatencySource::choicesChanged, box, [this, box] { fillBox(box); });
    connect(this, &LatencySource::choiceChanged, box, [box](int index) {
        const QSignalBlocker blocker(box);
        box->setCurrentIndex(index);
    });
    connect(box, &QComboBox::activated, this, &LatencySource::setChoice);
    return box;
}

void LatencySource::fillBox(QComboBox *box) const
{
    const QSignalBlocker blocker(box);
    box->clear();
    for (int i = 0; i < m_choices.size(); ++i)
        box->addItem(choiceText(i));
    box->setCurrentIndex(m_choice);
}

bool LatencySource::accepts(const Choice &choice, const QString &target, const QString &watchName) const
{
    switch (choice.kind) {
    case Kind::Bench: return false;
    case Kind::Link: return choice.key == target;
    case Kind::Watch: return choice.key == watchName;
    }
    return false;
}

Transaction LatencySource::forChoice(const Kept &kept) const
{
    Transaction t = kept.transaction;
    const Choice &c = m_choices.at(m_choice);
    if (c.kind == Kind::Link) {
        // The watch's place among the watches of its link: the histogram's items.
        int item = 0;
        for (const WatchDefinition &watch : m_watches.watches) {
            if (watch.target != c.key)
                continue;
            if (watch.name == kept.watchName) {
                t.item = item;
                break;
            }
            ++item;
        }
    }
    return t;
}

void LatencySource::addBenchTransactions(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    m_bench.append(transactions);
    if (m_bench.size() > kKeep)
        m_bench.remove(0, m_bench.size() - kKeep);
    if (isBench())
        Q_EMIT transactionsChosen(transactions);
}

void LatencySource::restartBench()
{
    m_bench.clear();
    if (isBench())
        Q_EMIT reset();
}

Transaction LatencySource::transactionOf(const WatchSample &sample, qint64 nowNs, qint64 nowMs)
{
    Transaction t;
    t.id = sample.poll;
    switch (sample.status) {
    case WatchSample::Status::Ok: t.status = TransactionStatus::Ok; break;
    case WatchSample::Status::Exception: t.status = TransactionStatus::Exception; break;
    case WatchSample::Status::Timeout: t.status = TransactionStatus::Timeout; break;
    case WatchSample::Status::CrcError: t.status = TransactionStatus::CrcError; break;
    case WatchSample::Status::Error: t.status = TransactionStatus::LinkError; break;
    }
    // A malformed or unexpected answer has a latency; only a link error has none.
    if (sample.status == WatchSample::Status::Error && sample.latencyNs >= 0)
        t.status = TransactionStatus::Malformed;
    t.exceptionCode = sample.exceptionCode;
    t.problem = sample.error;
    // The sample's time (when the answer came, or the poll failed) on the monotonic clock.
    const qint64 endNs = nowNs - (nowMs - sample.timeMs) * 1000000;
    if (sample.latencyNs >= 0) {
        t.sentNs = endNs - sample.latencyNs;
        t.doneNs = endNs;
        t.firstByteNs = endNs;
    } else {
        t.sentNs = endNs;
    }
    t.writeNs = t.sentNs;
    return t;
}

void LatencySource::addWatchSamples(const QList<WatchSample> &samples)
{
    if (samples.isEmpty())
        return;
    const qint64 nowNs = monotonicNowNs();
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    const Choice chosen = m_choices.value(m_choice);
    QList<Transaction> shown;
    for (const WatchSample &sample : samples) {
        Kept kept;
        kept.watchName = sample.watchName;
        if (sample.watch >= 0 && sample.watch < m_watches.watches.size() && m_watches.watches.at(sample.watch).name == sample.watchName)
            kept.target = m_watches.watches.at(sample.watch).target;
        kept.transaction = transactionOf(sample, nowNs, nowMs);
        if (accepts(chosen, kept.target, kept.watchName))
            shown.append(forChoice(kept));
        m_polls.append(std::move(kept));
    }
    if (m_polls.size() > kKeep)
        m_polls.remove(0, m_polls.size() - kKeep);
    if (!shown.isEmpty())
        Q_EMIT transactionsChosen(shown);
}

} // namespace mbscope
