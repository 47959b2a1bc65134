#include "engineharness.h"

#include "peer_datamap.h"

#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QThread>
#include <QtCore/QTimer>

namespace mbscope::testpeers {

LinkUrl targetUrl(const QString &text)
{
    const LinkUrl::Result parsed = LinkUrl::parse(text);
    if (!parsed.url)
        qFatal("test target %s does not parse: %s", qPrintable(text), qPrintable(parsed.error));
    return *parsed.url;
}

LinkUrl networkTarget(const QString &scheme, quint16 port)
{
    return targetUrl(scheme + QStringLiteral("://127.0.0.1:") + QString::number(port));
}

LinkUrl serialTarget(const QString &scheme, const QString &device)
{
    return targetUrl(scheme + QStringLiteral("://") + device + QStringLiteral("?baud=115200&parity=N&data=8&stop=1"));
}

RequestItem request(const LinkUrl &url, const QByteArray &pdu, quint8 unit, quint16 transactionId, int timeoutMs)
{
    AduOptions options;
    options.framing = url.framing();
    options.unitId = unit;
    options.transactionId = transactionId;
    RequestItem item = RequestItem::forLink(AduBuilder::complete(pdu, options), url);
    item.timeoutMs = timeoutMs;
    return item;
}

QByteArray responsePdu(const Transaction &t, Framing framing)
{
    return AduBuilder::parse(t.response, framing).pdu;
}

QByteArray expectedReadBits(quint8 functionCode, int start, int quantity)
{
    QByteArray pdu;
    pdu.append(char(functionCode)).append(char((quantity + 7) / 8));
    for (int byte = 0; byte < (quantity + 7) / 8; ++byte) {
        int value = 0;
        for (int bit = 0; bit < 8 && byte * 8 + bit < quantity; ++bit) {
            const unsigned a = unsigned(start + byte * 8 + bit);
            if (functionCode == 0x01 ? peer_coil(a) : peer_discrete_input(a))
                value |= 1 << bit; // V1.1b3 6.1: the first coil in the low bit of the first byte
        }
        pdu.append(char(value));
    }
    return pdu;
}

QByteArray expectedReadRegisters(quint8 functionCode, int start, int quantity)
{
    QByteArray pdu;
    pdu.append(char(functionCode)).append(char(2 * quantity));
    for (int i = 0; i < quantity; ++i) {
        const unsigned a = unsigned(start + i);
        const quint16 v = functionCode == 0x03 ? peer_holding_register(a) : peer_input_register(a);
        pdu.append(char(v >> 8)).append(char(v & 0xFF));
    }
    return pdu;
}

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

QString describe(const Transaction &t)
{
    QString text = transactionStatusName(t.status);
    if (t.status == TransactionStatus::Exception)
        text += QStringLiteral(" 0x") + QString::number(t.exceptionCode, 16);
    if (!t.problem.isEmpty())
        text += QStringLiteral(": ") + t.problem;
    text += QStringLiteral(" [request ") + QString::fromLatin1(t.request.toHex(' ')) + QStringLiteral(", response ")
            + QString::fromLatin1(t.response.toHex(' ')) + QLatin1Char(']');
    return text;
}

QString describe(const std::optional<Transaction> &t)
{
    return t ? describe(*t) : QStringLiteral("no record at all");
}

QString describe(const EngineCounters &c)
{
    return QStringLiteral("requests sent %1 (retries %2), records %3, late %4, unsolicited %5 (duplicates %6), "
                          "skipped %7 runs / %8 bytes, bytes in %9 out %10, connects %11, link errors %12")
        .arg(c.requestsSent).arg(c.retries).arg(c.transactions).arg(c.late).arg(c.unsolicitedFrames)
        .arg(c.duplicateFrames).arg(c.skippedRuns).arg(c.skippedBytes).arg(c.bytesIn).arg(c.bytesOut)
        .arg(c.connects).arg(c.linkErrors);
}

EngineProbe::EngineProbe(TransactionEngine *engine)
{
    connect(engine, &TransactionEngine::transactionsFinished, this,
            [this](const QList<Transaction> &batch) { m_records += batch; });
    connect(engine, &TransactionEngine::progress, this,
            [this](const EngineProgress &progress) { m_counters = progress.counters; });
}

bool EngineProbe::waitFor(const std::function<bool()> &condition, int timeoutMs)
{
    QDeadlineTimer deadline(timeoutMs);
    while (!condition()) {
        if (deadline.hasExpired())
            return false;
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

std::optional<Transaction> EngineProbe::find(quint64 id, TransactionStatus status) const
{
    for (qsizetype i = m_records.size() - 1; i >= 0; --i) {
        if (m_records.at(i).id == id && m_records.at(i).status == status)
            return m_records.at(i);
    }
    return std::nullopt;
}

} // namespace mbscope::testpeers
