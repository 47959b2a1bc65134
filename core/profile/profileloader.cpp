#include "profileloader.h"

#include "devicelimitsreader.h"
#include "faultrulereader.h"
#include "json/jsonreader.h"
#include "linetablereader.h"
#include "profileunitreader.h"
#include "protocol/functioncode.h"
#include "transport/linkurl.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QStringList>

#include <algorithm>

namespace mbscope {

namespace {

constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024; // a profile is text written by hand
constexpr qint64 kMaxSeed = 9007199254740991LL;     // 2^53 - 1: exact as a JSON number

ProfileProblem fileProblem(const QString &source, const QString &message)
{
    ProfileProblem p;
    p.source = source;
    p.message = message;
    return p;
}

// The document's top-level object, or problems (syntax errors with line and column).
std::optional<QJsonObject> parseObject(const QByteArray &json, const QString &source, QList<ProfileProblem> *problems)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError) {
        ProfileProblem p = fileProblem(source, QStringLiteral("JSON syntax error: %1").arg(error.errorString()));
        // Qt reports the offset just past the token it gave up on; point at that token's last
        // character instead, unless the parser ran into the end of the text.
        qsizetype at = error.offset;
        if (at > 0 && at <= json.size() && !QChar::isSpace(uchar(json.at(at - 1))))
            --at;
        const auto [line, column] = ProfileLoader::lineColumn(json, at);
        p.line = line;
        p.column = column;
        problems->append(p);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        problems->append(fileProblem(source, QStringLiteral("expected a JSON object at the top level, found %1")
                                                 .arg(doc.isArray() ? QStringLiteral("an array") : QStringLiteral("nothing"))));
        return std::nullopt;
    }
    return doc.object();
}

// A unit that lists its functions and has a table none of them reads: every read of it gets
// exception 01 (docs/profiles.md's own example once left Read Coils out beside its coils).
QList<ProfileProblem> unreadableTables(const DeviceProfile &profile, const QString &source)
{
    struct Table {
        SimTable table;
        const char *key;
        QList<quint8> reads; // the function codes that read it (V1.1b3 6.1-6.4, 6.17)
    };
    const Table tables[] = {{SimTable::Coils, "coils", {0x01}},
                            {SimTable::DiscreteInputs, "discrete", {0x02}},
                            {SimTable::HoldingRegisters, "holding", {0x03, 0x17}},
                            {SimTable::InputRegisters, "input", {0x04}}};
    QList<ProfileProblem> warnings;
    for (qsizetype i = 0; i < profile.units.size(); ++i) {
        const UnitProfile &unit = profile.units.at(i);
        if (unit.functions.isEmpty())
            continue;
        for (const Table &t : tables) {
            if (unit.entriesOf(t.table).isEmpty())
                continue;
            if (std::any_of(t.reads.cbegin(), t.reads.cend(), [&unit](quint8 code) { return unit.functions.contains(code); }))
                continue;
            const quint8 read = t.reads.constFirst();
            ProfileProblem w;
            w.source = source;
            w.path = JsonReader::member(JsonReader::member(JsonReader::element(QStringLiteral("units"), i), "tables"), t.key);
            w.message = QStringLiteral("the table has entries but its read function %1 (%2) is not in functions: every read "
                                       "of it gets exception 01 (add \"0x%1\" to functions)")
                            .arg(QString::number(read, 16).toUpper().rightJustified(2, QLatin1Char('0')),
                                 QLatin1String(functionName(read)));
            warnings.append(w);
        }
    }
    return warnings;
}

std::optional<QByteArray> readFile(const QString &path, const QString &what, QList<ProfileProblem> *problems)
{
    QFile file(path);
    if (!file.exists()) {
        problems->append(fileProblem(path, QStringLiteral("no such %1 file").arg(what)));
        return std::nullopt;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        problems->append(fileProblem(path, QStringLiteral("cannot be read: %1").arg(file.errorString())));
        return std::nullopt;
    }
    if (file.size() > kMaxFileBytes) {
        problems->append(fileProblem(path, QStringLiteral("%1 bytes is too large for a %2 file (at most %3)")
                                               .arg(file.size()).arg(what).arg(kMaxFileBytes)));
        return std::nullopt;
    }
    return file.readAll();
}

void checkRuleUnits(JsonReader &reader, const FaultRuleSet &set, const QList<UnitProfile> &units)
{
    for (qsizetype i = 0; i < set.rules.size(); ++i) {
        const FaultRule &rule = set.rules.at(i);
        for (qsizetype j = 0; j < rule.units.size(); ++j) {
            const bool known = std::any_of(units.cbegin(), units.cend(),
                                           [&](const UnitProfile &u) { return u.id == rule.units.at(j); });
            if (!known)
                reader.error(QStringLiteral("faults.rules[%1].units[%2]").arg(i).arg(j),
                             QStringLiteral("unit %1 is not in this profile").arg(rule.units.at(j)));
        }
    }
}

} // namespace

std::pair<int, int> ProfileLoader::lineColumn(const QByteArray &text, qsizetype offset)
{
    int line = 1;
    int column = 1;
    const qsizetype end = std::min(offset, text.size());
    for (qsizetype i = 0; i < end; ++i) {
        const auto c = quint8(text.at(i));
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0) != 0x80) { // count characters: skip UTF-8 continuation bytes
            ++column;
        }
    }
    return {line, column};
}

bool ProfileLoader::isPath(const QString &nameOrPath)
{
    return nameOrPath.contains(QLatin1Char('/')) || nameOrPath.contains(QLatin1Char('\\'))
        || nameOrPath.endsWith(QLatin1String(".json"), Qt::CaseInsensitive);
}

