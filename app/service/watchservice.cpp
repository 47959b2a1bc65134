#include "service/watchservice.h"

#include "service/metricsendpoint.h"

#include "service/watchmessage.h"

#include "fleet/watchrunner.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFileInfo>
#include <QtCore/QProcessEnvironment>

namespace mbscope::app {

void WatchService::addOptions(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("metrics"),
                      QStringLiteral("Serve Prometheus metrics (OpenMetrics) at http://HOST:PORT/metrics; a port alone listens on the "
                                     "loopback interface, 0.0.0.0:PORT on every interface, port 0 on any free port."),
                      QStringLiteral("HOST:PORT")});
    parser.addOption({QStringLiteral("mqtt"),
                      QStringLiteral("Publish each watch's polls as JSON to an MQTT broker: mqtt://HOST[:PORT][/PREFIX] or mqtts://... "
                                     "(TLS; ?cafile=, certfile=, keyfile=, client-id=). Topics PREFIX/WATCH, PREFIX/status "
                                     "(default prefix: mbscope/SESSION)."),
                      QStringLiteral("URL")});
    parser.addOption({QStringLiteral("mqtt-credentials"),
                      QStringLiteral("File with the MQTT user name (line 1) and password (line 2); without it, "
                                     "MBSCOPE_MQTT_USERNAME and MBSCOPE_MQTT_PASSWORD from the environment. Never in the URL."),
                      QStringLiteral("FILE")});
    parser.addOption({QStringLiteral("mqtt-writes"),
                      QStringLiteral("Accept writes from PREFIX/WATCH/set to points the watch marks writable (off by default).")});
    parser.addOption({QStringLiteral("mqtt-on-change"),
                      QStringLiteral("Publish a watch's poll only when its values or status changed (default: every poll).")});
    parser.addOption({QStringLiteral("log-level"),
                      QStringLiteral("Lowest level logged to standard error: error, warning, notice, info (default) or debug."),
                      QStringLiteral("LEVEL")});
}

std::optional<WatchService::Options> WatchService::readOptions(const QCommandLineParser &parser, const QString &sessionPath,
                                                               QString *error)
{
    Options options;
    if (parser.isSet(QStringLiteral("log-level")) &&
        !ServiceLog::parseLevel(parser.value(QStringLiteral("log-level")), &options.logLevel)) {
        *error = QStringLiteral("--log-level: '%1' is not a level (error, warning, notice, info, debug)")
                     .arg(parser.value(QStringLiteral("log-level")));
        return std::nullopt;
    }
    if (parser.isSet(QStringLiteral("metrics"))) {
        QString why;
        options.metrics = ListenAddress::parse(parser.value(QStringLiteral("metrics")), &why);
        if (!options.metrics) {
            *error = QStringLiteral("--metrics: ") + why;
            return std::nullopt;
        }
    }
    const bool mqttOnly = parser.isSet(QStringLiteral("mqtt-credentials")) || parser.isSet(QStringLiteral("mqtt-writes")) ||
                          parser.isSet(QStringLiteral("mqtt-on-change"));
    if (!parser.isSet(QStringLiteral("mqtt"))) {
        if (mqttOnly) {
            *error = QStringLiteral("--mqtt-credentials, --mqtt-writes and --mqtt-on-change need --mqtt URL");
            return std::nullopt;
        }
        return options;
    }
    QString why;
    std::optional<MqttSettings> settings = MqttSettings::fromUrl(parser.value(QStringLiteral("mqtt")), &why);
    if (!settings) {
        *error = QStringLiteral("--mqtt: ") + why;
        return std::nullopt;
    }
    QStringList warnings;
    if (!settings->loadCredentials(parser.value(QStringLiteral("mqtt-credentials")), QProcessEnvironment::systemEnvironment(), &why,
                                   &warnings)) {
        *error = QStringLiteral("--mqtt-credentials: ") + why;
        return std::nullopt;
    }
    for (const QString &warning : std::as_const(warnings))
        options.warnings.append(QStringLiteral("--mqtt-credentials: ") + warning);
    WatchMqtt::Options mqtt;
    mqtt.prefix = settings->prefix;
    if (mqtt.prefix.isEmpty()) {
        QString base = QFileInfo(sessionPath).fileName();
        for (const char *suffix : {".mbscope.json", ".json"}) {
            if (base.endsWith(QLatin1String(suffix))) {
                base.chop(qsizetype(qstrlen(suffix)));
                break;
            }
        }
        mqtt.prefix = QStringLiteral("mbscope/") + WatchMessage::topicLevel(base);
    }
    mqtt.settings = *settings;
    mqtt.writes = parser.isSet(QStringLiteral("mqtt-writes"));
    mqtt.onChange = parser.isSet(QStringLiteral("mqtt-on-change"));
    options.mqtt = mqtt;
    return options;
}

