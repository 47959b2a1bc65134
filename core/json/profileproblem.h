#pragma once

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// One thing wrong with a profile or faults file: where and what was expected. Syntax errors
// carry a line and column (1-based, characters); content errors the JSON path of the value,
// "units[0].tables.holding[2].address".
struct ProfileProblem {
    QString source;  // the file or resource ("rosrao-gamma.json", ":/profiles/conformance.json")
    QString path;    // JSON path; empty for syntax errors and problems of the file itself
    int line = 0;    // syntax errors only
    int column = 0;
    QString message; // "70000 is beyond 65535"

    // "file.json:3:17: message", "file.json: units[0].id: message", "file.json: message"
    [[nodiscard]] QString toString() const;
    [[nodiscard]] static QString join(const QList<ProfileProblem> &problems); // one per line
};

} // namespace mbscope
