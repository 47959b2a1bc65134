#include "profileproblem.h"

#include <QtCore/QStringList>

namespace mbscope {

QString ProfileProblem::toString() const
{
    QString out = source;
    if (line > 0)
        out += QStringLiteral(":%1:%2").arg(line).arg(column);
    out += QStringLiteral(": ");
    if (!path.isEmpty())
        out += path + QStringLiteral(": ");
    return out + message;
}

QString ProfileProblem::join(const QList<ProfileProblem> &problems)
{
    QStringList lines;
    for (const ProfileProblem &p : problems)
        lines.append(p.toString());
    return lines.join(QLatin1Char('\n'));
}

} // namespace mbscope
