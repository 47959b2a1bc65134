#pragma once

// Shared by tst_requestbuilder and tst_responsebuilder: parameter values, and the two kinds of
// data-driven rows. bytes: a build and the PDU it must give. limits: a build at the edge of a
// limit (parameter empty: it must succeed) or just past it (an error on parameter whose message
// holds fragment).

#include "protocol/buildresult.h"

#include <QtTest/QtTest>

namespace buildertest {

using mbscope::BuildResult;

inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

inline QString spaced(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

// count distinct register values: first, first + 0x0101, ...
inline QList<quint16> words(int count, int first = 0)
{
    QList<quint16> values;
    for (int i = 0; i < count; ++i)
        values.append(quint16(first + i * 0x0101));
    return values;
}

inline QList<bool> bits(const char *pattern) // "1011": first coil first
{
    QList<bool> values;
    for (const char *c = pattern; *c; ++c)
        values.append(*c == '1');
    return values;
}

inline void bytesColumns()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("errors");
    QTest::addColumn<QByteArray>("expected");
}

// A row named by the expected bytes (and suffix, to tell apart rows with the same bytes).
inline void addBytes(const BuildResult &result, const QByteArray &expected, const char *suffix = nullptr)
{
    QString name = spaced(expected);
    if (suffix)
        name += QStringLiteral(" (%1)").arg(QLatin1String(suffix));
    QTest::newRow(qPrintable(name)) << result.pdu << result.errorString() << expected;
}

inline void checkBytes()
{
    QFETCH(QByteArray, pdu);
    QFETCH(QString, errors);
    QFETCH(QByteArray, expected);
    QVERIFY2(errors.isEmpty(), qPrintable(errors));
    QCOMPARE(spaced(pdu), spaced(expected));
}

inline void limitsColumns()
{
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("errors");
    QTest::addColumn<QString>("parameter");
    QTest::addColumn<QString>("fragment");
    QTest::addColumn<QString>("message");
}

// parameter empty: the build must succeed (an edge that is still within the limit).
inline void addLimit(const char *name, const BuildResult &result, const char *parameter = "", const char *fragment = "")
{
    QTest::newRow(name) << result.isValid() << result.pdu << result.errorString() << QString::fromLatin1(parameter)
                        << QString::fromLatin1(fragment) << result.message(QString::fromLatin1(parameter));
}

inline void checkLimit()
{
    QFETCH(bool, valid);
    QFETCH(QByteArray, pdu);
    QFETCH(QString, errors);
    QFETCH(QString, parameter);
    QFETCH(QString, fragment);
    QFETCH(QString, message);
    if (parameter.isEmpty()) {
        QVERIFY2(valid, qPrintable(errors));
        QVERIFY(!pdu.isEmpty());
        QVERIFY2(pdu.size() <= 253, qPrintable(QString::number(pdu.size())));
        return;
    }
    QVERIFY2(!valid, "the builder accepted a value past the limit");
    QVERIFY2(pdu.isEmpty(), "a failed build must not return bytes");
    QVERIFY2(!message.isEmpty(), qPrintable(QStringLiteral("no error on %1; errors: %2").arg(parameter, errors)));
    QVERIFY2(message.contains(fragment),
             qPrintable(QStringLiteral("message: %1\nexpected fragment: %2").arg(message, fragment)));
}

} // namespace buildertest
