#pragma once

#include "service/mqttclient.h"
#include "service/servicelog.h"

#include "fleet/watchsample.h"
#include "service/watchchangefilter.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QHash>
#include <QtCore/QObject>

namespace mbscope {
class WatchRunner;
}

namespace mbscope::app {

// The watch service's MQTT side: a JSON message per watch per poll (or per change) on
// PREFIX/WATCH, rule events on PREFIX/WATCH/event, "online"/"offline" retained on PREFIX/status
// (the last will says "offline" when the service dies). With writes allowed, PREFIX/WATCH/set is
// subscribed and each message there, read by WatchSetRequest, goes to the runner; the outcome is
// published on PREFIX/WATCH/set/result. Without, nothing is subscribed: no message can reach a
// device.
class WatchMqtt : public QObject
{
    Q_OBJECT
public:
    struct Options {
        MqttSettings settings;
        QString prefix;        // never empty
        bool writes = false;
        bool onChange = false;
    };

    WatchMqtt(WatchRunner &runner, ServiceLog &log, Options options, QObject *parent = nullptr);

    [[nodiscard]] bool start(QString *error);
    void setWatches(const SessionWatches &watches);
    void stop();

    // Empty when the broker was reached during the run; else what was lost ("the broker at
    // mqtt://... was never reached: 12 messages not published"), for watch's exit status 3.
    [[nodiscard]] QString neverReached() const;

    [[nodiscard]] QString statusTopic() const { return m_options.prefix + QStringLiteral("/status"); }
    [[nodiscard]] QString topicOf(const QString &watchName) const;

private:
    void onSampled(const QList<mbscope::WatchSample> &samples);
    void onRule(const mbscope::WatchRuleEvent &event);
    void onMessage(const QString &topic, const QByteArray &payload);
    void onWriteFinished(quint64 id, int watch, quint16 address, bool ok, const QString &message);
    void publishResult(const QString &watchTopic, bool ok, const QString &point, const QString &message);

    WatchRunner &m_runner;
    ServiceLog &m_log;
    Options m_options;
    MqttClient m_client;
    SessionWatches m_watches;
    WatchChangeFilter m_changes;
    struct Pending {
        QString topic;
        QString point;
    };
    QHash<quint64, Pending> m_pending; // writes in flight, until the runner says how they went
    bool m_reached = false;            // connected at least once
};

} // namespace mbscope::app
