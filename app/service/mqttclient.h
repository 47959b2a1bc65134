#pragma once

#include "service/mqttsettings.h"

#include <QtCore/QObject>
#include <QtCore/QStringList>

#include <atomic>

struct mosquitto;
struct mosquitto_message;

namespace mbscope::app {

// One connection to an MQTT broker through libmosquitto (Eclipse Mosquitto's client library),
// which runs the network on its own thread, reconnects with backoff (1 s doubling to 30 s) and
// keeps the session alive. Its callbacks arrive on that thread and leave it as queued signals.
//
// The status topic carries "online" (retained) from every connect, and "offline" (retained) as the
// last will the broker publishes when the connection dies without a goodbye, and from stop().
// The subscriptions are made again on every connect.
//
// Values are published only while connected: a broker away for hours does not fill memory with a
// queue of stale readings (they are counted as dropped instead).
class MqttClient : public QObject
{
    Q_OBJECT
public:
    explicit MqttClient(QObject *parent = nullptr);
    ~MqttClient() override;

    // Starts connecting (in the background); false only for settings the library refuses
    // (unreadable CA file, bad client id).
    [[nodiscard]] bool start(const MqttSettings &settings, const QString &statusTopic, const QStringList &subscriptions,
                             QString *error);
    // Queued for sending; false when not connected (the message is dropped and counted).
    bool publish(const QString &topic, const QByteArray &payload, int qos = 0, bool retain = false);
    // "offline" to the status topic, waited for up to timeoutMs, then a clean disconnect.
    void stop(int timeoutMs = 2000);

    [[nodiscard]] bool isConnected() const { return m_connected.load(); }
    [[nodiscard]] quint64 published() const { return m_published.load(); }
    [[nodiscard]] quint64 dropped() const { return m_dropped.load(); }

Q_SIGNALS:
    void connected();
    void connectionLost(const QString &reason);
    // The broker answered the connect with a refusal (bad user or password, not authorised).
    void refused(const QString &reason);
    // The first connection failed (no broker listening yet, host unreachable); tried again in retryMs.
    void unreachable(const QString &reason, int retryMs);
    void messageReceived(const QString &topic, const QByteArray &payload);

private:
    static void onConnect(mosquitto *mosq, void *self, int rc);
    static void onDisconnect(mosquitto *mosq, void *self, int rc);
    static void onPublish(mosquitto *mosq, void *self, int mid);
    static void onMessage(mosquitto *mosq, void *self, const mosquitto_message *message);

    bool startLoop(QString *error);
    void scheduleFirstConnect(const QString &reason);

    static constexpr int kMaxRetryMs = 30000;
    mosquitto *m_mosq = nullptr;
    bool m_running = false;
    bool m_looping = false; // libmosquitto's network thread runs
    QByteArray m_host;
    int m_port = 1883;
    int m_keepAlive = 60;
    int m_retryMs = 1000;
    QByteArray m_statusTopic;
    QList<QByteArray> m_subscriptions;
    std::atomic<bool> m_connected{false};
    std::atomic<int> m_goodbyeMid{-1};
    std::atomic<bool> m_goodbyeSent{false};
    std::atomic<int> m_lastAcked{-1};
    std::atomic<quint64> m_published{0};
    std::atomic<quint64> m_dropped{0};
};

} // namespace mbscope::app
