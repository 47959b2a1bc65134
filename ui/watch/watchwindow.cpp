#include "watchwindow.h"

#include "watchtablemodel.h"

#include <QtCore/QDateTime>
#include <QtGui/QFontMetrics>
#include <QtGui/QKeyEvent>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>

namespace mbscope {

WatchWindow::WatchWindow(QWidget *parent)
    : QWidget(parent)
    , m_model(new WatchTableModel(this))
    , m_view(new QTableView(this))
    , m_counters(new QLabel(this))
{
    m_view->setObjectName(QStringLiteral("watchTable"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    m_view->horizontalHeader()->setSectionResizeMode(WatchTableModel::RuleColumn, QHeaderView::Stretch);
    // Fixed widths: resizing to contents would measure every row at every sample. Each column is
    // as wide as its widest expected text or its header (translated, in the header's font, with
    // room for the sort indicator and the section's margins), whichever is wider.
    const QFontMetrics metrics = m_view->fontMetrics();
    const QFontMetrics headerMetrics = m_view->horizontalHeader()->fontMetrics();
    const auto fit = [&](int column, const QString &sample) {
        const QString header = m_model->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
        m_view->setColumnWidth(column, std::max(metrics.horizontalAdvance(sample) + 12, headerMetrics.horizontalAdvance(header) + 16));
    };
    fit(WatchTableModel::AddressColumn, QStringLiteral("65535 (0xFFFF)"));
    fit(WatchTableModel::ReferenceColumn, QStringLiteral("400000"));
    fit(WatchTableModel::NameColumn, QStringLiteral("analog input 10"));
    fit(WatchTableModel::ValueColumn, QStringLiteral("-123456.78"));
    fit(WatchTableModel::UnitColumn, QStringLiteral("rpm"));
    fit(WatchTableModel::ChangedColumn, QStringLiteral("00:00:00.000"));
    m_view->installEventFilter(this);
    connect(m_view, &QTableView::doubleClicked, this, [this](const QModelIndex &index) {
        if (index.data(WatchTableModel::WritableRole).toBool())
            Q_EMIT writeRequested(index.row());
    });
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_view, &QWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        const QModelIndex index = m_view->indexAt(pos);
        if (index.isValid())
            m_view->setCurrentIndex(index);
        Q_EMIT contextMenuRequested(index.isValid() ? index.row() : -1, m_view->viewport()->mapToGlobal(pos));
    });
    m_counters->setObjectName(QStringLiteral("watchCounters"));
    m_counters->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_counters->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_counters);
    updateStatus();
}