QString ProfileLoader::resolve(const QString &nameOrPath)
{
    if (isPath(nameOrPath))
        return nameOrPath;
    return QStringLiteral(":/profiles/%1.json").arg(nameOrPath);
}

ProfileLoadResult ProfileLoader::load(const QString &nameOrPath)
{
    if (isPath(nameOrPath))
        return loadFile(nameOrPath);
    const QString resource = resolve(nameOrPath);
    if (QFile::exists(resource))
        return loadFile(resource);
    QStringList names;
    for (const ShippedProfile &p : shippedProfiles())
        names.append(p.name);
    ProfileLoadResult result;
    result.problems.append(fileProblem(nameOrPath, names.isEmpty()
        ? QStringLiteral("no shipped profile of that name (none is built in); give a file path to load a user profile")
        : QStringLiteral("no shipped profile of that name: expected one of %1, or a file path")
              .arg(names.join(QStringLiteral(", ")))));
    return result;
}

ProfileLoadResult ProfileLoader::loadFile(const QString &path)
{
    ProfileLoadResult result;
    const auto bytes = readFile(path, QStringLiteral("profile"), &result.problems);
    if (!bytes)
        return result;
    return parse(*bytes, path);
}

ProfileLoadResult ProfileLoader::parse(const QByteArray &json, const QString &source)
{
    ProfileLoadResult result;
    const auto root = parseObject(json, source, &result.problems);
    if (!root)
        return result;
    JsonReader reader(&result.problems, source);
    const QString top;
    reader.checkKeys(*root, top, {"$schema", "name", "description", "endpoints", "seed", "units", "faults",
                                    "unknownUnit", "answersBroadcasts", "limits", "delimited"});

    DeviceProfile profile;
    profile.source = source;
    if (reader.require(*root, top, "name")) {
        profile.name = reader.string(*root, top, "name").value_or(QString());
        if (root->value(QLatin1String("name")).isString() && profile.name.trimmed().isEmpty())
            reader.error(QStringLiteral("name"), QStringLiteral("the name is empty"));
    }
    profile.description = reader.string(*root, top, "description").value_or(QString());
    if (const auto seed = reader.integer(*root, top, "seed", 0, kMaxSeed))
        profile.seed = quint64(*seed);

    if (const auto endpoints = reader.array(*root, top, "endpoints")) {
        for (qsizetype i = 0; i < endpoints->size(); ++i) {
            const QString at = JsonReader::element(QStringLiteral("endpoints"), i);
            const auto text = reader.stringValue(endpoints->at(i), at);
            if (!text)
                continue;
            const LinkUrl::Result url = LinkUrl::parse(*text);
            if (!url.url)
                reader.error(at, url.error);
            else
                profile.endpoints.append(*text);
        }
    }

    if (reader.require(*root, top, "units")) {
        if (const auto units = reader.array(*root, top, "units")) {
            if (units->isEmpty())
                reader.error(QStringLiteral("units"), QStringLiteral("the list is empty: a profile has at least one unit"));
            for (qsizetype i = 0; i < units->size(); ++i) {
                const QString at = JsonReader::element(QStringLiteral("units"), i);
                const auto unit = ProfileUnitReader::read(reader, units->at(i), at);
                if (!unit)
                    continue;
                for (qsizetype j = 0; j < profile.units.size(); ++j) {
                    if (profile.units.at(j).id == unit->id)
                        reader.error(JsonReader::member(at, "id"),
                                     QStringLiteral("unit %1 is given twice (also an earlier unit)").arg(unit->id));
                }
                profile.units.append(*unit);
            }
        }
    }

    profile.limits = DeviceLimitsReader::read(reader, *root);
    if (root->contains(QLatin1String("delimited")))
        profile.delimited = LineTableReader::read(reader, root->value(QLatin1String("delimited")), QStringLiteral("delimited"));

    profile.faults.seed = profile.seed;
    if (root->contains(QLatin1String("faults"))) {
        profile.faults = FaultRuleReader::readRuleSet(reader, root->value(QLatin1String("faults")),
                                                      QStringLiteral("faults"), profile.seed);
        checkRuleUnits(reader, profile.faults, profile.units);
    }

    if (!result.problems.isEmpty())
        return result;
    result.warnings = unreadableTables(profile, source);
    result.profile = profile;
    result.ok = true;
    return result;
}

FaultRulesLoadResult ProfileLoader::loadFaults(const QString &path)
{
    FaultRulesLoadResult result;
    const auto bytes = readFile(path, QStringLiteral("faults"), &result.problems);
    if (!bytes)
        return result;
    return parseFaults(*bytes, path);
}

FaultRulesLoadResult ProfileLoader::parseFaults(const QByteArray &json, const QString &source)
{
    FaultRulesLoadResult result;
    const auto root = parseObject(json, source, &result.problems);
    if (!root)
        return result;
    JsonReader reader(&result.problems, source);
    const FaultRuleSet set = FaultRuleReader::readRuleSet(reader, *root, QString(), 1);
    if (!result.problems.isEmpty())
        return result;
    result.rules = set;
    result.ok = true;
    return result;
}

QList<ShippedProfile> ProfileLoader::shippedProfiles()
{
    QList<ShippedProfile> out;
    const QDir dir(QStringLiteral(":/profiles"));
    for (const QString &file : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        ShippedProfile p;
        p.resource = dir.filePath(file);
        p.name = QFileInfo(file).completeBaseName();
        QFile f(p.resource);
        if (f.open(QIODevice::ReadOnly))
            p.description = QJsonDocument::fromJson(f.readAll()).object().value(QLatin1String("description")).toString();
        out.append(p);
    }
    return out;
}

} // namespace mbscope
