#include "replay/recordedwrite.h"

#include "protocol/functionspec.h"

#include "protocol/diagnosticrules.h"
#include "protocol/functioncode.h"

#include <QtCore/QStringList>
#include <QtCore/QtEndian>

#include <map>

namespace mbscope {

namespace {

quint16 word(const QByteArray &pdu, qsizetype at)
{
    return qFromBigEndian<quint16>(pdu.constData() + at);
}

QString hex(quint32 value, int digits)
{
    return QStringLiteral("0x") + QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'));
}

} // namespace

bool RecordedWrite::isWriteFunction(quint8 function)
{
    return functionWrites(function);
}

bool RecordedWrite::isChangingDiagnostic(int subFunction)
{
    switch (subFunction) {
    case 0x01: case 0x03: case 0x04: case 0x0A: case 0x14:
        return true;
    default:
        return false;
    }
}

std::optional<RecordedWrite> RecordedWrite::of(qsizetype index, quint8 unitId, const QByteArray &pdu)
{
    if (pdu.isEmpty())
        return std::nullopt;
    RecordedWrite w;
    w.index = index;
    w.unitId = unitId;
    w.function = quint8(pdu.at(0));
    if (w.function == 0x08) {
        if (pdu.size() < 3)
            return w; // cannot tell which sub-function: held back
        w.subFunction = word(pdu, 1);
        w.known = true;
        if (!isChangingDiagnostic(w.subFunction))
            return std::nullopt;
        return w;
    }
    if (!isWriteFunction(w.function))
        return std::nullopt;
    switch (w.function) {
    case 0x05:
    case 0x06:
    case 0x16:
        if (pdu.size() >= 3) {
            w.address = word(pdu, 1);
            w.quantity = 1;
            w.known = true;
        }
        break;
    case 0x0F:
    case 0x10:
        if (pdu.size() >= 5) {
            w.address = word(pdu, 1);
            w.quantity = word(pdu, 3);
            w.known = true;
        }
        break;
    case 0x17: // read address, read quantity, write address, write quantity, ...
        if (pdu.size() >= 9) {
            w.address = word(pdu, 5);
            w.quantity = word(pdu, 7);
            w.known = true;
        }
        break;
    case 0x15: // byte count, then reference type, file number, record number, record length, data
        if (pdu.size() >= 9) {
            w.address = word(pdu, 5);
            w.quantity = word(pdu, 7);
            w.known = true;
        }
        break;
    default:
        break;
    }
    return w;
}

QString RecordedWrite::text() const
{
    QString text = QStringLiteral("#%1 unit %2 %3 (%4)")
                       .arg(index + 1)
                       .arg(unitId)
                       .arg(QLatin1String(functionName(function)), hex(function, 2));
    if (function == 0x08) {
        if (!known)
            return text + QStringLiteral(", too short to say which sub-function");
        const char *name = diagnosticrules::subFunctionName(subFunction);
        return text + QStringLiteral(" sub-function %1 %2").arg(hex(quint32(subFunction), 4), QLatin1String(name ? name : "(reserved)"));
    }
    if (!known)
        return text + QStringLiteral(", too short to say where it writes");
    return text + QStringLiteral(" %1 %2 quantity %3")
                      .arg(function == 0x15 ? QStringLiteral("record") : QStringLiteral("address"), hex(address, 4))
                      .arg(quantity);
}

QJsonObject RecordedWrite::toJson() const
{
    if (function == 0x08) {
        const char *name = known ? diagnosticrules::subFunctionName(subFunction) : nullptr;
        return QJsonObject{{QStringLiteral("request"), double(index + 1)},
                           {QStringLiteral("unit"), unitId},
                           {QStringLiteral("function"), hex(function, 2)},
                           {QStringLiteral("name"), QLatin1String(functionName(function))},
                           {QStringLiteral("subFunction"), known ? QJsonValue(hex(quint32(subFunction), 4)) : QJsonValue()},
                           {QStringLiteral("subFunctionName"), name ? QJsonValue(QLatin1String(name)) : QJsonValue()}};
    }
    return QJsonObject{{QStringLiteral("request"), double(index + 1)},
                       {QStringLiteral("unit"), unitId},
                       {QStringLiteral("function"), hex(function, 2)},
                       {QStringLiteral("name"), QLatin1String(functionName(function))},
                       {QStringLiteral("address"), known ? QJsonValue(address) : QJsonValue()},
                       {QStringLiteral("quantity"), known ? QJsonValue(quantity) : QJsonValue()}};
}

QString RecordedWrite::placesText(const QList<RecordedWrite> &writes)
{
    // unit -> (address, quantity; -1 for unknown) -> how many writes
    std::map<quint8, std::map<std::pair<int, int>, int>> places;
    // diagnostics: (-2, sub-function; -1 when unknown)
    for (const RecordedWrite &w : writes)
        ++places[w.unitId][w.function == 0x08 ? std::pair<int, int>(-2, w.known ? w.subFunction : -1)
                           : w.known          ? std::pair<int, int>(w.address, w.quantity)
                                              : std::pair<int, int>(-1, 0)];
    QStringList units;
    for (const auto &[unit, where] : places) {
        QStringList spots;
        QStringList diagnostics;
        for (const auto &[place, times] : where) {
            QString spot;
            if (place.first == -2) {
                const char *name = place.second >= 0 ? diagnosticrules::subFunctionName(place.second) : nullptr;
                spot = name ? QLatin1String(name) : QStringLiteral("a diagnostic");
            } else if (place.first < 0) {
                spot = QStringLiteral("an unknown address");
            } else if (place.second <= 1) {
                spot = hex(quint32(place.first), 4);
            } else {
                spot = QStringLiteral("%1-%2").arg(hex(quint32(place.first), 4), hex(quint32(place.first + place.second - 1), 4));
            }
            if (times > 1)
                spot += QStringLiteral(" (%1 times)").arg(times);
            (place.first == -2 ? diagnostics : spots).append(spot);
        }
        // "unit 1 at 0x007D", "unit 1: Restart Communications Option", "unit 1 at 0x007D; Force Listen Only Mode"
        QString text = QStringLiteral("unit %1").arg(unit);
        if (!spots.isEmpty())
            text += QStringLiteral(" at ") + spots.join(QStringLiteral(", "));
        if (!diagnostics.isEmpty())
            text += (spots.isEmpty() ? QStringLiteral(": ") : QStringLiteral(" and ")) + diagnostics.join(QStringLiteral(", "));
        units.append(text);
    }
    return units.join(QStringLiteral("; "));
}

} // namespace mbscope
