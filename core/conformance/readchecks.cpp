#include "readchecks.h"

#include "conformancecontext.h"
#include "conformancejudge.h"

#include "profile/simtable.h"
#include "protocol/functioncode.h"
#include "protocol/functionspec.h"

namespace mbscope {

namespace {

struct ReadFunction {
    quint8 function;
    SimTable table;
    const char *items;
};

const ReadFunction kReads[] = {
    {0x01, SimTable::Coils, "coils"},
    {0x02, SimTable::DiscreteInputs, "discrete inputs"},
    {0x03, SimTable::HoldingRegisters, "registers"},
    {0x04, SimTable::InputRegisters, "registers"},
};

QString code(quint8 function)
{
    return QString::number(function, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

QString clause(quint8 function)
{
    return QStringLiteral("Application Protocol V1.1b3, %1").arg(QLatin1String(QuantityLimits::clause(function)));
}

ConformanceCheck make(const ReadFunction &r, const char *suffix, const QString &title, CheckLevel level,
                      std::function<void(ConformanceContext &, CheckResult &)> run)
{
    ConformanceCheck c;
    c.id = QStringLiteral("read.%1.%2").arg(code(r.function), QLatin1String(suffix));
    c.title = QStringLiteral("%1 %2: %3").arg(code(r.function), QLatin1String(functionName(r.function)), title);
    c.clause = clause(r.function);
    c.level = level;
    c.needs.function = r.function;
    c.run = std::move(run);
    return c;
}

// Bits packed into bytes, first item in the lowest bit of the first byte (V1.1b3 6.1).
QList<bool> unpack(const QByteArray &data, int count)
{
    QList<bool> bits;
    for (int i = 0; i < count && i / 8 < data.size(); ++i)
        bits.append((quint8(data.at(i / 8)) >> (i % 8)) & 1);
    return bits;
}

void addChecks(QList<ConformanceCheck> &out, const ReadFunction &r)
{
    const int max = QuantityLimits::maxQuantity(r.function);
    const bool bits = isBitTable(r.table);

    ConformanceCheck answer = make(r, "answer", QStringLiteral("a read of one item is answered well-formed"), CheckLevel::Mandatory,
                                   [r](ConformanceContext &ctx, CheckResult &res) {
                                       const ConformanceExchange e = ctx.ask(ReadChecks::readPdu(r.function, ctx.readable(r.table), 1));
                                       ConformanceJudge::normal(res, e, QStringLiteral("a normal answer with a byte count of %1 for one item")
                                                                              .arg(isBitTable(r.table) ? 1 : 2));
                                   });
    answer.needs.readable = int(r.table);
    out.append(answer);

    out.append(make(r, "quantity-zero", QStringLiteral("quantity 0 gets exception 03"), CheckLevel::Mandatory,
                    [r](ConformanceContext &ctx, CheckResult &res) {
                        const int at = qMax(0, ctx.readable(r.table));
                        ConformanceJudge::exception(res, ctx.ask(ReadChecks::readPdu(r.function, at, 0)), {0x03},
                                                    QStringLiteral("exception 03 (Illegal Data Value) for quantity 0"));
                    }));

    out.append(make(r, "quantity-over", QStringLiteral("quantity %1 (one above the maximum) gets exception 03").arg(max + 1),
                    CheckLevel::Mandatory, [r, max](ConformanceContext &ctx, CheckResult &res) {
                        const int at = qMax(0, ctx.readable(r.table));
                        ConformanceJudge::exception(res, ctx.ask(ReadChecks::readPdu(r.function, at, max + 1)), {0x03},
                                                    QStringLiteral("exception 03 (Illegal Data Value) for quantity %1: %2 reads 1-%3 %4")
                                                        .arg(max + 1)
                                                        .arg(QLatin1String(functionName(r.function)))
                                                        .arg(max)
                                                        .arg(QLatin1String(r.items)));
                    }));

    ConformanceCheck atMax = make(r, "quantity-max", QStringLiteral("quantity %1 (the maximum) is not refused with 03").arg(max),
                                  CheckLevel::Recommended, [r, max](ConformanceContext &ctx, CheckResult &res) {
                                      const ConformanceExchange e = ctx.ask(ReadChecks::readPdu(r.function, ctx.readable(r.table), max));
                                      ConformanceJudge::record(res, e);
                                      if (e.transaction.status == TransactionStatus::Ok)
                                          res.pass(QStringLiteral("answered all %1 %2").arg(max).arg(QLatin1String(r.items)));
                                      else if (e.transaction.status == TransactionStatus::Exception && e.transaction.exceptionCode == 0x02)
                                          res.pass(QStringLiteral("answered exception 02: the block runs past the device's map, which is allowed"));
                                      else
                                          res.fail(ConformanceJudge::failure(res, e,
                                                                             QStringLiteral("a normal answer of %1 %2, or exception 02 when the "
                                                                                            "block is not all there: quantity %1 is legal")
                                                                                 .arg(max)
                                                                                 .arg(QLatin1String(r.items))));
                                  });
    atMax.needs.readable = int(r.table);
    out.append(atMax);

    out.append(make(r, "past-end", QStringLiteral("a block from 65535 running past the address space gets exception 02"),
                    CheckLevel::Mandatory, [r](ConformanceContext &ctx, CheckResult &res) {
                        ConformanceJudge::exception(res, ctx.ask(ReadChecks::readPdu(r.function, 0xFFFF, 2)), {0x02},
                                                    QStringLiteral("exception 02 (Illegal Data Address): start 65535 plus "
                                                                   "quantity 2 runs past the last address"));
                    }));

    out.append(make(r, "missing-address", QStringLiteral("an address the device lacks gets exception 02"), CheckLevel::Mandatory,
                    [r](ConformanceContext &ctx, CheckResult &res) {
                        const int given = ctx.settings().missing[int(r.table)];
                        const int at = given >= 0 ? given : 0xFFFF;
                        const ConformanceExchange e = ctx.ask(ReadChecks::readPdu(r.function, at, 1));
                        if (given < 0 && e.transaction.status == TransactionStatus::Ok) {
                            ConformanceJudge::record(res, e);
                            res.skip(QStringLiteral("the device answers address 65535, so it may have every address: "
                                                    "name one it lacks with --missing %1:ADDRESS")
                                         .arg(QLatin1String(r.function == 1 ? "coils" : r.function == 2 ? "discrete"
                                                            : r.function == 3 ? "holding" : "input")));
                            return;
                        }
                        ConformanceJudge::exception(res, e, {0x02},
                                                    QStringLiteral("exception 02 (Illegal Data Address) for address %1, "
                                                                   "which the device does not have")
                                                        .arg(at));
                    }));

    ConformanceCheck edge = make(r, "block-past-map", QStringLiteral("a block that runs past the end of the map gets exception 02"),
                                 CheckLevel::Mandatory, [r](ConformanceContext &ctx, CheckResult &res) {
                                     const int missing = ctx.settings().missing[int(r.table)];
                                     if (missing <= 0) {
                                         res.skip(QStringLiteral("no address the device lacks is known (give --missing or --profile)"));
                                         return;
                                     }
                                     ConformanceJudge::exception(res, ctx.ask(ReadChecks::readPdu(r.function, missing - 1, 2)), {0x02},
                                                                 QStringLiteral("exception 02 (Illegal Data Address): the block "
                                                                                "%1-%2 runs into address %2, which the device lacks")
                                                                     .arg(missing - 1)
                                                                     .arg(missing));
                                 });
    out.append(edge);

    if (bits) {
        ConformanceCheck order = make(r, "bit-order", QStringLiteral("bits packed first item in the lowest bit, padding zero"),
                                      CheckLevel::Mandatory, [r](ConformanceContext &ctx, CheckResult &res) {
                                          constexpr int kCount = 5; // three padding bits in the byte
                                          const int at = ctx.readable(r.table);
                                          const ConformanceExchange block = ctx.ask(ReadChecks::readPdu(r.function, at, kCount));
                                          ConformanceJudge::record(res, block);
                                          if (block.transaction.status == TransactionStatus::Exception
                                              && block.transaction.exceptionCode == 0x02) {
                                              res.skip(QStringLiteral("the device has no %1 %2 from address %3 (exception 02)")
                                                           .arg(kCount).arg(QLatin1String(r.items)).arg(at));
                                              return;
                                          }
                                          if (block.transaction.status != TransactionStatus::Ok) {
                                              res.fail(ConformanceJudge::failure(res, block, QStringLiteral("a normal answer")));
                                              return;
                                          }
                                          const QByteArray pdu = ConformanceJudge::pdu(block.transaction.response, ctx.link().framing());
                                          const QByteArray data = pdu.mid(2);
                                          if (data.size() == 1 && (quint8(data.at(0)) & 0xE0) != 0) {
                                              res.fail(QStringLiteral("sent %1; got %2; %3 requires the 3 unused high bits of the last "
                                                                      "byte to be 0")
                                                           .arg(ConformanceJudge::hex(block.request), ConformanceJudge::hex(block.answer), res.clause));
                                              return;
                                          }
                                          const QList<bool> packed = unpack(data, kCount);
                                          for (int i = 0; i < kCount; ++i) {
                                              const ConformanceExchange one = ctx.ask(ReadChecks::readPdu(r.function, at + i, 1));
                                              if (one.transaction.status != TransactionStatus::Ok)
                                                  continue;
                                              const QByteArray p = ConformanceJudge::pdu(one.transaction.response, ctx.link().framing());
                                              const bool alone = p.size() >= 3 && (quint8(p.at(2)) & 1);
                                              if (i < packed.size() && alone != packed.at(i)) {
                                                  res.fail(QStringLiteral("address %1 read alone is %2 but bit %3 of the block read from %4 is "
                                                                          "%5 (block answer %6); %7 requires the first item in the lowest bit")
                                                               .arg(at + i)
                                                               .arg(alone ? 1 : 0)
                                                               .arg(i)
                                                               .arg(at)
                                                               .arg(packed.at(i) ? 1 : 0)
                                                               .arg(ConformanceJudge::hex(block.answer), res.clause));
                                                  return;
                                              }
                                          }
                                          res.pass(QStringLiteral("%1 %2 from %3 read as a block match each read alone")
                                                       .arg(kCount).arg(QLatin1String(r.items)).arg(at));
                                      });
        order.needs.readable = int(r.table);
        out.append(order);
    }
}

} // namespace

QByteArray ReadChecks::readPdu(quint8 function, int address, int quantity)
{
    QByteArray pdu;
    pdu.append(char(function));
    pdu.append(char((address >> 8) & 0xFF));
    pdu.append(char(address & 0xFF));
    pdu.append(char((quantity >> 8) & 0xFF));
    pdu.append(char(quantity & 0xFF));
    return pdu;
}

int ReadChecks::tableOf(quint8 function)
{
    for (const ReadFunction &r : kReads) {
        if (r.function == function)
            return int(r.table);
    }
    return -1;
}

QList<ConformanceCheck> ReadChecks::checks()
{
    QList<ConformanceCheck> out;
    {
        // The first code the specification leaves unassigned: no device implements it.
        quint8 unassigned = 0;
        for (int c = 1; c < 0x80 && unassigned == 0; ++c) {
            if (functionKind(quint8(c)) == FunctionKind::Unassigned)
                unassigned = quint8(c);
        }
        ConformanceCheck c;
        c.id = QStringLiteral("exception.illegal-function");
        c.title = QStringLiteral("an unassigned function code (%1) gets exception 01").arg(code(unassigned));
        c.clause = QStringLiteral("Application Protocol V1.1b3, 7 and 4.1");
        c.run = [unassigned](ConformanceContext &ctx, CheckResult &res) {
            QByteArray pdu;
            pdu.append(char(unassigned));
            pdu.append(QByteArray::fromHex("00000001"));
            ConformanceJudge::exception(res, ctx.ask(pdu), {0x01},
                                        QStringLiteral("exception 01 (Illegal Function) for function code %1, which it does not implement")
                                            .arg(code(unassigned)));
        };
        out.append(c);
    }
    for (const ReadFunction &r : kReads)
        addChecks(out, r);
    return out;
}

} // namespace mbscope
