#include "trafficmetadata.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSysInfo>

namespace mbscope {

namespace {

constexpr auto kFormat = "mbscope-journal-metadata";
constexpr int kFormatVersion = 1;

QString hexOf(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

void insertText(QJsonObject &o, const char *key, const QString &value)
{
    if (!value.isEmpty())
        o.insert(QLatin1String(key), value);
}

// A key's string value, or false with *error naming the key when it is not a string.
bool readText(const QJsonObject &o, const char *key, QString *out, QString *error)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined() || v.isNull())
        return true;
    if (!v.isString()) {
        *error = QStringLiteral("metadata \"%1\": expected a string").arg(QLatin1String(key));
        return false;
    }
    *out = v.toString();
    return true;
}

bool readTextList(const QJsonObject &o, const char *key, QStringList *out, QString *error)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined() || v.isNull())
        return true;
    if (!v.isArray()) {
        *error = QStringLiteral("metadata \"%1\": expected an array of strings").arg(QLatin1String(key));
        return false;
    }
    const QJsonArray a = v.toArray();
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (!a.at(i).isString()) {
            *error = QStringLiteral("metadata \"%1\"[%2]: expected a string").arg(QLatin1String(key)).arg(i);
            return false;
        }
        out->append(a.at(i).toString());
    }
    return true;
}

} // namespace

QJsonObject TrafficMetadata::toJson() const
{
    QJsonObject o{{QStringLiteral("format"), QLatin1String(kFormat)}, {QStringLiteral("format_version"), kFormatVersion}};
    insertText(o, "mbscope", mbscopeVersion);
    insertText(o, "host", host);
    if (started.isValid())
        o.insert(QStringLiteral("started"), started.toUTC().toString(Qt::ISODateWithMs));
    insertText(o, "command", command);
    if (!arguments.isEmpty())
        o.insert(QStringLiteral("arguments"), QJsonArray::fromStringList(arguments));
    o.insert(QStringLiteral("role"), role == Role::Server ? QStringLiteral("server") : QStringLiteral("client"));
    insertText(o, "target", target);
    if (!listen.isEmpty())
        o.insert(QStringLiteral("listen"), QJsonArray::fromStringList(listen));
    if (!profileName.isEmpty() || !profileSource.isEmpty()) {
        QJsonObject profile;
        insertText(profile, "name", profileName);
        insertText(profile, "source", profileSource);
        o.insert(QStringLiteral("profile"), profile);
    }
    if (!requests.isEmpty()) {
        QJsonArray list;
        for (const TrafficMetadataRequest &r : requests) {
            QJsonObject request;
            insertText(request, "name", r.name);
            insertText(request, "description", r.description);
            request.insert(QStringLiteral("hex"), hexOf(r.bytes));
            list.append(request);
        }
        o.insert(QStringLiteral("requests"), list);
    }
    if (!settings.isEmpty())
        o.insert(QStringLiteral("settings"), settings);
    return o;
}

QByteArray TrafficMetadata::toUtf8() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Compact);
}

