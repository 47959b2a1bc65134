#include "jsonreader.h"

#include <QtCore/QStringList>

#include <cmath>

namespace mbscope {

JsonReader::JsonReader(QList<ProfileProblem> *problems, const QString &source)
    : m_problems(problems), m_source(source)
{
}

void JsonReader::error(const QString &path, const QString &message)
{
    ProfileProblem problem;
    problem.source = m_source;
    problem.path = path;
    problem.message = message;
    m_problems->append(problem);
}

QString JsonReader::member(const QString &path, const QString &key)
{
    if (path.isEmpty())
        return key;
    return path + QLatin1Char('.') + key;
}

QString JsonReader::element(const QString &path, qsizetype index)
{
    return path + QStringLiteral("[%1]").arg(index);
}

QString JsonReader::numberText(double value)
{
    if (std::isfinite(value) && std::fabs(value) < 1e15 && value == std::trunc(value))
        return QString::number(qint64(value));
    return QString::number(value, 'g', 12);
}

QString JsonReader::describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return QStringLiteral("the number %1").arg(numberText(value.toDouble()));
    case QJsonValue::String: {
        QString text = value.toString();
        if (text.size() > 40)
            text = text.left(37) + QStringLiteral("...");
        return QStringLiteral("a string \"%1\"").arg(text);
    }
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

bool JsonReader::checkKeys(const QJsonObject &object, const QString &path,
                           std::initializer_list<const char *> allowed)
{
    return checkKeys(object, path, QList<const char *>(allowed));
}

bool JsonReader::checkKeys(const QJsonObject &object, const QString &path, const QList<const char *> &allowed)
{
    bool clean = true;
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool known = false;
        for (const char *key : allowed)
            known = known || it.key() == QLatin1String(key);
        if (known)
            continue;
        QStringList names;
        for (const char *key : allowed)
            names.append(QString::fromLatin1(key));
        error(path.isEmpty() ? QString() : path,
              QStringLiteral("unknown key '%1': expected one of %2").arg(it.key(), names.join(QStringLiteral(", "))));
        clean = false;
    }
    return clean;
}

bool JsonReader::require(const QJsonObject &object, const QString &path, const char *key)
{
    if (object.contains(QLatin1String(key)))
        return true;
    error(path, QStringLiteral("'%1' is missing").arg(QLatin1String(key)));
    return false;
}

std::optional<QString> JsonReader::string(const QJsonObject &o, const QString &path, const char *key)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    return stringValue(v, member(path, key));
}

std::optional<bool> JsonReader::boolean(const QJsonObject &o, const QString &path, const char *key)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isBool()) {
        error(member(path, key), QStringLiteral("expected true or false, found %1").arg(describe(v)));
        return std::nullopt;
    }
    return v.toBool();
}

std::optional<double> JsonReader::number(const QJsonObject &o, const QString &path, const char *key, double min,
                                         double max)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    return numberValue(v, member(path, key), min, max);
}

std::optional<qint64> JsonReader::integer(const QJsonObject &o, const QString &path, const char *key, qint64 min,
                                          qint64 max)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    return integerValue(v, member(path, key), min, max);
}

std::optional<QJsonObject> JsonReader::object(const QJsonObject &o, const QString &path, const char *key)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    return objectValue(v, member(path, key));
}

std::optional<QJsonArray> JsonReader::array(const QJsonObject &o, const QString &path, const char *key)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isArray()) {
        error(member(path, key), QStringLiteral("expected an array, found %1").arg(describe(v)));
        return std::nullopt;
    }
    return v.toArray();
}

std::optional<QString> JsonReader::stringValue(const QJsonValue &v, const QString &valuePath)
{
    if (!v.isString()) {
        error(valuePath, QStringLiteral("expected a string, found %1").arg(describe(v)));
        return std::nullopt;
    }
    return v.toString();
}

std::optional<double> JsonReader::numberValue(const QJsonValue &v, const QString &valuePath, double min, double max)
{
    if (!v.isDouble()) {
        error(valuePath, QStringLiteral("expected a number, found %1").arg(describe(v)));
        return std::nullopt;
    }
    const double d = v.toDouble();
    if (d < min) {
        error(valuePath, QStringLiteral("%1 is below %2").arg(numberText(d), numberText(min)));
        return std::nullopt;
    }
    if (d > max) {
        error(valuePath, QStringLiteral("%1 is beyond %2").arg(numberText(d), numberText(max)));
        return std::nullopt;
    }
    return d;
}

std::optional<qint64> JsonReader::integerValue(const QJsonValue &v, const QString &valuePath, qint64 min, qint64 max)
{
    qint64 n = 0;
    QString shown;
    if (v.isString()) {
        const QString text = v.toString().trimmed();
        bool ok = false;
        if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) && text.size() > 2)
            n = text.mid(2).toLongLong(&ok, 16);
        if (!ok) {
            error(valuePath, QStringLiteral("expected a whole number or hex text such as \"0x0079\", found %1")
                                 .arg(describe(v)));
            return std::nullopt;
        }
        shown = text;
    } else if (v.isDouble()) {
        const double d = v.toDouble();
        if (d != std::trunc(d) || std::fabs(d) > 9.0e15) {
            error(valuePath, QStringLiteral("%1 is not a whole number").arg(numberText(d)));
            return std::nullopt;
        }
        n = qint64(d);
        shown = numberText(d);
    } else {
        error(valuePath, QStringLiteral("expected a whole number, found %1").arg(describe(v)));
        return std::nullopt;
    }
    if (n < min) {
        error(valuePath, QStringLiteral("%1 is below %2").arg(shown).arg(min));
        return std::nullopt;
    }
    if (n > max) {
        error(valuePath, QStringLiteral("%1 is beyond %2").arg(shown).arg(max));
        return std::nullopt;
    }
    return n;
}

std::optional<QJsonObject> JsonReader::objectValue(const QJsonValue &v, const QString &valuePath)
{
    if (!v.isObject()) {
        error(valuePath, QStringLiteral("expected an object, found %1").arg(describe(v)));
        return std::nullopt;
    }
    return v.toObject();
}

} // namespace mbscope
