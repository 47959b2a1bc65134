#include "writechecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"
#include "readchecks.h"

#include "protocol/quantitylimits.h"

#include <optional>

namespace mbscope {

namespace {

void appendU16(QByteArray &pdu, int value)
{
    pdu.append(char((value >> 8) & 0xFF));
    pdu.append(char(value & 0xFF));
}

QByteArray single(quint8 function, int address, int value)
{
    QByteArray pdu(1, char(function));
    appendU16(pdu, address);
    appendU16(pdu, value);
    return pdu;
}

// The values of count registers (or bits as 0/1) from address, or nullopt (*seen, when given:
// what came back instead).
std::optional<QList<int>> readValues(ConformanceContext &ctx, bool bits, int address, int count, QString *seen = nullptr)
{
    const ConformanceExchange e = ctx.ask(ReadChecks::readPdu(bits ? 0x01 : 0x03, address, count));
    if (seen)
        *seen = ConformanceJudge::seen(e);
    if (e.transaction.status != TransactionStatus::Ok)
        return std::nullopt;
    const QByteArray pdu = ConformanceJudge::pdu(e.transaction.response, ctx.link().framing());
    QList<int> values;
    for (int i = 0; i < count; ++i) {
        if (bits) {
            if (2 + i / 8 >= pdu.size())
                return std::nullopt;
            values.append((quint8(pdu.at(2 + i / 8)) >> (i % 8)) & 1);
        } else {
            if (3 + 2 * i >= pdu.size())
                return std::nullopt;
            values.append((quint8(pdu.at(2 + 2 * i)) << 8) | quint8(pdu.at(3 + 2 * i)));
        }
    }
    return values;
}

// Puts the values found back, one write each (05 or 06).
void restore(ConformanceContext &ctx, bool bits, int address, const QList<int> &values)
{
    for (int i = 0; i < values.size(); ++i)
        (void)ctx.ask(single(bits ? 0x05 : 0x06, address + i, bits ? (values.at(i) ? 0xFF00 : 0x0000) : values.at(i)));
}

QByteArray multiple(bool bits, int address, const QList<int> &values, int byteCountDelta = 0, int quantity = -1)
{
    QByteArray pdu(1, char(bits ? 0x0F : 0x10));
    appendU16(pdu, address);
    appendU16(pdu, quantity >= 0 ? quantity : int(values.size()));
    QByteArray data;
    if (bits) {
        data.fill(0, (values.size() + 7) / 8);
        for (int i = 0; i < values.size(); ++i) {
            if (values.at(i))
                data[i / 8] = char(quint8(data.at(i / 8)) | (1 << (i % 8)));
        }
    } else {
        for (int v : values)
            appendU16(data, v);
    }
    if (byteCountDelta > 0)
        data.append(QByteArray(byteCountDelta, '\0'));
    pdu.append(char(data.size()));
    pdu.append(data);
    return pdu;
}

ConformanceCheck check(const char *id, const QString &title, const char *clause, quint8 function, SimTable table,
                       std::function<void(ConformanceContext &, CheckResult &, const TableRange &)> run)
{
    ConformanceCheck c;
    c.id = QLatin1String(id);
    c.title = title;
    c.clause = QLatin1String(clause);
    c.needs.function = function;
    c.needs.writable = int(table);
    c.run = [run = std::move(run), table](ConformanceContext &ctx, CheckResult &res) {
        run(ctx, res, *ctx.settings().writableIn(table));
    };
    return c;
}

bool readBefore(ConformanceContext &ctx, CheckResult &res, bool bits, int address, int count, QList<int> *values)
{
    QString seen;
    const std::optional<QList<int>> found = readValues(ctx, bits, address, count, &seen);
    if (!found) {
        res.skip(QStringLiteral("the values to put back could not be read (%1, %2 %3 from %4: %5)")
                     .arg(QLatin1String(bits ? "01" : "03"))
                     .arg(count)
                     .arg(QLatin1String(bits ? (count == 1 ? "coil" : "coils") : (count == 1 ? "register" : "registers")))
                     .arg(address)
                     .arg(seen));
        return false;
    }
    *values = *found;
    return true;
}

} // namespace

QList<ConformanceCheck> WriteChecks::checks()
{
    QList<ConformanceCheck> out;
    out.append(check("write.05.echo", QStringLiteral("05 Write Single Coil echoes the request"), "Application Protocol V1.1b3, 6.5",
                     0x05, SimTable::Coils, [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         QList<int> before;
                         if (!readBefore(ctx, res, true, w.first, 1, &before))
                             return;
                         const QByteArray pdu = single(0x05, w.first, before.at(0) ? 0x0000 : 0xFF00);
                         const ConformanceExchange e = ctx.ask(pdu);
                         if (ConformanceJudge::normal(res, e, QStringLiteral("the request echoed"))
                             && ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()) != pdu)
                             res.fail(ConformanceJudge::failure(res, e, QStringLiteral("the request echoed byte for byte")));
                         restore(ctx, true, w.first, before);
                     }));
    out.append(check("write.05.bad-value", QStringLiteral("05 with a value other than FF00 or 0000 gets exception 03"),
                     "Application Protocol V1.1b3, 6.5", 0x05, SimTable::Coils,
                     [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         QList<int> before;
                         if (!readBefore(ctx, res, true, w.first, 1, &before))
                             return;
                         ConformanceJudge::exception(res, ctx.ask(single(0x05, w.first, 0x1234)), {0x03},
                                                     QStringLiteral("exception 03 (Illegal Data Value): only FF00 and 0000 are coil values"));
                         restore(ctx, true, w.first, before);
                     }));
    out.append(check("write.06.echo", QStringLiteral("06 Write Single Register echoes the request and the value reads back"),
                     "Application Protocol V1.1b3, 6.6", 0x06, SimTable::HoldingRegisters,
                     [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         QList<int> before;
                         if (!readBefore(ctx, res, false, w.first, 1, &before))
                             return;
                         const int value = before.at(0) ^ 0x5AA5;
                         const QByteArray pdu = single(0x06, w.first, value);
                         const ConformanceExchange e = ctx.ask(pdu);
                         if (ConformanceJudge::normal(res, e, QStringLiteral("the request echoed"))) {
                             if (ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()) != pdu)
                                 res.fail(ConformanceJudge::failure(res, e, QStringLiteral("the request echoed byte for byte")));
                             else if (readValues(ctx, false, w.first, 1) != QList<int>{value})
                                 res.fail(QStringLiteral("the write of %1 to %2 was echoed but the register does not read back %1")
                                              .arg(value).arg(w.first));
                         }
                         restore(ctx, false, w.first, before);
                     }));

    struct Multiple {
        const char *echoId;
        const char *countId;
        const char *zeroId;
        bool bits;
        quint8 function;
        SimTable table;
        const char *clause;
        int most;
    };
    const Multiple kMultiple[] = {
        {"write.0F.echo", "write.0F.byte-count", "write.0F.quantity-zero", true, 0x0F, SimTable::Coils, "Application Protocol V1.1b3, 6.11", 10},
        {"write.10.echo", "write.10.byte-count", "write.10.quantity-zero", false, 0x10, SimTable::HoldingRegisters,
         "Application Protocol V1.1b3, 6.12", 4},
    };
    for (const Multiple &m : kMultiple) {
        out.append(check(m.echoId, QStringLiteral("%1 echoes the start address and quantity").arg(QLatin1String(m.bits ? "0F Write Multiple Coils" : "10 Write Multiple Registers")),
                         m.clause, m.function, m.table, [m](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                             const int n = qMin(w.count(), m.most);
                             QList<int> before;
                             if (!readBefore(ctx, res, m.bits, w.first, n, &before))
                                 return;
                             QList<int> values;
                             for (int v : before)
                                 values.append(m.bits ? 1 - v : v ^ 0x5AA5);
                             const QByteArray pdu = multiple(m.bits, w.first, values);
                             const ConformanceExchange e = ctx.ask(pdu);
                             if (ConformanceJudge::normal(res, e, QStringLiteral("the start address and quantity echoed"))) {
                                 if (ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()) != pdu.left(5))
                                     res.fail(ConformanceJudge::failure(res, e, QStringLiteral("function, start address and quantity echoed (%1)")
                                                                                  .arg(ConformanceJudge::hex(pdu.left(5)))));
                                 else if (readValues(ctx, m.bits, w.first, n) != values)
                                     res.fail(QStringLiteral("the write was echoed but the values do not read back as written"));
                             }
                             restore(ctx, m.bits, w.first, before);
                         }));
        out.append(check(m.countId, QStringLiteral("%1 with a byte count that does not match the quantity gets exception 03").arg(QString::number(m.function, 16).toUpper().rightJustified(2, QLatin1Char('0'))),
                         m.clause, m.function, m.table, [m](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                             QList<int> before;
                             if (!readBefore(ctx, res, m.bits, w.first, 1, &before))
                                 return;
                             // The values found, so that a device that writes anyway changes nothing.
                             ConformanceJudge::exception(res, ctx.ask(multiple(m.bits, w.first, before, 2)), {0x03},
                                                         QStringLiteral("exception 03 (Illegal Data Value): the byte count must match the quantity"));
                             restore(ctx, m.bits, w.first, before);
                         }));
        out.append(check(m.zeroId, QStringLiteral("%1 with quantity 0 gets exception 03").arg(QString::number(m.function, 16).toUpper().rightJustified(2, QLatin1Char('0'))),
                         m.clause, m.function, m.table, [m](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                             ConformanceJudge::exception(res, ctx.ask(multiple(m.bits, w.first, {}, 0, 0)), {0x03},
                                                         QStringLiteral("exception 03 (Illegal Data Value) for quantity 0"));
                         }));
    }

    // One coil over the most 0F may write (1969, 0x07B1): its 247 data bytes still fit a legal
    // frame (a PDU of 253 bytes). The register writes cannot be asked so: 124 registers for 10, or
    // 122 for 17's write, need a PDU over 253 bytes, which tests the framing, not the quantity.
    out.append(check("write.0F.quantity-over", QStringLiteral("0F with quantity 1969 (one over the most) gets exception 03"),
                     "Application Protocol V1.1b3, 6.11", 0x0F, SimTable::Coils, [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         const int over = QuantityLimits::kWriteCoils + 1;
                         if (w.count() < over) {
                             res.skip(QStringLiteral("needs %1 writable coils from one address (--writable coils:FIRST-LAST), the "
                                                     "writable range %2 has %3: a device that took the write would change coils "
                                                     "nobody named")
                                          .arg(over)
                                          .arg(w.toString())
                                          .arg(w.count()));
                             return;
                         }
                         QList<int> before;
                         if (!readBefore(ctx, res, true, w.first, over, &before))
                             return;
                         // The values found: a device that writes anyway changes nothing.
                         ConformanceJudge::exception(res, ctx.ask(multiple(true, w.first, before)), {0x03},
                                                     QStringLiteral("exception 03 (Illegal Data Value): at most 1968 coils (0x07B0) a request"));
                         if (res.verdict != CheckVerdict::Failed)
                             return;
                         // It took it: any coil it changed is put back.
                         const std::optional<QList<int>> after = readValues(ctx, true, w.first, over);
                         for (int i = 0; after && i < over; ++i) {
                             if (after->at(i) != before.at(i))
                                 (void)ctx.ask(single(0x05, w.first + i, before.at(i) ? 0xFF00 : 0x0000));
                         }
                     }));

    out.append(check("write.16.mask", QStringLiteral("16 Mask Write Register echoes and leaves (value AND and) OR (or AND NOT and)"),
                     "Application Protocol V1.1b3, 6.16", 0x16, SimTable::HoldingRegisters,
                     [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         QList<int> before;
                         if (!readBefore(ctx, res, false, w.first, 1, &before))
                             return;
                         constexpr int kAnd = 0x00F2; // the specification's example
                         constexpr int kOr = 0x0025;
                         QByteArray pdu = single(0x16, w.first, kAnd);
                         appendU16(pdu, kOr);
                         const ConformanceExchange e = ctx.ask(pdu);
                         if (ConformanceJudge::normal(res, e, QStringLiteral("the request echoed"))) {
                             const int expected = (before.at(0) & kAnd) | (kOr & ~kAnd & 0xFFFF);
                             const std::optional<QList<int>> after = readValues(ctx, false, w.first, 1);
                             if (ConformanceJudge::pdu(e.transaction.response, ctx.link().framing()) != pdu)
                                 res.fail(ConformanceJudge::failure(res, e, QStringLiteral("the request echoed byte for byte")));
                             else if (!after || after->at(0) != expected)
                                 res.fail(QStringLiteral("register %1 held 0x%2; AND 0x00F2 OR 0x0025 must leave 0x%3, it reads %4; %5")
                                              .arg(w.first)
                                              .arg(before.at(0), 4, 16, QLatin1Char('0'))
                                              .arg(expected, 4, 16, QLatin1Char('0'))
                                              .arg(after ? QStringLiteral("0x%1").arg(after->at(0), 4, 16, QLatin1Char('0')) : QStringLiteral("nothing"), res.clause));
                         }
                         restore(ctx, false, w.first, before);
                     }));

    out.append(check("write.17.order", QStringLiteral("17 Read/Write Multiple Registers writes before it reads"),
                     "Application Protocol V1.1b3, 6.17", 0x17, SimTable::HoldingRegisters,
                     [](ConformanceContext &ctx, CheckResult &res, const TableRange &w) {
                         QList<int> before;
                         if (!readBefore(ctx, res, false, w.first, 1, &before))
                             return;
                         const int value = before.at(0) ^ 0xA55A;
                         QByteArray pdu(1, char(0x17));
                         appendU16(pdu, w.first); // read the register...
                         appendU16(pdu, 1);
                         appendU16(pdu, w.first); // ...that the same request writes
                         appendU16(pdu, 1);
                         pdu.append(char(2));
                         appendU16(pdu, value);
                         const ConformanceExchange e = ctx.ask(pdu);
                         if (ConformanceJudge::normal(res, e, QStringLiteral("a read answer"))) {
                             const QByteArray answer = ConformanceJudge::pdu(e.transaction.response, ctx.link().framing());
                             const int read = answer.size() >= 4 ? (quint8(answer.at(2)) << 8) | quint8(answer.at(3)) : -1;
                             if (read != value)
                                 res.fail(QStringLiteral("sent %1 (write 0x%2 to %3 and read it); got %4, reading 0x%5 (the value before); "
                                                         "%6 requires the write to be done before the read")
                                              .arg(ConformanceJudge::hex(e.request))
                                              .arg(value, 4, 16, QLatin1Char('0'))
                                              .arg(w.first)
                                              .arg(ConformanceJudge::hex(e.answer))
                                              .arg(read, 4, 16, QLatin1Char('0'))
                                              .arg(res.clause));
                             else
                                 res.pass(QStringLiteral("read back 0x%1, the value written").arg(value, 4, 16, QLatin1Char('0')));
                         }
                         restore(ctx, false, w.first, before);
                     }));
    return out;
}

} // namespace mbscope
