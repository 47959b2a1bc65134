#include "scriptsettingsreader.h"

#include "json/jsonreader.h"
#include "script/scripthost.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

constexpr double kMaxTimeoutMs = 10000;
constexpr double kMinTickMs = 1;
constexpr double kMaxTickMs = 86400000; // a day

} // namespace

std::optional<ScriptSettings> ScriptSettingsReader::read(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    ScriptSettings settings;
    QString filePath = path;
    if (value.isString()) {
        settings.name = value.toString();
    } else {
        const auto o = reader.objectValue(value, path);
        if (!o)
            return std::nullopt;
        const int before = reader.problemCount();
        reader.checkKeys(*o, path, {"file", "tickMs", "timeoutMs", "onError"});
        if (reader.require(*o, path, "file"))
            settings.name = reader.string(*o, path, "file").value_or(QString());
        filePath = JsonReader::member(path, "file");
        settings.tickMs = reader.number(*o, path, "tickMs", kMinTickMs, kMaxTickMs).value_or(0);
        settings.timeoutMs = reader.number(*o, path, "timeoutMs", 1, kMaxTimeoutMs).value_or(settings.timeoutMs);
        if (const auto onError = reader.string(*o, path, "onError")) {
            if (*onError == QLatin1String("exception"))
                settings.onError = ScriptSettings::OnError::Exception;
            else if (*onError == QLatin1String("silence"))
                settings.onError = ScriptSettings::OnError::Silence;
            else if (*onError == QLatin1String("answer"))
                settings.onError = ScriptSettings::OnError::Normal;
            else
                reader.error(JsonReader::member(path, "onError"),
                             QStringLiteral("'%1': expected \"exception\" (04, server device failure), \"silence\" or "
                                            "\"answer\" (the profile's answer)").arg(*onError));
        }
        if (reader.problemCount() != before)
            return std::nullopt;
    }
    if (settings.name.trimmed().isEmpty()) {
        reader.error(filePath, QStringLiteral("the script's file name is empty"));
        return std::nullopt;
    }
    // Beside the profile: a shipped profile's script is a resource too (":/profiles/x.js").
    settings.path = QFileInfo(settings.name).isAbsolute()
                        ? settings.name
                        : QFileInfo(reader.source()).dir().filePath(settings.name);
    if (const auto problem = ScriptHost::check(settings)) {
        reader.error(path, problem->toString());
        return std::nullopt;
    }
    return settings;
}

} // namespace mbscope
