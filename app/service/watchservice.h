#pragma once

#include "common/listenaddress.h"
#include "service/servicelog.h"
#include "service/watchmqtt.h"

#include "service/watchmetrics.h"

#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QStringList>
#include <QtCore/QUrl>

#include <memory>
#include <optional>

class QCommandLineParser;

namespace mbscope {
class WatchRunner;
struct WatchLinkState;
}

namespace mbscope::app {

class MetricsEndpoint;

// What `mbscope watch` adds to the runner to run as a service: the Prometheus endpoint
// (--metrics), MQTT (--mqtt, --mqtt-credentials, --mqtt-writes, --mqtt-on-change) and the log of
// link changes and rule events with levels (--log-level). The runner polls; this only listens to it.
class WatchService : public QObject
{
    Q_OBJECT
public:
    struct Options {
        std::optional<ListenAddress> metrics;
        std::optional<WatchMqtt::Options> mqtt;
        ServiceLog::Level logLevel = ServiceLog::Level::Info;
        QStringList warnings; // about the options, said as the service starts (a credentials file others may read)
    };

    static void addOptions(QCommandLineParser &parser);
    // The options as given; sessionPath names the default MQTT prefix (mbscope/SESSION).
    [[nodiscard]] static std::optional<Options> readOptions(const QCommandLineParser &parser, const QString &sessionPath,
                                                            QString *error);

    WatchService(WatchRunner &runner, Options options, QObject *parent = nullptr);
    ~WatchService() override;

    [[nodiscard]] ServiceLog &log() { return m_log; }
    // Listens and starts connecting to the broker; false with the reason (port in use...).
    [[nodiscard]] bool start(QString *error);
    // The watches the runner runs now (at start and after each reload).
    void setWatches(const SessionWatches &watches);
    // Says goodbye to the broker ("offline", retained).
    void stop();

    [[nodiscard]] QUrl metricsUrl() const;
    // With --mqtt, a broker never reached during the run: what was lost (else empty).
    [[nodiscard]] QString mqttNeverReached() const;

private:
    void onLinkState(const mbscope::WatchLinkState &state);
    void onRule(const mbscope::WatchRuleEvent &event);

    WatchRunner &m_runner;
    Options m_options;
    ServiceLog m_log;
    WatchMetrics m_metrics;
    std::unique_ptr<MetricsEndpoint> m_endpoint;
    std::unique_ptr<WatchMqtt> m_mqtt;
    QSet<QString> m_downLinks; // links said to be down, until they are up again
};

} // namespace mbscope::app
