#pragma once

#include "probechannel.h"
#include "job/jobend.h"
#include "job/jobprogress.h"
#include "unitprobe.h"
#include "unitscansettings.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QList>
#include <QtCore/QObject>

namespace mbscope {

// Asks every unit id of a range the same harmless read, one at a time with a gap, and names what
// each did (UnitClassifier). Bounded: one request per id, no retries, and a time limit for the
// whole scan. Never writes. Runs in the caller's event loop; stop() ends it after the probe in
// flight is abandoned. A link error ends the scan: the ids after it were not asked.
class UnitScanner : public QObject
{
    Q_OBJECT
public:
    explicit UnitScanner(QObject *parent = nullptr);

    // Starts a scan (settings.problem() must be empty); false, with nothing started, otherwise.
    bool start(const UnitScanSettings &settings);
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] const QList<UnitProbe> &results() const { return m_results; }
    [[nodiscard]] const UnitScanSettings &settings() const { return m_settings; }
    [[nodiscard]] JobProgress progress() const;
    [[nodiscard]] ProbeChannel *channel() { return m_channel; }

    // The read a scan sends (function, address, quantity), as a PDU.
    [[nodiscard]] static QByteArray readPdu(quint8 function, quint16 address, quint16 quantity);

Q_SIGNALS:
    void probed(const mbscope::UnitProbe &probe);
    void progressChanged(const mbscope::JobProgress &progress);
    void finished(mbscope::JobEnd end);

private:
    void next();
    void onAnswered(const Transaction &transaction, const QByteArray &bytesRead);
    void end(JobEnd how);

    ProbeChannel *m_channel;
    UnitScanSettings m_settings;
    QList<UnitProbe> m_results;
    QElapsedTimer m_clock;
    int m_nextUnit = 0;
    int m_current = -1;
    bool m_running = false;
};

} // namespace mbscope
