#include "blocksampler.h"

#include "discovery/unitscanner.h"
#include "protocol/adubuilder.h"
#include "protocol/readanswer.h"
#include "protocol/quantitylimits.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QTimer>

#include <algorithm>

namespace mbscope {

void SampleSettings::takeBlocks(const RegisterMap &map)
{
    for (const TableMap &t : map.tables) {
        if (t.maxQuantity > 0 && t.function >= 3)
            maxQuantity = std::min(maxQuantity, t.maxQuantity);
        for (const MapBlock &b : t.blocks)
            blocks.append(BlockRequest{t.function, b.address, b.count()});
    }
}

BlockSampler::BlockSampler(QObject *parent)
    : QObject(parent), m_channel(new ProbeChannel(this))
{
}

void BlockSampler::stop()
{
    m_stopRequested = true;
    m_channel->cancel();
}

bool BlockSampler::readBlock(const SampleSettings &settings, const BlockRequest &block, QList<quint16> *words)
{
    const bool bits = block.function <= 2;
    const int most = bits ? std::min(QuantityLimits::kReadBits, settings.maxQuantity * 16)
                           : std::min(QuantityLimits::kReadRegisters, settings.maxQuantity);
    words->clear();
    for (int at = 0; at < block.count; at += most) {
        const int quantity = std::min(most, block.count - at);
        const int address = block.address + at;
        const std::optional<ProbeChannel::Answer> answer = m_channel->ask(
            settings.unit, UnitScanner::readPdu(block.function, quint16(address), quint16(quantity)), settings.timeoutMs);
        if (!answer)
            return false;
        const Transaction &t = answer->transaction;
        if (t.status != TransactionStatus::Ok) {
            m_linkFailed = m_linkFailed || t.status == TransactionStatus::LinkError;
            if (m_problem.isEmpty())
                m_problem = t.status == TransactionStatus::Exception
                                ? QStringLiteral("read %1 at %2 x %3 answered exception %4").arg(block.function).arg(address).arg(quantity).arg(t.exceptionCode)
                                : QStringLiteral("read %1 at %2 x %3 got no usable answer%4")
                                      .arg(block.function)
                                      .arg(address)
                                      .arg(quantity)
                                      .arg(t.problem.isEmpty() ? QString() : QStringLiteral(": ") + t.problem);
            return false;
        }
        const QByteArray pdu = AduBuilder::parse(t.response, settings.url.framing()).pdu;
        const ReadAnswerResult parsed = ReadAnswer::fromResponse(block.function, address, quantity, pdu);
        if (!parsed.ok)
            return false;
        if (parsed.answer.isBits()) {
            for (const bool b : parsed.answer.bits)
                words->append(b ? 1 : 0);
        } else {
            words->append(parsed.answer.registers);
        }
    }
    return words->size() == block.count;
}

QList<BlockSamples> BlockSampler::run(const SampleSettings &settings)
{
    m_stopRequested = false;
    m_linkFailed = false;
    m_problem.clear();
    m_channel->setTarget(settings.url);
    QList<BlockSamples> out;
    for (const BlockRequest &b : settings.blocks)
        out.append(BlockSamples{b.function, b.address, b.count, {}, 0});
    QElapsedTimer clock;
    clock.start();
    for (int round = 0; round < settings.samples && !m_stopRequested; ++round) {
        const qint64 due = qint64(round) * settings.intervalMs;
        if (const qint64 wait = due - clock.elapsed(); wait > 0) {
            QEventLoop loop;
            QTimer::singleShot(int(wait), &loop, &QEventLoop::quit);
            loop.exec();
        }
        for (qsizetype i = 0; i < settings.blocks.size() && !m_stopRequested; ++i) {
            QList<quint16> words;
            if (readBlock(settings, settings.blocks.at(i), &words))
                out[i].samples.append(words);
            else if (!m_stopRequested)
                ++out[i].failedReads;
        }
        Q_EMIT roundDone(round + 1, settings.samples);
    }
    m_channel->closeLink();
    return out;
}

} // namespace mbscope

#include "moc_blocksampler.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
