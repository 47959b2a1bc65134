#include "sim/simscriptreply.h"

#include "protocol/functionspec.h"

#include "script/scripthost.h"
#include "sim/simprocessor.h"

namespace mbscope {

namespace {

QString hex2(int value)
{
    return QString::number(value, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

// The answer of a read made of the script's values (V1.1b3 6.1-6.4, 6.17): bits packed LSB
// first, registers big-endian, behind the byte count.
SimReply valuesReply(quint8 function, const QList<quint16> &values, QString *why)
{
    const bool bits = function == 0x01 || function == 0x02;
    if (!functionReadsValues(function)) {
        *why = QStringLiteral("values answer a read (01-04, 17), not function %1").arg(hex2(function));
        return {};
    }
    const int byteCount = bits ? int((values.size() + 7) / 8) : int(values.size() * 2);
    if (values.isEmpty() || byteCount > 250) {
        *why = QStringLiteral("%1 values do not fit one answer (1 to %2)").arg(values.size()).arg(QuantityLimits::maxQuantity(function));
        return {};
    }
    QByteArray pdu(2 + byteCount, 0);
    pdu[0] = char(function);
    pdu[1] = char(byteCount);
    for (qsizetype i = 0; i < values.size(); ++i) {
        if (bits) {
            if (values.at(i) != 0)
                pdu[2 + i / 8] = char(quint8(pdu.at(2 + i / 8)) | (1 << (i % 8)));
        } else {
            pdu[2 + 2 * i] = char(values.at(i) >> 8);
            pdu[3 + 2 * i] = char(values.at(i) & 0xFF);
        }
    }
    SimReply reply = SimReply::normal(pdu);
    reply.note = QStringLiteral("script: %1 value(s)").arg(values.size());
    return reply;
}

} // namespace

SimScriptReply SimScriptReply::make(ScriptHost &script, SimProcessor &processor, const Request &request)
{
    ScriptRequest r = ScriptRequest::fromPdu(request.pdu);
    r.unit = request.unitId;
    r.endpoint = request.endpoint;
    r.peer = request.peer;
    r.transactionId = request.transactionId;
    r.timeMs = script.elapsedMs();
    ScriptAnswer answer = script.request(r);
    const quint8 function = quint8(request.pdu.at(0)) & 0x7F;

    SimScriptReply out;
    out.delayNs = answer.delayNs;
    if (answer.kind == ScriptAnswer::Kind::Values) {
        QString why;
        out.reply = valuesReply(function, answer.values, &why);
        if (!out.reply.hasAnswer()) {
            answer = ScriptAnswer::failed(script.settings().name + QStringLiteral(": onRequest returned ") + why);
            Q_EMIT script.logged(answer.note, true);
        }
    }
    switch (answer.kind) {
    case ScriptAnswer::Kind::Normal:
        out.reply = processor.process(request.pdu, false);
        break;
    case ScriptAnswer::Kind::Silence:
        out.reply = SimReply::silent(QStringLiteral("script: no answer"));
        break;
    case ScriptAnswer::Kind::Values:
        break;
    case ScriptAnswer::Kind::Exception:
        out.reply = SimReply::exception(function, quint8(answer.exceptionCode),
                                        QStringLiteral("script: exception %1").arg(hex2(answer.exceptionCode)));
        break;
    case ScriptAnswer::Kind::Pdu:
        out.reply.kind = (quint8(answer.bytes.at(0)) & 0x80) != 0 ? SimReply::Kind::Exception : SimReply::Kind::Normal;
        out.reply.pdu = answer.bytes;
        out.reply.exceptionCode = answer.bytes.size() > 1 && out.reply.kind == SimReply::Kind::Exception ? quint8(answer.bytes.at(1)) : 0;
        out.reply.note = QStringLiteral("script: PDU of %1 byte(s)").arg(answer.bytes.size());
        break;
    case ScriptAnswer::Kind::Adu:
        out.reply = SimReply::normal(answer.bytes);
        out.reply.note = QStringLiteral("script: %1 byte(s) as given").arg(answer.bytes.size());
        out.adu = answer.bytes;
        break;
    case ScriptAnswer::Kind::Failed:
        switch (script.settings().onError) {
        case ScriptSettings::OnError::Exception:
            // V1.1b3 7: 04, server device failure.
            out.reply = SimReply::exception(function, 0x04, QStringLiteral("script error (exception 04): ") + answer.note);
            break;
        case ScriptSettings::OnError::Silence:
            out.reply = SimReply::silent(QStringLiteral("script error (no answer): ") + answer.note);
            break;
        case ScriptSettings::OnError::Normal:
            out.reply = processor.process(request.pdu, false);
            out.reply.note = QStringLiteral("script error (the profile's answer): ") + answer.note;
            break;
        }
        out.delayNs = -1;
        break;
    }
    return out;
}

} // namespace mbscope
