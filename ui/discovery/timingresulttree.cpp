#include "timingresulttree.h"

#include "common/severitystyle.h"

#include <QtWidgets/QHeaderView>

namespace mbscope {

namespace {

QString milliseconds(qint64 us)
{
    return TimingResultTree::tr("%1 ms").arg(QString::number(double(us) / 1000.0, 'f', 2));
}

QTreeWidgetItem *row(QTreeWidgetItem *parent, const QString &measure, const QString &result)
{
    auto *item = new QTreeWidgetItem(parent);
    item->setText(TimingResultTree::MeasureColumn, measure);
    item->setText(TimingResultTree::ResultColumn, result);
    return item;
}

} // namespace

TimingResultTree::TimingResultTree(QWidget *parent)
    : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("timingResults"));
    setColumnCount(ColumnCount);
    setHeaderLabels({tr("Measurement"), tr("Result")});
    setUniformRowHeights(true);
    header()->setStretchLastSection(true);
    setColumnWidth(MeasureColumn, 260);
}

QString TimingResultTree::settingsText(const TimingReport &r)
{
    // Only what was measured becomes a setting: without a gap measured, none is given.
    const bool gapKnown = r.gapMeasured();
    const int gap = r.recommendedGapMs();
    const int timeout = r.recommendedTimeoutMs();
    const qint64 pause = r.pauseAfterConnectMs();
    return QStringLiteral("mbscope watch link:    %1\"timeoutMs\": %2%4\n"
                          "mbscope poll/read:     --timeout %2ms\n"
                          "Telegraf inputs.modbus: timeout = \"%2ms\"\n"
                          "  [inputs.modbus.workarounds] %5pause_after_connect = \"%3ms\"\n")
        .arg(gapKnown ? QStringLiteral("\"gapMs\": %1, ").arg(gap) : QString())
        .arg(timeout)
        .arg(pause)
        .arg(pause > 0 ? QStringLiteral(", \"warmUpMs\": %1").arg(pause) : QString())
        .arg(gapKnown ? QStringLiteral("pause_between_requests = \"%1ms\", ").arg(gap) : QString());
}

void TimingResultTree::showReport(const TimingScanSettings &s, const TimingReport &r)
{
    clear();
    QTreeWidgetItem *root = invisibleRootItem();
    row(root, tr("First answer after connecting"),
        r.firstAnswerMs < 0 ? tr("none within %1 ms").arg(s.warmupLimitMs)
                            : tr("%1 ms (%2 failed before it)").arg(r.firstAnswerMs).arg(r.warmupFailures));
    if (r.warmUpMs >= 0)
        row(root, tr("Warm-up after connecting"),
            tr("%1 ms (answered after waiting %1 ms, not after %2 ms)").arg(r.warmUpMs).arg(r.warmUpRefusedMs));
    if (!r.gaps.isEmpty()) {
        QTreeWidgetItem *gaps = row(root, tr("Gaps between requests"), tr("%n tried, longest first", nullptr, int(r.gaps.size())));
        for (const TimingReport::GapTrial &g : r.gaps) {
            QTreeWidgetItem *trial = row(gaps, tr("%1 ms").arg(g.gapMs),
                                         tr("%1 ok, %2 failed, slowest %3").arg(g.ok).arg(g.failed).arg(milliseconds(g.maxLatencyUs)));
            if (g.failed > 0)
                trial->setForeground(ResultColumn, SeverityStyle::textColor(Severity::Error));
        }
        if (r.gapsHeldByWarmUp)
            row(gaps, tr("shorter"), tr("not measured: the device hangs up after each answer and each new connection waits "
                                        "its warm-up (%1 ms)").arg(r.pauseAfterConnectMs()));
        gaps->setExpanded(true);
    }
    // What a part cut short (Stop, the time limit) did not measure is said so, never shown as a figure.
    row(root, tr("Shortest gap without errors"),
        r.gapsHeldByWarmUp ? tr("not measured (the warm-up kept every request apart)")
        : !r.gapMeasured() ? tr("not measured (stopped before a gap was tried through)")
        : r.shortestCleanGapMs < 0 ? tr("none of those tried (every gap had errors)")
        : r.gapsComplete ? tr("%1 ms").arg(r.shortestCleanGapMs)
                         : tr("%1 ms (shorter gaps not tried: stopped)").arg(r.shortestCleanGapMs));
    if (r.largestQuantity > 0)
        row(root, tr("Largest read answered"),
            (r.largestComplete ? tr("%1 at address %2 (an answer PDU of %3 bytes)")
                               : tr("at least %1 at address %2 (an answer PDU of %3 bytes; stopped before the largest was found)"))
                    .arg(r.largestQuantity)
                    .arg(s.address)
                    .arg(r.largestAnswerPdu)
                + (r.largestEndsMap ? tr(": one more ran past the device's map (no exception 03), not a quantity limit") : QString()));
    else
        row(root, tr("Largest read answered"), tr("not measured"));
    if (r.gapReconnects >= 0 && r.gapAnswered >= 3)
        row(root, tr("Connection after each answer"),
            r.closesAfterAnswer() ? tr("closed by the device (%1 connections for %2 answers): pipelining and clients at once not measured")
                                        .arg(r.gapReconnects)
                                        .arg(r.gapAnswered)
                                  : tr("kept open"));
    if (r.pipelineSent > 0)
        row(root, tr("Pipelined requests"),
            r.pipelineOk == r.pipelineSent ? tr("%1 of %2 answered: pipelining works").arg(r.pipelineOk).arg(r.pipelineSent)
                                           : tr("%1 of %2 answered: send one at a time").arg(r.pipelineOk).arg(r.pipelineSent));
    if (r.clientsTried > 0)
        row(root, tr("TCP clients served at once"),
            r.oldestDropped ? tr("%1 (client %2 was served by closing client 1: the device knocks its oldest client off)")
                                  .arg(r.clientsServed)
                                  .arg(r.clientsTried)
            : r.clientsServed == s.maxClients ? tr("%1 (all tried; there may be room for more)").arg(r.clientsServed)
                                              : tr("%1 (client %2 was not served)").arg(r.clientsServed).arg(r.clientsTried));
    QTreeWidgetItem *settings = row(root, tr("Recommended"), tr("twice the shortest clean gap, three times the slowest answer"));
    row(settings, tr("Gap between requests"), r.gapMeasured() ? tr("%1 ms").arg(r.recommendedGapMs()) : tr("none: no gap was measured"));
    row(settings, tr("Timeout"), tr("%1 ms").arg(r.recommendedTimeoutMs()));
    row(settings, tr("Pause after connecting"), tr("%1 ms").arg(r.pauseAfterConnectMs()));
    settings->setExpanded(true);
    QFont bold = settings->font(MeasureColumn);
    bold.setBold(true);
    settings->setFont(MeasureColumn, bold);
}

} // namespace mbscope
