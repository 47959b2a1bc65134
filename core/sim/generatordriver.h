#pragma once

#include "profile/deviceprofile.h"
#include "profile/scaledvalue.h"
#include "sim/valuegenerator.h"

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <vector>

class QTimer;

namespace mbscope {

class SimUnit;

// Runs the value generators of a device profile: one ValueGenerator per generated value, ticked by
// one QTimer per distinct period, each tick writing the new value into its SimUnit (setValues, so
// clients read changing values and views see valuesChanged).
//
// A value a client (or anyone) changed since the last tick is adopted first, so a counter counts
// on from what a master wrote. Generators draw from seeds derived from the profile's seed and the
// value's place (unit, table, address), or from the generator's own "seed" and the value's index.
//
// Lives in the simulator's thread; the timers are children, so moveToThread takes them along.
class GeneratorDriver : public QObject
{
    Q_OBJECT
public:
    explicit GeneratorDriver(QObject *parent = nullptr);
    ~GeneratorDriver() override;

    // Builds the generators of every unit of the profile found among units (matched by id).
    // Replaces what was attached before; stops the timers.
    void attach(const DeviceProfile &profile, const QList<SimUnit *> &units);
    void clear();

    void start();
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] int generatorCount() const { return int(m_slots.size()); }
    // The distinct periods, in ms, ascending: one timer each.
    [[nodiscard]] QList<double> periods() const;

    // One period of every generator whose period is periodMs: what its timer does. Tests and
    // single-stepping call it directly, without waiting for real time.
    void tickPeriod(double periodMs);
    // Every tick due in the next ms of simulated time, in time order (ties in period order).
    void advance(double ms);

    // The seed of one generated value, as attach() derives it.
    [[nodiscard]] static quint64 valueSeed(quint64 profileSeed, const GeneratorSpec &spec, quint8 unit,
                                           SimTable table, int address, int index);

Q_SIGNALS:
    // After each tickPeriod(): how many values were written.
    void ticked(double periodMs, int values);

private:
    struct Slot {
        QPointer<SimUnit> unit;
        SimTable table = SimTable::HoldingRegisters;
        int address = 0;
        int width = 1;
        ScaledValue codec;          // registers; bits are 0/1
        ValueGenerator generator;
        QList<quint16> lastWritten; // to notice what others wrote in between
        // Copy: the source value's place and codec.
        SimTable sourceTable = SimTable::HoldingRegisters;
        int sourceAddress = 0;
        int sourceWidth = 1;
        ScaledValue sourceCodec;
    };

    void tickSlot(Slot &slot);
    [[nodiscard]] static double readValue(const SimUnit &unit, SimTable table, int address, int width,
                                          const ScaledValue &codec, bool *ok);

    std::vector<Slot> m_slots;
    QMap<double, QTimer *> m_timers;
    QMap<double, double> m_nextDue; // advance(): simulated time of each period's next tick
    double m_now = 0;
    bool m_running = false;
};

} // namespace mbscope
