#pragma once

#include "session/planresult.h"

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QList>
#include <QtCore/QPair>
#include <QtCore/QString>

namespace mbscope {

// One <testcase>: what JUnit says of one test, whoever ran it (a plan's step, a conformance check).
struct JUnitTestCase {
    enum class Outcome : quint8 { Passed, Failed, Error, Skipped };
    QString name;
    QString classname;
    Outcome outcome = Outcome::Passed;
    QString message;   // <failure message>, <error message>, <skipped message>
    QString type;      // <failure type>, <error type>
    QString text;      // the failure's or error's text
    QString systemOut; // <system-out>, when not empty
    qint64 elapsedNs = 0;
};

// One <testsuite> inside <testsuites>, with its <properties>.
struct JUnitTestSuite {
    QString name;
    QList<QPair<QString, QString>> properties;
    QDateTime started;
    qint64 elapsedNs = 0;
    QList<JUnitTestCase> cases;
    // Tests counted for each case; a case may stand for several runs (a long repeat's skipped rest).
    QList<int> runs;
};

// Results as JUnit XML, the format CI servers read (Jenkins, GitLab, GitHub actions): one
// <testsuite>, one <testcase> per result, with <failure> for a failed expectation, <error> for a
// test that could not run (link errors) and <skipped/>. A plan's steps (mbscope run) and the
// conformance battery's checks (mbscope conform) are written alike.
class JUnitReport
{
public:
    [[nodiscard]] static QByteArray toXml(const PlanResult &result);
    [[nodiscard]] static QByteArray toXml(const JUnitTestSuite &suite);
    // Atomically (QSaveFile); false with *error naming the file.
    static bool write(const PlanResult &result, const QString &path, QString *error = nullptr);
    static bool write(const JUnitTestSuite &suite, const QString &path, QString *error = nullptr);
    // A plan's results as a suite: one case per step result.
    [[nodiscard]] static JUnitTestSuite suiteOf(const PlanResult &result);
};

} // namespace mbscope
