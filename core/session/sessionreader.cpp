#include "session/sessionreader.h"

#include "session/fieldexpectation.h"
#include "session/planstepreader.h"
#include "session/sessionrequestreader.h"
#include "json/jsonreader.h"
#include "profile/profileloader.h"
#include "transport/linkurl.h"
#include "watch/watchreader.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

#include <functional>

namespace mbscope {

namespace {

constexpr qint64 kMaxFileBytes = 64 * 1024 * 1024; // traffic lives in the journal, not here

ProfileProblem fileProblem(const QString &source, const QString &message, int line = 0, int column = 0)
{
    ProfileProblem p;
    p.source = source;
    p.message = message;
    p.line = line;
    p.column = column;
    return p;
}

// The offset of the opening quote of the first string holding a raw line end, or -1.
qsizetype unclosedStringStart(const QByteArray &json)
{
    qsizetype start = -1;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json.at(i);
        if (start < 0) {
            if (c == '"')
                start = i;
        } else if (c == '\\') {
            ++i;
        } else if (c == '"') {
            start = -1;
        } else if (c == '\n' || c == '\r') {
            return start;
        }
    }
    return -1;
}

void readTarget(JsonReader &reader, const QJsonValue &value, SessionTarget *target)
{
    const QString path = QStringLiteral("target");
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"url", "timeoutMs", "retries", "pipeline"});
    if (const auto url = reader.string(*o, path, "url")) {
        const LinkUrl::Result parsed = LinkUrl::parse(*url);
        if (!parsed.url)
            reader.error(JsonReader::member(path, "url"), parsed.error);
        target->url = *url;
    }
    target->timeoutMs = int(reader.integer(*o, path, "timeoutMs", 1, 3'600'000).value_or(-1));
    target->retries = int(reader.integer(*o, path, "retries", 0, 100).value_or(0));
    target->pipelineDepth = int(reader.integer(*o, path, "pipeline", 1, 256).value_or(1));
}

void readProfile(JsonReader &reader, const QJsonValue &value, SessionProfile *profile, QList<ProfileProblem> *problems)
{
    const QString path = QStringLiteral("profile");
    if (value.isString()) {
        profile->kind = SessionProfile::Kind::Reference;
        profile->reference = value.toString();
        if (profile->reference.trimmed().isEmpty())
            reader.error(path, QStringLiteral("the reference is empty: give a shipped profile's name or a profile file's path"));
        return;
    }
    if (!value.isObject()) {
        reader.error(path, QStringLiteral("expected a profile's name or path (a string) or the profile itself (an object), found %1")
                               .arg(JsonReader::describe(value)));
        return;
    }
    profile->kind = SessionProfile::Kind::Inline;
    profile->profile = value.toObject();
    // The profile loader checks it as it would a profile file; its paths start inside the profile.
    const ProfileLoadResult loaded = ProfileLoader::parse(QJsonDocument(profile->profile).toJson(), reader.source());
    for (ProfileProblem p : loaded.problems) {
        p.source = reader.source();
        p.path = p.path.isEmpty() ? path : JsonReader::member(path, p.path);
        p.line = p.column = 0;
        problems->append(p);
    }
}

// A string of an array (URLs, routes): each one a non-empty string, checked by check (an error
// text, empty when it is fine) when there is one.
QStringList readStrings(JsonReader &reader, const QJsonArray &array, const QString &at, const std::function<QString(const QString &)> &check)
{
    QStringList out;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString element = JsonReader::element(at, i);
        const std::optional<QString> text = reader.stringValue(array.at(i), element);
        if (!text)
            continue;
        const QString problem = text->trimmed().isEmpty() ? QStringLiteral("empty") : check ? check(*text) : QString();
        if (!problem.isEmpty())
            reader.error(element, problem);
        else
            out.append(*text);
    }
    return out;
}

// One of the words an option takes ("auto", "exception", "silence"), or an error naming them.
QString readWord(JsonReader &reader, const QJsonObject &o, const QString &path, const char *key, const QStringList &words,
                 const QString &fallback)
{
    const std::optional<QString> word = reader.string(o, path, key);
    if (!word)
        return fallback;
    if (!words.contains(*word)) {
        reader.error(JsonReader::member(path, key),
                     QStringLiteral("'%1': expected %2").arg(*word, words.join(QStringLiteral(", "))));
        return fallback;
    }
    return *word;
}

