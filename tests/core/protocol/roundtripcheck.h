#pragma once

// Helpers of tst_roundtrip.cpp: random parameters that favour the limits, and Trip, which
// dissects a built PDU and compares the fields it finds by key with the values that built it.

#include "protocol/buildresult.h"
#include "protocol/fieldtree.h"
#include "protocol/pdudissector.h"

#include <QtCore/QRandomGenerator>
#include <QtCore/QStringList>

#include <cstring>

namespace roundtrip {

inline QString spaced(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

// Uniform in [min, max], but each edge one time in eight, so that limits are exercised often.
inline int pick(QRandomGenerator &rng, int min, int max)
{
    const quint32 r = rng.bounded(8u);
    if (r == 0)
        return min;
    if (r == 1)
        return max;
    return min + int(rng.bounded(quint32(max - min + 1)));
}

inline QList<quint16> randomWords(QRandomGenerator &rng, int count)
{
    QList<quint16> values;
    for (int i = 0; i < count; ++i)
        values.append(quint16(rng.bounded(0x10000u)));
    return values;
}

inline QList<bool> randomBits(QRandomGenerator &rng, int count)
{
    QList<bool> values;
    for (int i = 0; i < count; ++i)
        values.append(rng.bounded(2u) == 1);
    return values;
}

inline QByteArray randomBytes(QRandomGenerator &rng, int count)
{
    QByteArray bytes(count, '\0');
    for (int i = 0; i < count; ++i)
        bytes[i] = char(rng.bounded(256u));
    return bytes;
}

template<typename T>
QList<quint64> widen(const QList<T> &values)
{
    QList<quint64> out;
    for (const T &v : values)
        out.append(quint64(v));
    return out;
}

inline QList<int> run(int first, int count)
{
    QList<int> out;
    for (int i = 0; i < count; ++i)
        out.append(first + i);
    return out;
}

template<typename T>
QString listText(const QList<T> &values)
{
    QStringList parts;
    for (const T &v : values)
        parts.append(QString::number(v));
    return QLatin1Char('[') + parts.join(QStringLiteral(", ")) + QLatin1Char(']');
}

inline QString listText(const QList<QByteArray> &values)
{
    QStringList parts;
    for (const QByteArray &v : values)
        parts.append(QLatin1Char('"') + spaced(v) + QLatin1Char('"'));
    return QLatin1Char('[') + parts.join(QStringLiteral(", ")) + QLatin1Char(']');
}

// One dissected PDU and the checks on it. The first problem is kept with enough context
// (iteration, direction, bytes) to repeat it; later checks are skipped.
class Trip
{
public:
    Trip(QString *problem, int iteration)
        : m_problem(problem)
        , m_iteration(iteration)
    {
    }

    bool ok() const { return m_problem->isEmpty(); }

    // Dissects pdu, which must have been built without error.
    void dissect(const mbscope::BuildResult &built, mbscope::Direction direction, const QByteArray &request = {})
    {
        m_direction = direction;
        if (!ok())
            return;
        if (!built.isValid()) {
            fail(QStringLiteral("the builder refused valid parameters: %1").arg(built.errorString()));
            return;
        }
        m_pdu = built.pdu;
        m_tree.reset(m_pdu);
        mbscope::pdu::dissect(mbscope::PduContext{m_tree, -1, 0, int(m_pdu.size()), direction, QByteArrayView(request)});
        if (m_tree.count(mbscope::Severity::Error) > 0) {
            QStringList errors;
            for (int i = 0; i < m_tree.size(); ++i) {
                if (m_tree.at(i).severity == mbscope::Severity::Error)
                    errors.append(QLatin1String(m_tree.at(i).key) + QStringLiteral(": ") + m_tree.at(i).message);
            }
            fail(QStringLiteral("Error fields in a valid PDU: %1").arg(errors.join(QStringLiteral(" | "))));
        }
    }

    void values(const char *key, const QList<quint64> &expected)
    {
        if (!ok())
            return;
        QList<quint64> got;
        for (int i : m_tree.indexesOf(key))
            got.append(m_tree.at(i).value);
        if (got != expected)
            fail(QStringLiteral("%1: expected %2, got %3").arg(QLatin1String(key), listText(expected), listText(got)));
    }

    void value(const char *key, quint64 expected) { values(key, {expected}); }

    void raws(const char *key, const QList<QByteArray> &expected)
    {
        if (!ok())
            return;
        QList<QByteArray> got;
        for (int i : m_tree.indexesOf(key))
            got.append(m_tree.raw(i));
        if (got != expected)
            fail(QStringLiteral("%1: expected %2, got %3").arg(QLatin1String(key), listText(expected), listText(got)));
    }

    // The bytes of key, or no such field when expected is empty.
    void rawOrAbsent(const char *key, const QByteArray &expected)
    {
        raws(key, expected.isEmpty() ? QList<QByteArray>() : QList<QByteArray>{expected});
    }

    void addresses(const char *key, const QList<int> &expected)
    {
        if (!ok())
            return;
        QList<int> got;
        for (int i : m_tree.indexesOf(key))
            got.append(m_tree.at(i).address);
        if (got != expected)
            fail(QStringLiteral("%1 addresses: expected %2, got %3").arg(QLatin1String(key), listText(expected), listText(got)));
    }

    void meanings(const char *key, const QList<const char *> &expected)
    {
        if (!ok())
            return;
        const QList<int> found = m_tree.indexesOf(key);
        bool same = found.size() == expected.size();
        for (int i = 0; same && i < found.size(); ++i) {
            const char *meaning = m_tree.at(found[i]).meaning;
            same = meaning && std::strcmp(meaning, expected[i]) == 0;
        }
        if (!same)
            fail(QStringLiteral("%1: meanings differ from the expected ON/OFF").arg(QLatin1String(key)));
    }

    // The dissection has exactly these top-level keys, in this order.
    void topLevel(const QList<const char *> &keys)
    {
        if (!ok())
            return;
        QStringList got;
        for (int i : m_tree.children(-1))
            got.append(QLatin1String(m_tree.at(i).key));
        QStringList want;
        for (const char *k : keys)
            want.append(QLatin1String(k));
        if (got != want)
            fail(QStringLiteral("top-level fields: expected %1, got %2")
                     .arg(want.join(QLatin1Char(' ')), got.join(QLatin1Char(' '))));
    }

private:
    void fail(const QString &what)
    {
        *m_problem = QStringLiteral("iteration %1, %2 %3: %4")
                         .arg(m_iteration)
                         .arg(m_direction == mbscope::Direction::Request ? QStringLiteral("request") : QStringLiteral("response"),
                              spaced(m_pdu), what);
    }

    QString *m_problem;
    int m_iteration;
    mbscope::Direction m_direction = mbscope::Direction::Request;
    QByteArray m_pdu;
    mbscope::FieldTree m_tree;
};

} // namespace roundtrip
