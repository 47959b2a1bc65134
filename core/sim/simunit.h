#pragma once

#include "sim/simcounters.h"
#include "sim/simrange.h"
#include "profile/simtable.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <array>
#include <bitset>
#include <optional>

namespace mbscope {

// One simulated Modbus unit (server device): its data model and its state, without any
// knowledge of framings or sockets. The request processor (SimProcessor) reads and writes it;
// device profiles and value generators fill it; views watch it through the signals.
//
// Values are set in two ways: locally (setValue/setValues: profiles, generators, the GUI), which
// ignores the writable flag, and by clients through the processor, which respects it and emits
// clientWrote() besides valuesChanged(), so that a "copy of another register" generator or a
// view can react to what a master wrote.
//
// Not thread-safe: lives in the simulator's thread.
class SimUnit : public QObject
{
    Q_OBJECT
public:
    explicit SimUnit(quint8 id, QObject *parent = nullptr);

    [[nodiscard]] quint8 id() const { return m_id; }
    [[nodiscard]] QString name() const { return m_name; }
    void setName(const QString &name) { m_name = name; }

    // ---- Tables ----
    // Adds a range; fails (returns false, with a message in *error) when it is empty, runs past
    // 65535, or overlaps a range of the same table.
    bool addRange(const SimRange &range, QString *error = nullptr);
    void clearRanges(SimTable table);
    // The ranges of a table in address order; values() reflect the current values.
    [[nodiscard]] QList<SimRange> ranges(SimTable table) const;
    // Every address of [start, start+count) lies in some range.
    [[nodiscard]] bool contains(SimTable table, int start, int count = 1) const;
    // Every address of [start, start+count) lies in a writable range.
    [[nodiscard]] bool isWritable(SimTable table, int start, int count = 1) const;

    // Local access (no writable check). Bits read and write as 0/1 (a non-zero bit value is 1).
    // value() and values() read through a shared table (setSharedTable).
    [[nodiscard]] std::optional<quint16> value(SimTable table, int address) const;
    // All count values, or an empty list when any address is missing (unless gap reads are zeros).
    [[nodiscard]] QList<quint16> values(SimTable table, int start, int count) const;
    bool setValue(SimTable table, int address, quint16 value);
    // All or nothing: false (and no change) when any address is missing.
    bool setValues(SimTable table, int start, const QList<quint16> &values);

    // Client access, used by the request processor: refuses (false, no change) when an address is
    // missing or not writable; emits clientWrote() after valuesChanged().
    bool clientWrite(SimTable table, int start, const QList<quint16> &values);

    // ---- How reads are answered (a device profile's "sharedTables" and "gapReads") ----
    // Reads of asked (values(), value()) answer answering's values instead: a device whose 03 and
    // 04 read the same registers, or whose 02 reads the coils 05 writes. Writes are not affected.
    void setSharedTable(SimTable asked, SimTable answering) { m_answering[size_t(asked)] = answering; }
    [[nodiscard]] SimTable answeringTable(SimTable asked) const { return m_answering[size_t(asked)]; }
    // On: values() of a span between the first and the last address of a table's ranges answers 0
    // for the addresses no range holds, instead of failing (which the processor answers with 02).
    void setGapReadsZeros(bool on) { m_gapReadsZeros = on; }
    [[nodiscard]] bool gapReadsZeros() const { return m_gapReadsZeros; }

    // ---- Function codes ----
    // Function codes the unit answers; any other gets exception 01 (V1.1b3, 7). By default every
    // code SimProcessor implements (01-08, 0B, 0C, 0F-11, 14-18, 2B).
    [[nodiscard]] bool supportsFunction(quint8 functionCode) const { return m_functions.test(functionCode); }
    void setSupportedFunctions(const QList<quint8> &codes);
    void setFunctionSupported(quint8 functionCode, bool supported) { m_functions.set(functionCode, supported); }
    [[nodiscard]] QList<quint8> supportedFunctions() const;
    [[nodiscard]] static QList<quint8> implementedFunctions();

    // ---- Read Exception Status (07) ----
    [[nodiscard]] quint8 exceptionStatus() const { return m_exceptionStatus; }
    void setExceptionStatus(quint8 status) { m_exceptionStatus = status; }

    // ---- Report Server ID (11, V1.1b3 6.13): "device specific" server id bytes ----
    [[nodiscard]] QByteArray serverId() const { return m_serverId; }
    void setServerId(const QByteArray &id) { m_serverId = id; }
    [[nodiscard]] bool runIndicator() const { return m_runIndicator; } // ON = 0xFF
    void setRunIndicator(bool on) { m_runIndicator = on; }
    [[nodiscard]] QByteArray additionalData() const { return m_additionalData; }
    void setAdditionalData(const QByteArray &data) { m_additionalData = data; }

    // ---- Read Device Identification (2B/0E, V1.1b3 6.21) ----
    // Objects 00-06 basic/regular strings (VendorName, ProductCode, MajorMinorRevision, VendorUrl,
    // ProductName, ModelName, UserApplicationName), 07-7F reserved regular, 80-FF extended.
    [[nodiscard]] QMap<quint8, QByteArray> deviceIdObjects() const { return m_deviceId; }
    void setDeviceIdObject(quint8 objectId, const QByteArray &value) { m_deviceId.insert(objectId, value); }
    void removeDeviceIdObject(quint8 objectId) { m_deviceId.remove(objectId); }
    // Conformity level byte: 01/02/03 (stream only) or 81/82/83 (stream and individual access).
    // 0 (the default) derives it from the objects present, with individual access.
    [[nodiscard]] quint8 conformityLevel() const;
    void setConformityLevel(quint8 level) { m_conformityLevel = level; }

