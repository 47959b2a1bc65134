#include "service/mqttclient.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QDeadlineTimer>
#include <QtCore/QFileInfo>
#include <QtCore/QSysInfo>
#include <QtCore/QThread>
#include <QtCore/QTimer>

#include <mosquitto.h>

#include <cerrno>
#include <cstring>
#include <mutex>

namespace mbscope::app {

namespace {

const QByteArray kOnline = QByteArrayLiteral("online");
const QByteArray kOffline = QByteArrayLiteral("offline");

void initLibrary()
{
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

QString errorText(int rc)
{
    if (rc == MOSQ_ERR_ERRNO)
        return QString::fromLocal8Bit(strerror(errno));
    return QString::fromUtf8(mosquitto_strerror(rc));
}

} // namespace

MqttClient::MqttClient(QObject *parent)
    : QObject(parent)
{
    initLibrary();
}

MqttClient::~MqttClient()
{
    stop(0);
}

bool MqttClient::start(const MqttSettings &settings, const QString &statusTopic, const QStringList &subscriptions,
                       QString *error)
{
    QByteArray clientId = settings.clientId.toUtf8();
    if (clientId.isEmpty())
        clientId = "mbscope-" + QSysInfo::machineHostName().toUtf8().left(40) + '-' + QByteArray::number(QCoreApplication::applicationPid());
    // Clean session: a restarted service subscribes afresh, and nothing queued for it while it was
    // away is delivered late (a write from minutes ago must not reach a device).
    m_mosq = mosquitto_new(clientId.constData(), true, this);
    if (!m_mosq) {
        *error = QStringLiteral("cannot make an MQTT client: %1").arg(QString::fromLocal8Bit(strerror(errno)));
        return false;
    }
    m_statusTopic = statusTopic.toUtf8();
    for (const QString &s : subscriptions)
        m_subscriptions.append(s.toUtf8());
    mosquitto_int_option(m_mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    mosquitto_connect_callback_set(m_mosq, &MqttClient::onConnect);
    mosquitto_disconnect_callback_set(m_mosq, &MqttClient::onDisconnect);
    mosquitto_publish_callback_set(m_mosq, &MqttClient::onPublish);
    mosquitto_message_callback_set(m_mosq, &MqttClient::onMessage);
    mosquitto_reconnect_delay_set(m_mosq, 1, 30, true);
    int rc = mosquitto_will_set(m_mosq, m_statusTopic.constData(), int(kOffline.size()), kOffline.constData(), 1, true);
    if (rc != MOSQ_ERR_SUCCESS) {
        *error = QStringLiteral("MQTT status topic '%1': %2").arg(statusTopic, errorText(rc));
        return false;
    }
    if (!settings.username.isEmpty()) {
        rc = mosquitto_username_pw_set(m_mosq, settings.username.toUtf8().constData(),
                                       settings.password.isEmpty() ? nullptr : settings.password.toUtf8().constData());
        if (rc != MOSQ_ERR_SUCCESS) {
            *error = QStringLiteral("MQTT credentials: %1").arg(errorText(rc));
            return false;
        }
    }
    if (settings.tls) {
        for (const QString &file : {settings.caFile, settings.certFile, settings.keyFile}) {
            if (!file.isEmpty() && !QFileInfo(file).isReadable()) {
                *error = QStringLiteral("cannot read %1 (named in the MQTT URL)").arg(file);
                return false;
            }
        }
        if (settings.caFile.isEmpty())
            mosquitto_int_option(m_mosq, MOSQ_OPT_TLS_USE_OS_CERTS, 1);
        const QByteArray ca = settings.caFile.toLocal8Bit();
        const QByteArray cert = settings.certFile.toLocal8Bit();
        const QByteArray key = settings.keyFile.toLocal8Bit();
        if (!ca.isEmpty() || !cert.isEmpty()) {
            rc = mosquitto_tls_set(m_mosq, ca.isEmpty() ? nullptr : ca.constData(), nullptr,
                                   cert.isEmpty() ? nullptr : cert.constData(), key.isEmpty() ? nullptr : key.constData(), nullptr);
            if (rc != MOSQ_ERR_SUCCESS) {
                *error = QStringLiteral("MQTT TLS settings: %1").arg(errorText(rc));
                return false;
            }
        }
    }
    // A broker that is not there yet (refused, unreachable) makes connect_async fail at once, and
    // libmosquitto's network thread then never tries again: the first connection is retried here,
    // with the same backoff as a later loss (1 s doubling to 30 s), each failure said.
    m_host = settings.host.toUtf8();
    m_port = settings.port;
    m_keepAlive = settings.keepAliveSeconds;
    rc = mosquitto_connect_async(m_mosq, m_host.constData(), m_port, m_keepAlive);
    if (rc != MOSQ_ERR_SUCCESS && rc != MOSQ_ERR_ERRNO) {
        *error = QStringLiteral("MQTT broker %1: %2").arg(settings.displayUrl(), errorText(rc));
        return false;
    }
    m_running = true;
    if (rc == MOSQ_ERR_ERRNO) {
        // Said after start() returns, so that the caller's "connecting" line comes first.
        const QString reason = QString::fromLocal8Bit(strerror(errno));
        QTimer::singleShot(0, this, [this, reason] { scheduleFirstConnect(reason); });
        return true;
    }
    return startLoop(error);
}

bool MqttClient::startLoop(QString *error)
{
    const int rc = mosquitto_loop_start(m_mosq);
    if (rc != MOSQ_ERR_SUCCESS) {
        if (error)
            *error = QStringLiteral("cannot start the MQTT network thread: %1").arg(errorText(rc));
        return false;
    }
    m_looping = true;
    return true;
}

void MqttClient::scheduleFirstConnect(const QString &reason)
{
    Q_EMIT unreachable(reason, m_retryMs);
    QTimer::singleShot(m_retryMs, this, [this] {
        if (!m_mosq || !m_running)
            return;
        const int rc = mosquitto_connect_async(m_mosq, m_host.constData(), m_port, m_keepAlive);
        if (rc == MOSQ_ERR_SUCCESS) {
            QString error;
            if (!startLoop(&error))
                Q_EMIT connectionLost(error);
            return;
        }
        m_retryMs = qMin(m_retryMs * 2, kMaxRetryMs);
        scheduleFirstConnect(rc == MOSQ_ERR_ERRNO ? QString::fromLocal8Bit(strerror(errno)) : errorText(rc));
    });
}

bool MqttClient::publish(const QString &topic, const QByteArray &payload, int qos, bool retain)
{
    if (!m_running || !m_connected.load()) {
        ++m_dropped;
        return false;
    }
    const int rc = mosquitto_publish(m_mosq, nullptr, topic.toUtf8().constData(), int(payload.size()), payload.constData(), qos, retain);
    if (rc != MOSQ_ERR_SUCCESS) {
        ++m_dropped;
        return false;
    }
    ++m_published;
    return true;
}

void MqttClient::stop(int timeoutMs)
{
    if (!m_mosq)
        return;
    if (m_running && m_connected.load()) {
        int mid = 0;
        if (mosquitto_publish(m_mosq, &mid, m_statusTopic.constData(), int(kOffline.size()), kOffline.constData(), 1, true) ==
            MOSQ_ERR_SUCCESS) {
            m_goodbyeMid = mid;
            // The acknowledgement may come before mid was stored above: the last one acknowledged counts too.
            const QDeadlineTimer deadline(timeoutMs);
            while (!m_goodbyeSent.load() && m_lastAcked.load() != mid && !deadline.hasExpired() && m_connected.load())
                QThread::msleep(5);
        }
    }
    // A DISCONNECT tells the broker to drop the will: the "offline" above said goodbye already.
    mosquitto_disconnect(m_mosq);
    if (m_looping)
        mosquitto_loop_stop(m_mosq, false);
    m_looping = false;
    m_running = false;
    mosquitto_destroy(m_mosq);
    m_mosq = nullptr;
    m_connected = false;
}

void MqttClient::onConnect(mosquitto *mosq, void *self, int rc)
{
    auto *client = static_cast<MqttClient *>(self);
    if (rc != 0) {
        Q_EMIT client->refused(QString::fromUtf8(mosquitto_connack_string(rc)));
        return;
    }
    client->m_connected = true;
    mosquitto_publish(mosq, nullptr, client->m_statusTopic.constData(), int(kOnline.size()), kOnline.constData(), 1, true);
    for (const QByteArray &topic : std::as_const(client->m_subscriptions))
        mosquitto_subscribe(mosq, nullptr, topic.constData(), 1);
    Q_EMIT client->connected();
}

void MqttClient::onDisconnect(mosquitto *, void *self, int rc)
{
    auto *client = static_cast<MqttClient *>(self);
    const bool was = client->m_connected.exchange(false);
    // rc 0: our own disconnect (stop); anything else: the connection was lost.
    if (rc != 0 && was)
        Q_EMIT client->connectionLost(errorText(rc));
}

void MqttClient::onPublish(mosquitto *, void *self, int mid)
{
    auto *client = static_cast<MqttClient *>(self);
    client->m_lastAcked = mid;
    if (mid == client->m_goodbyeMid.load())
        client->m_goodbyeSent = true;
}

void MqttClient::onMessage(mosquitto *, void *self, const mosquitto_message *message)
{
    auto *client = static_cast<MqttClient *>(self);
    Q_EMIT client->messageReceived(QString::fromUtf8(message->topic),
                                   QByteArray(static_cast<const char *>(message->payload), message->payloadlen));
}

} // namespace mbscope::app
