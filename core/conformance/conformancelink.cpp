#include "conformancelink.h"

#include "discovery/probechannel.h"
#include "protocol/adubuilder.h"

#include <QtCore/QEventLoop>
#include <QtCore/QTimer>

namespace mbscope {

ConformanceLink::ConformanceLink(const LinkUrl &url, int timeoutMs)
    : m_url(url)
    , m_timeoutMs(timeoutMs)
    , m_channel(new ProbeChannel)
{
    m_channel->setTarget(url);
    QObject::connect(m_channel, &ProbeChannel::linkOpened, m_channel, [this] { ++m_opens; });
    QObject::connect(m_channel, &ProbeChannel::framesLogged, m_channel, [this](const QList<TrafficFrame> &frames) {
        for (const TrafficFrame &f : frames) {
            if (f.direction == TrafficDirection::In)
                m_in.append(f);
        }
    });
}

ConformanceLink::~ConformanceLink()
{
    delete m_channel;
}

QByteArray ConformanceLink::frame(quint8 unit, const QByteArray &pdu)
{
    AduOptions options;
    options.framing = framing();
    options.unitId = unit;
    options.transactionId = ++m_transactionId;
    return AduBuilder::complete(pdu, options);
}

quint16 ConformanceLink::transactionId(const QByteArray &adu)
{
    return adu.size() >= 2 ? quint16((quint8(adu.at(0)) << 8) | quint8(adu.at(1))) : 0;
}

ConformanceExchange ConformanceLink::exchange(const QByteArray &adu, int timeoutMs)
{
    ConformanceExchange e;
    e.request = adu;
    e.timeoutMs = timeoutMs < 0 ? m_timeoutMs : timeoutMs;
    const qsizetype before = m_in.size();
    const std::optional<ProbeChannel::Answer> answer = m_channel->askRaw(adu, e.timeoutMs);
    if (answer) {
        e.transaction = answer->transaction;
        e.answer = answer->bytesRead;
        if (e.transaction.status == TransactionStatus::Timeout) {
            for (qsizetype i = before; i < m_in.size() && !e.late; ++i)
                e.late = m_in.at(i).verdict == TrafficVerdict::Late && m_in.at(i).transactionId == e.transaction.id;
        }
    } else {
        e.transaction.status = TransactionStatus::LinkError;
        e.transaction.problem = QStringLiteral("the request could not be sent");
    }
    if (e.linkFailed())
        m_lastProblem = e.transaction.problem;
    if (e.unreachable())
        ++m_unreachable;
    else if (e.linkFailed())
        ++m_dropped;
    return e;
}

QByteArray ConformanceLink::listen(int ms)
{
    const qsizetype from = m_in.size();
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
    return bytesReadSince(from);
}

QByteArray ConformanceLink::bytesReadSince(qsizetype frame) const
{
    QByteArray bytes;
    for (qsizetype i = frame; i < m_in.size(); ++i)
        bytes += m_in.at(i).bytes;
    return bytes;
}

bool ConformanceLink::answeredLate(quint64 transactionId) const
{
    for (const TrafficFrame &f : m_in) {
        if (f.verdict == TrafficVerdict::Late && f.transactionId == transactionId)
            return true;
    }
    return false;
}

bool ConformanceLink::isExcused(qsizetype frame) const
{
    for (const auto &range : m_excused) {
        if (frame >= range.first && frame < range.second)
            return true;
    }
    return false;
}

void ConformanceLink::closeLink()
{
    m_channel->closeLink();
}

void ConformanceLink::onFramesLogged(const std::function<void(const QList<TrafficFrame> &, const QString &)> &each)
{
    QObject::connect(m_channel, &ProbeChannel::framesLogged, m_channel, each);
}

void ConformanceLink::setTrafficLog(TrafficLog *log)
{
    m_channel->setTrafficLog(log);
}

} // namespace mbscope
