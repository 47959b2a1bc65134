#pragma once

// Shared by the PDU dissector tests: run pdu::dissect over a bare PDU and compare the field tree
// with a compact expectation, one item per field in tree order, separated by '|':
//
//   [>]key[=value|=[v1,v2,...]|*count][@address][!E|!W|!I][%display][~message fragment]
//
// key without a dot means "modbus.key". '>' marks a child of the last top-level item. value is
// decimal or 0x hex; a list expands to one field per value with addresses counting up from
// @address; *count stands for count fields whose values are not checked. No '!' means the field
// must be Ok with no message. %text must occur in FieldTree::display, ~text in the message.
// The function code (field 0) is checked to be Ok unless the expectation starts with it. The
// Modicon reference children (modbus.reference) that the dispatch adds are skipped.
//
// For data-driven tests: columns() in a _data function, then one req()/rsp() per row, and check()
// as the test function's body.

#include "protocol/fieldtree.h"
#include "protocol/pducontext.h"
#include "protocol/pdudissector.h"

#include <QtCore/QStringList>
#include <QtTest/QtTest>

#include <cstring>

namespace pdutest {

using namespace mbscope;

inline QByteArray bytes(const char *hexText) { return QByteArray::fromHex(QByteArray(hexText)); }

inline void dissect(FieldTree &tree, const QByteArray &pdu, Direction direction, const QByteArray &request)
{
    tree.reset(pdu);
    pdu::dissect(PduContext{tree, -1, 0, int(pdu.size()), direction, QByteArrayView(request)});
}

struct Item {
    QByteArray key;
    bool child = false;
    bool hasValue = false;
    quint64 value = 0;
    int address = -1;
    bool anyValue = false;
    Severity severity = Severity::Ok;
    QString display;
    QString fragment;
};

inline QString dump(const FieldTree &tree)
{
    QStringList out;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        out << QStringLiteral("  [%1] p%2 %3 @%4+%5 = %6 addr %7 %8 %9 %10")
                   .arg(i)
                   .arg(f.parent)
                   .arg(QString::fromLatin1(f.key))
                   .arg(f.offset)
                   .arg(f.length)
                   .arg(f.value)
                   .arg(f.address)
                   .arg(tree.display(i), severityName(f.severity), f.message);
    }
    return out.join(QLatin1Char('\n'));
}

inline bool parseNumber(const QString &text, quint64 *value)
{
    bool ok = false;
    *value = text.startsWith(QLatin1String("0x")) ? text.mid(2).toULongLong(&ok, 16) : text.toULongLong(&ok, 10);
    return ok;
}

// Expands one expectation item (a list value becomes several items).
inline QList<Item> parseItem(QString text, QString *error)
{
    Item item;
    text = text.trimmed();
    if (text.startsWith(QLatin1Char('>'))) {
        item.child = true;
        text.remove(0, 1);
    }
    int at = text.indexOf(QLatin1Char('~'));
    if (at >= 0) {
        item.fragment = text.mid(at + 1);
        text.truncate(at);
    }
    at = text.indexOf(QLatin1Char('%'));
    if (at >= 0) {
        item.display = text.mid(at + 1);
        text.truncate(at);
    }
    at = text.indexOf(QLatin1Char('!'));
    if (at >= 0) {
        const QString s = text.mid(at + 1);
        item.severity = s == QLatin1String("E") ? Severity::Error
                        : s == QLatin1String("W") ? Severity::Warning
                        : s == QLatin1String("I") ? Severity::Info
                                                  : Severity::Ok;
        text.truncate(at);
    }
    at = text.indexOf(QLatin1Char('@'));
    if (at >= 0) {
        item.address = text.mid(at + 1).toInt();
        text.truncate(at);
    }
    int count = 1;
    QList<quint64> values;
    at = text.indexOf(QLatin1Char('*'));
    if (at >= 0) {
        count = text.mid(at + 1).toInt();
        item.anyValue = true;
        text.truncate(at);
    }
    at = text.indexOf(QLatin1Char('='));
    if (at >= 0) {
        QString v = text.mid(at + 1);
        text.truncate(at);
        if (v.startsWith(QLatin1Char('['))) {
            v = v.mid(1, v.size() - 2);
            for (const QString &one : v.split(QLatin1Char(','))) {
                quint64 n = 0;
                if (!parseNumber(one.trimmed(), &n))
                    *error = QStringLiteral("bad value %1").arg(one);
                values << n;
            }
            count = int(values.size());
        } else {
            quint64 n = 0;
            if (!parseNumber(v, &n))
                *error = QStringLiteral("bad value %1").arg(v);
            values << n;
        }
    }
    item.key = text.contains(QLatin1Char('.')) ? text.toLatin1() : QByteArray("modbus.") + text.toLatin1();
    QList<Item> out;
    for (int i = 0; i < count; ++i) {
        Item one = item;
        if (!values.isEmpty()) {
            one.hasValue = true;
            one.value = values.at(i);
        }
        if (item.address >= 0 && (count > 1))
            one.address = item.address + i;
        out << one;
    }
    return out;
}

