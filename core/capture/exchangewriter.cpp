#include "exchangewriter.h"

#include "capture/exchangerow.h"

#include <QtCore/QJsonDocument>

namespace mbscope {

ExchangeWriter::ExchangeWriter() = default;
ExchangeWriter::~ExchangeWriter() = default;

bool ExchangeWriter::open(const QString &path, TrafficFormat format, QString *error)
{
    m_format = format;
    m_rows = 0;
    if (format == TrafficFormat::Journal || format == TrafficFormat::Unknown) {
        *error = QStringLiteral("cannot write %1 as %2: exchanges go to csv, jsonl, pcapng or pcap").arg(path, trafficformat::name(format));
        return false;
    }
    if (trafficformat::isCapture(format)) {
        if (!m_capture.open(path, format, error))
            return false;
        m_pcap.emplace(m_capture);
        return true;
    }
    const bool ok = path == QLatin1String("-") ? m_file.open(stdout, QIODevice::WriteOnly)
                                               : (m_file.setFileName(path), m_file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    if (!ok) {
        *error = QStringLiteral("cannot create %1: %2").arg(path, m_file.errorString());
        return false;
    }
    m_text = std::make_unique<QTextStream>(&m_file);
    m_text->setEncoding(QStringConverter::Utf8);
    if (format == TrafficFormat::Csv)
        *m_text << ExchangeRow::columns().join(QLatin1Char(',')) << '\n';
    return true;
}

void ExchangeWriter::addConversation(const CaptureConversation &conversation)
{
    if (m_conversations.size() <= conversation.id)
        m_conversations.resize(std::size_t(conversation.id) + 1);
    m_conversations[conversation.id] = conversation;
    if (m_pcap)
        m_pcap->addConversation(conversation);
}

void ExchangeWriter::add(const CaptureExchange &exchange)
{
    if (m_pcap) {
        m_pcap->add(exchange);
        return;
    }
    if (!m_text)
        return;
    const CaptureConversation *c = exchange.conversation < m_conversations.size() ? &m_conversations[exchange.conversation] : nullptr;
    if (m_format == TrafficFormat::Csv) {
        QStringList cells = ExchangeRow::cells(exchange, c);
        for (QString &cell : cells)
            cell = ExchangeRow::csvCell(cell);
        *m_text << cells.join(QLatin1Char(',')) << '\n';
    } else {
        *m_text << QJsonDocument(ExchangeRow::json(exchange, c)).toJson(QJsonDocument::Compact) << '\n';
    }
    ++m_rows;
}

bool ExchangeWriter::close(QString *error)
{
    if (m_pcap) {
        m_pcap->finish();
        return m_capture.close(error);
    }
    if (!m_text)
        return true;
    m_text->flush();
    const bool ok = m_text->status() == QTextStream::Ok && m_file.error() == QFileDevice::NoError;
    if (!ok)
        *error = QStringLiteral("cannot write %1: %2").arg(m_file.fileName().isEmpty() ? QStringLiteral("standard output") : m_file.fileName(),
                                                            m_file.errorString());
    m_text.reset();
    m_file.close();
    return ok;
}

quint64 ExchangeWriter::packets() const
{
    return m_pcap ? m_pcap->packets() : 0;
}

QStringList ExchangeWriter::decodeOptions() const
{
    return m_pcap ? m_pcap->decodeOptions() : QStringList();
}

} // namespace mbscope