    // ---- Read FIFO Queue (18, V1.1b3 6.18): queues by their pointer address ----
    // A queue holds at most 31 registers (more gives exception 03 on reading).
    [[nodiscard]] bool hasFifo(quint16 pointerAddress) const { return m_fifos.contains(pointerAddress); }
    [[nodiscard]] QList<quint16> fifo(quint16 pointerAddress) const { return m_fifos.value(pointerAddress); }
    void setFifo(quint16 pointerAddress, const QList<quint16> &values) { m_fifos.insert(pointerAddress, values); }
    void removeFifo(quint16 pointerAddress) { m_fifos.remove(pointerAddress); }

    // ---- File records (14/15, V1.1b3 6.14-6.15): file 1-65535, records 0-9999, one register each ----
    [[nodiscard]] bool hasFile(quint16 fileNumber) const { return m_files.contains(fileNumber); }
    [[nodiscard]] QList<quint16> fileRecords(quint16 fileNumber) const { return m_files.value(fileNumber).records; }
    [[nodiscard]] bool isFileWritable(quint16 fileNumber) const { return m_files.value(fileNumber).writable; }
    // records.size() is the file's length (at most 10000); records past it do not exist (exception 02).
    void setFile(quint16 fileNumber, const QList<quint16> &records, bool writable = true);
    void removeFile(quint16 fileNumber) { m_files.remove(fileNumber); }
    [[nodiscard]] QList<quint16> fileNumbers() const { return m_files.keys(); }
    // Client write through 15: false when the file is missing, read-only or too short.
    bool writeFileRecords(quint16 fileNumber, int recordNumber, const QList<quint16> &values);

    // ---- Diagnostics (08), comm event counter and log (0B/0C) ----
    [[nodiscard]] const SimCounters &counters() const { return m_counters; }
    SimCounters &counters() { return m_counters; }
    [[nodiscard]] quint16 diagnosticRegister() const { return m_diagnosticRegister; }
    void setDiagnosticRegister(quint16 value) { m_diagnosticRegister = value; }
    [[nodiscard]] char asciiDelimiter() const { return m_asciiDelimiter; } // 08/03; LF by default
    void setAsciiDelimiter(char c) { m_asciiDelimiter = c; }
    // 08/04: in listen-only mode the unit processes nothing and answers nothing, until 08/01.
    [[nodiscard]] bool isListenOnly() const { return m_listenOnly; }
    void setListenOnly(bool on) { m_listenOnly = on; }
    // Event log bytes (V1.1b3 6.10), newest first, at most 64.
    [[nodiscard]] QList<quint8> eventLog() const { return m_eventLog; }
    void logEvent(quint8 event);
    void clearEventLog() { m_eventLog.clear(); }
    // 0B/0C status word: 0xFFFF while a previous program command is still being processed.
    [[nodiscard]] bool isBusy() const { return m_busy; }
    void setBusy(bool busy) { m_busy = busy; } // when set, commands answer exception 06

    // ---- Timing ----
    // The answer leaves this long after the request arrived (when no fault plan says otherwise).
    [[nodiscard]] qint64 responseDelayNs() const { return m_responseDelayNs; }
    void setResponseDelayNs(qint64 ns) { m_responseDelayNs = ns; }

Q_SIGNALS:
    // Any change of values, local or by a client (one signal per call, not per address).
    void valuesChanged(mbscope::SimTable table, int start, int count);
    // A client wrote [start, start+count) (05, 06, 0F, 10, 16, 17).
    void clientWrote(mbscope::SimTable table, int start, int count);
    // A client wrote file records (15).
    void fileWritten(quint16 fileNumber, int recordNumber, int count);

private:
    struct Block {
        quint16 start = 0;
        bool writable = true;
        QString name;
        QList<quint16> values;
        [[nodiscard]] int end() const { return int(start) + int(values.size()); }
    };
    struct File {
        QList<quint16> records;
        bool writable = true;
    };
    // Index of the block holding address, or -1.
    [[nodiscard]] int blockIndex(SimTable table, int address) const;
    // Calls f(block, offset in block, index in span, run length) for each run of a span that
    // lies wholly in blocks; returns false (calling nothing) when any address is missing.
    template<typename F>
    bool forSpan(SimTable table, int start, int count, F &&f) const;

    quint8 m_id = 1;
    QString m_name;
    std::array<QList<Block>, SimTableCount> m_tables;
    std::array<SimTable, SimTableCount> m_answering{SimTable::Coils, SimTable::DiscreteInputs,
                                                    SimTable::InputRegisters, SimTable::HoldingRegisters};
    bool m_gapReadsZeros = false;
    std::bitset<256> m_functions;
    quint8 m_exceptionStatus = 0;
    QByteArray m_serverId;
    bool m_runIndicator = true;
    QByteArray m_additionalData;
    QMap<quint8, QByteArray> m_deviceId;
    quint8 m_conformityLevel = 0;
    QMap<quint16, QList<quint16>> m_fifos;
    QMap<quint16, File> m_files;
    SimCounters m_counters;
    quint16 m_diagnosticRegister = 0;
    char m_asciiDelimiter = '\n';
    bool m_listenOnly = false;
    QList<quint8> m_eventLog;
    bool m_busy = false;
    qint64 m_responseDelayNs = 0;
};

} // namespace mbscope
