#pragma once

#include "session/planresult.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// A plan's results as JUnit XML, the format CI servers read (Jenkins, GitLab, GitHub actions):
// one <testsuite> named after the plan, one <testcase> per step result, with <failure> for a
// failed expectation, <error> for a step that could not run (link errors) and <skipped/>.
class JUnitReport
{
public:
    [[nodiscard]] static QByteArray toXml(const PlanResult &result);
    // Atomically (QSaveFile); false with *error naming the file.
    static bool write(const PlanResult &result, const QString &path, QString *error = nullptr);
};

} // namespace mbscope
