#include "service/watchmqtt.h"

#include "fleet/watchrunner.h"
#include "service/watchmessage.h"
#include "service/watchsetrequest.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope::app {

WatchMqtt::WatchMqtt(WatchRunner &runner, ServiceLog &log, Options options, QObject *parent)
    : QObject(parent)
    , m_runner(runner)
    , m_log(log)
    , m_options(std::move(options))
{
    connect(&m_runner, &WatchRunner::sampled, this, [this](const QList<WatchSample> &samples, const QList<WatchCounters> &) {
        onSampled(samples);
    });
    connect(&m_runner, &WatchRunner::ruleChanged, this, &WatchMqtt::onRule);
    connect(&m_runner, &WatchRunner::writeFinished, this, &WatchMqtt::onWriteFinished);
    connect(&m_client, &MqttClient::messageReceived, this, &WatchMqtt::onMessage);
    connect(&m_client, &MqttClient::connected, this, [this] {
        m_reached = true;
        m_log.notice(QStringLiteral("MQTT: connected to %1, publishing under %2/").arg(m_options.settings.displayUrl(), m_options.prefix));
    });
    connect(&m_client, &MqttClient::connectionLost, this, [this](const QString &reason) {
        m_log.warning(QStringLiteral("MQTT: connection to %1 lost (%2); reconnecting").arg(m_options.settings.displayUrl(), reason));
    });
    connect(&m_client, &MqttClient::unreachable, this, [this](const QString &reason, int retryMs) {
        m_log.warning(QStringLiteral("MQTT: cannot reach %1 (%2); trying again in %3 s")
                          .arg(m_options.settings.displayUrl(), reason)
                          .arg(retryMs / 1000.0));
    });
    connect(&m_client, &MqttClient::refused, this, [this](const QString &reason) {
        m_log.error(QStringLiteral("MQTT: %1 refused the connection: %2").arg(m_options.settings.displayUrl(), reason));
    });
}

QString WatchMqtt::topicOf(const QString &watchName) const
{
    return m_options.prefix + QLatin1Char('/') + WatchMessage::topicLevel(watchName);
}

bool WatchMqtt::start(QString *error)
{
    QStringList subscriptions;
    if (m_options.writes)
        subscriptions.append(m_options.prefix + QStringLiteral("/+/set"));
    return m_client.start(m_options.settings, statusTopic(), subscriptions, error);
}

QString WatchMqtt::neverReached() const
{
    if (m_reached)
        return {};
    const quint64 lost = m_client.dropped();
    return QStringLiteral("MQTT: the broker at %1 was never reached: %2 %3 not published")
        .arg(m_options.settings.displayUrl())
        .arg(lost)
        .arg(lost == 1 ? QStringLiteral("message") : QStringLiteral("messages"));
}

void WatchMqtt::setWatches(const SessionWatches &watches)
{
    m_watches = watches;
    m_changes.clear();
    m_pending.clear();
    for (const WatchDefinition &w : watches.watches) {
        if (WatchMessage::topicLevel(w.name) == QLatin1String("status"))
            m_log.warning(QStringLiteral("MQTT: watch 'status' shares its topic with the service's status (%1); rename the watch")
                              .arg(statusTopic()));
    }
}

void WatchMqtt::stop()
{
    m_client.stop();
}

void WatchMqtt::onSampled(const QList<WatchSample> &samples)
{
    for (const WatchSample &s : samples) {
        if (s.watch < 0 || s.watch >= m_watches.watches.size())
            continue;
        if (m_options.onChange && !m_changes.changed(s))
            continue;
        const WatchDefinition &w = m_watches.watches.at(s.watch);
        m_client.publish(topicOf(w.name), WatchMessage::sample(w, s));
    }
}

void WatchMqtt::onRule(const WatchRuleEvent &event)
{
    m_client.publish(topicOf(event.watchName) + QStringLiteral("/event"), WatchMessage::ruleEvent(event), 1);
}

void WatchMqtt::onMessage(const QString &topic, const QByteArray &payload)
{
    if (!m_options.writes || !topic.endsWith(QLatin1String("/set")))
        return;
    const QString watchTopic = topic.chopped(4);
    int index = -1;
    for (int i = 0; i < m_watches.watches.size(); ++i) {
        if (topicOf(m_watches.watches.at(i).name) == watchTopic)
            index = i;
    }
    if (index < 0) {
        m_log.warning(QStringLiteral("MQTT: write to %1 refused: no watch publishes at %2").arg(topic, watchTopic));
        publishResult(watchTopic, false, QString(), QStringLiteral("no watch publishes at %1").arg(watchTopic));
        return;
    }
    const WatchDefinition &w = m_watches.watches.at(index);
    const WatchSetRequest request = WatchSetRequest::parse(w, payload);
    if (!request.isOk()) {
        m_log.warning(QStringLiteral("MQTT: write to watch '%1' refused: %2").arg(w.name, request.error));
        publishResult(watchTopic, false, QString(), request.error);
        return;
    }
    for (const WatchSetRequest::Write &write : request.writes) {
        const quint64 id = m_runner.write(index, write.address, write.words);
        m_pending.insert(id, Pending{watchTopic, write.point});
        m_log.info(QStringLiteral("MQTT: writing %1 of watch '%2' (address %3) as asked on %4")
                       .arg(write.point, w.name)
                       .arg(write.address)
                       .arg(topic));
    }
}

void WatchMqtt::onWriteFinished(quint64 id, int watch, quint16 address, bool ok, const QString &message)
{
    const auto it = m_pending.find(id);
    if (it == m_pending.end())
        return; // a write of the window's, or of a session reloaded since
    const Pending pending = *it;
    m_pending.erase(it);
    const QString name = watch >= 0 && watch < m_watches.watches.size() ? m_watches.watches.at(watch).name : QString();
    if (ok)
        m_log.info(QStringLiteral("MQTT: wrote %1 of watch '%2' (address %3)").arg(pending.point, name).arg(address));
    else
        m_log.warning(QStringLiteral("MQTT: writing %1 of watch '%2' (address %3) failed: %4").arg(pending.point, name).arg(address).arg(message));
    publishResult(pending.topic, ok, pending.point, ok ? QStringLiteral("written") : message);
}

void WatchMqtt::publishResult(const QString &watchTopic, bool ok, const QString &point, const QString &message)
{
    QJsonObject o;
    o.insert(QStringLiteral("ok"), ok);
    if (!point.isEmpty())
        o.insert(QStringLiteral("point"), point);
    o.insert(QStringLiteral("message"), message);
    m_client.publish(watchTopic + QStringLiteral("/set/result"), QJsonDocument(o).toJson(QJsonDocument::Compact), 1);
}

} // namespace mbscope::app
