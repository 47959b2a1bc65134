#include "dissector.h"

#include "adudissectors.h"
#include "broadcastrule.h"
#include "checksum.h"
#include "hexformat.h"

namespace mbscope {

namespace {

// The largest frame each framing allows: a PDU is at most 253 bytes (V1.1b3, 4.1), so an RTU
// ADU at most 256 (Serial Line V1.02, 2.5.1.1), an MBAP ADU at most 260 (Messaging on TCP/IP
// V1.0b, 4.1) and an ASCII frame at most 513 characters (Serial Line V1.02, 2.5.2.1).
struct AduLimit {
    int bytes;
    const char *what;
    const char *where;
};

AduLimit aduLimit(Framing framing)
{
    switch (framing) {
    case Framing::Rtu: return {256, "an RTU ADU is at most 256 bytes", "MODBUS over Serial Line V1.02, 2.5.1.1"};
    case Framing::Ascii: return {513, "an ASCII frame is at most 513 characters", "MODBUS over Serial Line V1.02, 2.5.2.1"};
    case Framing::Tcp:
    case Framing::Udp: return {260, "an MBAP ADU is at most 260 bytes", "MODBUS Messaging on TCP/IP V1.0b, 4.1"};
    case Framing::Pdu:
    case Framing::Auto: break;
    }
    return {253, "a PDU is at most 253 bytes", "MODBUS Application Protocol V1.1b3, 4.1"};
}

// n is the frame's size as it travels: for ASCII its characters, although the tree then holds
// the decoded bytes (the field goes at their end).
void checkAduSize(FieldTree &tree, Framing framing, int n)
{
    const AduLimit limit = aduLimit(framing);
    if (n <= limit.bytes)
        return;
    const int at = qMin(limit.bytes, int(tree.frame().size()));
    const int f = tree.add(-1, "frame.too_long", QT_TRANSLATE_NOOP("mbscope::Field", "Frame too long"), at, 0,
                           quint64(n - limit.bytes), ValueFormat::Decimal);
    // An ASCII frame's bytes are its characters.
    const QString unit = framing == Framing::Ascii ? QStringLiteral("characters") : QStringLiteral("bytes");
    tree.flag(f, Severity::Error,
              QStringLiteral("the frame is %1 %2; %3 (%4): %5 %2 too many")
                  .arg(n).arg(unit, QLatin1String(limit.what), QLatin1String(limit.where)).arg(n - limit.bytes));
}

// Serial Line V1.02, 2.1: a read to unit 0 is a broadcast nobody answers. Said of a frame that is
// otherwise whole and correct: bytes with a wrong check sum are no broadcast (tryout 8: MBAP bytes
// sent to an RTU link read as "unit 0").
void checkBroadcastRead(Dissection &out)
{
    if (out.direction != Direction::Request || (out.framing != Framing::Rtu && out.framing != Framing::Ascii)
        || out.fields.worstSeverity() >= Severity::Error)
        return;
    const int unit = out.fields.indexOf(out.framing == Framing::Rtu ? "rtu.unit_id" : "ascii.unit_id");
    const QByteArray &b = out.fields.frame(); // ASCII: the decoded bytes
    if (unit < 0 || b.size() < 2 || b.at(0) != 0 || !BroadcastRule::wantsAnswer(quint8(b.at(1))))
        return;
    out.fields.flag(unit, Severity::Error, BroadcastRule::readProblem(quint8(b.at(1))));
}

void runFraming(Dissection &out, const adu::RequestInfo &request)
{
    const int wireSize = int(out.fields.frame().size());
    switch (out.framing) {
    case Framing::Rtu: adu::dissectRtu(out, request); break;
    case Framing::Ascii: adu::dissectAscii(out, request); break;
    case Framing::Tcp:
    case Framing::Udp: adu::dissectMbap(out, request); break;
    case Framing::Pdu:
    case Framing::Auto: adu::dissectBarePdu(out, request); break;
    }
    checkAduSize(out.fields, out.framing, wireSize);
    checkBroadcastRead(out);
}

bool rtuCrcValid(const QByteArray &b)
{
    if (b.size() < 4)
        return false;
    const quint16 sent = quint16(quint8(b.at(b.size() - 2)) | (quint8(b.at(b.size() - 1)) << 8));
    return checksum::crc16Modbus(QByteArrayView(b).first(b.size() - 2)) == sent;
}

// Which framing do the bytes carry? Each rule says why, so the user can judge it.
Framing detectFraming(const QByteArray &b, QString &reason)
{
    if (b.startsWith(':')) {
        reason = QStringLiteral("starts with ':' (0x3A), the ASCII frame start");
        return Framing::Ascii;
    }
    const bool crc = rtuCrcValid(b);
    const bool mbapHeader = b.size() >= 8 && b.at(2) == 0 && b.at(3) == 0;
    const int mbapLength = b.size() >= 6 ? (quint8(b.at(4)) << 8) | quint8(b.at(5)) : -1;
    const bool mbapExact = mbapHeader && mbapLength == b.size() - 6;
    if (crc && !mbapExact) {
        reason = QStringLiteral("the last two bytes are a valid CRC-16/MODBUS of the bytes before them");
        return Framing::Rtu;
    }
    if (mbapExact && !crc) {
        reason = QStringLiteral("bytes 2-3 are protocol id 0 and the MBAP length field (%1) matches the bytes after it").arg(mbapLength);
        return Framing::Tcp;
    }
    if (crc && mbapExact) {
        reason = QStringLiteral("the bytes fit both a Modbus TCP header and an RTU CRC; read as RTU because a valid CRC is the "
                                "stronger sign (use --framing tcp to read it as Modbus TCP)");
        return Framing::Rtu;
    }
    if (mbapHeader && mbapLength >= 2 && mbapLength <= 254) {
        reason = QStringLiteral("bytes 2-3 are protocol id 0 and the length field (%1) is plausible, but it does not match the "
                                "%2 bytes after it and no CRC is valid; read as Modbus TCP")
                     .arg(mbapLength).arg(b.size() - 6);
        return Framing::Tcp;
    }
    reason = QStringLiteral("no valid CRC, no MBAP header and no ':' start: read as RTU, whose CRC check then fails");
    return Framing::Rtu;
}

struct Score {
    int errors = 0;
    int warnings = 0;
    QString firstProblem;
};

Score score(const FieldTree &tree)
{
    Score s;
    for (const Field &f : tree.fields()) {
        if (f.severity == Severity::Error) {
            if (s.errors++ == 0)
                s.firstProblem = QString::fromLatin1(f.key) + QStringLiteral(": ") + f.message;
        } else if (f.severity == Severity::Warning) {
            ++s.warnings;
        }
    }
    return s;
}

QString describe(const Score &s)
{
    if (s.errors == 0 && s.warnings == 0)
        return QStringLiteral("no problems");
    QString text = QStringLiteral("%1 error(s), %2 warning(s)").arg(s.errors).arg(s.warnings);
    if (!s.firstProblem.isEmpty())
        text += QStringLiteral(" (") + s.firstProblem + QLatin1Char(')');
    return text;
}

int functionCodeOf(const Dissection &d)
{
    const int f = d.fields.indexOf("modbus.function_code");
    return f >= 0 && d.fields.at(f).length > 0 ? int(d.fields.at(f).value) : -1;
}

} // namespace

Dissection Dissector::dissect(const QByteArray &frame, const DissectOptions &options)
{
    Dissection out;
    dissect(frame, options, out);
    return out;
}

void Dissector::dissect(const QByteArray &frame, const DissectOptions &options, Dissection &out)
{
    out.framingReason.clear();
    out.directionReason.clear();
    out.note.clear();
    out.framing = options.framing;
    if (out.framing == Framing::Auto)
        out.framing = detectFraming(frame, out.framingReason);

    const adu::RequestInfo request = adu::requestInfo(options.request, out.framing);

    if (options.direction != Direction::Auto) {
        out.direction = options.direction;
        out.fields.reset(frame);
        runFraming(out, request);
        return;
    }

    // Direction unknown: read the frame both ways and keep the reading with fewer problems.
    if (!options.request.isEmpty()) {
        out.direction = Direction::Response;
        out.directionReason = QStringLiteral("a matching request was given, so this is its response");
        out.fields.reset(frame);
        runFraming(out, request);
        return;
    }
    // Reused per thread: auto-detection dissects twice, and the second tree keeps its capacity.
    thread_local Dissection asResponse;
    asResponse.framingReason.clear();
    asResponse.directionReason.clear();
    asResponse.note.clear();
    asResponse.framing = out.framing;
    asResponse.direction = Direction::Response;
    asResponse.fields.reset(frame);
    runFraming(asResponse, request);

    out.direction = Direction::Request;
    out.fields.reset(frame);
    runFraming(out, request);

    const int code = functionCodeOf(out);
    if (code >= 0x80) {
        out = asResponse;
        out.directionReason = QStringLiteral("function code %1 has bit 7 set: an exception, which only a response carries")
                                  .arg(hexByte(quint64(code)));
        return;
    }
    const Score req = score(out.fields);
    const Score rsp = score(asResponse.fields);
    const bool responseBetter = rsp.errors < req.errors || (rsp.errors == req.errors && rsp.warnings < req.warnings);
    const QString both = QStringLiteral("as a request: %1; as a response: %2").arg(describe(req), describe(rsp));
    if (responseBetter) {
        const QString reasonFraming = out.framingReason;
        const QString note = out.note;
        out = asResponse;
        out.framingReason = reasonFraming;
        out.note = note;
        out.directionReason = QStringLiteral("read as a response, which fits better: ") + both;
    } else if (req.errors == rsp.errors && req.warnings == rsp.warnings) {
        out.directionReason = QStringLiteral("request and response read the same way (%1); shown as a request, "
                                             "use --direction response to read it as the answer")
                                  .arg(describe(req));
    } else {
        out.directionReason = QStringLiteral("read as a request, which fits better: ") + both;
    }
}

namespace adu {

RequestInfo requestInfo(const QByteArray &request, Framing framing)
{
    RequestInfo info;
    if (request.isEmpty())
        return info;
    switch (framing) {
    case Framing::Rtu:
        info.unit = quint8(request.at(0));
        if (request.size() >= 4)
            info.pdu = QByteArrayView(request).sliced(1, request.size() - 3);
        else
            info.pdu = QByteArrayView(request).sliced(1);
        break;
    case Framing::Ascii: {
        (void)decodeAsciiPayload(request, info.storage, nullptr, nullptr);
        if (!info.storage.isEmpty())
            info.unit = quint8(info.storage.at(0));
        if (info.storage.size() >= 3)
            info.pdu = QByteArrayView(info.storage).sliced(1, info.storage.size() - 2);
        break;
    }
    case Framing::Tcp:
    case Framing::Udp:
        if (request.size() >= 2)
            info.transactionId = (quint8(request.at(0)) << 8) | quint8(request.at(1));
        if (request.size() >= 7)
            info.unit = quint8(request.at(6));
        if (request.size() > 7)
            info.pdu = QByteArrayView(request).sliced(7);
        break;
    case Framing::Pdu:
    case Framing::Auto:
        info.pdu = QByteArrayView(request);
        break;
    }
    return info;
}

} // namespace adu

} // namespace mbscope
