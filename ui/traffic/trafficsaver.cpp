#include "trafficsaver.h"

#include "trafficmodel.h"

#include "capture/captureoptions.h"
#include "capture/exchangesource.h"
#include "capture/exchangewriter.h"
#include "traffic/trafficjournal.h"
#include "traffic/trafficmetadata.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QLocale>
#include <QtCore/QTemporaryDir>

namespace mbscope {

namespace {

// The frames to a journal at path (a new file), with the links' names and the window as its
// recorder; false with *error.
bool writeJournal(const TrafficModel &model, bool shownOnly, const QString &path, const QString &target, quint64 *frames,
                  QString *error)
{
    TrafficMetadata metadata = TrafficMetadata::forCommand(QStringLiteral("window"), QCoreApplication::arguments().mid(1),
                                                           QCoreApplication::applicationVersion());
    metadata.target = target;
    TrafficJournalWriter::Options options;
    options.metadata = metadata.toUtf8();
    options.batchEntries = 4096;
    TrafficJournalWriter journal;
    if (!journal.open(path, options, true, error))
        return false;
    const QStringList &links = model.links().names();
    for (qsizetype i = 0; i < links.size(); ++i)
        journal.addLink(quint16(i), links.at(i));
    *frames = 0;
    if (shownOnly) {
        for (int row = 0; row < model.rowCount(); ++row) {
            journal.addFrame(model.frameAt(model.storeRow(row)));
            ++*frames;
        }
    } else {
        model.visitFrames(model.firstKept(), true, [&](const TrafficEntry &e) {
            journal.addFrame(e);
            ++*frames;
            return true;
        });
    }
    journal.close();
    if (!journal.error().isEmpty()) {
        *error = journal.error();
        return false;
    }
    return true;
}

} // namespace

TrafficFormat TrafficSaver::formatFor(const QString &path)
{
    return trafficformat::ofEnding(path).value_or(TrafficFormat::Journal);
}

QStringList TrafficSaver::nameFilters()
{
    return {tr("Traffic journal (*.mbscope.journal)"), tr("Wireshark capture, pcapng (*.pcapng)"),
            tr("Wireshark capture, pcap (*.pcap)"), tr("CSV, a row per transaction (*.csv)"),
            tr("JSON lines, an object per transaction (*.jsonl)")};
}

TrafficFormat TrafficSaver::formatOfFilter(const QString &filter)
{
    static constexpr TrafficFormat inOrder[] = {TrafficFormat::Journal, TrafficFormat::Pcapng, TrafficFormat::Pcap, TrafficFormat::Csv,
                                                TrafficFormat::JsonLines};
    const qsizetype i = nameFilters().indexOf(filter);
    return i < 0 ? TrafficFormat::Journal : inOrder[i];
}

QString TrafficSaver::Result::summary(TrafficFormat format, const QString &path) const
{
    const QLocale locale;
    const QString name = QDir::toNativeSeparators(path);
    if (!ok)
        return tr("Traffic not saved to %1: %2").arg(name, error);
    QString text;
    switch (format) {
    case TrafficFormat::Journal:
        text = tr("%1 frame(s) saved to %2").arg(locale.toString(frames), name);
        break;
    case TrafficFormat::Pcapng:
    case TrafficFormat::Pcap:
        text = tr("%1 frame(s) saved to %2 as %3 packet(s)").arg(locale.toString(frames), name, locale.toString(written));
        break;
    case TrafficFormat::Csv:
    case TrafficFormat::JsonLines:
    case TrafficFormat::Unknown: // save() writes no other
        text = tr("%1 frame(s) saved to %2 as %3 transaction(s)").arg(locale.toString(frames), name, locale.toString(written));
        break;
    }
    if (!decodeOptions.isEmpty())
        text += tr(". Wireshark decodes the RTU frames with: %1").arg(decodeOptions.join(QStringLiteral("; ")));
    return text;
}

TrafficSaver::Result TrafficSaver::save(const TrafficModel &model, bool shownOnly, const QString &path, TrafficFormat format,
                                        const QString &target)
{
    Result result;
    // Written beside the file and renamed over it once complete: a failed save leaves any file
    // there as it was.
    const QString part = path + QStringLiteral(".part");
    QFile::remove(part);
    if (format == TrafficFormat::Journal) {
        if (!writeJournal(model, shownOnly, part, target, &result.frames, &result.error)) {
            QFile::remove(part);
            return result;
        }
        result.written = result.frames;
    } else {
        QTemporaryDir scratch;
        if (!scratch.isValid()) {
            result.error = tr("no room for a temporary journal: %1").arg(scratch.errorString());
            return result;
        }
        const QString journal = scratch.filePath(QStringLiteral("traffic.mbscope.journal"));
        if (!writeJournal(model, shownOnly, journal, target, &result.frames, &result.error))
            return result;
        ExchangeWriter writer;
        if (!writer.open(part, format, &result.error))
            return result;
        const ExchangeSourceReport report = ExchangeSource::read(
            journal, CaptureOptions{}, [&writer](const CaptureExchange &e) { writer.add(e); },
            [&writer](const CaptureConversation &c) { writer.addConversation(c); });
        const bool closed = writer.close(&result.error);
        if (!report.isReadable() || !report.error.isEmpty() || !closed) {
            if (result.error.isEmpty())
                result.error = report.error;
            QFile::remove(part);
            return result;
        }
        result.written = trafficformat::isCapture(format) ? writer.packets() : writer.rows();
        result.decodeOptions = writer.decodeOptions();
    }
    QFile::remove(path);
    if (!QFile::rename(part, path)) {
        result.error = tr("cannot move %1 to %2").arg(part, path);
        QFile::remove(part);
        return result;
    }
    result.ok = true;
    return result;
}

} // namespace mbscope