WatchService::WatchService(WatchRunner &runner, Options options, QObject *parent)
    : QObject(parent)
    , m_runner(runner)
    , m_options(std::move(options))
    , m_metrics(QStringLiteral(MBSCOPE_VERSION))
{
    m_log.setLevel(m_options.logLevel);
    connect(&m_runner, &WatchRunner::sampled, this, [this](const QList<WatchSample> &samples, const QList<WatchCounters> &counters) {
        m_metrics.addSamples(samples);
        m_metrics.setCounters(counters);
    });
    connect(&m_runner, &WatchRunner::linkStateChanged, this, &WatchService::onLinkState);
    connect(&m_runner, &WatchRunner::ruleChanged, this, &WatchService::onRule);
    connect(&m_runner, &WatchRunner::logDroppedRows, this, [this](int watch, quint64 rows) { m_metrics.setLogDroppedRows(watch, rows); });
    if (m_options.metrics) {
        m_endpoint = std::make_unique<MetricsEndpoint>(m_metrics.registry());
        m_endpoint->setBeforeScrape([this] { m_metrics.refreshProcess(); });
    }
    if (m_options.mqtt)
        m_mqtt = std::make_unique<WatchMqtt>(m_runner, m_log, *m_options.mqtt);
}

WatchService::~WatchService() = default;

bool WatchService::start(QString *error)
{
    for (const QString &warning : std::as_const(m_options.warnings))
        m_log.warning(warning);
    if (m_endpoint) {
        if (!m_endpoint->listen(*m_options.metrics, error)) {
            *error = QStringLiteral("--metrics: ") + *error;
            return false;
        }
        m_log.notice(QStringLiteral("metrics at %1").arg(m_endpoint->url().toString()));
    }
    if (m_mqtt) {
        if (!m_mqtt->start(error)) {
            *error = QStringLiteral("--mqtt: ") + *error;
            return false;
        }
        m_log.notice(QStringLiteral("MQTT: connecting to %1 (topics %2/WATCH, status %3%4)")
                         .arg(m_options.mqtt->settings.displayUrl(), m_options.mqtt->prefix, m_mqtt->statusTopic(),
                              m_options.mqtt->writes ? QStringLiteral(", writes from %1/WATCH/set").arg(m_options.mqtt->prefix)
                                                     : QString()));
    }
    return true;
}

void WatchService::setWatches(const SessionWatches &watches)
{
    m_metrics.reset(watches);
    m_downLinks.clear();
    if (m_mqtt)
        m_mqtt->setWatches(watches);
}

void WatchService::stop()
{
    if (m_mqtt)
        m_mqtt->stop();
}

QString WatchService::mqttNeverReached() const
{
    return m_mqtt ? m_mqtt->neverReached() : QString();
}

QUrl WatchService::metricsUrl() const
{
    return m_endpoint ? m_endpoint->url() : QUrl();
}

void WatchService::onLinkState(const WatchLinkState &state)
{
    m_metrics.setLinkState(state);
    // A link that stays away cycles down, backoff, connecting, down...: said once when it goes,
    // once when it is back, and each attempt at debug level.
    const bool wasDown = m_downLinks.contains(state.target);
    switch (state.state) {
    case WatchLinkState::State::Up:
        if (wasDown) {
            m_downLinks.remove(state.target);
            // reconnects counts opens after a loss: 0 when the link was down from the start.
            if (state.reconnects == 0)
                m_log.notice(QStringLiteral("link %1: up (first connection, after %2 failed %3)")
                                 .arg(state.target)
                                 .arg(state.failures)
                                 .arg(state.failures == 1 ? QStringLiteral("attempt") : QStringLiteral("attempts")));
            else
                m_log.notice(QStringLiteral("link %1: up again (reconnect %2)").arg(state.target).arg(state.reconnects));
        } else {
            m_log.notice(QStringLiteral("link %1: up").arg(state.target));
        }
        break;
    case WatchLinkState::State::Down:
        if (!wasDown) {
            m_downLinks.insert(state.target);
            m_log.warning(QStringLiteral("link %1: down: %2").arg(state.target, state.message));
        } else {
            m_log.debug(QStringLiteral("link %1: still down: %2").arg(state.target, state.message));
        }
        break;
    case WatchLinkState::State::Backoff:
        m_log.debug(QStringLiteral("link %1: next attempt in %2 ms").arg(state.target).arg(state.retryInMs));
        break;
    case WatchLinkState::State::Connecting:
    case WatchLinkState::State::Stopped:
        m_log.debug(QStringLiteral("link %1: %2").arg(state.target, watchLinkStateName(state.state)));
        break;
    }
}

void WatchService::onRule(const WatchRuleEvent &event)
{
    m_metrics.addRuleEvent(event); // mbscope_watch_rule_active: never set before
    const QString text = QStringLiteral("watch '%1': %2 %3 (%4 = %5)")
                             .arg(event.watchName, event.message, event.fired ? QStringLiteral("fired") : QStringLiteral("cleared"),
                                  event.point)
                             .arg(event.value);
    if (!event.fired)
        m_log.info(text);
    else if (event.severity == WatchSeverity::Alarm)
        m_log.error(text);
    else if (event.severity == WatchSeverity::Warning)
        m_log.warning(text);
    else
        m_log.notice(text);
}

} // namespace mbscope::app
