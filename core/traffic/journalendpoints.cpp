#include "journalendpoints.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope {

QByteArray JournalEndpoints::toJson() const
{
    const QJsonObject endpoints{{QStringLiteral("client"), client}, {QStringLiteral("server"), server}};
    return QJsonDocument(QJsonObject{{QStringLiteral("endpoints"), endpoints}}).toJson(QJsonDocument::Compact);
}

std::optional<JournalEndpoints> JournalEndpoints::fromJson(QByteArrayView json)
{
    if (!json.contains(QByteArrayView("\"endpoints\""))) // fault notes, without a parse
        return std::nullopt;
    const QJsonObject endpoints = QJsonDocument::fromJson(json.toByteArray()).object().value(QStringLiteral("endpoints")).toObject();
    JournalEndpoints e{endpoints.value(QStringLiteral("client")).toString(), endpoints.value(QStringLiteral("server")).toString()};
    if (e.client.isEmpty() && e.server.isEmpty())
        return std::nullopt;
    return e;
}

} // namespace mbscope
