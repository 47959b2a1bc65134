#pragma once

#include "common/requestoptions.h"

#include "protocol/framing.h"

#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QString>

class QTextStream;

namespace mbscope {
struct Transaction;
}

namespace mbscope::app {

// poll's per-transaction output, as the transactions come (in the engine's batches, at most ~30
// a second): --print values writes one line per answer with its values in the --format(s) given
// to standard output; --csv FILE writes one row per transaction (time, item, status, latency,
// values), flushed after every batch so that a killed poll keeps its rows. Late answers are
// records about requests already counted: neither prints them.
class PollTranscript
{
public:
    PollTranscript(const RequestPlan &plan, Framing framing, QTextStream &out);

    void setPrintValues(bool on) { m_printValues = on; }
    // Creates the CSV file (an existing one is replaced, as --histogram's is) and writes the heading.
    bool openCsv(const QString &path, QString *error);
    [[nodiscard]] bool isActive() const { return m_printValues || m_csv.isOpen(); }

    void add(const QList<Transaction> &transactions);
    void close();

private:
    struct Values {
        QStringList columns; // one per format (registers) or one (bits); empty when the answer has none
        bool bits = false;
    };
    [[nodiscard]] Values valuesOf(const Transaction &t) const;
    [[nodiscard]] QString itemName(const Transaction &t) const;
    [[nodiscard]] QStringList formatNames() const;

    RequestPlan m_plan;
    Framing m_framing;
    QTextStream &m_out;
    bool m_printValues = false;
    QFile m_csv;
    qint64 m_wallOffsetNs = 0; // wall ns minus monotonic ns
};

} // namespace mbscope::app
