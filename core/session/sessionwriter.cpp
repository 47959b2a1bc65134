#include "session/sessionwriter.h"

#include "watch/watchwriter.h"

#include <QtCore/QJsonArray>
#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QSaveFile>

namespace mbscope {

namespace {

QJsonObject requestJson(const SessionRequest &r, bool named)
{
    QJsonObject o;
    if (named)
        o.insert(QLatin1String("name"), r.name);
    if (!r.notes.isEmpty())
        o.insert(QLatin1String("notes"), r.notes);
    if (r.kind == SessionRequest::Kind::Hex) {
        o.insert(QLatin1String("hex"), r.hex);
        if (r.complete) {
            o.insert(QLatin1String("complete"), true);
            o.insert(QLatin1String("unit"), r.unit);
        }
        return o;
    }
    o.insert(QLatin1String("function"), r.function);
    o.insert(QLatin1String("unit"), r.unit);
    o.insert(QLatin1String("address"), r.address);
    if (r.function >= 1 && r.function <= 4)
        o.insert(QLatin1String("quantity"), r.quantity);
    if (r.function == 6 || r.function == 16) {
        QJsonArray values;
        for (quint16 v : r.values)
            values.append(int(v));
        o.insert(QLatin1String("values"), values);
    }
    if (r.function == 5 || r.function == 15) {
        QJsonArray coils;
        for (bool c : r.coils)
            coils.append(c);
        o.insert(QLatin1String("coils"), coils);
    }
    return o;
}

QJsonObject pollJson(const SessionPoll &p, const QList<qint64> *intervalsMs)
{
    QJsonObject o;
    o.insert(QLatin1String("requests"), QJsonArray::fromStringList(p.requests));
    if (intervalsMs) {
        QJsonArray list;
        for (qint64 ms : *intervalsMs)
            list.append(double(ms));
        o.insert(QLatin1String("intervalsMs"), list);
    } else {
        o.insert(QLatin1String("intervalMs"), double(p.intervalMs));
    }
    if (p.count > 0)
        o.insert(QLatin1String("count"), double(p.count));
    if (p.durationMs > 0)
        o.insert(QLatin1String("durationMs"), double(p.durationMs));
    return o;
}

QJsonObject expectationJson(const StepExpectation &e)
{
    QJsonObject o;
    if (e.bytes)
        o.insert(QLatin1String("bytes"), *e.bytes);
    if (e.exception)
        o.insert(QLatin1String("exception"), *e.exception);
    if (e.noAnswer)
        o.insert(QLatin1String("noAnswer"), true);
    if (!e.fields.isEmpty()) {
        QJsonObject fields;
        for (const FieldExpectation &f : e.fields) {
            if (f.equals) {
                fields.insert(f.selector, double(*f.equals));
                continue;
            }
            QJsonObject range;
            if (f.min)
                range.insert(QLatin1String("min"), double(*f.min));
            if (f.max)
                range.insert(QLatin1String("max"), double(*f.max));
            fields.insert(f.selector, range);
        }
        o.insert(QLatin1String("fields"), fields);
    }
    return o;
}

QJsonArray stepsJson(const std::vector<PlanStep> &steps)
{
    QJsonArray list;
    for (const PlanStep &s : steps) {
        QJsonObject o;
        o.insert(QLatin1String("name"), s.name);
        if (!s.notes.isEmpty())
            o.insert(QLatin1String("notes"), s.notes);
        switch (s.kind) {
        case PlanStep::Kind::Send:
            if (!s.requestName.isEmpty())
                o.insert(QLatin1String("send"), s.requestName);
            else
                o.insert(QLatin1String("send"), requestJson(s.request, false));
            if (!s.expect.isEmpty())
                o.insert(QLatin1String("expect"), expectationJson(s.expect));
            break;
        case PlanStep::Kind::Expect:
            o.insert(QLatin1String("expect"), expectationJson(s.expect));
            break;
        case PlanStep::Kind::Poll: {
            o.insert(QLatin1String("poll"), pollJson(s.poll, nullptr));
            if (!s.bounds.isEmpty()) {
                QJsonArray bounds;
                for (const PollBound &b : s.bounds)
                    bounds.append(b.text);
                o.insert(QLatin1String("expect"), bounds);
            }
            break;
        }
        case PlanStep::Kind::Wait:
            o.insert(QLatin1String("wait"), double(s.waitMs));
            break;
        case PlanStep::Kind::Repeat:
            o.insert(QLatin1String("repeat"), s.times);
            o.insert(QLatin1String("steps"), stepsJson(s.steps));
            break;
        }
        list.append(o);
    }
    return list;
}

} // namespace

QJsonObject SessionWriter::toJson(const SessionDocument &d)
{
    QJsonObject root;
    root.insert(QLatin1String("format"), QLatin1String(SessionDocument::kFormat));
    root.insert(QLatin1String("version"), d.versionNeeded());
    if (!d.name.isEmpty())
        root.insert(QLatin1String("name"), d.name);
    if (!d.notes.isEmpty())
        root.insert(QLatin1String("notes"), d.notes);
    if (!(d.target == SessionTarget{})) {
        QJsonObject t;
        if (!d.target.url.isEmpty())
            t.insert(QLatin1String("url"), d.target.url);
        if (d.target.timeoutMs > 0)
            t.insert(QLatin1String("timeoutMs"), d.target.timeoutMs);
        if (d.target.retries != 0)
            t.insert(QLatin1String("retries"), d.target.retries);
        if (d.target.pipelineDepth != 1)
            t.insert(QLatin1String("pipeline"), d.target.pipelineDepth);
        root.insert(QLatin1String("target"), t);
    }
    if (!d.requests.isEmpty()) {
        QJsonArray requests;
        for (const SessionRequest &r : d.requests)
            requests.append(requestJson(r, true));
        root.insert(QLatin1String("requests"), requests);
    }
    if (d.poll)
        root.insert(QLatin1String("poll"), pollJson(*d.poll, nullptr));
    if (d.sweep)
        root.insert(QLatin1String("sweep"), pollJson(d.sweep->poll, &d.sweep->intervalsMs));
    if (d.profile.kind == SessionProfile::Kind::Reference)
        root.insert(QLatin1String("profile"), d.profile.reference);
    else if (d.profile.kind == SessionProfile::Kind::Inline)
        root.insert(QLatin1String("profile"), d.profile.profile);
    if (d.tap) {
        QJsonObject t;
        t.insert(QLatin1String("listen"), QJsonArray::fromStringList(d.tap->listen));
        if (!d.tap->routes.isEmpty())
            t.insert(QLatin1String("routes"), QJsonArray::fromStringList(d.tap->routes));
        if (d.tap->readOnly) {
            t.insert(QLatin1String("readOnly"), true);
            t.insert(QLatin1String("refuse"), d.tap->refuse);
        }
        t.insert(QLatin1String("noAnswer"), d.tap->noAnswer);
        if (d.tap->retries > 0)
            t.insert(QLatin1String("retries"), d.tap->retries);
        root.insert(QLatin1String("tap"), t);
    }
    if (d.capture) {
        QJsonObject c;
        c.insert(QLatin1String("journal"), d.capture->journal);
        if (!d.capture->notes.isEmpty())
            c.insert(QLatin1String("notes"), d.capture->notes);
        if (!d.capture->ignore.isEmpty())
            c.insert(QLatin1String("ignore"), QJsonArray::fromStringList(d.capture->ignore));
        root.insert(QLatin1String("capture"), c);
    }
    if (!d.plan.empty())
        root.insert(QLatin1String("plan"), stepsJson(d.plan));
    WatchWriter::write(d.watches, &root);
    return root;
}

QByteArray SessionWriter::toBytes(const SessionDocument &document)
{
    return QJsonDocument(toJson(document)).toJson(QJsonDocument::Indented);
}

QString SessionWriter::upgradeNotice(int version, int written)
{
    if (version <= 0 || version >= written)
        return {};
    const QString what = version < 2 && written >= 3 ? QStringLiteral("watches, tap")
                         : version < 2               ? QStringLiteral("watches")
                                                     : QStringLiteral("tap");
    return QStringLiteral("upgraded from session version %1 to %2 (%3); mbscope versions that read only version %1 "
                          "no longer open it")
        .arg(version)
        .arg(written)
        .arg(what);
}

bool SessionWriter::save(const SessionDocument &document, const QString &path, QString *error, QString *notice)
{
    if (notice) {
        // The version of the file being replaced, when it is a session document.
        notice->clear();
        QFile old(path);
        if (old.open(QIODevice::ReadOnly) && old.size() < 64 * 1024 * 1024) {
            const QJsonObject previous = QJsonDocument::fromJson(old.readAll()).object();
            if (previous.value(QLatin1String("format")).toString() == QLatin1String(SessionDocument::kFormat))
                *notice = upgradeNotice(previous.value(QLatin1String("version")).toInt(), document.versionNeeded());
        }
        if (!notice->isEmpty())
            *notice = QStringLiteral("%1: %2").arg(path, *notice);
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = QStringLiteral("%1: cannot save the session: %2").arg(path, file.errorString());
        return false;
    }
    const QByteArray bytes = toBytes(document);
    if (file.write(bytes) != bytes.size()) {
        if (error)
            *error = QStringLiteral("%1: cannot save the session: %2 (the previous file is unchanged)").arg(path, file.errorString());
        file.cancelWriting();
        return false;
    }
    // commit() flushes, fsyncs and renames over the previous file in one step.
    if (!file.commit()) {
        if (error)
            *error = QStringLiteral("%1: cannot save the session: %2 (the previous file is unchanged)").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace mbscope
