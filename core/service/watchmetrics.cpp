#include "watchmetrics.h"

namespace mbscope {

namespace {

const QStringList kWatch{QStringLiteral("watch"), QStringLiteral("target")};
const QStringList kValue{QStringLiteral("watch"), QStringLiteral("target"), QStringLiteral("unit"), QStringLiteral("table"),
                         QStringLiteral("address"), QStringLiteral("name"), QStringLiteral("engineering_unit")};

QStringList plus(QStringList labels, const QString &more)
{
    labels.append(more);
    return labels;
}

QString codeText(int code)
{
    return QStringLiteral("%1").arg(code, 2, 16, QLatin1Char('0')).toUpper();
}

} // namespace

WatchMetrics::WatchMetrics(const QString &version)
    : m_process(m_registry)
    , m_version(version)
    , m_value(m_registry.gauge(QStringLiteral("mbscope_watch_value"),
                               QStringLiteral("A watched register's or bit's value, scaled to its engineering unit."), kValue))
    , m_bitField(m_registry.gauge(QStringLiteral("mbscope_watch_bit_field_value"), QStringLiteral("A named bit field's value."),
                                  plus(kValue, QStringLiteral("field"))))
    , m_up(m_registry.gauge(QStringLiteral("mbscope_watch_up"),
                            QStringLiteral("1 when the watch's last poll was answered with values, else 0."), kWatch))
    , m_polls(m_registry.counter(QStringLiteral("mbscope_watch_polls_total"), QStringLiteral("Polls ended, answered or not."), kWatch))
    , m_ok(m_registry.counter(QStringLiteral("mbscope_watch_ok_total"), QStringLiteral("Polls answered with values."), kWatch))
    , m_exceptions(m_registry.counter(QStringLiteral("mbscope_watch_exceptions_total"),
                                      QStringLiteral("Exception answers, by exception code (hex)."), plus(kWatch, QStringLiteral("code"))))
    , m_timeouts(m_registry.counter(QStringLiteral("mbscope_watch_timeouts_total"), QStringLiteral("Polls not answered in time."), kWatch))
    , m_crcErrors(m_registry.counter(QStringLiteral("mbscope_watch_crc_errors_total"),
                                     QStringLiteral("Answers with a wrong CRC or LRC."), kWatch))
    , m_linkErrors(m_registry.counter(QStringLiteral("mbscope_watch_link_errors_total"),
                                      QStringLiteral("Polls lost to the link (refused, closed, I/O error)."), kWatch))
    , m_badAnswers(m_registry.counter(QStringLiteral("mbscope_watch_bad_answers_total"),
                                      QStringLiteral("Malformed or unexpected answers."), kWatch))
    , m_overruns(m_registry.counter(QStringLiteral("mbscope_watch_overruns_total"),
                                    QStringLiteral("Polls that started later than their interval asked."), kWatch))
    , m_ruleFirings(m_registry.counter(QStringLiteral("mbscope_watch_rule_firings_total"),
                                       QStringLiteral("Rules of the watch that fired."), kWatch))
    , m_ruleActive(m_registry.gauge(QStringLiteral("mbscope_watch_rule_active"), QStringLiteral("1 while a rule of the watch holds."),
                                    {QStringLiteral("watch"), QStringLiteral("rule"), QStringLiteral("point"), QStringLiteral("severity")}))
    , m_logDropped(m_registry.counter(QStringLiteral("mbscope_watch_log_dropped_rows_total"),
                                      QStringLiteral("CSV log rows dropped because the log could not keep up with the polls."), kWatch))
    , m_latency(m_registry.histogram(QStringLiteral("mbscope_watch_latency_seconds"),
                                     QStringLiteral("Request sent to answer complete, answered polls."), kWatch, latencyBuckets()))
    , m_lastSuccess(m_registry.gauge(QStringLiteral("mbscope_watch_last_success_timestamp_seconds"),
                                     QStringLiteral("When the watch last got a good answer, seconds since the epoch."), kWatch))
    , m_linkUp(m_registry.gauge(QStringLiteral("mbscope_link_up"), QStringLiteral("1 while the link is open, else 0."),
                                {QStringLiteral("target")}))
    , m_linkReconnects(m_registry.counter(QStringLiteral("mbscope_link_reconnects_total"),
                                          QStringLiteral("Times the link opened again after it was lost."), {QStringLiteral("target")}))
    , m_linkFailures(m_registry.counter(QStringLiteral("mbscope_link_failures_total"),
                                        QStringLiteral("Link errors, failed opens included."), {QStringLiteral("target")}))
{
    setBuildInfo();
}

void WatchMetrics::setBuildInfo()
{
    m_registry.gauge(QStringLiteral("mbscope_build_info"), QStringLiteral("The mbscope version, as a label; always 1."),
                     {QStringLiteral("version")})
        .set({m_version}, 1);
}

QList<double> WatchMetrics::latencyBuckets()
{
    return {0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10};
}

QString WatchMetrics::tableName(quint8 function)
{
    switch (function) {
    case 1:
        return QStringLiteral("coils");
    case 2:
        return QStringLiteral("discrete_inputs");
    case 4:
        return QStringLiteral("input_registers");
    default:
        return QStringLiteral("holding_registers");
    }
}

QStringList WatchMetrics::watchLabels(int watch) const
{
    const WatchDefinition &w = m_watches.watches.at(watch);
    return {w.name, w.target};
}

void WatchMetrics::reset(const SessionWatches &watches)
{
    // Every family starts over, one added later too (the process's are read again at the next
    // scrape); the version is the one series that stays.
    m_registry.clearSeries();
    setBuildInfo();
    m_watches = watches;
    m_slots = QList<WatchSlots>(m_watches.watches.size());
    for (int i = 0; i < m_watches.watches.size(); ++i) {
        if (!m_watches.watches.at(i).enabled)
            continue;
        const QStringList labels = watchLabels(i);
        m_up.set(labels, 0);
        for (MetricFamily *f : {&m_polls, &m_ok, &m_timeouts, &m_crcErrors, &m_linkErrors, &m_badAnswers, &m_overruns, &m_ruleFirings,
                                &m_logDropped, &m_latency})
            f->touch(labels);
        const QStringList target{m_watches.watches.at(i).target};
        m_linkUp.touch(target);
        m_linkReconnects.touch(target);
        m_linkFailures.touch(target);
    }
}

void WatchMetrics::addSamples(const QList<WatchSample> &samples)
{
    for (const WatchSample &s : samples) {
        if (s.watch < 0 || s.watch >= m_watches.watches.size())
            continue;
        WatchSlots &slots = m_slots[s.watch];
        auto labels = [&] { return watchLabels(s.watch); };
        slots.up.get(m_up, labels).value = s.isOk() ? 1 : 0;
        if (s.latencyNs >= 0)
            m_latency.observe(slots.latency.get(m_latency, labels), double(s.latencyNs) / 1e9);
        if (!s.isOk()) {
            // No value is better than a stale one: the series shows a gap while the device is away.
            const QString &name = m_watches.watches.at(s.watch).name;
            m_value.removeWhere(0, name);
            m_bitField.removeWhere(0, name);
            continue;
        }
        addValues(s.watch, s.values);
    }
}

void WatchMetrics::addValues(int watch, const QList<WatchPointValue> &values)
{
    const WatchDefinition &w = m_watches.watches.at(watch);
    QList<ValueSlots> &slots = m_slots[watch].values;
    if (slots.size() != values.size())
        slots.resize(values.size());
    for (qsizetype i = 0; i < values.size(); ++i) {
        const WatchPointValue &v = values.at(i);
        ValueSlots &slot = slots[i];
        if (slot.address != v.address || slot.name != v.name || slot.unit != v.unit) {
            slot = ValueSlots{v.address, v.name, v.unit, {}, {}, {}};
        }
        auto labels = [&] {
            return QStringList{w.name, w.target, QString::number(w.unit), tableName(w.function), QString::number(v.address),
                               v.name, v.unit};
        };
        slot.value.get(m_value, labels).value = v.value;
        if (v.bitFields.isEmpty())
            continue;
        if (slot.fields.size() != v.bitFields.size()) {
            slot.fields = QList<MetricSeriesSlot>(v.bitFields.size());
            slot.fieldNames = QList<QString>(v.bitFields.size());
        }
        for (qsizetype f = 0; f < v.bitFields.size(); ++f) {
            const WatchBitFieldValue &field = v.bitFields.at(f);
            if (slot.fieldNames.at(f) != field.name) {
                slot.fieldNames[f] = field.name;
                slot.fields[f].forget();
            }
            slot.fields[f].get(m_bitField, [&] { return plus(labels(), field.name); }).value = double(field.value);
        }
    }
}

void WatchMetrics::setCounters(const QList<WatchCounters> &counters)
{
    for (const WatchCounters &c : counters) {
        if (c.watch < 0 || c.watch >= m_watches.watches.size())
            continue;
        const QStringList labels = watchLabels(c.watch);
        m_polls.set(labels, double(c.polls));
        m_ok.set(labels, double(c.ok));
        m_timeouts.set(labels, double(c.timeouts));
        m_crcErrors.set(labels, double(c.crcErrors));
        m_linkErrors.set(labels, double(c.linkErrors));
        m_badAnswers.set(labels, double(c.otherErrors));
        m_overruns.set(labels, double(c.overruns));
        m_ruleFirings.set(labels, double(c.ruleFirings));
        for (auto it = c.exceptionsByCode.cbegin(); it != c.exceptionsByCode.cend(); ++it)
            m_exceptions.set(plus(labels, codeText(it.key())), double(it.value()));
        if (c.lastOkMs > 0)
            m_lastSuccess.set(labels, double(c.lastOkMs) / 1000.0);
    }
}

void WatchMetrics::setLinkState(const WatchLinkState &state)
{
    const QStringList target{state.target};
    m_linkUp.set(target, state.state == WatchLinkState::State::Up ? 1 : 0);
    m_linkReconnects.set(target, double(state.reconnects));
    m_linkFailures.set(target, double(state.failures));
}

void WatchMetrics::addRuleEvent(const WatchRuleEvent &event)
{
    m_ruleActive.set({event.watchName, QString::number(event.rule), event.point, watchSeverityName(event.severity)},
                     event.fired ? 1 : 0);
}

void WatchMetrics::setLogDroppedRows(int watch, quint64 rows)
{
    if (watch >= 0 && watch < m_watches.watches.size())
        m_logDropped.set(watchLabels(watch), double(rows));
}

} // namespace mbscope
