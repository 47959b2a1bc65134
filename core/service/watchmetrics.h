#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"
#include "fleet/watchsample.h"
#include "metrics/metricsregistry.h"
#include "metrics/processmetrics.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// What the watch service tells Prometheus, made from what the runner reports (WatchRunner's
// samples, counters, link states and rule events). Every name follows Prometheus's conventions:
// mbscope_ prefix, base units (seconds), counters ending in _total, timestamps in seconds since
// the epoch. Labels of a value: watch, target, unit (the Modbus unit id), table, address (0-based,
// decimal), name (the point's, empty for an address no point names), engineering_unit.
//
//   mbscope_watch_value                   gauge      a point's value, scaled (bit fields: mbscope_watch_bit_field_value);
//                                                    absent after a failed poll, so an outage is a gap, not a stale line
//   mbscope_watch_up                      gauge      1 when the watch's last poll was answered with values
//   mbscope_watch_polls_total             counter    polls ended (answered or not)
//   mbscope_watch_ok_total                counter    polls answered with values
//   mbscope_watch_exceptions_total        counter    exception answers, by code ("02")
//   mbscope_watch_timeouts_total          counter    polls not answered in time
//   mbscope_watch_crc_errors_total        counter    answers with a wrong CRC or LRC
//   mbscope_watch_link_errors_total       counter    polls lost to the link
//   mbscope_watch_bad_answers_total       counter    malformed or unexpected answers
//   mbscope_watch_overruns_total          counter    polls that started late (the link was busy)
//   mbscope_watch_rule_firings_total      counter    rules of the watch that fired
//   mbscope_watch_rule_active             gauge      1 while a rule holds (labels rule, point, severity)
//   mbscope_watch_log_dropped_rows_total  counter    CSV rows dropped because the log fell behind the polls
//   mbscope_watch_latency_seconds         histogram  request to answer, answered polls
//   mbscope_watch_last_success_timestamp_seconds  gauge  the last good answer
//   mbscope_link_up                       gauge      1 while the link is open
//   mbscope_link_reconnects_total         counter    times the link opened again after it was lost
//   mbscope_link_failures_total           counter    link errors, failed opens included
//   mbscope_build_info, process_*         the version; memory, CPU and descriptors of the process
//
// Series are bounded by the session: one per point, per watch, per link, per exception code
// seen (at most 255). reset() starts over for a reloaded session.
class WatchMetrics
{
public:
    explicit WatchMetrics(const QString &version);

    [[nodiscard]] const MetricsRegistry &registry() const { return m_registry; }

    // The series of a session's watches: counters at 0, links down, until the runner reports.
    void reset(const SessionWatches &watches);
    void addSamples(const QList<WatchSample> &samples);
    void setCounters(const QList<WatchCounters> &counters);
    void setLinkState(const WatchLinkState &state);
    void addRuleEvent(const WatchRuleEvent &event);
    // The CSV rows of a watch (index) dropped since the watches started (WatchRunner::logDroppedRows).
    void setLogDroppedRows(int watch, quint64 rows);
    // Before a scrape: the process's memory and CPU.
    void refreshProcess() { m_process.update(); }

    // "holding_registers", "input_registers", "coils", "discrete_inputs" (FIFO: holding_registers).
    [[nodiscard]] static QString tableName(quint8 function);
    // Latency bounds in seconds, 0.5 ms to 10 s.
    [[nodiscard]] static QList<double> latencyBuckets();

private:
    // The series one value of a watch writes, kept from sample to sample: a poll of N values
    // looks up no labels while the value's address, name and unit stay the same and no series
    // was removed (issue 32: the lookups of 7 labels a value were 40 % of the service's work).
    struct ValueSlots {
        quint16 address = 0;
        QString name;
        QString unit;
        MetricSeriesSlot value;
        QList<QString> fieldNames;
        QList<MetricSeriesSlot> fields;
    };
    // The series of one watch.
    struct WatchSlots {
        MetricSeriesSlot up, latency;
        QList<ValueSlots> values;
    };

    [[nodiscard]] QStringList watchLabels(int watch) const;
    void setBuildInfo();
    void addValues(int watch, const QList<WatchPointValue> &values);

    MetricsRegistry m_registry;
    ProcessMetrics m_process;
    QString m_version;
    SessionWatches m_watches;
    MetricFamily &m_value;
    MetricFamily &m_bitField;
    MetricFamily &m_up;
    MetricFamily &m_polls;
    MetricFamily &m_ok;
    MetricFamily &m_exceptions;
    MetricFamily &m_timeouts;
    MetricFamily &m_crcErrors;
    MetricFamily &m_linkErrors;
    MetricFamily &m_badAnswers;
    MetricFamily &m_overruns;
    MetricFamily &m_ruleFirings;
    MetricFamily &m_ruleActive;
    MetricFamily &m_logDropped;
    MetricFamily &m_latency;
    MetricFamily &m_lastSuccess;
    MetricFamily &m_linkUp;
    MetricFamily &m_linkReconnects;
    MetricFamily &m_linkFailures;
    QList<WatchSlots> m_slots; // by watch index
};

} // namespace mbscope
