#pragma once

#include "session/planstep.h"

#include <QtCore/QJsonArray>
#include <QtCore/QStringList>

#include <vector>

namespace mbscope {

class JsonReader;

// Reads a test plan's steps (planstep.h), every problem with its JSON path:
// "plan[2].expect.fields.modbus.register_value@0x0079: expected a whole number or {\"min\": ..,
// \"max\": ..}, found a string \"x\"", "plan[4].expect[1]: 'p95 < 20': p95 is a latency: ...".
class PlanStepReader
{
public:
    PlanStepReader(JsonReader &reader, const QStringList &requestNames);
    [[nodiscard]] std::vector<PlanStep> readSteps(const QJsonArray &steps, const QString &path);

private:
    bool readStep(const QJsonValue &value, const QString &path, PlanStep *step);
    bool readExpectation(const QJsonValue &value, const QString &path, StepExpectation *out);
    bool readBounds(const QJsonValue &value, const QString &path, QList<PollBound> *out);
    bool readWait(const QJsonValue &value, const QString &path, qint64 *ms);

    JsonReader &m_reader;
    QStringList m_requestNames;
    bool m_sawSend = false; // an expect step checks the answer of a send before it
};

} // namespace mbscope
