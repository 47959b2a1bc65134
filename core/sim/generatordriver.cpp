#include "sim/generatordriver.h"

#include "sim/simrandom.h"
#include "sim/simunit.h"

#include <QtCore/QTimer>

#include <algorithm>
#include <cmath>

namespace mbscope {

GeneratorDriver::GeneratorDriver(QObject *parent) : QObject(parent) {}

GeneratorDriver::~GeneratorDriver() = default;

quint64 GeneratorDriver::valueSeed(quint64 profileSeed, const GeneratorSpec &spec, quint8 unit, SimTable table,
                                   int address, int index)
{
    if (spec.seed)
        return SimRandom::derive(*spec.seed, quint64(index));
    return SimRandom::derive(profileSeed, unit, quint64(table) + 1, quint64(address));
}

void GeneratorDriver::clear()
{
    stop();
    m_slots.clear();
    m_nextDue.clear();
    m_now = 0;
}

void GeneratorDriver::attach(const DeviceProfile &profile, const QList<SimUnit *> &units)
{
    clear();
    for (const UnitProfile &unitProfile : profile.units) {
        SimUnit *unit = nullptr;
        for (SimUnit *u : units) {
            if (u && u->id() == unitProfile.id)
                unit = u;
        }
        if (!unit)
            continue;
        for (const TableEntry &entry : unitProfile.entries) {
            if (!entry.generator)
                continue;
            const GeneratorSpec &spec = *entry.generator;
            const int width = entry.width();
            ScaledValue codec{entry.format, entry.scale, entry.offset};
            ScaledValue sourceCodec;
            int sourceWidth = 1;
            if (spec.kind == GeneratorSpec::Kind::Copy) {
                if (const TableEntry *source = unitProfile.entryAt(spec.sourceTable, spec.sourceAddress)) {
                    sourceCodec = ScaledValue{source->format, source->scale, source->offset};
                    sourceWidth = source->width();
                }
            }
            for (int i = 0; i < entry.valueCount(); ++i) {
                const int address = entry.address + i * width;
                const QList<quint16> words = entry.initial.mid(i * width, width);
                const double initial = isBitTable(entry.table)
                    ? double(words.value(0))
                    : codec.decode(std::span<const quint16>(words.constData(), size_t(words.size())));
                const quint64 seed = valueSeed(profile.seed, spec, unitProfile.id, entry.table, address, i);
                m_slots.push_back(Slot{unit, entry.table, address, width, codec, ValueGenerator(spec, seed, initial),
                                       words, spec.sourceTable, spec.sourceAddress, sourceWidth, sourceCodec});
            }
        }
    }
    for (double period : periods())
        m_nextDue.insert(period, period);
}

QList<double> GeneratorDriver::periods() const
{
    QList<double> out;
    for (const Slot &slot : m_slots) {
        if (!out.contains(slot.generator.spec().periodMs))
            out.append(slot.generator.spec().periodMs);
    }
    std::sort(out.begin(), out.end());
    return out;
}

void GeneratorDriver::start()
{
    if (m_running)
        return;
    m_running = true;
    for (double period : periods()) {
        auto *timer = new QTimer(this);
        timer->setInterval(int(std::max<qint64>(1, std::llround(period))));
        timer->setTimerType(period < 100 ? Qt::PreciseTimer : Qt::CoarseTimer);
        connect(timer, &QTimer::timeout, this, [this, period] { tickPeriod(period); });
        m_timers.insert(period, timer);
        timer->start();
    }
}

void GeneratorDriver::stop()
{
    m_running = false;
    qDeleteAll(m_timers);
    m_timers.clear();
}

double GeneratorDriver::readValue(const SimUnit &unit, SimTable table, int address, int width,
                                  const ScaledValue &codec, bool *ok)
{
    const QList<quint16> words = unit.values(table, address, width);
    *ok = words.size() == width;
    if (!*ok)
        return 0;
    if (isBitTable(table))
        return words.at(0) ? 1.0 : 0.0;
    return codec.decode(std::span<const quint16>(words.constData(), size_t(words.size())));
}

void GeneratorDriver::tickSlot(Slot &slot)
{
    SimUnit *unit = slot.unit.data();
    if (!unit)
        return;
    const QList<quint16> current = unit->values(slot.table, slot.address, slot.width);
    if (current.size() != slot.width)
        return; // the range was removed since
    if (current != slot.lastWritten) {
        bool ok = false;
        slot.generator.adopt(readValue(*unit, slot.table, slot.address, slot.width, slot.codec, &ok));
    }
    double source = 0;
    if (slot.generator.spec().kind == GeneratorSpec::Kind::Copy) {
        bool ok = false;
        source = readValue(*unit, slot.sourceTable, slot.sourceAddress, slot.sourceWidth, slot.sourceCodec, &ok);
        if (!ok)
            return;
    }
    const double value = slot.generator.next(source);
    QList<quint16> words;
    if (isBitTable(slot.table)) {
        words = {quint16(value >= 0.5 ? 1 : 0)};
    } else {
        const RegisterValueResult encoded = slot.codec.encode(value, true);
        if (!encoded.ok)
            return; // NaN into an integer register: keep the last value
        words = encoded.value.registers();
    }
    slot.lastWritten = words;
    if (words != current)
        unit->setValues(slot.table, slot.address, words);
}

void GeneratorDriver::tickPeriod(double periodMs)
{
    int written = 0;
    for (Slot &slot : m_slots) {
        if (slot.generator.spec().periodMs == periodMs) {
            tickSlot(slot);
            ++written;
        }
    }
    Q_EMIT ticked(periodMs, written);
}

void GeneratorDriver::advance(double ms)
{
    const double until = m_now + ms;
    for (;;) {
        // The earliest due period not beyond `until` (QMap iterates periods ascending, so ties go
        // to the shorter period).
        double best = -1;
        double bestDue = 0;
        for (auto it = m_nextDue.cbegin(); it != m_nextDue.cend(); ++it) {
            if (it.value() <= until && (best < 0 || it.value() < bestDue)) {
                best = it.key();
                bestDue = it.value();
            }
        }
        if (best < 0)
            break;
        m_now = bestDue;
        m_nextDue[best] = bestDue + best;
        tickPeriod(best);
    }
    m_now = until;
}

} // namespace mbscope

#include "moc_generatordriver.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
