#pragma once

#include "capture/captureexchange.h"
#include "capture/capturefilewriter.h"
#include "capture/exchangepcapexporter.h"

#include <QtCore/QFile>
#include <QtCore/QStringList>
#include <QtCore/QTextStream>

#include <memory>
#include <optional>
#include <vector>

namespace mbscope {

// Exchanges written to one kind of file, as `mbscope export` writes them and the window's "Save
// Traffic As" does: CSV (ExchangeRow's columns, a row per exchange), JSON lines (an object per
// exchange) or a capture Wireshark decodes (pcapng, or classic pcap; ExchangePcapExporter).
class ExchangeWriter
{
public:
    ExchangeWriter();
    ~ExchangeWriter();
    ExchangeWriter(const ExchangeWriter &) = delete;
    ExchangeWriter &operator=(const ExchangeWriter &) = delete;

    // Creates the file (replacing one there; "-": standard output, for CSV and JSON lines); false
    // with *error naming the file and why.
    bool open(const QString &path, TrafficFormat format, QString *error);
    void addConversation(const CaptureConversation &conversation);
    void add(const CaptureExchange &exchange);
    // Writes what is held back and closes; false with *error when the file could not be written.
    bool close(QString *error);

    [[nodiscard]] quint64 rows() const { return m_rows; } // exchanges written (CSV and JSON lines)
    [[nodiscard]] quint64 packets() const;                // capture packets
    // What tshark needs to decode RTU frames on their ports ("port 4001 (RTU over TCP): -o
    // mbrtu.tcp.port:4001"); empty for the other formats.
    [[nodiscard]] QStringList decodeOptions() const;

private:
    TrafficFormat m_format = TrafficFormat::Csv;
    QFile m_file;
    std::unique_ptr<QTextStream> m_text;
    CaptureFileWriter m_capture;
    std::optional<ExchangePcapExporter> m_pcap;
    std::vector<CaptureConversation> m_conversations;
    quint64 m_rows = 0;
};

} // namespace mbscope
