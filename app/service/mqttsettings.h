#pragma once

#include <QtCore/QProcessEnvironment>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace mbscope::app {

// Where and how the watch service publishes (--mqtt URL):
//   mqtt://HOST[:PORT][/PREFIX][?OPTIONS]    plain TCP, port 1883 by default
//   mqtts://HOST[:PORT][/PREFIX][?OPTIONS]   TLS, port 8883, the system's CAs unless cafile= names one
// OPTIONS: cafile=PATH, certfile=PATH and keyfile=PATH (a client certificate), client-id=ID,
// keepalive=SECONDS. PREFIX is the start of every topic (empty: the caller's default).
// A user name and password are never taken from the URL (any user can read a command line in
// ps): they come from a file (loadCredentials) or from MBSCOPE_MQTT_USERNAME and
// MBSCOPE_MQTT_PASSWORD.
struct MqttSettings {
    QString host;
    quint16 port = 1883;
    bool tls = false;
    QString prefix;
    QString caFile;
    QString certFile;
    QString keyFile;
    QString clientId;
    int keepAliveSeconds = 30;
    QString username;
    QString password;

    [[nodiscard]] static std::optional<MqttSettings> fromUrl(const QString &url, QString *error);
    // The file holds the user name on its first line and the password on its second (a file made
    // for it, readable by the service only: systemd's LoadCredential= puts one in %d). Without a
    // file, the environment's MBSCOPE_MQTT_USERNAME and MBSCOPE_MQTT_PASSWORD, when set.
    // Refused, naming the line: no user name, a line after the password. Said in *warnings, as ssh
    // says of a private key: a file that others than its owner may read (they may read the
    // password), and a file without a password (the broker gets the user name alone).
    [[nodiscard]] bool loadCredentials(const QString &file, const QProcessEnvironment &environment, QString *error,
                                       QStringList *warnings = nullptr);
    // "mqtts://broker:8883" for logs: never the credentials.
    [[nodiscard]] QString displayUrl() const;
    // A topic level may not hold the wildcards '+' and '#' (MQTT 3.1.1, 4.7.1).
    [[nodiscard]] static bool isValidTopicPrefix(const QString &prefix);
};

} // namespace mbscope::app
