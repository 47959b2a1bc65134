#include "session/expectationcheck.h"

#include "protocol/broadcastrule.h"
#include "protocol/dissector.h"
#include "protocol/functioncode.h"
#include "protocol/hextext.h"

#include <algorithm>

namespace mbscope {

namespace {

// requestProblem()'s words for a read sent to unit 0 on a serial framing.
const QLatin1String kUnanswerable("the read cannot be answered: ");

QString exceptionText(int code)
{
    return QStringLiteral("exception 0x%1 (%2)")
        .arg(QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0')), QLatin1String(exceptionName(quint8(code))));
}

} // namespace

QString ExpectationCheck::describeAnswer(const Transaction &t)
{
    switch (t.status) {
    case TransactionStatus::Ok:
        return QStringLiteral("a normal answer");
    case TransactionStatus::Exception:
        return QStringLiteral("an ") + exceptionText(t.exceptionCode);
    case TransactionStatus::Timeout:
        return QStringLiteral("no answer within the timeout");
    case TransactionStatus::Broadcast:
        return QStringLiteral("no answer (a broadcast)");
    default:
        break;
    }
    return QStringLiteral("%1: %2").arg(transactionStatusName(t.status), t.problem);
}

QString ExpectationCheck::requestProblem(const Transaction &t, Framing framing, bool delimited)
{
    if (delimited || t.request.isEmpty())
        return {};
    DissectOptions options;
    options.framing = framing;
    options.direction = Direction::Request;
    const Dissection d = Dissector::dissect(t.request, options);
    int errors = 0;
    QString first;
    for (const Field &f : d.fields.fields()) {
        if (f.severity != Severity::Error)
            continue;
        if (errors++ == 0)
            first = QString::fromLatin1(f.key) + QStringLiteral(": ") + f.message;
    }
    if (errors == 0)
        return {};
    // A read to unit 0 on a serial framing is a well-formed broadcast that nobody can answer.
    if (const QString why = BroadcastRule::broadcastReadProblem(t.request, framing); errors == 1 && !why.isEmpty())
        return QString(kUnanswerable) + why;
    // send says the same of one frame (app/common/transactionreport.cpp calls this).
    return QStringLiteral("the request itself is malformed, %1 error(s) (%2)").arg(errors).arg(first);
}

ExpectationCheck::Outcome ExpectationCheck::check(const StepExpectation &e, const Transaction &t, Framing framing,
                                                  bool delimited)
{
    Outcome out = checkAnswer(e, t, framing, delimited);
    // A device says nothing to a frame it cannot read (Serial Line V1.02, 2.4.2: a frame with a
    // wrong CRC is discarded): "no answer within the timeout" alone hides why (tryout 8, item 6).
    const QString problem = requestProblem(t, framing, delimited);
    if (problem.isEmpty())
        return out;
    // A read nobody can answer passes only a step that expects no answer.
    const bool unanswerable = !e.noAnswer && problem.startsWith(kUnanswerable);
    if (out.passed() && !unanswerable)
        out.checks.append(problem + QStringLiteral(", sent as written"));
    else
        out.failures.append(problem);
    return out;
}

ExpectationCheck::Outcome ExpectationCheck::checkAnswer(const StepExpectation &e, const Transaction &t, Framing framing,
                                                        bool delimited)
{
    Outcome out;
    auto fail = [&](const QString &why) {
        out.failures.append(why);
    };
    if (e.isEmpty()) {
        // A send without expectations passes when the device gave a well-formed answer.
        if (t.status == TransactionStatus::Ok || t.status == TransactionStatus::Broadcast)
            out.checks.append(QStringLiteral("answered"));
        else
            fail(QStringLiteral("expected an answer, got %1").arg(describeAnswer(t)));
        return out;
    }
    if (e.noAnswer) {
        if (t.status == TransactionStatus::Timeout || t.status == TransactionStatus::Broadcast)
            out.checks.append(QStringLiteral("no answer, as expected"));
        else
            fail(QStringLiteral("expected no answer, got %1: %2").arg(describeAnswer(t), HexText::format(t.response)));
        return out;
    }
    const bool answered = t.status == TransactionStatus::Ok || t.status == TransactionStatus::Exception;
    if (e.exception) {
        if (t.status == TransactionStatus::Exception && t.exceptionCode == *e.exception)
            out.checks.append(exceptionText(*e.exception) + QStringLiteral(", as expected"));
        else
            fail(QStringLiteral("expected %1, got %2").arg(exceptionText(*e.exception), describeAnswer(t)));
    } else if (t.status != TransactionStatus::Ok && !e.bytes) {
        fail(QStringLiteral("expected a normal answer, got %1").arg(describeAnswer(t)));
    }
    if (e.bytes) {
        const QByteArray expected = HexText::parse(*e.bytes).bytes;
        if (t.response == expected) {
            out.checks.append(QStringLiteral("answer is %1, as expected").arg(HexText::format(expected)));
        } else if (t.response.isEmpty()) {
            fail(QStringLiteral("expected the answer %1, got %2").arg(HexText::format(expected), describeAnswer(t)));
        } else {
            qsizetype at = 0;
            while (at < expected.size() && at < t.response.size() && expected.at(at) == t.response.at(at))
                ++at;
            const bool prefix = at == std::min(expected.size(), t.response.size());
            fail(QStringLiteral("answer is %1, expected %2 (%3)")
                     .arg(HexText::format(t.response), HexText::format(expected),
                          prefix ? QStringLiteral("%1 bytes where %2 were expected").arg(t.response.size()).arg(expected.size())
                                 : QStringLiteral("they differ from byte %1").arg(at)));
        }
    }
    if (e.fields.isEmpty())
        return out;
    if (!answered) {
        fail(QStringLiteral("no fields to check: %1").arg(describeAnswer(t)));
        return out;
    }
    if (delimited) {
        fail(QStringLiteral("fields cannot be decoded on a delimited link: check the bytes instead"));
        return out;
    }
    DissectOptions options;
    options.framing = framing;
    options.direction = Direction::Response;
    options.request = t.request;
    const Dissection d = Dissector::dissect(t.response, options);
    for (const FieldExpectation &f : e.fields) {
        const int index = f.find(d.fields);
        if (index < 0) {
            fail(QStringLiteral("%1: no such field in the answer").arg(f.selector));
            continue;
        }
        const auto value = qint64(d.fields.at(index).value);
        if (f.accepts(value))
            out.checks.append(QStringLiteral("%1 = %2").arg(f.selector).arg(value));
        else
            fail(QStringLiteral("%1 is %2, expected %3").arg(f.selector).arg(value).arg(f.expectedText()));
    }
    return out;
}

} // namespace mbscope
