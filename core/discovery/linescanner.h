#pragma once

#include "probechannel.h"
#include "job/jobend.h"
#include "job/jobprogress.h"
#include "unitprobe.h"

#include "transport/linkurl.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QList>
#include <QtCore/QObject>

#include <optional>

namespace mbscope {

// What a serial-settings scan tries: every baud rate, parity and stop-bit count of the lists, in
// that order, each with the same read to each unit id asked.
struct LineScanSettings {
    LinkUrl url;                 // rtu:// or ascii://: the port; its line settings are replaced
    QList<int> bauds{9600, 19200, 38400, 57600, 115200, 4800, 2400, 1200};
    QList<char> parities{'E', 'N', 'O'};
    QList<int> stopBits{1, 2};
    // Ids asked on every setting; empty: 1 on every setting first, then (when nothing answered)
    // 2-247 on every setting, until something does or the time limit comes.
    QList<quint8> units;
    quint8 function = 3;
    quint16 address = 0;
    quint16 quantity = 1;
    int timeoutMs = 200;         // plus the time the request and a long answer take at the baud rate
    bool stopAtFirst = false;    // stop at the first setting that answers (else try them all)
    qint64 maxDurationMs = 600000;

    [[nodiscard]] QString problem() const;
};

// One setting tried: what came back.
struct LineTrial {
    int baud = 0;
    char parity = 'N';
    int stopBits = 1;
    quint8 unit = 0;
    UnitProbe probe;

    // A CRC-valid (or LRC-valid) answer from the unit asked: the line settings work, whatever
    // the answer said (data, exception or gateway exception).
    [[nodiscard]] bool works() const;
    [[nodiscard]] QString settingText() const; // "19200 8E1"
};

// Tries serial line settings with a known request until CRC-valid answers come back (MODBUS over
// Serial Line V1.02, 2.5.1: 11-bit characters, even parity by default, 2 stop bits without
// parity). Wrong baud rates give silence or garbage; a parity mismatch on a real UART gives parity
// and framing errors, so CRC errors. Only reads; bounded by the lists and a time limit.
class LineScanner : public QObject
{
    Q_OBJECT
public:
    explicit LineScanner(QObject *parent = nullptr);

    [[nodiscard]] std::optional<QList<LineTrial>> run(const LineScanSettings &settings);
    void stop()
    {
        m_stopRequested = true;
        m_channel->cancel();
    }
    [[nodiscard]] JobEnd end() const { return m_end; }
    [[nodiscard]] ProbeChannel *channel() { return m_channel; }
    // Trials done of the plan (every setting with every id; without ids, 1 and then 2-247 on
    // each: trials not needed, as the ids after one that answered, count as done), and the time
    // left: the plan's timeouts left, scaled by what the trials so far took of theirs.
    [[nodiscard]] JobProgress progress() const;

Q_SIGNALS:
    void progressChanged(const mbscope::JobProgress &progress);
    void tried(const mbscope::LineTrial &trial);

private:
    [[nodiscard]] bool mayContinue(int timeoutMs);
    // Every setting with the ids given; false when the scan must end.
    bool pass(const QList<quint8> &ids, QList<LineTrial> &out);
    // A trial's timeout at a baud rate: the settings' timeout and the time on the line.
    [[nodiscard]] int timeoutAt(int baud) const;
    // Trials left out of the plan (not needed): counted as done.
    void skip(int trials, int timeoutMs);

    ProbeChannel *m_channel;
    LineScanSettings m_settings;
    QElapsedTimer m_clock;
    bool m_stopRequested = false;
    JobEnd m_end = JobEnd::Completed;
    int m_done = 0;
    int m_total = 0;
    int m_found = 0;
    qint64 m_plannedLeftMs = 0; // the timeouts of the trials not done yet
    qint64 m_plannedRunMs = 0;  // the timeouts of the trials asked so far
};

} // namespace mbscope
