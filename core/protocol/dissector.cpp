#include "dissector.h"
#include "framingtraits.h"

#include "adudissectors.h"
#include "broadcastrule.h"
#include "checksum.h"
#include "hexformat.h"

namespace mbscope {

namespace {

// The largest frame each framing allows (framingtraits.h).
struct AduLimit {
    int bytes;
    const char *what;
    const char *where;
};

AduLimit aduLimit(Framing framing)
{
    const FramingTraits &t = framingTraits(framing);
    return {t.maxFrameBytes, t.maxFrameRule, t.maxFrameClause};
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
    if (out.direction != Direction::Request || !isSerialLine(out.framing)
        || out.fields.worstSeverity() >= Severity::Error)
        return;
    const int unit = out.fields.indexOf(out.framing == Framing::Rtu ? "rtu.unit_id" : "ascii.unit_id");
    const QByteArray &b = out.fields.frame(); // ASCII: the decoded bytes
    if (unit < 0 || b.size() < 2 || b.at(0) != 0 || !BroadcastRule::wantsAnswer(quint8(b.at(1))))
        return;
    out.fields.flag(unit, Severity::Error, BroadcastRule::readProblem(quint8(b.at(1))));
}

void runFraming(Dissection &out, const adu::RequestInfo &request, int frameCrc = -1)
{
    const int wireSize = int(out.fields.frame().size());
    switch (out.framing) {
    case Framing::Rtu: adu::dissectRtu(out, request, frameCrc); break;
    case Framing::Ascii: adu::dissectAscii(out, request); break;
    case Framing::Tcp:
    case Framing::Udp: adu::dissectMbap(out, request); break;
    case Framing::Pdu:
    case Framing::Auto: adu::dissectBarePdu(out, request); break;
    }
    checkAduSize(out.fields, out.framing, wireSize);
    checkBroadcastRead(out);
}

// computed: the CRC of all bytes but the last two, -1 for a frame of fewer than 4 bytes.
bool rtuCrcValid(const QByteArray &b, int &computed)
{
    computed = -1;
    if (b.size() < 4)
        return false;
    const quint16 sent = quint16(quint8(b.at(b.size() - 2)) | (quint8(b.at(b.size() - 1)) << 8));
    computed = checksum::crc16Modbus(QByteArrayView(b).first(b.size() - 2));
    return computed == sent;
}

// Which rule of detectFraming decided; the reason's text is written from it when it is read.
enum class FramingRule : int { AsciiStart, Crc, Mbap, CrcAndMbap, MbapPlausible, Fallback };

QString framingReasonText(const QByteArray &b, int rule, int mbapLength)
{
    switch (FramingRule(rule)) {
    case FramingRule::AsciiStart: return QStringLiteral("starts with ':' (0x3A), the ASCII frame start");
    case FramingRule::Crc: return QStringLiteral("the last two bytes are a valid CRC-16/MODBUS of the bytes before them");
    case FramingRule::Mbap:
        return QStringLiteral("bytes 2-3 are protocol id 0 and the MBAP length field (%1) matches the bytes after it").arg(mbapLength);
    case FramingRule::CrcAndMbap:
        return QStringLiteral("the bytes fit both a Modbus TCP header and an RTU CRC; read as RTU because a valid CRC is the "
                              "stronger sign (use --framing tcp to read it as Modbus TCP)");
    case FramingRule::MbapPlausible:
        return QStringLiteral("bytes 2-3 are protocol id 0 and the length field (%1) is plausible, but it does not match the "
                              "%2 bytes after it and no CRC is valid; read as Modbus TCP")
            .arg(mbapLength).arg(b.size() - 6);
    case FramingRule::Fallback: break;
    }
    return QStringLiteral("no valid CRC, no MBAP header and no ':' start: read as RTU, whose CRC check then fails");
}

// Which framing do the bytes carry? Each rule says why, so the user can judge it. Structural
// checks only: the ':' start, one CRC over the frame, the MBAP header's fields.
Framing detectFraming(const QByteArray &b, DetectionReason &reason, bool &crcValid, int &frameCrc)
{
    const auto decide = [&](Framing framing, FramingRule rule, int mbapLength = 0) {
        reason = DetectionReason::deferred(framingReasonText, b, int(rule), mbapLength);
        return framing;
    };
    crcValid = false;
    frameCrc = -1;
    if (b.startsWith(':'))
        return decide(Framing::Ascii, FramingRule::AsciiStart);
    const bool mbapHeader = b.size() >= 8 && b.at(2) == 0 && b.at(3) == 0;
    const int mbapLength = b.size() >= 6 ? (quint8(b.at(4)) << 8) | quint8(b.at(5)) : -1;
    const bool mbapExact = mbapHeader && mbapLength == b.size() - 6;
    const bool crc = rtuCrcValid(b, frameCrc);
    crcValid = crc;
    if (crc && !mbapExact)
        return decide(Framing::Rtu, FramingRule::Crc);
    if (mbapExact && !crc)
        return decide(Framing::Tcp, FramingRule::Mbap, mbapLength);
    if (crc && mbapExact)
        return decide(Framing::Rtu, FramingRule::CrcAndMbap);
    if (mbapHeader && mbapLength >= 2 && mbapLength <= 254)
        return decide(Framing::Tcp, FramingRule::MbapPlausible, mbapLength);
    return decide(Framing::Rtu, FramingRule::Fallback);
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

// The counts alone, for choosing: the first problem's text is only wanted for the reason.
Score count(const FieldTree &tree)
{
    Score s;
    for (const Field &f : tree.fields()) {
        s.errors += f.severity == Severity::Error ? 1 : 0;
        s.warnings += f.severity == Severity::Warning ? 1 : 0;
    }
    return s;
}

bool responseFitsBetter(const Score &req, const Score &rsp)
{
    return rsp.errors < req.errors || (rsp.errors == req.errors && rsp.warnings < req.warnings);
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

// The direction's reason, written when it is read: the frame read both ways (no matching request:
// with one the direction is not detected), the first problem of each quoted.
QString directionReasonText(const QByteArray &frame, int framing, int)
{
    Dissection asRequest;
    asRequest.framing = Framing(framing);
    asRequest.direction = Direction::Request;
    asRequest.fields.reset(frame);
    runFraming(asRequest, {});
    const int code = functionCodeOf(asRequest);
    if (code >= 0x80)
        return QStringLiteral("function code %1 has bit 7 set: an exception, which only a response carries").arg(hexByte(quint64(code)));
    Dissection asResponse;
    asResponse.framing = Framing(framing);
    asResponse.direction = Direction::Response;
    asResponse.fields.reset(frame);
    runFraming(asResponse, {});
    const Score req = score(asRequest.fields);
    const Score rsp = score(asResponse.fields);
    const QString both = QStringLiteral("as a request: %1; as a response: %2").arg(describe(req), describe(rsp));
    if (responseFitsBetter(req, rsp))
        return QStringLiteral("read as a response, which fits better: ") + both;
    if (req.errors == rsp.errors && req.warnings == rsp.warnings)
        return QStringLiteral("request and response read the same way (%1); shown as a request, "
                              "use --direction response to read it as the answer")
            .arg(describe(req));
    return QStringLiteral("read as a request, which fits better: ") + both;
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
    bool crcKnown = false;
    bool crcValid = false;
    int frameCrc = -1; // computed once, by detection, and handed to the RTU layer
    if (out.framing == Framing::Auto) {
        out.framing = detectFraming(frame, out.framingReason, crcValid, frameCrc);
        crcKnown = out.framing == Framing::Rtu;
    }

    const adu::RequestInfo request = adu::requestInfo(options.request, out.framing);

    if (options.direction != Direction::Auto) {
        out.direction = options.direction;
        out.fields.reset(frame);
        runFraming(out, request, frameCrc);
        return;
    }

    // Direction unknown: read the frame both ways and keep the reading with fewer problems.
    if (!options.request.isEmpty()) {
        out.direction = Direction::Response;
        out.directionReason = QStringLiteral("a matching request was given, so this is its response");
        out.fields.reset(frame);
        runFraming(out, request, frameCrc);
        return;
    }
    out.directionReason = DetectionReason::deferred(directionReasonText, frame, int(out.framing));
    const auto readAs = [&frame, &request, &frameCrc](Dissection &d, Direction direction) {
        d.direction = direction;
        d.fields.reset(frame);
        runFraming(d, request, frameCrc);
    };
    // Reused per thread: the second reading's tree keeps its capacity, and the trees are swapped
    // rather than copied.
    thread_local Dissection other;
    other.note.clear();
    other.framing = out.framing;

    // An RTU read request (01-04) is 8 bytes: read as a request, a longer frame whose CRC is valid
    // has bytes after its 5-byte PDU, an error whatever else it holds (the PDU's trailing bytes,
    // or the RTU layer's when a valid CRC ends the request early). So when it reads as a response
    // without errors or warnings, that reading wins without the request reading (a read response
    // with its register values, the common large frame).
    const qsizetype n = frame.size();
    if (out.framing == Framing::Rtu && n > 8 && quint8(frame.at(1)) >= 0x01 && quint8(frame.at(1)) <= 0x04
        && (crcKnown ? crcValid : rtuCrcValid(frame, frameCrc))) {
        readAs(out, Direction::Response);
        if (out.fields.worstSeverity() < Severity::Warning)
            return;
        std::swap(out.fields, other.fields);
        other.direction = Direction::Response;
        other.note = out.note;
        readAs(out, Direction::Request);
        if (responseFitsBetter(count(out.fields), count(other.fields))) {
            std::swap(out.fields, other.fields);
            out.direction = Direction::Response;
        }
        return;
    }

    // Otherwise read it as a request first. A reading without errors or warnings cannot be
    // bettered (a tie is shown as a request), so unless it is an exception the response reading
    // is not needed to choose; it is made again only if the reason is read.
    readAs(out, Direction::Request);
    const int code = functionCodeOf(out);
    if (code < 0x80 && out.fields.worstSeverity() < Severity::Warning)
        return;
    readAs(other, Direction::Response);
    if (code >= 0x80) {
        // Only a response carries an exception code. The reading replaces the whole result,
        // the framing's reason included, as it always has.
        std::swap(out.fields, other.fields);
        out.direction = Direction::Response;
        out.note = other.note;
        out.framingReason.clear();
        return;
    }
    if (responseFitsBetter(count(out.fields), count(other.fields))) {
        std::swap(out.fields, other.fields);
        out.direction = Direction::Response;
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
