#include "poll/polltranscript.h"

#include "common/transactionreport.h"
#include "common/valuetable.h"

#include "exchange/transaction.h"
#include "protocol/adubuilder.h"
#include "protocol/readanswer.h"
#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled.
QString csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

} // namespace

PollTranscript::PollTranscript(const RequestPlan &plan, Framing framing, QTextStream &out)
    : m_plan(plan)
    , m_framing(framing)
    , m_out(out)
    , m_wallOffsetNs(QDateTime::currentMSecsSinceEpoch() * 1'000'000 - monotonicNowNs())
{
    if (m_plan.formats.isEmpty())
        m_plan.formats = {RegisterFormat()};
}

QStringList PollTranscript::formatNames() const
{
    QStringList names;
    for (const RegisterFormat &f : m_plan.formats)
        names.append(f.name());
    return names;
}

bool PollTranscript::openCsv(const QString &path, QString *error)
{
    m_csv.setFileName(path);
    if (!m_csv.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, m_csv.errorString());
        return false;
    }
    QStringList heading{QStringLiteral("time"), QStringLiteral("item"), QStringLiteral("status"), QStringLiteral("latency_ms")};
    // Bits have one column of values; registers one per format.
    bool registers = false, bits = false;
    for (const PlannedRequest &r : m_plan.requests) {
        const AduParts parts = AduBuilder::parse(r.item.bytes, m_framing);
        const quint8 code = parts.pdu.isEmpty() ? 0 : quint8(parts.pdu.at(0));
        registers = registers || code == 3 || code == 4;
        bits = bits || code == 1 || code == 2;
    }
    if (registers) {
        for (const QString &name : formatNames())
            heading.append(QStringLiteral("values_") + name);
    } else if (bits) {
        heading.append(QStringLiteral("values"));
    }
    m_csv.write(heading.join(QLatin1Char(',')).toUtf8() + '\n');
    m_csv.flush();
    return true;
}

QString PollTranscript::itemName(const Transaction &t) const
{
    if (t.item >= 0 && t.item < m_plan.requests.size())
        return m_plan.requests.at(t.item).item.name;
    return QString();
}

PollTranscript::Values PollTranscript::valuesOf(const Transaction &t) const
{
    Values v;
    if (t.status != TransactionStatus::Ok)
        return v;
    const QByteArray requestPdu = AduBuilder::parse(t.request, m_framing).pdu;
    const QByteArray responsePdu = AduBuilder::parse(t.response, m_framing).pdu;
    const ReadAnswerResult read = ReadAnswer::fromPdus(requestPdu, responsePdu);
    if (!read.ok)
        return v;
    ValueTable table;
    table.functionCode = read.answer.functionCode;
    table.address = read.answer.address;
    table.registers = read.answer.registers;
    table.bits = read.answer.bits;
    v.bits = read.answer.isBits();
    if (v.bits) {
        v.columns.append(table.bitTexts().join(QLatin1Char(' ')));
    } else {
        for (const RegisterFormat &f : m_plan.formats)
            v.columns.append(table.valueTexts(f).join(QLatin1Char(' ')));
    }
    return v;
}

void PollTranscript::add(const QList<Transaction> &transactions)
{
    if (!isActive())
        return;
    const QStringList formats = formatNames();
    for (const Transaction &t : transactions) {
        if (t.status == TransactionStatus::Late)
            continue;
        const Values values = valuesOf(t);
        const QDateTime when = QDateTime::fromMSecsSinceEpoch((t.sentNs + m_wallOffsetNs) / 1'000'000, Qt::UTC);
        const QString status = transactionStatusName(t.status);
        const qint64 latency = t.latencyNs();
        if (m_printValues) {
            QString line = when.toLocalTime().toString(QStringLiteral("HH:mm:ss.zzz")) + QStringLiteral("  ") + itemName(t)
                           + QStringLiteral("  ") + status;
            if (latency >= 0)
                line += QStringLiteral("  ") + latencyText(latency);
            if (values.bits) {
                line += QStringLiteral("  ") + values.columns.constFirst();
            } else {
                for (qsizetype i = 0; i < values.columns.size(); ++i)
                    line += QStringLiteral("  %1: %2").arg(formats.at(i), values.columns.at(i));
            }
            if (t.status != TransactionStatus::Ok && !t.problem.isEmpty())
                line += QStringLiteral("  (%1)").arg(t.problem);
            m_out << line << '\n';
        }
        if (m_csv.isOpen()) {
            QStringList row{when.toString(Qt::ISODateWithMs), csvField(itemName(t)), status,
                            latency >= 0 ? QString::number(double(latency) / 1e6, 'f', 3) : QString()};
            for (const QString &column : values.columns)
                row.append(csvField(column));
            m_csv.write(row.join(QLatin1Char(',')).toUtf8() + '\n');
        }
    }
    if (m_printValues)
        m_out.flush();
    if (m_csv.isOpen())
        m_csv.flush();
}

void PollTranscript::close()
{
    if (m_csv.isOpen())
        m_csv.close();
}

} // namespace mbscope::app
