#pragma once

#include <QtCore/QString>

namespace mbscope {

// One error of a device script, located: the file as the profile names it, the line (1-based)
// and the column when QJSEngine gives one (syntax errors; runtime errors carry the line only).
struct ScriptProblem {
    QString file;    // "gamma.js"
    int line = 0;    // 0: not known (the file could not be read)
    int column = 0;  // 0: not known
    QString message; // "SyntaxError: Expected token `)'"

    // "gamma.js:12:5: SyntaxError: ...", "gamma.js:12: ReferenceError: ...", "gamma.js: ..."
    [[nodiscard]] QString toString() const
    {
        QString where = file;
        if (line > 0)
            where += QLatin1Char(':') + QString::number(line);
        if (line > 0 && column > 0)
            where += QLatin1Char(':') + QString::number(column);
        return where + QStringLiteral(": ") + message;
    }
};

} // namespace mbscope
