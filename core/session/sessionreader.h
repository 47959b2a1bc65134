#pragma once

#include "session/sessiondocument.h"
#include "json/profileproblem.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

struct SessionLoadResult {
    std::optional<SessionDocument> document; // set only when there is no problem: never half loaded
    QList<ProfileProblem> problems;          // every problem found, in document order
    int version = 0;                         // the session version the document was written in
    [[nodiscard]] bool ok() const { return document.has_value(); }
    [[nodiscard]] QString errorText() const { return ProfileProblem::join(problems); }
};

// Reads session documents (docs/session.schema.json). Every problem comes back with where it is:
// line and column for JSON syntax errors, the JSON path for content
// ("requests[3].address: 70000 is beyond 65535"), and what was expected. Unknown keys are errors.
// A document of a newer version than this mbscope reads is refused as a whole, with one message
// saying so (its content is not checked against rules it was not written for).
class SessionReader
{
public:
    [[nodiscard]] static SessionLoadResult load(const QString &path);
    [[nodiscard]] static SessionLoadResult parse(const QByteArray &json, const QString &source);
};

} // namespace mbscope
