#include "replay/answercomparison.h"

#include "protocol/dissector.h"
#include "protocol/functioncode.h"

#include <QtCore/QHash>

#include <cstring>
#include <vector>

namespace mbscope {

namespace {

bool answered(TransactionStatus status)
{
    return status == TransactionStatus::Ok || status == TransactionStatus::Exception;
}

bool silent(TransactionStatus status)
{
    return status == TransactionStatus::Timeout || status == TransactionStatus::Broadcast;
}

// The framing's own fields are how the answer travelled, not what the device said.
bool isFramingKey(const char *key)
{
    return std::strncmp(key, "mbap.", 5) == 0 || std::strncmp(key, "rtu.", 4) == 0 || std::strncmp(key, "ascii.", 6) == 0;
}

struct LabelledValue {
    QString label;
    QString value;
};

// Every valued field of the answer, labelled as a plan's expectations select fields
// (FieldExpectation): key@0xADDRESS where the field has an address, key[N] for the N-th of
// several without one, the key alone otherwise.
std::vector<LabelledValue> labelledFields(const Transaction &t, Framing framing)
{
    DissectOptions options;
    options.framing = framing;
    options.direction = Direction::Response;
    options.request = t.request;
    const Dissection d = Dissector::dissect(t.response, options);
    const FieldTree &tree = d.fields;
    QHash<QByteArray, int> occurrences;
    for (const Field &f : tree.fields()) {
        if (f.format != ValueFormat::None && f.address < 0 && !isFramingKey(f.key))
            ++occurrences[QByteArray(f.key)];
    }
    QHash<QByteArray, int> seen;
    std::vector<LabelledValue> out;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        if (f.format == ValueFormat::None || isFramingKey(f.key))
            continue;
        QString label = QString::fromLatin1(f.key);
        if (f.address >= 0) {
            label += QStringLiteral("@0x") + QString::number(f.address, 16).toUpper().rightJustified(4, QLatin1Char('0'));
        } else {
            const QByteArray key(f.key);
            const int n = seen[key]++;
            if (occurrences.value(key) > 1)
                label += QStringLiteral("[%1]").arg(n);
        }
        out.push_back({label, tree.valueText(i)});
    }
    return out;
}

} // namespace

QString AnswerComparison::describeOutcome(const Transaction &t)
{
    switch (t.status) {
    case TransactionStatus::Ok:
        return QStringLiteral("a normal answer");
    case TransactionStatus::Exception:
        return QStringLiteral("exception 0x%1 (%2)")
            .arg(QString::number(t.exceptionCode, 16).toUpper().rightJustified(2, QLatin1Char('0')),
                 QLatin1String(exceptionName(t.exceptionCode)));
    case TransactionStatus::Timeout:
        return QStringLiteral("no answer");
    case TransactionStatus::Broadcast:
        return QStringLiteral("no answer (a broadcast)");
    default:
        break;
    }
    return t.problem.isEmpty() ? transactionStatusName(t.status)
                               : QStringLiteral("%1 (%2)").arg(transactionStatusName(t.status), t.problem);
}

QString AnswerComparison::verdictName(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Match: return QStringLiteral("match");
    case Verdict::ValuesDiffer: return QStringLiteral("values differ");
    case Verdict::OutcomeDiffers: return QStringLiteral("outcome differs");
    case Verdict::MissingAnswer: return QStringLiteral("missing answer");
    }
    return {};
}

AnswerComparison::Result AnswerComparison::compare(const Transaction &recorded, Framing recordedFraming, const Transaction &now,
                                                   Framing nowFraming, const IgnoredFields &ignore)
{
    Result result;
    const bool sameOutcome = recorded.status == now.status
        && (recorded.status != TransactionStatus::Exception || recorded.exceptionCode == now.exceptionCode);
    if (!sameOutcome) {
        if (silent(now.status) && !silent(recorded.status)) {
            result.verdict = Verdict::MissingAnswer;
            result.differences.append(QStringLiteral("no answer now (recorded %1)").arg(describeOutcome(recorded)));
        } else {
            result.verdict = Verdict::OutcomeDiffers;
            result.differences.append(QStringLiteral("recorded %1, now %2").arg(describeOutcome(recorded), describeOutcome(now)));
        }
        return result;
    }
    // Same failure without an answer to read (both timed out, both CRC errors...): nothing more to compare.
    if (!answered(now.status))
        return result;

    const std::vector<LabelledValue> before = labelledFields(recorded, recordedFraming);
    const std::vector<LabelledValue> after = labelledFields(now, nowFraming);
    QHash<QString, QString> afterByLabel;
    for (const LabelledValue &v : after)
        afterByLabel.insert(v.label, v.value);
    const auto differ = [&result, &ignore](const QString &label, const QString &difference) {
        const QString selector = ignore.isEmpty() ? QString() : ignore.selectorFor(label);
        if (selector.isEmpty())
            result.differences.append(difference);
        else
            result.ignored.append({selector, difference});
    };
    QHash<QString, bool> beforeLabels;
    for (const LabelledValue &v : before) {
        beforeLabels.insert(v.label, true);
        const auto it = afterByLabel.constFind(v.label);
        if (it == afterByLabel.constEnd())
            differ(v.label, QStringLiteral("%1: recorded %2, now absent").arg(v.label, v.value));
        else if (*it != v.value)
            differ(v.label, QStringLiteral("%1: recorded %2, now %3").arg(v.label, v.value, *it));
    }
    for (const LabelledValue &v : after) {
        if (!beforeLabels.contains(v.label))
            differ(v.label, QStringLiteral("%1: recorded absent, now %2").arg(v.label, v.value));
    }
    if (!result.differences.isEmpty())
        result.verdict = Verdict::ValuesDiffer;
    return result;
}

} // namespace mbscope
