#include "buildresult.h"

#include <QtCore/QStringList>

namespace mbscope {

bool BuildResult::hasError(QStringView parameter) const
{
    for (const BuildError &error : errors) {
        if (error.parameter == parameter)
            return true;
    }
    return false;
}

QString BuildResult::message(QStringView parameter) const
{
    for (const BuildError &error : errors) {
        if (error.parameter == parameter)
            return error.message;
    }
    return {};
}

QString BuildResult::errorString() const
{
    QStringList parts;
    parts.reserve(errors.size());
    for (const BuildError &error : errors)
        parts.append(error.parameter + QStringLiteral(": ") + error.message);
    return parts.join(QStringLiteral("; "));
}

} // namespace mbscope
