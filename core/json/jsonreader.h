#pragma once

#include "profileproblem.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtCore/QJsonValue>
#include <QtCore/QList>
#include <QtCore/QString>

#include <initializer_list>
#include <optional>

namespace mbscope {

// Reads typed values out of a parsed JSON document and records every problem with the JSON path
// of the value at fault and what was expected. Nothing throws; a read that fails gives nullopt
// (or the caller's fallback) and a problem, so that a loader carries on and reports them all.
//
// Integers may be written as JSON numbers (whole) or as strings "0x0079" (hex), since Modbus
// addresses and codes are usually given in hex.
class JsonReader
{
public:
    JsonReader(QList<ProfileProblem> *problems, const QString &source);

    void error(const QString &path, const QString &message);
    [[nodiscard]] int problemCount() const { return int(m_problems->size()); }
    [[nodiscard]] const QString &source() const { return m_source; }

    [[nodiscard]] static QString member(const QString &path, const QString &key); // "units[0].id"
    [[nodiscard]] static QString member(const QString &path, const char *key)
    {
        return member(path, QString::fromLatin1(key));
    }
    [[nodiscard]] static QString element(const QString &path, qsizetype index); // "units[0]"
    // "a string \"abc\"", "the number 1.5", "true", "null", "an object", "an array"
    [[nodiscard]] static QString describe(const QJsonValue &value);

    // Refuses any key not listed: "units[0]: unknown key 'tabels': expected one of id, name, ...".
    // False when there was such a key.
    bool checkKeys(const QJsonObject &object, const QString &path, std::initializer_list<const char *> allowed);
    bool checkKeys(const QJsonObject &object, const QString &path, const QList<const char *> &allowed);
    // "units[0]: 'id' is missing"; false when absent.
    bool require(const QJsonObject &object, const QString &path, const char *key);

    // Reads of object[key]; absent keys give nullopt without a problem.
    [[nodiscard]] std::optional<QString> string(const QJsonObject &o, const QString &path, const char *key);
    [[nodiscard]] std::optional<bool> boolean(const QJsonObject &o, const QString &path, const char *key);
    [[nodiscard]] std::optional<double> number(const QJsonObject &o, const QString &path, const char *key,
                                               double min, double max);
    [[nodiscard]] std::optional<qint64> integer(const QJsonObject &o, const QString &path, const char *key,
                                                qint64 min, qint64 max);
    [[nodiscard]] std::optional<QJsonObject> object(const QJsonObject &o, const QString &path, const char *key);
    [[nodiscard]] std::optional<QJsonArray> array(const QJsonObject &o, const QString &path, const char *key);

    // The same for a value at hand; valuePath names the value itself.
    [[nodiscard]] std::optional<QString> stringValue(const QJsonValue &v, const QString &valuePath);
    [[nodiscard]] std::optional<double> numberValue(const QJsonValue &v, const QString &valuePath, double min,
                                                    double max);
    [[nodiscard]] std::optional<qint64> integerValue(const QJsonValue &v, const QString &valuePath, qint64 min,
                                                     qint64 max);
    [[nodiscard]] std::optional<QJsonObject> objectValue(const QJsonValue &v, const QString &valuePath);

    // Number text for messages: "70000", "1.5", "0.001".
    [[nodiscard]] static QString numberText(double value);

private:
    QList<ProfileProblem> *m_problems;
    QString m_source;
};

} // namespace mbscope