void readTap(JsonReader &reader, const QJsonValue &value, std::optional<SessionTap> *tap)
{
    const QString path = QStringLiteral("tap");
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"listen", "routes", "readOnly", "refuse", "noAnswer", "retries"});
    SessionTap t;
    if (reader.require(*o, path, "listen")) {
        if (const auto listen = reader.array(*o, path, "listen")) {
            t.listen = readStrings(reader, *listen, JsonReader::member(path, "listen"), [](const QString &text) {
                const LinkUrl::Result url = LinkUrl::parse(text, LinkUse::Listen);
                return url.url ? QString() : url.error;
            });
            if (listen->isEmpty())
                reader.error(JsonReader::member(path, "listen"), QStringLiteral("no URL: where do the masters connect?"));
        }
    }
    if (const auto routes = reader.array(*o, path, "routes"))
        t.routes = readStrings(reader, *routes, JsonReader::member(path, "routes"), {});
    t.readOnly = reader.boolean(*o, path, "readOnly").value_or(false);
    t.refuse = readWord(reader, *o, path, "refuse", {QStringLiteral("exception"), QStringLiteral("silence")}, t.refuse);
    t.noAnswer = readWord(reader, *o, path, "noAnswer", {QStringLiteral("auto"), QStringLiteral("exception"), QStringLiteral("silence")},
                          t.noAnswer);
    t.retries = int(reader.integer(*o, path, "retries", 0, 100).value_or(0));
    *tap = t;
}

void readCapture(JsonReader &reader, const QJsonValue &value, std::optional<SessionCapture> *capture)
{
    const QString path = QStringLiteral("capture");
    const auto o = reader.objectValue(value, path);
    if (!o)
        return;
    reader.checkKeys(*o, path, {"journal", "notes", "ignore"});
    SessionCapture c;
    if (reader.require(*o, path, "journal")) {
        if (const auto journal = reader.string(*o, path, "journal")) {
            c.journal = *journal;
            const QString clean = QDir::cleanPath(*journal);
            if (journal->trimmed().isEmpty())
                reader.error(JsonReader::member(path, "journal"), QStringLiteral("the journal's file name is empty"));
            else if (QDir::isAbsolutePath(*journal) || clean.startsWith(QLatin1String("..")))
                reader.error(JsonReader::member(path, "journal"),
                             QStringLiteral("'%1' is not beside the document: give a file name relative to the document's folder "
                                            "(a session and its capture move together)")
                                 .arg(*journal));
        }
    }
    c.notes = reader.string(*o, path, "notes").value_or(QString());
    if (const auto ignore = reader.array(*o, path, "ignore")) {
        const QString at = JsonReader::member(path, "ignore");
        for (qsizetype i = 0; i < ignore->size(); ++i) {
            const QString element = JsonReader::element(at, i);
            const QJsonValue v = ignore->at(i);
            if (!v.isString()) {
                reader.error(element, QStringLiteral("expected a field selector such as \"modbus.register_value@0x007D\", found %1")
                                          .arg(JsonReader::describe(v)));
                continue;
            }
            FieldExpectation parsed;
            QString error;
            if (!FieldExpectation::parseSelector(v.toString(), &parsed, &error))
                reader.error(element, error);
            else
                c.ignore.append(v.toString());
        }
    }
    *capture = c;
}

} // namespace

SessionLoadResult SessionReader::load(const QString &path)
{
    SessionLoadResult result;
    QFile file(path);
    if (!file.exists()) {
        result.problems.append(fileProblem(path, QStringLiteral("no such session file")));
        return result;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        result.problems.append(fileProblem(path, QStringLiteral("cannot be read: %1").arg(file.errorString())));
        return result;
    }
    if (file.size() > kMaxFileBytes) {
        result.problems.append(fileProblem(path, QStringLiteral("%1 bytes is too large for a session document (at most %2; "
                                                                "captured traffic belongs in its journal)")
                                                     .arg(file.size()).arg(kMaxFileBytes)));
        return result;
    }
    result = parse(file.readAll(), path);
    // A profile given by path is a file beside the document (or under it): it must be there.
    // Names of shipped profiles are checked where they are used (core may run without them).
    if (result.document && result.document->profile.kind == SessionProfile::Kind::Reference
        && ProfileLoader::isPath(result.document->profile.reference)) {
        const QString reference = result.document->profile.reference;
        const QString resolved = QFileInfo(path).absoluteDir().absoluteFilePath(reference);
        if (!QFileInfo::exists(resolved)) {
            ProfileProblem p = fileProblem(path, QStringLiteral("no such profile file '%1' (a path is relative to the document's folder)").arg(reference));
            p.path = QStringLiteral("profile");
            result.problems.append(p);
            result.document.reset();
        }
    }
    return result;
}

