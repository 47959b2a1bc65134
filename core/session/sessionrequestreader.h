#pragma once

#include "session/sessionpoll.h"
#include "session/sessionrequest.h"

#include <QtCore/QJsonValue>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace mbscope {

class JsonReader;

// Reads a request (the document's list, or a send step's own) and a poll's settings, recording
// every problem with its JSON path. A form request is built once here, so that an out-of-spec
// parameter is reported at load time ("requests[3].quantity: quantity 126 is out of range: Read
// Holding Registers reads 1-125 registers"), not when a plan runs.
class SessionRequestReader
{
public:
    // named: the request belongs to the document's list (its name is required).
    [[nodiscard]] static std::optional<SessionRequest> read(JsonReader &reader, const QJsonValue &value,
                                                            const QString &path, bool named);
    // requestNames: the document's requests, which a poll names.
    [[nodiscard]] static std::optional<SessionPoll> readPoll(JsonReader &reader, const QJsonValue &value,
                                                             const QString &path, const QStringList &requestNames,
                                                             bool sweep, QList<qint64> *intervalsMs = nullptr);
    // A check that name is one of requestNames: "no request named 'x': the document has a, b".
    static bool checkName(JsonReader &reader, const QString &path, const QString &name, const QStringList &requestNames);
};

} // namespace mbscope