bool TrafficMetadata::fromJson(QByteArrayView utf8, TrafficMetadata *out, QString *error)
{
    QJsonParseError parse;
    const QJsonDocument document = QJsonDocument::fromJson(utf8.toByteArray(), &parse);
    if (parse.error != QJsonParseError::NoError) {
        *error = QStringLiteral("metadata is not JSON: %1 at byte %2").arg(parse.errorString()).arg(parse.offset);
        return false;
    }
    if (!document.isObject()) {
        *error = QStringLiteral("metadata is not a JSON object");
        return false;
    }
    const QJsonObject o = document.object();
    TrafficMetadata m;
    QString started, role;
    if (!readText(o, "mbscope", &m.mbscopeVersion, error) || !readText(o, "host", &m.host, error)
        || !readText(o, "started", &started, error) || !readText(o, "command", &m.command, error)
        || !readTextList(o, "arguments", &m.arguments, error) || !readText(o, "role", &role, error)
        || !readText(o, "target", &m.target, error) || !readTextList(o, "listen", &m.listen, error))
        return false;
    if (!started.isEmpty()) {
        m.started = QDateTime::fromString(started, Qt::ISODateWithMs);
        if (!m.started.isValid()) {
            *error = QStringLiteral("metadata \"started\": '%1' is not an ISO 8601 time").arg(started);
            return false;
        }
        m.started = m.started.toUTC();
    }
    if (role == QLatin1String("server")) {
        m.role = Role::Server;
    } else if (!role.isEmpty() && role != QLatin1String("client")) {
        *error = QStringLiteral("metadata \"role\": '%1', expected client or server").arg(role);
        return false;
    }
    if (const QJsonValue p = o.value(QStringLiteral("profile")); !p.isUndefined() && !p.isNull()) {
        if (!p.isObject()) {
            *error = QStringLiteral("metadata \"profile\": expected an object");
            return false;
        }
        if (!readText(p.toObject(), "name", &m.profileName, error) || !readText(p.toObject(), "source", &m.profileSource, error))
            return false;
    }
    if (const QJsonValue r = o.value(QStringLiteral("requests")); !r.isUndefined() && !r.isNull()) {
        if (!r.isArray()) {
            *error = QStringLiteral("metadata \"requests\": expected an array");
            return false;
        }
        const QJsonArray list = r.toArray();
        for (qsizetype i = 0; i < list.size(); ++i) {
            if (!list.at(i).isObject()) {
                *error = QStringLiteral("metadata \"requests\"[%1]: expected an object").arg(i);
                return false;
            }
            const QJsonObject item = list.at(i).toObject();
            TrafficMetadataRequest request;
            QString hex;
            if (!readText(item, "name", &request.name, error) || !readText(item, "description", &request.description, error)
                || !readText(item, "hex", &hex, error)) {
                error->insert(0, QStringLiteral("\"requests\"[%1]: ").arg(i));
                return false;
            }
            request.bytes = QByteArray::fromHex(hex.toLatin1());
            m.requests.append(request);
        }
    }
    if (const QJsonValue s = o.value(QStringLiteral("settings")); s.isObject())
        m.settings = s.toObject();
    *out = m;
    return true;
}

QStringList TrafficMetadata::summaryLines() const
{
    const auto padded = [](const char *label) { return QString::fromLatin1(label).leftJustified(14); };
    QStringList lines;
    QString recorded = command.isEmpty() ? QStringLiteral("traffic") : command;
    if (!mbscopeVersion.isEmpty())
        recorded += QStringLiteral(" by mbscope %1").arg(mbscopeVersion);
    if (!host.isEmpty())
        recorded += QStringLiteral(" on %1").arg(host);
    if (started.isValid())
        recorded += QStringLiteral(", %1 UTC").arg(started.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    lines << padded("recorded") + recorded;
    if (!target.isEmpty())
        lines << padded("target") + target;
    if (!listen.isEmpty())
        lines << padded("served on") + listen.join(QStringLiteral(", "));
    if (!profileName.isEmpty())
        lines << padded("profile") + profileName + (profileSource.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(profileSource));
    for (const TrafficMetadataRequest &r : requests)
        lines << padded("request") + (r.description.isEmpty() ? r.name : r.description) + QStringLiteral(": ") + hexOf(r.bytes);
    return lines;
}

TrafficMetadata TrafficMetadata::forCommand(const QString &command, const QStringList &arguments, const QString &mbscopeVersion)
{
    TrafficMetadata m;
    m.mbscopeVersion = mbscopeVersion;
    m.host = QSysInfo::machineHostName();
    m.started = QDateTime::currentDateTimeUtc();
    m.command = command;
    m.arguments = arguments;
    return m;
}

} // namespace mbscope
