#pragma once

#include "tapsettings.h"

#include "engine/recordlistener.h"
#include "exchange/requestitem.h"
#include "sim/simremote.h"

#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QObject>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace mbscope {

class EngineCore;
class TapMetrics;
class TrafficLog;

// The inline tap's forwarding (issue 27): the Simulator's remote (SimRemote), so that masters
// talk to the simulator's endpoints (any listening URL: tcp, rtu-tcp, udp, a serial port...) and
// each request goes on to the device its unit's route names, over an EngineCore of that target's
// own (any link: tcp, rtu-tcp, a serial port...), framed for it; the device's answer comes back
// to the master that asked, framed for the master, the function code and data unchanged.
//
// - One engine per target, in the calling thread: requests to a target wait their turn in its
//   queue, each with its route's timeout and the retries; a Modbus/TCP target numbers its own
//   transaction ids (the masters' ids are kept for their answers). On an RTU serial port one
//   request at a time, the next never before t3.5 of silence after the previous answer's last
//   byte: the engine keeps that gap on every RTU serial link (EngineCore::lineQuiet).
// - An answer is framed by what arrived (the engine's framer: an exception is complete with its
//   5 bytes and passed on at once), never by waiting for the timeout.
// - Same serial framing on both sides and no renumbering: the device's bytes go back exactly as
//   they came, a bad CRC included (a man in the middle changes nothing). Otherwise the answer's
//   PDU is framed anew, and an answer with a bad checksum is not passed on (counted as damaged).
// - Timeouts, link failures and damaged answers: exception 0B or silence, unrouted units 0A or
//   silence (TapSettings::NoAnswer); read-only mode refuses writes (TapSettings::Refusal).
// - The device leg is recorded by the engines into the traffic log (setTrafficLog), a link per
//   target, next to the simulator's record of the master leg: one journal holds both.
class TapForwarder : public QObject, public SimRemote, private RecordListener
{
    Q_OBJECT
public:
    explicit TapForwarder(const TapSettings &settings, QObject *parent = nullptr);
    ~TapForwarder() override;

    void setTrafficLog(TrafficLog *log);
    // Each answered request observed into metrics (not owned; nullptr: none).
    void setMetrics(TapMetrics *metrics) { m_metrics = metrics; }
    void forward(const Request &request, Done done) override;

    [[nodiscard]] const TapSettings &settings() const { return m_settings; }
    [[nodiscard]] const TapCounters &counters() const { return m_counters; }
    // Requests waiting for a device (queued or in flight), over every target.
    [[nodiscard]] int waiting() const { return int(m_waiting.size()); }
    // The targets, as their engines were given them (one per link, whatever the routes' timeouts).
    [[nodiscard]] QList<LinkUrl> targets() const;

Q_SIGNALS:
    // A target's link opened, or failed or closed with requests in flight (what it said).
    void targetOpened(const QString &target);
    void targetMessage(const QString &target, const QString &message);

private:
    struct Target {
        LinkUrl url; // without a response timeout: routes differing only in timeout= share it
        QString name; // url.toString(), made once: every answer's note and metrics name it
        EngineCore *core = nullptr;
    };
    struct Waiting {
        Done done;
        Framing masterFraming = Framing::Tcp;
        Framing deviceFraming = Framing::Tcp;
        bool passThrough = false; // the device's bytes go back as they are
        bool broadcast = false;
        quint8 function = 0;
        quint8 masterUnit = 0;
        qint64 receivedNs = 0; // the master's request in
        QString target;
        // A read, to send once more on a new connection when the link fails under it (the
        // device closed just as the request went: some close after every answer). Empty for
        // writes and broadcasts, and once re-sent.
        std::optional<RequestItem> resend;
        EngineCore *core = nullptr;
    };

    void onRecord(const Transaction &transaction, quint64 tag) override;
    Target &targetFor(const LinkUrl &url);
    // What a master gets instead of an answer: exception `code` when the policy says so.
    [[nodiscard]] Answer nothing(Framing masterFraming, quint8 function, quint8 code, const QString &why) const;
    [[nodiscard]] bool exceptionsFor(Framing masterFraming) const;

    TapSettings m_settings;
    std::vector<Target> m_targets;
    TrafficLog *m_log = nullptr;
    TapMetrics *m_metrics = nullptr;
    QHash<quint64, Waiting> m_waiting; // by the engine's transaction id
    TapCounters m_counters;
};

} // namespace mbscope