bool WatchWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if ((key->key() == Qt::Key_F2 || key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter)
            && key->modifiers() == Qt::NoModifier && m_view->currentIndex().isValid()) {
            Q_EMIT writeRequested(m_view->currentIndex().row());
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

QString WatchWindow::countersText(const WatchCounters &c)
{
    QString text = tr("polls %1 \u00b7 ok %2 \u00b7 exceptions %3 \u00b7 timeouts %4").arg(c.polls).arg(c.ok).arg(c.exceptions).arg(c.timeouts);
    const quint64 others = c.crcErrors + c.otherErrors + c.linkErrors;
    if (others)
        text += tr(" \u00b7 other errors %1").arg(others);
    if (c.ruleFirings)
        text += tr(" \u00b7 rules fired %1").arg(c.ruleFirings);
    if (c.lastLatencyNs >= 0 && c.latencyCount)
        text += tr(" \u00b7 latency %1 ms").arg(double(c.lastLatencyNs) / 1e6, 0, 'f', 1);
    if (!c.lastError.isEmpty())
        text += tr(" \u00b7 last error at %1: %2")
                    .arg(QDateTime::fromMSecsSinceEpoch(c.lastErrorMs).toString(QStringLiteral("HH:mm:ss")), c.lastError);
    return text;
}

WatchCounters WatchWindow::carried(const WatchCounters &before, const WatchCounters &now)
{
    WatchCounters c = now;
    c.polls += before.polls;
    c.ok += before.ok;
    c.exceptions += before.exceptions;
    for (auto it = before.exceptionsByCode.cbegin(); it != before.exceptionsByCode.cend(); ++it)
        c.exceptionsByCode[it.key()] += it.value();
    c.timeouts += before.timeouts;
    c.crcErrors += before.crcErrors;
    c.otherErrors += before.otherErrors;
    c.linkErrors += before.linkErrors;
    c.reconnects += before.reconnects;
    c.ruleFirings += before.ruleFirings;
    c.overruns += before.overruns;
    if (now.lastErrorMs == 0) {
        c.lastError = before.lastError;
        c.lastErrorMs = before.lastErrorMs;
    }
    c.lastOkMs = std::max(before.lastOkMs, now.lastOkMs);
    if (now.latencyCount == 0) {
        c.lastLatencyNs = before.lastLatencyNs;
        c.minLatencyNs = before.minLatencyNs;
        c.maxLatencyNs = before.maxLatencyNs;
    } else if (before.latencyCount > 0) {
        c.minLatencyNs = std::min(before.minLatencyNs, now.minLatencyNs);
        c.maxLatencyNs = std::max(before.maxLatencyNs, now.maxLatencyNs);
    }
    c.latencyCount = before.latencyCount + now.latencyCount;
    if (c.latencyCount > 0)
        c.meanLatencyNs = (before.meanLatencyNs * double(before.latencyCount) + now.meanLatencyNs * double(now.latencyCount))
            / double(c.latencyCount);
    if (c.latencyBuckets.isEmpty())
        c.latencyBuckets = before.latencyBuckets;
    else
        for (int i = 0; i < std::min(c.latencyBuckets.size(), before.latencyBuckets.size()); ++i)
            c.latencyBuckets[i] += before.latencyBuckets.at(i);
    return c;
}

void WatchWindow::setCounters(const WatchCounters &counters)
{
    m_lastCounters = counters;
    updateStatus();
}

void WatchWindow::setLinkState(const WatchLinkState &state)
{
    m_link = state;
    m_hasLink = true;
    updateStatus();
}

void WatchWindow::setPolling(bool polling)
{
    if (m_polling == polling)
        return;
    m_polling = polling;
    updateStatus();
}

void WatchWindow::updateStatus()
{
    QString text = countersText(m_lastCounters);
    if (m_hasLink) {
        QString link;
        switch (m_link.state) {
        case WatchLinkState::State::Connecting: link = tr("link: connecting"); break;
        case WatchLinkState::State::Up: link = tr("link: up"); break;
        case WatchLinkState::State::Down: link = tr("link: down (%1)").arg(m_link.message); break;
        case WatchLinkState::State::Backoff:
            link = tr("link: down (%1), retry in %2 s").arg(m_link.message).arg(double(m_link.retryInMs) / 1000, 0, 'f', 1);
            break;
        case WatchLinkState::State::Stopped: link = tr("link: stopped"); break;
        }
        if (m_link.reconnects)
            link += tr(", reconnected %1\u00d7").arg(m_link.reconnects);
        text = link + QStringLiteral(" \u00b7 ") + text;
    }
    text = (m_polling ? tr("Polling") : tr("Stopped")) + QStringLiteral(" \u00b7 ") + text;
    m_counters->setText(text);
}

QString WatchWindow::selectionText() const
{
    QModelIndexList selected = m_view->selectionModel()->selectedIndexes();
    if (selected.isEmpty() && m_view->currentIndex().isValid())
        selected << m_view->currentIndex();
    std::sort(selected.begin(), selected.end());
    QList<int> columns;
    for (const QModelIndex &index : std::as_const(selected)) {
        if (!columns.contains(index.column()))
            columns << index.column();
    }
    std::sort(columns.begin(), columns.end());
    QStringList lines;
    QStringList header;
    for (int column : std::as_const(columns))
        header << m_model->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
    lines << header.join(QLatin1Char('\t'));
    int currentRow = -1;
    QStringList cells;
    for (const QModelIndex &index : std::as_const(selected)) {
        if (index.row() != currentRow) {
            if (currentRow >= 0)
                lines << cells.join(QLatin1Char('\t'));
            cells.clear();
            currentRow = index.row();
        }
        cells << index.data().toString();
    }
    if (currentRow >= 0)
        lines << cells.join(QLatin1Char('\t'));
    return lines.join(QLatin1Char('\n'));
}

} // namespace mbscope
