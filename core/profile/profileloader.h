#pragma once

#include "deviceprofile.h"
#include "faultrule.h"
#include "json/profileproblem.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

struct ProfileLoadResult {
    DeviceProfile profile;          // empty unless ok: nothing is ever half loaded
    QList<ProfileProblem> problems; // every problem found, in document order
    // What loads but is likely a mistake, with where it is: a table no function in the unit's
    // `functions` can read ("units[0].tables.coils: ... function 01 is not in functions").
    QList<ProfileProblem> warnings;
    bool ok = false;
    [[nodiscard]] QString errorText() const { return ProfileProblem::join(problems); }
    [[nodiscard]] QString warningText() const { return ProfileProblem::join(warnings); }
};

struct FaultRulesLoadResult {
    FaultRuleSet rules; // empty unless ok
    QList<ProfileProblem> problems;
    bool ok = false;
    [[nodiscard]] QString errorText() const { return ProfileProblem::join(problems); }
};

struct ShippedProfile {
    QString name;        // "rosrao-gamma"
    QString description;
    QString resource;    // ":/profiles/rosrao-gamma.json"
};

// Loads device profiles and fault rule files (formats: docs/profiles.md, docs/profile.schema.json).
// Problems come back as data with where they are: line and column for JSON syntax errors, the JSON
// path for content ("units[0].tables.holding[2].address: 70000 is beyond 65535"), and what was
// expected. Unknown keys are errors (a misspelt key must not be ignored silently).
class ProfileLoader
{
public:
    // A shipped profile by name ("rosrao-gamma" -> ":/profiles/rosrao-gamma.json") or a user file
    // by path (anything holding a '/' or ending in ".json").
    [[nodiscard]] static ProfileLoadResult load(const QString &nameOrPath);
    [[nodiscard]] static ProfileLoadResult loadFile(const QString &path);
    [[nodiscard]] static ProfileLoadResult parse(const QByteArray &json, const QString &source);

    // A faults file: {"seed": 7, "rules": [...]}.
    [[nodiscard]] static FaultRulesLoadResult loadFaults(const QString &path);
    [[nodiscard]] static FaultRulesLoadResult parseFaults(const QByteArray &json, const QString &source);

    // Where load() looks for nameOrPath.
    [[nodiscard]] static QString resolve(const QString &nameOrPath);
    [[nodiscard]] static bool isPath(const QString &nameOrPath);
    // The profiles compiled in (the mbscope_resources library), by name. Empty when the
    // executable does not link them.
    [[nodiscard]] static QList<ShippedProfile> shippedProfiles();

    // 1-based line and column (in characters) of a byte offset into UTF-8 text.
    [[nodiscard]] static std::pair<int, int> lineColumn(const QByteArray &text, qsizetype offset);
};

} // namespace mbscope
