#include "scan/scanline.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/progressline.h"
#include "scan/scanreport.h"

#include "protocol/hexnumber.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QSet>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

QString text(const LineScanSettings &settings, const QList<LineTrial> &trials, JobEnd end, qint64 elapsedMs)
{
    QString t = QStringLiteral("LINE %1  read %2 at %3, quantity %4\n")
                    .arg(settings.url.serial.device)
                    .arg(hexNumber(settings.function, 2))
                    .arg(settings.address)
                    .arg(settings.quantity);
    t += QStringLiteral("%1  %2  %3\n").arg(QStringLiteral("SETTING"), -14).arg(QStringLiteral("UNITS"), -9).arg(QStringLiteral("RESULT"));
    QStringList working;
    for (qsizetype i = 0; i < trials.size();) {
        // The ids of one setting on one line: "1-247 silent".
        qsizetype j = i + 1;
        while (j < trials.size() && trials.at(j).settingText() == trials.at(i).settingText()
               && trials.at(j).probe.kind == trials.at(i).probe.kind)
            ++j;
        const LineTrial &a = trials.at(i);
        const QString ids = j - i > 1 ? QStringLiteral("%1-%2").arg(a.unit).arg(trials.at(j - 1).unit) : QString::number(a.unit);
        t += QStringLiteral("%1  %2  %3\n").arg(a.settingText(), -14).arg(ids, -9).arg(a.works() ? QStringLiteral("WORKS: ") + a.probe.summary() : a.probe.summary());
        if (a.works())
            working.append(QStringLiteral("%1 (unit %2)").arg(a.settingText()).arg(a.unit));
        i = j;
    }
    t += QStringLiteral("\n%1 trials in %2; %3\n").arg(trials.size()).arg(ScanReport::durationText(elapsedMs)).arg(QString::fromLatin1(jobEndName(end)));
    if (working.isEmpty()) {
        t += QStringLiteral("no setting answered\n");
    } else {
        t += QStringLiteral("answered: %1\n").arg(working.join(QStringLiteral(", ")));
        // The bytes of a pty, or of a converter that re-times them, carry no parity bit: every
        // parity then answers at the right baud rate, and only a real UART can tell them apart.
        QSet<QString> parities;
        for (const LineTrial &trial : trials) {
            if (trial.works())
                parities.insert(QString(QLatin1Char(trial.parity)));
        }
        if (parities.size() > 1)
            t += QStringLiteral("note: several parities answered: this line does not carry the parity bit (a pseudo "
                                "terminal, or a converter that ignores it); the device's parity cannot be told here\n");
    }
    return t;
}

QJsonObject json(const LineScanSettings &settings, const QList<LineTrial> &trials, JobEnd end, qint64 elapsedMs)
{
    QJsonArray list;
    QJsonArray working;
    for (const LineTrial &t : trials) {
        QJsonObject o{{QStringLiteral("baud"), t.baud},
                      {QStringLiteral("parity"), QString(QLatin1Char(t.parity))},
                      {QStringLiteral("stop_bits"), t.stopBits},
                      {QStringLiteral("setting"), t.settingText()},
                      {QStringLiteral("unit"), int(t.unit)},
                      {QStringLiteral("result"), QString::fromLatin1(unitProbeKindName(t.probe.kind))},
                      {QStringLiteral("works"), t.works()}};
        list.append(o);
        if (t.works())
            working.append(o);
    }
    return QJsonObject{{QStringLiteral("port"), settings.url.serial.device},
                       {QStringLiteral("tried"), list},
                       {QStringLiteral("working"), working},
                       {QStringLiteral("elapsed_ms"), double(elapsedMs)},
                       {QStringLiteral("end"), QString::fromLatin1(jobEndName(end))}};
}

} // namespace

int runLineScan(const LineScanSettings &settings, bool asJson, const ScanRecord &record, QTextStream &out, QTextStream &err)
{
    if (const QString problem = settings.problem(); !problem.isEmpty()) {
        err << "mbscope scan: " << problem << '\n';
        return ExitUsage;
    }
    TrafficRecording recording;
    if (!openRecording(recording, record.settings, record.metadata, QStringLiteral("scan"), err))
        return ExitUsage;
    FrameLog frames;
    if (!openFrameLog(frames, record.print, QStringLiteral("scan"), err))
        return ExitUsage;
    frames.setNamesLinks(true); // every setting tried is a link of its own
    LineScanner scanner;
    if (recording.isOpen())
        scanner.channel()->setTrafficLog(recording.log()); // every setting tried, a link of its own
    QObject::connect(scanner.channel(), &ProbeChannel::framesLogged, &frames, &FrameLog::addFrames);
    InterruptWatcher interrupts;
    ProgressLine line;
    frames.setProgressLine(&line);
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &scanner, &LineScanner::stop);
    QString lastTried; // the setting of the last trial: "19200 8E1 unit 1 silent"
    QObject::connect(&scanner, &LineScanner::tried, &scanner, [&](const LineTrial &t) {
        lastTried = QStringLiteral("%1 unit %2 %3").arg(t.settingText()).arg(t.unit).arg(QString::fromLatin1(unitProbeKindName(t.probe.kind)));
    });
    QObject::connect(&scanner, &LineScanner::progressChanged, &scanner,
                     [&](const JobProgress &p) { line.show(ScanReport::progressText(QStringLiteral("trials"), p, lastTried)); });
    QElapsedTimer clock;
    clock.start();
    const std::optional<QList<LineTrial>> trials = scanner.run(settings);
    line.clear();
    scanner.channel()->setTrafficLog(nullptr); // the last frames reach the journal
    finishRecording(recording, err);
    if (!trials)
        return ExitUsage;
    if (scanner.end() == JobEnd::LinkError && !trials->isEmpty() && trials->size() == 1) {
        err << "mbscope scan: " << trials->constLast().probe.problem << '\n';
        return ExitLinkError;
    }
    if (asJson)
        out << QJsonDocument(json(settings, *trials, scanner.end(), clock.elapsed())).toJson(QJsonDocument::Indented);
    else
        out << text(settings, *trials, scanner.end(), clock.elapsed());
    out.flush();
    for (const LineTrial &t : *trials) {
        if (t.works())
            return ExitOk;
    }
    return ExitFailure;
}

} // namespace mbscope::app
