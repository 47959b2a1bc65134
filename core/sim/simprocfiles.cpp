// SimProcessor: Read File Record (14) and Write File Record (15), V1.1b3 6.14-6.15.
#include "sim/simbytes.h"
#include "sim/simprocessor.h"
#include "sim/simunit.h"

namespace mbscope {

using simbytes::appendWord;
using simbytes::word;

namespace {

constexpr quint8 kReferenceType = 6;   // the only reference type (6.14)
constexpr int kMaxRecordNumber = 0x270F;

struct SubRequest {
    quint8 referenceType = 0;
    quint16 file = 0;
    quint16 record = 0;
    quint16 length = 0;
    qsizetype dataOffset = 0; // 15: where the record data starts in the PDU
};

// The 02 checks of 6.14/6.15's state diagrams, for one sub-request; empty when it passes.
QString addressProblem(const SimUnit &unit, const SubRequest &s, int index, bool writing)
{
    const QString where = QStringLiteral("sub-request %1: ").arg(index + 1);
    if (s.referenceType != kReferenceType)
        return where + QStringLiteral("reference type %1, expected 6").arg(s.referenceType);
    if (!unit.hasFile(s.file))
        return where + QStringLiteral("file %1 does not exist").arg(s.file);
    if (s.record > kMaxRecordNumber)
        return where + QStringLiteral("record number %1 is above 9999 (0x270F)").arg(s.record);
    const int size = int(unit.fileRecords(s.file).size());
    if (int(s.record) + s.length > size)
        return where + QStringLiteral("records %1-%2 run past the end of file %3 (%4 records)")
                           .arg(s.record)
                           .arg(int(s.record) + s.length - 1)
                           .arg(s.file)
                           .arg(size);
    if (writing && !unit.isFileWritable(s.file))
        return where + QStringLiteral("file %1 is read-only").arg(s.file);
    return {};
}

} // namespace

SimReply SimProcessor::readFileRecord(QByteArrayView pdu)
{
    auto bad = [](const QString &why) { return SimReply::exception(0x14, 0x03, why); };
    if (pdu.size() < 2)
        return bad(QStringLiteral("14 needs a byte count"));
    const int byteCount = quint8(pdu[1]);
    // 6.14: byte count 0x07-0xF5, sub-requests of 7 bytes each.
    if (byteCount < 0x07 || byteCount > 0xF5 || byteCount % 7 != 0)
        return bad(QStringLiteral("byte count %1 is not a multiple of 7 in 7-245").arg(byteCount));
    if (pdu.size() != 2 + byteCount)
        return bad(QStringLiteral("byte count %1 announces %1 bytes but %2 follow").arg(byteCount).arg(pdu.size() - 2));
    QList<SubRequest> subs;
    int responseSize = 2; // function code, response data length
    for (int offset = 2; offset < pdu.size(); offset += 7) {
        SubRequest s{quint8(pdu[offset]), word(pdu, offset + 1), word(pdu, offset + 3), word(pdu, offset + 5), 0};
        if (s.length == 0)
            return bad(QStringLiteral("sub-request %1: record length 0").arg(subs.size() + 1));
        responseSize += 2 + 2 * s.length; // sub-response length, reference type, the records
        if (responseSize > 253)
            return bad(QStringLiteral("the records asked for do not fit a response (%1 bytes, at most 253)").arg(responseSize));
        subs.append(s);
    }
    for (int i = 0; i < subs.size(); ++i) {
        if (const QString problem = addressProblem(*m_unit, subs.at(i), i, false); !problem.isEmpty())
            return SimReply::exception(0x14, 0x02, problem);
    }
    QByteArray bytes(1, char(0x14));
    bytes.append(char(responseSize - 2));
    for (const SubRequest &s : subs) {
        bytes.append(char(1 + 2 * s.length));
        bytes.append(char(kReferenceType));
        const QList<quint16> records = m_unit->fileRecords(s.file);
        for (int r = 0; r < s.length; ++r)
            appendWord(bytes, records.at(s.record + r));
    }
    return SimReply::normal(bytes);
}

SimReply SimProcessor::writeFileRecord(QByteArrayView pdu)
{
    auto bad = [](const QString &why) { return SimReply::exception(0x15, 0x03, why); };
    if (pdu.size() < 2)
        return bad(QStringLiteral("15 needs a byte count"));
    const int byteCount = quint8(pdu[1]);
    // 6.15: request data length 0x09-0xFB.
    if (byteCount < 0x09 || byteCount > 0xFB)
        return bad(QStringLiteral("request data length %1 is outside 9-251").arg(byteCount));
    if (pdu.size() != 2 + byteCount)
        return bad(QStringLiteral("request data length %1 announces %1 bytes but %2 follow").arg(byteCount).arg(pdu.size() - 2));
    QList<SubRequest> subs;
    qsizetype offset = 2;
    while (offset < pdu.size()) {
        if (pdu.size() - offset < 7)
            return bad(QStringLiteral("sub-request %1 is cut short: %2 of its 7 header bytes").arg(subs.size() + 1).arg(pdu.size() - offset));
        SubRequest s{quint8(pdu[offset]), word(pdu, offset + 1), word(pdu, offset + 3), word(pdu, offset + 5), offset + 7};
        if (s.length == 0)
            return bad(QStringLiteral("sub-request %1: record length 0").arg(subs.size() + 1));
        if (pdu.size() - s.dataOffset < 2 * s.length)
            return bad(QStringLiteral("sub-request %1: record length %2 needs %3 bytes, %4 present")
                           .arg(subs.size() + 1)
                           .arg(s.length)
                           .arg(2 * s.length)
                           .arg(pdu.size() - s.dataOffset));
        subs.append(s);
        offset = s.dataOffset + 2 * s.length;
    }
    for (int i = 0; i < subs.size(); ++i) {
        if (const QString problem = addressProblem(*m_unit, subs.at(i), i, true); !problem.isEmpty())
            return SimReply::exception(0x15, 0x02, problem);
    }
    // All sub-requests checked: write them all (nothing is written when one is refused).
    for (const SubRequest &s : subs) {
        QList<quint16> values;
        values.reserve(s.length);
        for (int r = 0; r < s.length; ++r)
            values.append(word(pdu, s.dataOffset + 2 * r));
        if (!m_unit->writeFileRecords(s.file, s.record, values))
            return SimReply::exception(0x15, 0x04, QStringLiteral("file %1 could not be written").arg(s.file));
    }
    return SimReply::normal(pdu.toByteArray()); // 6.15: the response echoes the request
}

} // namespace mbscope
