#include "poll/devicepace.h"

#include "common/requestnames.h"

#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "transport/linkurl.h"

#include <numeric>

namespace mbscope::app {

namespace {

QString hexCode(quint8 code)
{
    return QStringLiteral("0x%1").arg(QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0')));
}

BuildResult buildRead(quint8 function, int address, int quantity)
{
    switch (function) {
    case 1: return RequestBuilder::readCoils(address, quantity);
    case 2: return RequestBuilder::readDiscreteInputs(address, quantity);
    case 3: return RequestBuilder::readHoldingRegisters(address, quantity);
    default: return RequestBuilder::readInputRegisters(address, quantity);
    }
}

// The quantity a request's PDU asks for (reads and multiple writes; 17: its read), 0 for others.
int quantityOf(const QByteArray &pdu)
{
    if (pdu.size() < 5)
        return 0;
    const quint8 code = quint8(pdu.at(0));
    const bool counted = (code >= 1 && code <= 4) || code == 0x0F || code == 0x10 || code == 0x17;
    return counted ? (quint8(pdu.at(3)) << 8) | quint8(pdu.at(4)) : 0;
}

} // namespace

DevicePace::Fit DevicePace::fitReads(RequestPlan &plan, const QMap<quint8, int> &maxQuantity, const LinkUrl &url,
                                     const QString &source)
{
    Fit fit;
    QStringList &notes = fit.notes;
    if (maxQuantity.isEmpty())
        return fit;
    // A cut falls between whole values of every format: f32 and u64 together cut at 4 registers.
    int whole = 1;
    for (const RegisterFormat &f : std::as_const(plan.formats))
        whole = std::lcm(whole, qMax(1, f.registerCount()));
    QList<PlannedRequest> fitted;
    for (qsizetype index = 0; index < plan.requests.size(); ++index) {
        const PlannedRequest &r = plan.requests.at(index);
        const bool builtRead = plan.built && r.functionCode >= 1 && r.functionCode <= 4;
        const quint8 code = builtRead ? r.functionCode : r.item.functionCode;
        const int limit = maxQuantity.value(code, 0);
        const QByteArray pdu = builtRead ? QByteArray() : AduBuilder::parse(r.item.bytes, r.item.framing).pdu;
        if (!builtRead && pdu.isEmpty()) {
            ++fit.unchecked; // not a frame of the link's framing: what it asks is not known
            fitted.append(r);
            continue;
        }
        const int asked = builtRead ? r.quantity : quantityOf(pdu);
        if (limit <= 0 || asked <= limit) {
            fitted.append(r);
            continue;
        }
        const QString over = QStringLiteral("%1 asks %2 with %3, more than the device takes (limits.maxQuantity %4 of %5)")
                                 .arg(builtRead ? RequestNames::itemName(code, r.address, r.quantity, r.oneBased)
                                                : QStringLiteral("request %1 (%2)").arg(index + 1).arg(r.item.name.isEmpty()
                                                                                                       ? QStringLiteral("--hex")
                                                                                                       : r.item.name))
                                 .arg(asked)
                                 .arg(hexCode(code))
                                 .arg(limit)
                                 .arg(source);
        const int step = code >= 3 ? limit - limit % whole : limit;
        if (!builtRead || step < 1) {
            fitted.append(r);
            ++fit.sentOver;
            notes.append(over + (builtRead ? QStringLiteral(": one value of --format takes %1 registers, more than a read "
                                                            "may ask; sent as given")
                                                 .arg(whole)
                                           : QStringLiteral(": sent as given (only reads built from the read "
                                                            "options, --function or -t, are cut)")));
            continue;
        }
        AduOptions options;
        options.framing = url.framing();
        options.unitId = r.unit;
        options.transactionId = 1;
        QStringList pieces;
        for (int offset = 0; offset < r.quantity; offset += step) {
            const int count = qMin(step, r.quantity - offset);
            const int address = r.address + offset;
            PlannedRequest piece = r;
            piece.address = address;
            piece.quantity = count;
            piece.description = RequestNames::describe(code, r.unit, address, count, RequestNames::readNoun(code, count),
                                                       r.oneBased);
            RequestItem item = RequestItem::forLink(AduBuilder::complete(buildRead(code, address, count).pdu, options), url,
                                                    RequestNames::itemName(code, address, count, r.oneBased));
            item.timeoutMs = r.item.timeoutMs;
            item.retries = r.item.retries;
            item.engineNumbered = r.item.engineNumbered;
            piece.item = item;
            fitted.append(piece);
            const int shown = address + (r.oneBased ? 1 : 0);
            pieces.append(count == 1 ? QString::number(shown) : QStringLiteral("%1-%2").arg(shown).arg(shown + count - 1));
        }
        if (plan.requests.size() == 1) // the heading says what the cycle reads, all together
            plan.summary = RequestNames::describeItems(code, r.unit, r.address, r.quantity,
                                                       RequestNames::readNoun(code, r.quantity), r.oneBased);
        ++fit.cut;
        notes.append(over + QStringLiteral(": read as %1 requests of at most %2 (%3)")
                                .arg(pieces.size())
                                .arg(step)
                                .arg(pieces.join(QStringLiteral(", "))));
    }
    plan.requests = fitted;
    return fit;
}

} // namespace mbscope::app
