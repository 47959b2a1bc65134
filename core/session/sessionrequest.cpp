#include "session/sessionrequest.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"
#include "protocol/requestbuilder.h"
#include "transport/linkurl.h"

namespace mbscope {

namespace {

SessionRequest::Bytes fromBuild(const BuildResult &built)
{
    SessionRequest::Bytes out;
    if (built.isValid()) {
        out.bytes = built.pdu;
        return out;
    }
    const BuildError &first = built.errors.constFirst();
    // RequestBuilder names its parameters as C++ does; the document names them as JSON keys.
    out.parameter = first.parameter == QLatin1String("startAddress") ? QStringLiteral("address") : first.parameter;
    out.error = first.message;
    return out;
}

} // namespace

bool SessionRequest::formSupports(int function)
{
    return (function >= 1 && function <= 6) || function == 15 || function == 16;
}

SessionRequest::Bytes SessionRequest::pdu() const
{
    switch (function) {
    case 1:
        return fromBuild(RequestBuilder::readCoils(address, quantity));
    case 2:
        return fromBuild(RequestBuilder::readDiscreteInputs(address, quantity));
    case 3:
        return fromBuild(RequestBuilder::readHoldingRegisters(address, quantity));
    case 4:
        return fromBuild(RequestBuilder::readInputRegisters(address, quantity));
    case 5:
        if (coils.size() != 1)
            return {{}, QStringLiteral("coils"), QStringLiteral("Write Single Coil writes one coil, %1 given").arg(coils.size())};
        return fromBuild(RequestBuilder::writeSingleCoil(address, coils.constFirst()));
    case 6:
        if (values.size() != 1)
            return {{}, QStringLiteral("values"),
                    QStringLiteral("Write Single Register writes one value, %1 given").arg(values.size())};
        return fromBuild(RequestBuilder::writeSingleRegister(address, values.constFirst()));
    case 15:
        return fromBuild(RequestBuilder::writeMultipleCoils(address, coils));
    case 16:
        return fromBuild(RequestBuilder::writeMultipleRegisters(address, values));
    default:
        break;
    }
    return {{}, QStringLiteral("function"),
            QStringLiteral("function %1 cannot be built from a form: give its bytes as hex (forms build 1, 2, 3, 4, 5, 6, 15 and 16)")
                .arg(function)};
}

SessionRequest::Bytes SessionRequest::hexBytes() const
{
    const HexTextResult parsed = HexText::parse(hex);
    if (!parsed.ok)
        return {{}, QStringLiteral("hex"), parsed.error.message};
    return {parsed.bytes, {}, {}};
}

SessionRequest::Bytes SessionRequest::wireBytes(const LinkUrl &url, quint16 transactionId) const
{
    Bytes made = kind == Kind::Form ? pdu() : hexBytes();
    if (!made.ok())
        return made;
    if (kind == Kind::Hex && !complete)
        return made; // exact bytes: never rewritten
    if (url.delimited.enabled) {
        made.parameter = kind == Kind::Hex ? QStringLiteral("complete") : QStringLiteral("function");
        made.error = QStringLiteral("%1 uses delimited framing: a Modbus header or checksum cannot be added; give the exact bytes as hex")
                         .arg(url.toString());
        made.bytes.clear();
        return made;
    }
    AduOptions options;
    options.framing = url.framing();
    options.unitId = quint8(unit);
    options.transactionId = transactionId;
    made.bytes = AduBuilder::complete(made.bytes, options);
    return made;
}

} // namespace mbscope
