#pragma once

// Shared by the engine's unit tests: a TransactionEngine whose links are ScriptedLinks, and
// collectors of what it reports.

#include "scriptedlink.h"

#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "transport/linkurl.h"

#include <QtCore/QObject>
#include <QtTest/QTest>

#include <memory>

namespace mbscope::test {

inline LinkUrl parseUrl(const QString &text)
{
    const LinkUrl::Result r = LinkUrl::parse(text);
    if (!r.url)
        qFatal("bad test URL %s: %s", qPrintable(text), qPrintable(r.error));
    return *r.url;
}

inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

inline QByteArray rtu(const char *pduHex, quint8 unit = 1)
{
    return AduBuilder::rtu(hex(pduHex), unit);
}

inline QByteArray mbap(const char *pduHex, quint16 tid = 1, quint8 unit = 1)
{
    return AduBuilder::mbap(hex(pduHex), unit, tid);
}

inline QByteArray ascii(const char *pduHex, quint8 unit = 1)
{
    return AduBuilder::ascii(hex(pduHex), unit);
}

// The MBAP answer to an MBAP request: the request's transaction id and unit, the given PDU.
inline QByteArray mbapAnswer(const QByteArray &request, const char *pduHex)
{
    const quint16 tid = quint16(quint8(request.at(0)) << 8 | quint8(request.at(1)));
    return AduBuilder::mbap(hex(pduHex), quint8(request.at(6)), tid);
}

class EngineHarness
{
public:
    EngineHarness(const QString &url, PeerScript script, const EngineOptions &options = {})
        : m_url(parseUrl(url))
    {
        engine.setLinkFactory([script, state = peer](const LinkUrl &u, QObject *parent) -> Link * {
            return new ScriptedLink(u, script, state, parent);
        });
        engine.setTarget(m_url, options);
        QObject::connect(&engine, &TransactionEngine::transactionsFinished, &engine,
                         [this](const QList<Transaction> &batch) {
                             records += batch;
                             ++batches;
                         });
        QObject::connect(&engine, &TransactionEngine::progress, &engine,
                         [this](const EngineProgress &p) { progress = p; });
        QObject::connect(&engine, &TransactionEngine::finished, &engine,
                         [this](const PollReport &r) { reports.append(r); });
    }

    [[nodiscard]] const LinkUrl &url() const { return m_url; }
    [[nodiscard]] RequestItem item(const QByteArray &bytes, int timeoutMs = 2000, int retries = 0,
                                   const QString &name = {}) const
    {
        RequestItem i = RequestItem::forLink(bytes, m_url, name);
        i.timeoutMs = timeoutMs;
        i.retries = retries;
        return i;
    }
    [[nodiscard]] bool waitForRecords(qsizetype n, int ms = 10000)
    {
        return QTest::qWaitFor([&] { return records.size() >= n; }, ms);
    }
    template<typename Predicate>
    [[nodiscard]] bool waitFor(Predicate predicate, int ms = 10000)
    {
        return QTest::qWaitFor(predicate, ms);
    }
    [[nodiscard]] bool waitForReport(int ms = 20000)
    {
        return QTest::qWaitFor([&] { return !reports.isEmpty(); }, ms);
    }
    [[nodiscard]] QList<Transaction> withStatus(TransactionStatus status) const
    {
        QList<Transaction> out;
        for (const Transaction &t : records) {
            if (t.status == status)
                out.append(t);
        }
        return out;
    }

    std::shared_ptr<PeerState> peer = std::make_shared<PeerState>();
    TransactionEngine engine;
    QList<Transaction> records;
    EngineProgress progress;
    QList<PollReport> reports;
    int batches = 0;

private:
    LinkUrl m_url;
};

} // namespace mbscope::test