SessionLoadResult SessionReader::parse(const QByteArray &json, const QString &source)
{
    SessionLoadResult result;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Qt gives the offset just past the token it gave up on; point at that token's last
        // character, unless the parser ran into the end of the text (as the profile loader does).
        qsizetype at = parseError.offset;
        if (at > 0 && at <= json.size() && !QChar::isSpace(uchar(json.at(at - 1))))
            --at;
        QString message = QStringLiteral("JSON syntax error: %1").arg(parseError.errorString());
        // Qt reads an unterminated string to the end of the text and reports it there; the
        // string that was never closed is the first one that runs over a line end.
        if (parseError.error == QJsonParseError::UnterminatedString) {
            if (const qsizetype start = unclosedStringStart(json); start >= 0) {
                at = start;
                message = QStringLiteral("JSON syntax error: the string that starts here is not closed on its line");
            }
        }
        const auto [line, column] = ProfileLoader::lineColumn(json, at);
        result.problems.append(fileProblem(source, message, line, column));
        return result;
    }
    if (!doc.isObject()) {
        result.problems.append(fileProblem(source, QStringLiteral("expected a JSON object at the top level, found %1")
                                                       .arg(doc.isArray() ? QStringLiteral("an array") : QStringLiteral("nothing"))));
        return result;
    }
    const QJsonObject root = doc.object();
    JsonReader reader(&result.problems, source);
    const QString top;

    // Format and version first: a newer document is refused before its content is judged.
    if (reader.require(root, top, "format")) {
        const QJsonValue format = root.value(QLatin1String("format"));
        if (format.toString() != QLatin1String(SessionDocument::kFormat)) {
            reader.error(QStringLiteral("format"), QStringLiteral("%1 is not an mbscope session: expected \"%2\"")
                                                       .arg(JsonReader::describe(format), QLatin1String(SessionDocument::kFormat)));
            return result;
        }
    }
    if (reader.require(root, top, "version")) {
        const QJsonValue v = root.value(QLatin1String("version"));
        if (!v.isDouble())
            reader.error(QStringLiteral("version"), QStringLiteral("expected a whole number such as %1, found %2")
                                                        .arg(SessionDocument::kVersion)
                                                        .arg(JsonReader::describe(v)));
        else if (const auto version = reader.integer(root, top, "version", 1, 1'000'000)) {
            result.version = int(*version);
            if (*version > SessionDocument::kVersion) {
                reader.error(QStringLiteral("version"),
                             QStringLiteral("this session was written by a newer mbscope (session version %1); this mbscope reads "
                                            "version %2 and older: open it with a newer mbscope")
                                 .arg(*version)
                                 .arg(SessionDocument::kVersion));
                return result;
            }
        }
    }
    reader.checkKeys(root, top, {"$schema", "format", "version", "name", "notes", "target", "requests", "poll", "sweep",
                                 "profile", "capture", "plan", "watches", "watchLinks", "watchLog", "tap"});

    SessionDocument d;
    d.name = reader.string(root, top, "name").value_or(QString());
    d.notes = reader.string(root, top, "notes").value_or(QString());
    if (root.contains(QLatin1String("target")))
        readTarget(reader, root.value(QLatin1String("target")), &d.target);

    QStringList names;
    if (const auto requests = reader.array(root, top, "requests")) {
        for (qsizetype i = 0; i < requests->size(); ++i) {
            const QString at = JsonReader::element(QStringLiteral("requests"), i);
            const auto r = SessionRequestReader::read(reader, requests->at(i), at, true);
            if (!r) {
                // A request with problems of its own still has its name: a step or a poll naming
                // it is not told that no such request exists, and the names a misspelt one is
                // offered are all of the document's (tryout 8, item 11: two were left out).
                const QJsonValue name = requests->at(i).toObject().value(QLatin1String("name"));
                if (name.isString() && !name.toString().trimmed().isEmpty() && !names.contains(name.toString()))
                    names.append(name.toString());
                continue;
            }
            if (names.contains(r->name))
                reader.error(JsonReader::member(at, "name"),
                             QStringLiteral("'%1' names an earlier request too: steps and polls refer to requests by name").arg(r->name));
            names.append(r->name);
            d.requests.append(*r);
        }
    }
    if (root.contains(QLatin1String("poll")))
        d.poll = SessionRequestReader::readPoll(reader, root.value(QLatin1String("poll")), QStringLiteral("poll"), names, false);
    if (root.contains(QLatin1String("sweep"))) {
        QList<qint64> intervals;
        if (const auto poll = SessionRequestReader::readPoll(reader, root.value(QLatin1String("sweep")), QStringLiteral("sweep"),
                                                             names, true, &intervals))
            d.sweep = SessionSweep{*poll, intervals};
    }
    if (root.contains(QLatin1String("profile")))
        readProfile(reader, root.value(QLatin1String("profile")), &d.profile, &result.problems);
    if (root.contains(QLatin1String("capture")))
        readCapture(reader, root.value(QLatin1String("capture")), &d.capture);
    if (root.contains(QLatin1String("tap")))
        readTap(reader, root.value(QLatin1String("tap")), &d.tap);
    if (const auto plan = reader.array(root, top, "plan")) {
        PlanStepReader steps(reader, names);
        d.plan = steps.readSteps(*plan, QStringLiteral("plan"));
    }
    d.watches = WatchReader::read(reader, root);

    if (result.problems.isEmpty())
        result.document = std::move(d);
    return result;
}

} // namespace mbscope
