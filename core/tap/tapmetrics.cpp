#include "tapmetrics.h"

namespace mbscope {

namespace {

QList<double> latencyBuckets()
{
    return {0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5};
}

} // namespace

TapMetrics::TapMetrics(const QString &version)
    : m_requests(m_registry.counter(QStringLiteral("mbscope_tap_requests_total"),
                                    QStringLiteral("Requests taken from masters, by what became of them."), {QStringLiteral("outcome")}))
    , m_waiting(m_registry.gauge(QStringLiteral("mbscope_tap_waiting"),
                                 QStringLiteral("Requests waiting for a device: queued or in flight.")))
    , m_deviceLatency(m_registry.histogram(QStringLiteral("mbscope_tap_device_latency_seconds"),
                                           QStringLiteral("Request sent to the device until its answer was in: the device's own time."),
                                           {QStringLiteral("target")}, latencyBuckets()))
    , m_answer(m_registry.histogram(QStringLiteral("mbscope_tap_answer_seconds"),
                                    QStringLiteral("A master's request in until its answer left the tap, fault delays not included."),
                                    {QStringLiteral("target")}, latencyBuckets()))
{
    m_registry.gauge(QStringLiteral("mbscope_build_info"), QStringLiteral("The mbscope version, as a label; always 1."),
                     {QStringLiteral("version")})
        .set({version}, 1);
    update({}, 0);
}

void TapMetrics::update(const TapCounters &c, int waiting)
{
    const std::pair<const char *, quint64> outcomes[] = {
        {"answered", c.answered},    {"exception", c.exceptions}, {"no_answer", c.noAnswer},
        {"link_error", c.linkErrors}, {"damaged", c.damaged},     {"broadcast", c.broadcasts},
        {"no_route", c.noRoute},     {"refused", c.refusedWrites},
    };
    for (const auto &[name, value] : outcomes)
        m_requests.set({QString::fromLatin1(name)}, double(value));
    m_waiting.set({}, waiting);
}

void TapMetrics::observe(const QString &target, qint64 deviceNs, qint64 answerNs)
{
    if (deviceNs >= 0)
        m_deviceLatency.observe({target}, double(deviceNs) / 1e9);
    if (answerNs >= 0)
        m_answer.observe({target}, double(answerNs) / 1e9);
}

} // namespace mbscope
