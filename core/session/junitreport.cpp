#include "session/junitreport.h"

#include <QtCore/QSaveFile>
#include <QtCore/QXmlStreamWriter>

namespace mbscope {

namespace {

QString seconds(qint64 ns)
{
    return QString::number(double(ns) / 1e9, 'f', 3);
}

} // namespace

QByteArray JUnitReport::toXml(const PlanResult &result)
{
    QByteArray out;
    QXmlStreamWriter xml(&out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    const QString suite = result.name.isEmpty() ? QStringLiteral("mbscope plan") : result.name;
    // Every run counts, a long repeat's skipped rest (one testcase) for all its runs.
    const auto tests = QString::number(result.total());
    const auto failures = QString::number(result.count(StepResult::Outcome::Failed));
    const auto errors = QString::number(result.count(StepResult::Outcome::Error));
    const auto skipped = QString::number(result.count(StepResult::Outcome::Skipped));
    xml.writeStartElement(QStringLiteral("testsuites"));
    xml.writeAttribute(QStringLiteral("name"), suite);
    xml.writeAttribute(QStringLiteral("tests"), tests);
    xml.writeAttribute(QStringLiteral("failures"), failures);
    xml.writeAttribute(QStringLiteral("errors"), errors);
    xml.writeAttribute(QStringLiteral("time"), seconds(result.elapsedNs));
    xml.writeStartElement(QStringLiteral("testsuite"));
    xml.writeAttribute(QStringLiteral("name"), suite);
    xml.writeAttribute(QStringLiteral("tests"), tests);
    xml.writeAttribute(QStringLiteral("failures"), failures);
    xml.writeAttribute(QStringLiteral("errors"), errors);
    xml.writeAttribute(QStringLiteral("skipped"), skipped);
    xml.writeAttribute(QStringLiteral("time"), seconds(result.elapsedNs));
    xml.writeAttribute(QStringLiteral("timestamp"), result.started.toUTC().toString(Qt::ISODate));
    xml.writeStartElement(QStringLiteral("properties"));
    xml.writeStartElement(QStringLiteral("property"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("target"));
    xml.writeAttribute(QStringLiteral("value"), result.target);
    xml.writeEndElement();
    xml.writeEndElement();
    for (const StepResult &s : result.steps) {
        xml.writeStartElement(QStringLiteral("testcase"));
        xml.writeAttribute(QStringLiteral("name"), s.name);
        xml.writeAttribute(QStringLiteral("classname"), suite + QLatin1Char('.') + s.path);
        xml.writeAttribute(QStringLiteral("time"), seconds(s.elapsedNs));
        const QString reasons = s.reasons.join(QLatin1Char('\n'));
        switch (s.outcome) {
        case StepResult::Outcome::Passed:
            break;
        case StepResult::Outcome::Failed:
        case StepResult::Outcome::Error:
            xml.writeStartElement(s.outcome == StepResult::Outcome::Failed ? QStringLiteral("failure") : QStringLiteral("error"));
            xml.writeAttribute(QStringLiteral("message"), s.reasons.value(0));
            xml.writeAttribute(QStringLiteral("type"), planStepKindName(s.kind));
            xml.writeCharacters(reasons);
            xml.writeEndElement();
            break;
        case StepResult::Outcome::Skipped:
            xml.writeStartElement(QStringLiteral("skipped"));
            xml.writeAttribute(QStringLiteral("message"), s.reasons.value(0));
            xml.writeEndElement();
            break;
        }
        if (!s.detail.isEmpty() || (s.outcome == StepResult::Outcome::Passed && !reasons.isEmpty()))
            xml.writeTextElement(QStringLiteral("system-out"),
                                 s.outcome == StepResult::Outcome::Passed ? reasons + QLatin1Char('\n') + s.detail : s.detail);
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndElement();
    xml.writeEndDocument();
    return out;
}

bool JUnitReport::write(const PlanResult &result, const QString &path, QString *error)
{
    QSaveFile file(path);
    const QByteArray xml = toXml(result);
    if (!file.open(QIODevice::WriteOnly) || file.write(xml) != xml.size() || !file.commit()) {
        if (error)
            *error = QStringLiteral("%1: cannot write the JUnit report: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace mbscope
