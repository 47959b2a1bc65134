#include "conformancejudge.h"

#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"
#include "protocol/hextext.h"

namespace mbscope {

QString ConformanceJudge::hex(const QByteArray &bytes)
{
    return HexText::format(bytes);
}

QString ConformanceJudge::exceptionText(quint8 code)
{
    return QStringLiteral("exception %1 (%2)")
        .arg(QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0')), QLatin1String(exceptionName(code)));
}

QByteArray ConformanceJudge::pdu(const QByteArray &adu, Framing framing)
{
    const AduParts parts = AduBuilder::parse(adu, framing);
    return parts.pdu;
}

QString ConformanceJudge::seen(const ConformanceExchange &e)
{
    const Transaction &t = e.transaction;
    if (e.linkFailed())
        return QStringLiteral("a link error (%1)").arg(t.problem);
    if (e.silent())
        return QStringLiteral("no answer within %1 ms").arg(e.timeoutMs);
    switch (t.status) {
    case TransactionStatus::Ok:
        return QStringLiteral("%1 (a normal answer)").arg(hex(t.response));
    case TransactionStatus::Exception:
        return QStringLiteral("%1 (%2)").arg(hex(t.response), exceptionText(t.exceptionCode));
    case TransactionStatus::CrcError:
    case TransactionStatus::Malformed:
    case TransactionStatus::Unexpected:
        return QStringLiteral("%1 (%2)").arg(hex(t.response.isEmpty() ? e.answer : t.response), t.problem);
    default:
        if (e.late)
            return QStringLiteral("%1 only after the %2 ms timeout (a late answer, when a master has given up on it)")
                .arg(hex(e.answer))
                .arg(e.timeoutMs);
        return QStringLiteral("%1 (bytes that answer nothing it asked)").arg(hex(e.answer));
    }
}

QString ConformanceJudge::failure(const CheckResult &result, const ConformanceExchange &e, const QString &requirement)
{
    return QStringLiteral("sent %1; got %2; %3 requires %4").arg(hex(e.request), seen(e), result.clause, requirement);
}

void ConformanceJudge::record(CheckResult &result, const ConformanceExchange &e)
{
    result.request = e.request;
    result.answer = e.answer;
}

bool ConformanceJudge::exception(CheckResult &result, const ConformanceExchange &e, const QList<quint8> &codes,
                                 const QString &requirement)
{
    record(result, e);
    if (e.transaction.status == TransactionStatus::Exception && codes.contains(e.transaction.exceptionCode)) {
        result.pass(QStringLiteral("answered %1").arg(exceptionText(e.transaction.exceptionCode)));
        return true;
    }
    result.fail(failure(result, e, requirement));
    return false;
}

bool ConformanceJudge::normal(CheckResult &result, const ConformanceExchange &e, const QString &requirement)
{
    record(result, e);
    if (e.transaction.status == TransactionStatus::Ok) {
        result.pass(QStringLiteral("answered %1").arg(hex(e.transaction.response)));
        return true;
    }
    result.fail(failure(result, e, requirement));
    return false;
}

bool ConformanceJudge::silence(CheckResult &result, const ConformanceExchange &e, const QString &requirement,
                               const QByteArray &extra, bool closing)
{
    record(result, e);
    result.answer += extra;
    if (e.linkFailed() && closing && result.answer.isEmpty()) {
        result.pass(QStringLiteral("no answer: the device closed the connection (%1)").arg(e.transaction.problem));
        return true;
    }
    if (e.linkFailed()) {
        result.verdict = CheckVerdict::Error;
        result.sentence = QStringLiteral("the link failed: %1").arg(e.transaction.problem);
        return false;
    }
    if (result.answer.isEmpty()) {
        result.pass(QStringLiteral("no answer, as required"));
        return true;
    }
    result.fail(QStringLiteral("sent %1; got %2; %3 requires %4")
                    .arg(hex(e.request), hex(result.answer), result.clause, requirement));
    return false;
}

bool ConformanceJudge::silenceOrException(CheckResult &result, const ConformanceExchange &e, const QString &requirement)
{
    record(result, e);
    if (e.linkFailed() && e.silent()) {
        result.pass(QStringLiteral("no answer: the device closed the connection (%1)").arg(e.transaction.problem));
        return true;
    }
    if (e.linkFailed()) {
        result.verdict = CheckVerdict::Error;
        result.sentence = QStringLiteral("the link failed: %1").arg(e.transaction.problem);
        return false;
    }
    if (e.silent()) {
        result.pass(QStringLiteral("no answer"));
        return true;
    }
    if (e.transaction.status == TransactionStatus::Exception) {
        result.pass(QStringLiteral("answered %1").arg(exceptionText(e.transaction.exceptionCode)));
        return true;
    }
    result.fail(failure(result, e, requirement));
    return false;
}

} // namespace mbscope