// Returns an empty string when the tree matches, else what differs and the whole tree.
inline QString match(const FieldTree &tree, const QString &spec)
{
    QString error;
    QList<Item> items;
    for (const QString &text : spec.split(QLatin1Char('|'), Qt::SkipEmptyParts))
        items << parseItem(text, &error);
    if (!error.isEmpty())
        return error;
    QList<int> fields;
    for (int i = 0; i < tree.size(); ++i) {
        if (std::strcmp(tree.at(i).key, "modbus.reference") != 0)
            fields << i;
    }
    if (items.isEmpty() || items.first().key != "modbus.function_code") {
        if (fields.isEmpty() || std::strcmp(tree.at(0).key, "modbus.function_code") != 0)
            return QStringLiteral("no function code field first\n") + dump(tree);
        if (tree.at(0).severity != Severity::Ok)
            return QStringLiteral("function code flagged\n") + dump(tree);
        fields.removeFirst();
    }
    const auto fail = [&tree](int n, const QString &what) {
        return QStringLiteral("item %1: %2\n").arg(n).arg(what) + dump(tree);
    };
    int lastTop = -1;
    for (int n = 0; n < items.size(); ++n) {
        if (n >= fields.size())
            return fail(n, QStringLiteral("missing field ") + QString::fromLatin1(items.at(n).key));
        const Item &it = items.at(n);
        const int i = fields.at(n);
        const Field &f = tree.at(i);
        if (it.key != f.key)
            return fail(n, QStringLiteral("key %1, expected %2").arg(QString::fromLatin1(f.key), QString::fromLatin1(it.key)));
        if (it.child ? f.parent != lastTop : f.parent != -1)
            return fail(n, QStringLiteral("parent %1").arg(f.parent));
        if (!it.child)
            lastTop = i;
        if (it.hasValue && f.value != it.value)
            return fail(n, QStringLiteral("value %1, expected %2").arg(f.value).arg(it.value));
        if (it.address >= 0 && f.address != it.address)
            return fail(n, QStringLiteral("address %1, expected %2").arg(f.address).arg(it.address));
        if (f.severity != it.severity)
            return fail(n, QStringLiteral("severity %1, expected %2").arg(severityName(f.severity), severityName(it.severity)));
        // An Ok field carries no message, except a write's echo saying it matches its request
        // (what the decode view shows; tst_dissector checks where it is said).
        if (it.severity == Severity::Ok && !f.message.isEmpty() && f.message != QLatin1String("matches the request"))
            return fail(n, QStringLiteral("unexpected message"));
        if (!it.fragment.isEmpty() && !f.message.contains(it.fragment))
            return fail(n, QStringLiteral("message lacks \"%1\"").arg(it.fragment));
        if (!it.display.isEmpty() && !tree.display(i).contains(it.display))
            return fail(n, QStringLiteral("display lacks \"%1\"").arg(it.display));
    }
    if (fields.size() > items.size())
        return fail(int(items.size()), QStringLiteral("unexpected extra fields"));
    return {};
}

// Every field inside the frame, parents before children: what the dissector promises for any input.
inline QString checkBounds(const FieldTree &tree)
{
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        if (f.offset < 0 || f.length < 0 || f.offset + f.length > tree.frame().size() || f.parent >= i)
            return QStringLiteral("field %1 out of bounds\n").arg(i) + dump(tree);
    }
    return {};
}

// The columns of a data-driven test: pdu, direction, request, spec.
inline void columns()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<int>("direction");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QString>("spec");
}

// One row, named by direction, the PDU's hex (a long one cut), the request's and the note.
inline void row(Direction direction, const QByteArray &pdu, const QString &spec, const QByteArray &request,
                const char *note)
{
    QString text = QLatin1String(direction == Direction::Request ? "req " : "rsp ");
    text += pdu.size() > 20
        ? QString::fromLatin1(pdu.left(12).toHex(' ').toUpper()) + QStringLiteral(" ... (%1 bytes)").arg(pdu.size())
        : QString::fromLatin1(pdu.toHex(' ').toUpper());
    if (!request.isEmpty())
        text += QStringLiteral(" / req ") + QString::fromLatin1(request.left(16).toHex(' ').toUpper());
    if (note)
        text += QStringLiteral(" (") + QLatin1String(note) + QLatin1Char(')');
    QTest::newRow(qPrintable(text)) << pdu << int(direction) << request << spec;
}

inline void req(const char *pdu, const char *spec, const char *note = nullptr)
{
    row(Direction::Request, bytes(pdu), QLatin1String(spec), {}, note);
}

inline void rsp(const char *pdu, const char *spec, const char *request = "", const char *note = nullptr)
{
    row(Direction::Response, bytes(pdu), QLatin1String(spec), bytes(request), note);
}

// The body of a data-driven test function: dissect the row's PDU, check bounds and the spec.
inline void check()
{
    QFETCH(QByteArray, pdu);
    QFETCH(int, direction);
    QFETCH(QByteArray, request);
    QFETCH(QString, spec);
    FieldTree tree;
    dissect(tree, pdu, Direction(direction), request);
    const QString bounds = checkBounds(tree);
    QVERIFY2(bounds.isEmpty(), qPrintable(bounds));
    const QString result = match(tree, spec);
    QVERIFY2(result.isEmpty(), qPrintable(result));
}

} // namespace pdutest
