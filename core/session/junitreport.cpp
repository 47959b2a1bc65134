#include "session/junitreport.h"

#include <QtCore/QSaveFile>
#include <QtCore/QXmlStreamWriter>

namespace mbscope {

namespace {

QString seconds(qint64 ns)
{
    return QString::number(double(ns) / 1e9, 'f', 3);
}

bool save(const QByteArray &xml, const QString &path, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(xml) != xml.size() || !file.commit()) {
        if (error)
            *error = QStringLiteral("%1: cannot write the JUnit report: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace

JUnitTestSuite JUnitReport::suiteOf(const PlanResult &result)
{
    JUnitTestSuite suite;
    suite.name = result.name.isEmpty() ? QStringLiteral("mbscope plan") : result.name;
    suite.properties.append({QStringLiteral("target"), result.target});
    suite.started = result.started;
    suite.elapsedNs = result.elapsedNs;
    for (const StepResult &s : result.steps) {
        JUnitTestCase c;
        c.name = s.name;
        c.classname = suite.name + QLatin1Char('.') + s.path;
        c.elapsedNs = s.elapsedNs;
        const QString reasons = s.reasons.join(QLatin1Char('\n'));
        c.message = s.reasons.value(0);
        c.type = planStepKindName(s.kind);
        c.text = reasons;
        switch (s.outcome) {
        case StepResult::Outcome::Passed:
            c.outcome = JUnitTestCase::Outcome::Passed;
            break;
        case StepResult::Outcome::Failed:
            c.outcome = JUnitTestCase::Outcome::Failed;
            break;
        case StepResult::Outcome::Error:
            c.outcome = JUnitTestCase::Outcome::Error;
            break;
        case StepResult::Outcome::Skipped:
            c.outcome = JUnitTestCase::Outcome::Skipped;
            break;
        }
        if (!s.detail.isEmpty() || (s.outcome == StepResult::Outcome::Passed && !reasons.isEmpty()))
            c.systemOut = s.outcome == StepResult::Outcome::Passed ? reasons + QLatin1Char('\n') + s.detail : s.detail;
        suite.cases.append(c);
        suite.runs.append(s.runs);
    }
    return suite;
}

QByteArray JUnitReport::toXml(const PlanResult &result)
{
    return toXml(suiteOf(result));
}

QByteArray JUnitReport::toXml(const JUnitTestSuite &suite)
{
    int tests = 0;
    int failures = 0;
    int errors = 0;
    int skipped = 0;
    for (qsizetype i = 0; i < suite.cases.size(); ++i) {
        const int runs = suite.runs.value(i, 1);
        tests += runs;
        switch (suite.cases.at(i).outcome) {
        case JUnitTestCase::Outcome::Failed: failures += runs; break;
        case JUnitTestCase::Outcome::Error: errors += runs; break;
        case JUnitTestCase::Outcome::Skipped: skipped += runs; break;
        case JUnitTestCase::Outcome::Passed: break;
        }
    }
    QByteArray out;
    QXmlStreamWriter xml(&out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("testsuites"));
    xml.writeAttribute(QStringLiteral("name"), suite.name);
    xml.writeAttribute(QStringLiteral("tests"), QString::number(tests));
    xml.writeAttribute(QStringLiteral("failures"), QString::number(failures));
    xml.writeAttribute(QStringLiteral("errors"), QString::number(errors));
    xml.writeAttribute(QStringLiteral("time"), seconds(suite.elapsedNs));
    xml.writeStartElement(QStringLiteral("testsuite"));
    xml.writeAttribute(QStringLiteral("name"), suite.name);
    xml.writeAttribute(QStringLiteral("tests"), QString::number(tests));
    xml.writeAttribute(QStringLiteral("failures"), QString::number(failures));
    xml.writeAttribute(QStringLiteral("errors"), QString::number(errors));
    xml.writeAttribute(QStringLiteral("skipped"), QString::number(skipped));
    xml.writeAttribute(QStringLiteral("time"), seconds(suite.elapsedNs));
    xml.writeAttribute(QStringLiteral("timestamp"), suite.started.toUTC().toString(Qt::ISODate));
    xml.writeStartElement(QStringLiteral("properties"));
    for (const auto &p : suite.properties) {
        xml.writeStartElement(QStringLiteral("property"));
        xml.writeAttribute(QStringLiteral("name"), p.first);
        xml.writeAttribute(QStringLiteral("value"), p.second);
        xml.writeEndElement();
    }
    xml.writeEndElement();
    for (const JUnitTestCase &c : suite.cases) {
        xml.writeStartElement(QStringLiteral("testcase"));
        xml.writeAttribute(QStringLiteral("name"), c.name);
        xml.writeAttribute(QStringLiteral("classname"), c.classname);
        xml.writeAttribute(QStringLiteral("time"), seconds(c.elapsedNs));
        switch (c.outcome) {
        case JUnitTestCase::Outcome::Passed:
            break;
        case JUnitTestCase::Outcome::Failed:
        case JUnitTestCase::Outcome::Error:
            xml.writeStartElement(c.outcome == JUnitTestCase::Outcome::Failed ? QStringLiteral("failure") : QStringLiteral("error"));
            xml.writeAttribute(QStringLiteral("message"), c.message);
            xml.writeAttribute(QStringLiteral("type"), c.type);
            xml.writeCharacters(c.text);
            xml.writeEndElement();
            break;
        case JUnitTestCase::Outcome::Skipped:
            xml.writeStartElement(QStringLiteral("skipped"));
            xml.writeAttribute(QStringLiteral("message"), c.message);
            xml.writeEndElement();
            break;
        }
        if (!c.systemOut.isEmpty())
            xml.writeTextElement(QStringLiteral("system-out"), c.systemOut);
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndElement();
    xml.writeEndDocument();
    return out;
}

bool JUnitReport::write(const PlanResult &result, const QString &path, QString *error)
{
    return save(toXml(result), path, error);
}

bool JUnitReport::write(const JUnitTestSuite &suite, const QString &path, QString *error)
{
    return save(toXml(suite), path, error);
}

} // namespace mbscope
