#pragma once

// Shared by the tests of the diagnostic and other function codes (tst_pdudiagnostics,
// tst_pducommevents, tst_pdudeviceid, tst_pduexceptions): dissect a bare PDU over a FieldTree,
// render the tree as one comparable line, and check the invariants every tree must keep.

#include "protocol/pdudissector.h"

#include <QtCore/QRandomGenerator>
#include <QtCore/QStringList>
#include <QtTest/QtTest>

namespace diagtest {

using mbscope::Direction;
using mbscope::Field;
using mbscope::FieldTree;
using mbscope::Severity;

inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

inline void dissect(FieldTree &tree, const QByteArray &pdu, Direction direction, const QByteArray &request = {})
{
    tree.reset(pdu);
    mbscope::pdu::dissect(mbscope::PduContext{tree, -1, 0, int(pdu.size()), direction, QByteArrayView(request)});
}

inline int depth(const FieldTree &tree, int index)
{
    int d = 0;
    for (int p = tree.at(index).parent; p >= 0; p = tree.at(p).parent)
        ++d;
    return d;
}

// "key#address=display !severity" per field, children prefixed by '>' per level, joined by " | ".
inline QString render(const FieldTree &tree)
{
    QStringList parts;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        QString line = QString(depth(tree, i), QLatin1Char('>')) + QString::fromLatin1(f.key);
        if (f.address >= 0)
            line += QLatin1Char('#') + QString::number(f.address);
        line += QLatin1Char('=') + tree.display(i);
        if (f.severity != Severity::Ok)
            line += QStringLiteral(" !") + mbscope::severityName(f.severity);
        parts << line;
    }
    return parts.join(QStringLiteral(" | "));
}

inline QString messages(const FieldTree &tree)
{
    QStringList out;
    for (const Field &f : tree.fields()) {
        if (!f.message.isEmpty())
            out << QString::fromLatin1(f.key) + QStringLiteral(": ") + f.message;
    }
    return out.join(QStringLiteral(" | "));
}

// What every tree must satisfy whatever the input: fields inside the PDU, parents before their
// children, a message on every flagged field and none on a clean one, displays that can be made.
inline bool invariantsHold(const FieldTree &tree, int pduSize, QString *why)
{
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        auto fail = [&](const char *what) {
            *why = QStringLiteral("field %1 (%2): %3").arg(i).arg(QString::fromLatin1(f.key), QString::fromLatin1(what));
            return false;
        };
        if (f.offset < 0 || f.length < 0 || f.offset + f.length > pduSize)
            return fail("outside the PDU");
        if (f.parent >= i || f.parent < -1)
            return fail("parent does not come before it");
        if (!*f.key || !*f.name)
            return fail("empty key or name");
        // The one message an Ok field carries: a write's echo confirmed (pduchecks.cpp).
        if (f.severity == Severity::Ok && !f.message.isEmpty() && f.message != QLatin1String("matches the request"))
            return fail("message on a clean field");
        if (f.severity >= Severity::Warning && f.message.isEmpty())
            return fail("flagged without a message");
        if (f.format != mbscope::ValueFormat::None && tree.valueText(i).isEmpty())
            return fail("value format without text");
        (void)tree.display(i);
    }
    return true;
}

// Data-driven rows: pdu, direction, request (may be empty), expected rendering, a message part.
inline void addColumns()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<int>("direction");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<QString>("message");
}

inline void row(Direction direction, const char *pduHex, const char *expected, const char *message = "",
                const char *requestHex = "")
{
    QByteArray tag = QByteArray(pduHex) + (direction == Direction::Response ? " response" : " request");
    if (*requestHex)
        tag += QByteArray(" to ") + requestHex;
    QTest::newRow(tag.constData()) << hex(pduHex) << int(direction) << hex(requestHex)
                                   << QString::fromUtf8(expected) << QString::fromUtf8(message);
}

inline void req(const char *pduHex, const char *expected, const char *message = "")
{
    row(Direction::Request, pduHex, expected, message);
}

inline void rsp(const char *pduHex, const char *expected, const char *message = "", const char *requestHex = "")
{
    row(Direction::Response, pduHex, expected, message, requestHex);
}

// The body of every data-driven test function.
inline void checkRow()
{
    QFETCH(QByteArray, pdu);
    QFETCH(int, direction);
    QFETCH(QByteArray, request);
    QFETCH(QString, expected);
    QFETCH(QString, message);
    FieldTree tree;
    dissect(tree, pdu, Direction(direction), request);
    QString why;
    QVERIFY2(invariantsHold(tree, int(pdu.size()), &why), qPrintable(why));
    QCOMPARE(render(tree), expected);
    if (!message.isEmpty())
        QVERIFY2(messages(tree).contains(message), qPrintable(messages(tree)));
}

// Dissects every prefix of each PDU, and each PDU followed by random tails, in both directions
// and with and without a request; returns the number of dissections made.
inline int sweep(const QList<QByteArray> &pdus, quint32 seed)
{
    QRandomGenerator random(seed);
    FieldTree tree;
    int runs = 0;
    QString why;
    for (const QByteArray &pdu : pdus) {
        QList<QByteArray> inputs;
        for (qsizetype n = 0; n <= pdu.size(); ++n)
            inputs << pdu.left(n);
        for (int t = 0; t < 64; ++t) {
            QByteArray tail(int(random.bounded(0, 300)), '\0');
            for (char &c : tail)
                c = char(random.bounded(0, 256));
            inputs << pdu.left(random.bounded(0, int(pdu.size()) + 1)) + tail;
        }
        for (const QByteArray &input : inputs) {
            for (Direction d : {Direction::Request, Direction::Response}) {
                for (const QByteArray &request : {QByteArray(), pdu}) {
                    dissect(tree, input, d, request);
                    ++runs;
                    if (!invariantsHold(tree, int(input.size()), &why)) {
                        qWarning("input %s: %s", input.toHex(' ').constData(), qPrintable(why));
                        return -1;
                    }
                }
            }
        }
    }
    return runs;
}

} // namespace diagtest
