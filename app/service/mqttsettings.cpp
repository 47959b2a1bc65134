#include "service/mqttsettings.h"

#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QUrl>
#include <QtCore/QUrlQuery>

namespace mbscope::app {

std::optional<MqttSettings> MqttSettings::fromUrl(const QString &text, QString *error)
{
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid()) {
        *error = QStringLiteral("'%1' is not a URL (mqtt://HOST[:PORT][/PREFIX] or mqtts://...): %2").arg(text, url.errorString());
        return std::nullopt;
    }
    if (url.hasFragment()) {
        *error = QStringLiteral("'%1': the topic prefix may not hold the wildcards '+' or '#'").arg(text);
        return std::nullopt;
    }
    MqttSettings s;
    const QString scheme = url.scheme();
    if (scheme == QLatin1String("mqtts")) {
        s.tls = true;
        s.port = 8883;
    } else if (scheme != QLatin1String("mqtt")) {
        *error = QStringLiteral("'%1': the scheme must be mqtt:// or mqtts://, not '%2'").arg(text, scheme);
        return std::nullopt;
    }
    if (!url.userInfo().isEmpty()) {
        *error = QStringLiteral("'%1': the URL carries a user or password (shown removed here); refused, since a command line is visible to every user: "
                                "put them in a file named by --mqtt-credentials, or in MBSCOPE_MQTT_USERNAME and MBSCOPE_MQTT_PASSWORD")
                     .arg(url.toString(QUrl::RemoveUserInfo));
        return std::nullopt;
    }
    s.host = url.host();
    if (s.host.isEmpty()) {
        *error = QStringLiteral("'%1' names no broker host").arg(text);
        return std::nullopt;
    }
    if (url.port() == 0) {
        *error = QStringLiteral("'%1': port 0 is no broker's port").arg(text);
        return std::nullopt;
    }
    if (url.port() > 0)
        s.port = quint16(url.port());
    s.prefix = url.path();
    while (s.prefix.startsWith(QLatin1Char('/')))
        s.prefix.remove(0, 1);
    while (s.prefix.endsWith(QLatin1Char('/')))
        s.prefix.chop(1);
    if (!isValidTopicPrefix(s.prefix)) {
        *error = QStringLiteral("'%1': the topic prefix '%2' may not hold the wildcards '+' or '#'").arg(text, s.prefix);
        return std::nullopt;
    }
    const QUrlQuery query(url);
    for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
        if (key == QLatin1String("cafile")) {
            s.caFile = value;
        } else if (key == QLatin1String("certfile")) {
            s.certFile = value;
        } else if (key == QLatin1String("keyfile")) {
            s.keyFile = value;
        } else if (key == QLatin1String("client-id")) {
            s.clientId = value;
        } else if (key == QLatin1String("keepalive")) {
            bool ok = false;
            s.keepAliveSeconds = value.toInt(&ok);
            if (!ok || s.keepAliveSeconds < 5 || s.keepAliveSeconds > 65535) {
                *error = QStringLiteral("'%1': keepalive=%2 is not a number of seconds from 5 to 65535").arg(text, value);
                return std::nullopt;
            }
        } else {
            *error = QStringLiteral("'%1': unknown option '%2' (expected cafile, certfile, keyfile, client-id or keepalive)").arg(text, key);
            return std::nullopt;
        }
    }
    if (!s.tls && !(s.caFile.isEmpty() && s.certFile.isEmpty() && s.keyFile.isEmpty())) {
        *error = QStringLiteral("'%1': cafile, certfile and keyfile need mqtts://").arg(text);
        return std::nullopt;
    }
    if (s.certFile.isEmpty() != s.keyFile.isEmpty()) {
        *error = QStringLiteral("'%1': a client certificate needs both certfile and keyfile").arg(text);
        return std::nullopt;
    }
    return s;
}

bool MqttSettings::loadCredentials(const QString &file, const QProcessEnvironment &environment, QString *error,
                                   QStringList *warnings)
{
    if (file.isEmpty()) {
        username = environment.value(QStringLiteral("MBSCOPE_MQTT_USERNAME"));
        password = environment.value(QStringLiteral("MBSCOPE_MQTT_PASSWORD"));
        if (username.isEmpty() && !password.isEmpty()) {
            *error = QStringLiteral("MBSCOPE_MQTT_PASSWORD is set without MBSCOPE_MQTT_USERNAME");
            return false;
        }
        return true;
    }
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read the MQTT credentials %1: %2").arg(file, f.errorString());
        return false;
    }
    const QList<QByteArray> lines = f.read(64 * 1024).split('\n');
    const auto line = [&](int i) {
        QByteArray l = lines.value(i);
        if (l.endsWith('\r'))
            l.chop(1);
        return QString::fromUtf8(l);
    };
    username = line(0);
    password = line(1);
    if (username.isEmpty()) {
        *error = QStringLiteral("%1, line 1: expected the MQTT user name (line 1: user name, line 2: password)").arg(file);
        return false;
    }
    for (int i = 2; i < lines.size(); ++i) {
        if (!line(i).trimmed().isEmpty()) {
            *error = QStringLiteral("%1, line %2: unexpected: the file holds the MQTT user name (line 1) and password (line 2) only")
                         .arg(file)
                         .arg(i + 1);
            return false;
        }
    }
    if (!warnings)
        return true;
    // Group or others may read it: ssh refuses such a key; a service whose file systemd made
    // (LoadCredential=) never sees this, a file left 0644 by an editor does.
    const QFileDevice::Permissions others = QFileDevice::ReadGroup | QFileDevice::ReadOther;
    if (const QFileDevice::Permissions p = QFileInfo(file).permissions(); p & others) {
        warnings->append(QStringLiteral("%1 may be read by %2: it holds the MQTT password; chmod 600 %1")
                             .arg(file, (p & QFileDevice::ReadOther) ? QStringLiteral("every user") : QStringLiteral("its group")));
    }
    if (password.isEmpty())
        warnings->append(QStringLiteral("%1, line 2: no password: the broker gets the user name '%2' alone").arg(file, username));
    return true;
}

QString MqttSettings::displayUrl() const
{
    return QStringLiteral("%1://%2:%3").arg(tls ? QStringLiteral("mqtts") : QStringLiteral("mqtt"), host).arg(port);
}

bool MqttSettings::isValidTopicPrefix(const QString &prefix)
{
    return !prefix.contains(QLatin1Char('+')) && !prefix.contains(QLatin1Char('#')) && !prefix.contains(QChar(0));
}

} // namespace mbscope::app
