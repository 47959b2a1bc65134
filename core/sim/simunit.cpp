#include "sim/simunit.h"

#include <QtCore/QVarLengthArray>

#include <algorithm>

namespace mbscope {

namespace {

constexpr int MaxEventLog = 64;    // V1.1b3 6.10: the log holds up to 64 events
constexpr int MaxFileRecords = 10000; // V1.1b3 6.14: records 0-9999 (0x270F)

quint16 normalized(SimTable table, quint16 value)
{
    return isBitTable(table) ? quint16(value != 0) : value;
}

} // namespace

SimUnit::SimUnit(quint8 id, QObject *parent)
    : QObject(parent)
    , m_id(id)
{
    setSupportedFunctions(implementedFunctions());
}

QList<quint8> SimUnit::implementedFunctions()
{
    return {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0B, 0x0C, 0x0F, 0x10,
            0x11, 0x14, 0x15, 0x16, 0x17, 0x18, 0x2B};
}

void SimUnit::setSupportedFunctions(const QList<quint8> &codes)
{
    m_functions.reset();
    for (quint8 code : codes)
        m_functions.set(code);
}

QList<quint8> SimUnit::supportedFunctions() const
{
    QList<quint8> codes;
    for (int code = 0; code < 256; ++code) {
        if (m_functions.test(size_t(code)))
            codes.append(quint8(code));
    }
    return codes;
}

bool SimUnit::addRange(const SimRange &range, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (range.count < 1)
        return fail(QStringLiteral("a range of %1 needs at least one address").arg(QLatin1String(simTableName(range.table))));
    if (range.end() > 0x10000) {
        return fail(QStringLiteral("%1 range %2 + %3 runs past address 65535")
                        .arg(QLatin1String(simTableName(range.table)))
                        .arg(range.start)
                        .arg(range.count));
    }
    auto &blocks = m_tables[size_t(range.table)];
    for (const Block &b : blocks) {
        if (range.start < b.end() && int(b.start) < range.end()) {
            return fail(QStringLiteral("%1 range %2-%3 overlaps range %4-%5")
                            .arg(QLatin1String(simTableName(range.table)))
                            .arg(range.start)
                            .arg(range.end() - 1)
                            .arg(b.start)
                            .arg(b.end() - 1));
        }
    }
    Block block;
    block.start = range.start;
    block.writable = range.writable;
    block.name = range.name;
    block.values.resize(range.count, 0);
    for (int i = 0; i < range.count && i < range.values.size(); ++i)
        block.values[i] = normalized(range.table, range.values.at(i));
    auto pos = std::lower_bound(blocks.begin(), blocks.end(), block.start,
                                [](const Block &b, quint16 start) { return b.start < start; });
    blocks.insert(pos, block);
    Q_EMIT valuesChanged(range.table, range.start, range.count);
    return true;
}

void SimUnit::clearRanges(SimTable table)
{
    m_tables[size_t(table)].clear();
}

QList<SimRange> SimUnit::ranges(SimTable table) const
{
    QList<SimRange> out;
    for (const Block &b : m_tables[size_t(table)]) {
        SimRange r;
        r.table = table;
        r.start = b.start;
        r.count = int(b.values.size());
        r.writable = b.writable;
        r.name = b.name;
        r.values = b.values;
        out.append(r);
    }
    return out;
}

int SimUnit::blockIndex(SimTable table, int address) const
{
    const auto &blocks = m_tables[size_t(table)];
    // The last block starting at or before address.
    auto it = std::upper_bound(blocks.begin(), blocks.end(), address,
                               [](int a, const Block &b) { return a < int(b.start); });
    if (it == blocks.begin())
        return -1;
    --it;
    return address < it->end() ? int(it - blocks.begin()) : -1;
}

template<typename F>
bool SimUnit::forSpan(SimTable table, int start, int count, F &&f) const
{
    if (count < 1 || start < 0 || start + count > 0x10000)
        return false;
    struct Run {
        int block;
        int offset;
        int index;
        int length;
    };
    QVarLengthArray<Run, 4> runs;
    int address = start;
    while (address < start + count) {
        const int bi = blockIndex(table, address);
        if (bi < 0)
            return false;
        const Block &b = m_tables[size_t(table)].at(bi);
        const int length = std::min(b.end(), start + count) - address;
        runs.append(Run{bi, address - int(b.start), address - start, length});
        address += length;
    }
    for (const Run &r : runs)
        f(r.block, r.offset, r.index, r.length);
    return true;
}

bool SimUnit::contains(SimTable table, int start, int count) const
{
    return forSpan(table, start, count, [](int, int, int, int) {});
}

bool SimUnit::isWritable(SimTable table, int start, int count) const
{
    bool writable = true;
    const auto &blocks = m_tables[size_t(table)];
    const bool inside = forSpan(table, start, count, [&](int block, int, int, int) {
        writable = writable && blocks.at(block).writable;
    });
    return inside && writable;
}

std::optional<quint16> SimUnit::value(SimTable asked, int address) const
{
    const SimTable table = answeringTable(asked);
    if (address < 0 || address > 0xFFFF)
        return std::nullopt;
    const int bi = blockIndex(table, address);
    if (bi < 0)
        return std::nullopt;
    const Block &b = m_tables[size_t(table)].at(bi);
    return b.values.at(address - int(b.start));
}

QList<quint16> SimUnit::values(SimTable asked, int start, int count) const
{
    const SimTable table = answeringTable(asked);
    QList<quint16> out;
    if (count < 1)
        return out;
    out.resize(count);
    const auto &blocks = m_tables[size_t(table)];
    const bool inside = forSpan(table, start, count, [&](int block, int offset, int index, int length) {
        const auto &v = blocks.at(block).values;
        std::copy(v.begin() + offset, v.begin() + offset + length, out.begin() + index);
    });
    if (inside)
        return out;
    // A device that answers zeros over the gaps of its map, but 02 outside it.
    if (!m_gapReadsZeros || blocks.isEmpty() || start < int(blocks.constFirst().start)
        || start + count > blocks.constLast().end())
        return {};
    out.fill(0);
    for (int i = 0; i < count; ++i) {
        const int bi = blockIndex(table, start + i);
        if (bi >= 0)
            out[i] = blocks.at(bi).values.at(start + i - int(blocks.at(bi).start));
    }
    return out;
}

bool SimUnit::setValue(SimTable table, int address, quint16 value)
{
    return setValues(table, address, QList<quint16>{value});
}

bool SimUnit::setValues(SimTable table, int start, const QList<quint16> &values)
{
    auto &blocks = m_tables[size_t(table)];
    const bool inside = forSpan(table, start, int(values.size()), [&](int block, int offset, int index, int length) {
        auto &v = blocks[block].values;
        for (int i = 0; i < length; ++i)
            v[offset + i] = normalized(table, values.at(index + i));
    });
    if (inside)
        Q_EMIT valuesChanged(table, start, int(values.size()));
    return inside;
}

bool SimUnit::clientWrite(SimTable table, int start, const QList<quint16> &values)
{
    if (!isWritable(table, start, int(values.size())))
        return false;
    setValues(table, start, values);
    Q_EMIT clientWrote(table, start, int(values.size()));
    return true;
}

quint8 SimUnit::conformityLevel() const
{
    if (m_conformityLevel != 0)
        return m_conformityLevel;
    // V1.1b3 6.21, table of conformity levels: the highest category any object belongs to,
    // with bit 7 set because individual access (code 04) is always served here.
    quint8 level = 0x01;
    for (auto it = m_deviceId.cbegin(); it != m_deviceId.cend(); ++it) {
        if (it.key() >= 0x80)
            level = 0x03;
        else if (it.key() >= 0x03 && level < 0x02)
            level = 0x02;
    }
    return quint8(0x80 | level);
}

void SimUnit::setFile(quint16 fileNumber, const QList<quint16> &records, bool writable)
{
    File f;
    f.records = records.mid(0, MaxFileRecords);
    f.writable = writable;
    m_files.insert(fileNumber, f);
}

bool SimUnit::writeFileRecords(quint16 fileNumber, int recordNumber, const QList<quint16> &values)
{
    auto it = m_files.find(fileNumber);
    if (it == m_files.end() || !it->writable || recordNumber < 0
        || recordNumber + values.size() > it->records.size())
        return false;
    std::copy(values.begin(), values.end(), it->records.begin() + recordNumber);
    Q_EMIT fileWritten(fileNumber, recordNumber, int(values.size()));
    return true;
}

void SimUnit::logEvent(quint8 event)
{
    m_eventLog.prepend(event);
    if (m_eventLog.size() > MaxEventLog)
        m_eventLog.resize(MaxEventLog);
}

} // namespace mbscope

#include "moc_simunit.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
