#include "requestoptions.h"

#include "targetoptions.h"

#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"
#include "protocol/hextext.h"
#include "protocol/modiconreference.h"
#include "protocol/registervalue.h"
#include "protocol/requestbuilder.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

#include <limits>

namespace mbscope::app {

namespace {

// The Modicon references of a run of items: "40122-40143", or "40122" for one.
QString referenceRange(quint8 functionCode, int address, int quantity)
{
    const auto table = ModiconReference::tableOf(functionCode);
    if (!table || address < 0 || quantity < 1 || address + quantity - 1 > 0xFFFF)
        return {};
    const ModiconReference first(*table, quint16(address));
    const ModiconReference last(*table, quint16(address + quantity - 1));
    const bool five = last.hasFiveDigitForm();
    const QString a = five ? first.fiveDigit() : first.sixDigit();
    const QString b = five ? last.fiveDigit() : last.sixDigit();
    return quantity == 1 ? a : a + QLatin1Char('-') + b;
}

// "unit 1, 22 registers at 121 (0x0079), 40122-40143"
QString describeItems(quint8 functionCode, int unit, int address, int quantity, const char *items)
{
    QString text = QStringLiteral("unit %1, %2 %3 at %4 (0x%5)")
                       .arg(unit)
                       .arg(quantity)
                       .arg(QLatin1String(items))
                       .arg(address)
                       .arg(QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0')));
    const QString refs = referenceRange(functionCode, address, quantity);
    if (!refs.isEmpty())
        text += QStringLiteral(", ") + refs;
    return text;
}

QString describe(quint8 functionCode, int unit, int address, int quantity, const char *items)
{
    return QString::fromLatin1(functionName(functionCode)) + QStringLiteral(", ")
           + describeItems(functionCode, unit, address, quantity, items);
}

// RequestBuilder names its parameters; the user knows the options.
QString optionFor(const QString &parameter, bool registers)
{
    if (parameter == QLatin1String("startAddress") || parameter == QLatin1String("address"))
        return QStringLiteral("--address");
    if (parameter == QLatin1String("quantity"))
        return QStringLiteral("--quantity");
    if (parameter == QLatin1String("values") || parameter == QLatin1String("value"))
        return registers ? QStringLiteral("--registers") : QStringLiteral("--coils");
    return QStringLiteral("--") + parameter;
}

bool built(const BuildResult &result, bool registers, QString &error)
{
    if (result.isValid())
        return true;
    QStringList lines;
    for (const BuildError &e : result.errors)
        lines.append(optionFor(e.parameter, registers) + QStringLiteral(": ") + e.message);
    lines.removeDuplicates();
    error = lines.join(QStringLiteral("\n"));
    return false;
}

QString hintWithOption(int address)
{
    const QString hint = ModiconReference::addressHint(address);
    if (hint.isEmpty())
        return {};
    return hint + QStringLiteral(": give --address %1").arg(ModiconReference::parse(QString::number(address)).reference.address());
}

// A refused address of 10001 or more is most often a manual's Modicon reference.
void appendAddressHint(int address, QString &error)
{
    const QString hint = hintWithOption(address);
    if (!hint.isEmpty())
        error += QStringLiteral("\n") + hint;
}

QString hexName(const QByteArray &bytes)
{
    HexText::FormatOptions options;
    QString text = HexText::format(bytes.left(16), options);
    if (bytes.size() > 16)
        text += QStringLiteral(" ... (%1 bytes)").arg(bytes.size());
    return text;
}

} // namespace

RequestOptions::RequestOptions(int groups, bool repeatHex)
    : m_groups(groups)
    , m_repeatHex(repeatHex)
    , m_hex(QStringLiteral("hex"),
            repeatHex ? QStringLiteral("Bytes to send, exactly as given (\"01 03 00 79 00 16 15 DD\"), but for an MBAP "
                                       "transaction id: each request gets the connection's next one; repeat for several "
                                       "requests per cycle. On an ASCII link the frame may be typed as its characters.")
                      : QStringLiteral("Bytes to send, exactly as given (\"01 03 00 79 00 16 15 DD\"). On an ASCII link "
                                       "the frame may be typed as its characters (\":0103...\")."),
            QStringLiteral("hex"))
    , m_complete(QStringLiteral("complete"),
                 QStringLiteral("--hex is a PDU (function code first): add the MBAP header, or the unit id and CRC/LRC, "
                                "as the target's framing needs (unit from --unit)."))
    , m_unit(QStringLiteral("unit"), QStringLiteral("Unit (slave) id 0-255 of built and completed requests (default 1)."),
             QStringLiteral("id"), QStringLiteral("1"))
    , m_function(QStringLiteral("function"),
                 QStringLiteral("Read function: 1 coils, 2 discrete inputs, 3 holding registers, 4 input registers "
                                "(default 3)."),
                 QStringLiteral("code"), QStringLiteral("3"))
    , m_address(QStringLiteral("address"),
                QStringLiteral("First PDU address, 0-based as on the wire: decimal or 0x hex (0x79 is register 40122) "
                               "(default 0)."),
                QStringLiteral("address"), QStringLiteral("0"))
    , m_quantity(QStringLiteral("quantity"), QStringLiteral("Registers or bits to read (default 1)."), QStringLiteral("n"),
                 QStringLiteral("1"))
    , m_format(QStringLiteral("format"),
               groups & Read ? QStringLiteral("How register values are shown, one or more separated by commas: u16, i16, hex, "
                                              "bin, ascii, u32, i32, u64, i64, f32, f64, with a byte order: f32-cdab, "
                                              "i16-ba... (default u16).")
                             : QStringLiteral("How --registers values are read: u16, i16, hex, bin, ascii, u32, i32, f32, "
                                              "f64... with a byte order: f32-cdab (default u16)."),
               QStringLiteral("formats"), QStringLiteral("u16"))
    , m_coils(QStringLiteral("coils"), QStringLiteral("Coil values to write from --address: 1,0,0 (1/0, on/off, true/false)."),
              QStringLiteral("values"))
    , m_registers(QStringLiteral("registers"),
                  QStringLiteral("Register values to write from --address: 205,172,73 (typed as --format says)."),
                  QStringLiteral("values"))
    , m_single(QStringLiteral("single"),
               QStringLiteral("Write with Write Single Coil (05) / Write Single Register (06), one request per value, "
                              "instead of 15 / 16."))
{
}

void RequestOptions::addTo(QCommandLineParser &parser) const
{
    if (m_groups & Hex)
        parser.addOptions({m_hex, m_complete});
    parser.addOption(m_unit);
    if (m_groups & Read)
        parser.addOptions({m_function, m_quantity});
    if (m_groups & (Read | Write))
        parser.addOptions({m_address, m_format});
    if (m_groups & Write)
        parser.addOptions({m_coils, m_registers, m_single});
}

bool RequestOptions::read(const QCommandLineParser &parser, const QString &command, const TargetSettings &target,
                          RequestPlan &out, QTextStream &err) const
{
    const bool hex = (m_groups & Hex) && parser.isSet(m_hex);
    const bool write = (m_groups & Write) && (parser.isSet(m_coils) || parser.isSet(m_registers));
    const bool read = (m_groups & Read)
                      && (parser.isSet(m_function) || parser.isSet(m_quantity) || (!write && parser.isSet(m_address)));
    QString error;
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);

    if (int(hex) + int(write) + int(read) > 1) {
        err << prefix << "give one kind of request: --hex, read options (--function, --quantity) or write options "
            << "(--coils, --registers), not several\n";
        return false;
    }
    bool ok = false;
    if (hex) {
        ok = readHex(parser, target, out, error);
    } else if (write) {
        ok = readWrite(parser, target, out, error);
    } else if (read || m_groups == Read) {
        ok = readRead(parser, target, out, error);
    } else if (m_groups == (Hex | Read | Write)) {
        error = QStringLiteral("nothing to send: give --hex HEX (repeat it for several requests), read options "
                               "(--function 3 --address 0 --quantity 10) or write options (--coils 1,0 or "
                               "--registers 205,172 with --address)");
    } else if (m_groups & Write) {
        error = QStringLiteral("nothing to write: give --coils 1,0,1 or --registers 205,172,73");
    } else {
        error = QStringLiteral("--hex is required: the bytes to send, e.g. --hex \"01 03 00 79 00 16 15 DD\"");
    }
    if (!ok) {
        // A caret line under a typo ("  01 0G") keeps its alignment: no prefix there.
        for (const QString &line : error.split(QLatin1Char('\n')))
            err << (line.startsWith(QLatin1String("  ")) ? QString() : prefix) << line << '\n';
        return false;
    }
    // One request sent as typed keeps its MBAP transaction id; requests mbscope builds or
    // completes, and a poll's, which go out again and again, get the connection's next id from
    // the engine (a late answer then cannot pass for the next request's).
    const bool asTyped = hex && !parser.isSet(m_complete) && !m_repeatHex;
    for (PlannedRequest &r : out.requests) {
        r.item.timeoutMs = target.timeoutMs;
        r.item.retries = target.retries;
        r.item.engineNumbered = !asTyped;
    }
    return true;
}

bool RequestOptions::readUnit(const QCommandLineParser &parser, int &unit, QString &error) const
{
    const IntegerResult u = parseInteger(QStringLiteral("--unit"), parser.value(m_unit), 0, 255,
                                         QStringLiteral("0 broadcasts on serial links"));
    if (!u.ok) {
        error = u.error;
        return false;
    }
    unit = int(u.value);
    return true;
}

bool RequestOptions::readHex(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                             QString &error) const
{
    const LinkUrl &url = target.url;
    const bool complete = parser.isSet(m_complete);
    int unit = 1;
    if (complete) {
        if (url.delimited.enabled) {
            error = QStringLiteral("--complete adds a Modbus header or checksum, but %1 uses delimited framing: "
                                   "give the whole frame in --hex")
                        .arg(url.toString());
            return false;
        }
        if (!readUnit(parser, unit, error))
            return false;
    } else if (parser.isSet(m_unit)) {
        error = QStringLiteral("--unit applies to built requests and to --complete: the unit of --hex bytes sent as "
                               "they are is in the bytes");
        return false;
    }
    // A poll prints the values of the answers to --hex reads too (--print values), so --format
    // counts for them.
    if (m_groups & Read) {
        out.formats.clear();
        for (const QString &name : parser.value(m_format).split(QLatin1Char(','))) {
            const RegisterFormatResult f = RegisterFormat::parse(name);
            if (!f.ok) {
                error = QStringLiteral("--format: ") + f.error;
                return false;
            }
            out.formats.append(f.format);
        }
    }
    const QStringList texts = parser.values(m_hex);
    if (!m_repeatHex && texts.size() > 1) {
        error = QStringLiteral("--hex is given %1 times: give the bytes once").arg(texts.size());
        return false;
    }
    quint16 transactionId = 1;
    for (qsizetype i = 0; i < texts.size(); ++i) {
        const bool asciiCharacters = !complete && !url.delimited.enabled && url.framing() == Framing::Ascii;
        const FrameTextResult frame = parseFrameText(texts.at(i), asciiCharacters);
        const QString which = texts.size() > 1 ? QStringLiteral("--hex #%1").arg(i + 1) : QStringLiteral("--hex");
        if (!frame.ok) {
            error = which + QStringLiteral(": ") + frame.error;
            return false;
        }
        QByteArray bytes = frame.bytes;
        if (complete) {
            AduOptions options;
            options.framing = url.framing();
            options.unitId = quint8(unit);
            options.transactionId = transactionId++;
            bytes = AduBuilder::complete(bytes, options);
        }
        PlannedRequest r;
        r.item = RequestItem::forLink(bytes, url, hexName(bytes));
        r.description = complete ? QStringLiteral("PDU %1 completed for %2").arg(hexName(frame.bytes), framingName(url.framing()))
                                 : QStringLiteral("%1 bytes as given").arg(bytes.size());
        out.requests.append(r);
    }
    return true;
}

bool RequestOptions::readRead(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                              QString &error) const
{
    const LinkUrl &url = target.url;
    int unit = 1;
    if (!readUnit(parser, unit, error))
        return false;
    if (unit == 0 && (url.framing() == Framing::Rtu || url.framing() == Framing::Ascii) && !url.delimited.enabled) {
        // Serial Line V1.02, 2.1: every unit acts on a broadcast and none answers it.
        error = QStringLiteral("--unit 0 is the broadcast address on %1 framing (%2): no unit answers a broadcast, so a read "
                               "can return nothing (broadcasts are for writes only: MODBUS over Serial Line V1.02, 2.1); "
                               "give the unit's own address, 1-247")
                    .arg(framingName(url.framing()).toUpper(), url.toString());
        return false;
    }
    const IntegerResult function = parseInteger(QStringLiteral("--function"), parser.value(m_function));
    if (!function.ok) {
        error = function.error;
        return false;
    }
    if (function.value < 1 || function.value > 4) {
        error = QStringLiteral("--function %1 is not a read: expected 1 (coils), 2 (discrete inputs), 3 (holding "
                               "registers) or 4 (input registers)%2")
                    .arg(parser.value(m_function),
                         m_groups & Hex ? QStringLiteral("; other requests can be sent with --hex") : QString());
        return false;
    }
    constexpr qint64 kIntMax = std::numeric_limits<int>::max();
    const IntegerResult address = parseInteger(QStringLiteral("--address"), parser.value(m_address), -kIntMax, kIntMax);
    const IntegerResult quantity = parseInteger(QStringLiteral("--quantity"), parser.value(m_quantity), -kIntMax, kIntMax);
    for (const IntegerResult *r : {&address, &quantity}) {
        if (!r->ok) {
            error = r->error;
            return false;
        }
    }
    const bool registers = function.value >= 3;
    out.formats.clear();
    const QStringList formats = parser.value(m_format).split(QLatin1Char(','));
    if (!registers && parser.isSet(m_format)) {
        error = QStringLiteral("--format applies to registers (functions 3 and 4); coils and discrete inputs are "
                               "shown as ON/OFF");
        return false;
    }
    for (const QString &name : formats) {
        const RegisterFormatResult f = RegisterFormat::parse(name);
        if (!f.ok) {
            error = QStringLiteral("--format: ") + f.error;
            return false;
        }
        out.formats.append(f.format);
    }
    if (url.delimited.enabled) {
        error = QStringLiteral("%1 uses delimited framing, which carries no Modbus requests: send its frames with --hex")
                    .arg(url.toString());
        return false;
    }

    const int a = int(address.value);
    const int q = int(quantity.value);
    // A format wider than the registers read would print a blank column: said instead.
    for (const RegisterFormat &f : std::as_const(out.formats)) {
        if (registers && q >= 1 && f.registerCount() > q) {
            error = QStringLiteral("--format %1 needs %2 registers for one value, but --quantity %3 reads only %3: give "
                                   "--quantity %2 or more")
                        .arg(f.name())
                        .arg(f.registerCount())
                        .arg(q);
            return false;
        }
    }
    BuildResult pdu;
    switch (function.value) {
    case 1: pdu = RequestBuilder::readCoils(a, q); break;
    case 2: pdu = RequestBuilder::readDiscreteInputs(a, q); break;
    case 3: pdu = RequestBuilder::readHoldingRegisters(a, q); break;
    default: pdu = RequestBuilder::readInputRegisters(a, q); break;
    }
    if (!built(pdu, registers, error)) {
        appendAddressHint(a, error);
        return false;
    }
    AduOptions options;
    options.framing = url.framing();
    options.unitId = quint8(unit);
    options.transactionId = 1;
    PlannedRequest r;
    r.functionCode = quint8(function.value);
    r.address = a;
    r.quantity = q;
    const char *noun = registers ? (q == 1 ? "register" : "registers")
                       : function.value == 1 ? (q == 1 ? "coil" : "coils")
                                             : (q == 1 ? "discrete input" : "discrete inputs");
    r.description = describe(r.functionCode, unit, a, q, noun);
    r.item = RequestItem::forLink(AduBuilder::complete(pdu.pdu, options), url,
                                  QStringLiteral("%1 %2 x%3").arg(QString::fromLatin1(functionName(r.functionCode))).arg(a).arg(q));
    out.requests.append(r);
    out.summary = r.description;
    out.built = true;
    return true;
}

bool RequestOptions::readWrite(const QCommandLineParser &parser, const TargetSettings &target, RequestPlan &out,
                               QString &error) const
{
    const LinkUrl &url = target.url;
    if (parser.isSet(m_coils) && parser.isSet(m_registers)) {
        error = QStringLiteral("give --coils or --registers, not both: each write is one table");
        return false;
    }
    int unit = 1;
    if (!readUnit(parser, unit, error))
        return false;
    constexpr qint64 kIntMax = std::numeric_limits<int>::max();
    const IntegerResult address = parseInteger(QStringLiteral("--address"), parser.value(m_address), -kIntMax, kIntMax);
    if (!address.ok) {
        error = address.error;
        return false;
    }
    if (url.delimited.enabled) {
        error = QStringLiteral("%1 uses delimited framing, which carries no Modbus requests: send its frames with --hex")
                    .arg(url.toString());
        return false;
    }
    const bool registers = parser.isSet(m_registers);
    const bool single = parser.isSet(m_single);
    const QStringList items = parser.value(registers ? m_registers : m_coils).split(QLatin1Char(','));
    const QString option = registers ? QStringLiteral("--registers") : QStringLiteral("--coils");

    QList<bool> coils;
    QList<quint16> words;
    if (registers) {
        const RegisterFormatResult f = RegisterFormat::parse(parser.value(m_format));
        if (!f.ok) {
            error = QStringLiteral("--format: ") + f.error;
            return false;
        }
        out.formats = {f.format};
        for (qsizetype i = 0; i < items.size(); ++i) {
            const RegisterValueResult v = RegisterValue::fromText(items.at(i).trimmed(), f.format);
            if (!v.ok) {
                error = QStringLiteral("%1 value %2 of %3: %4").arg(option).arg(i + 1).arg(items.size()).arg(v.error);
                return false;
            }
            words.append(v.value.registers());
        }
    } else {
        if (parser.isSet(m_format)) {
            error = QStringLiteral("--format applies to --registers; coils are 1 or 0");
            return false;
        }
        for (qsizetype i = 0; i < items.size(); ++i) {
            const QString t = items.at(i).trimmed().toLower();
            if (t == QLatin1String("1") || t == QLatin1String("on") || t == QLatin1String("true")) {
                coils.append(true);
            } else if (t == QLatin1String("0") || t == QLatin1String("off") || t == QLatin1String("false")) {
                coils.append(false);
            } else {
                error = QStringLiteral("--coils value %1 of %2 '%3' is not a coil value: expected 1 or 0 (on/off, "
                                       "true/false), separated by commas")
                            .arg(i + 1)
                            .arg(items.size())
                            .arg(items.at(i));
                return false;
            }
        }
    }

    const int a = int(address.value);
    const int n = int(registers ? words.size() : coils.size());
    AduOptions options;
    options.framing = url.framing();
    options.unitId = quint8(unit);
    quint16 transactionId = 1;
    const auto plan = [&](const BuildResult &pdu, quint8 code, int at, int count) {
        options.transactionId = transactionId++;
        PlannedRequest r;
        r.functionCode = code;
        r.address = at;
        r.quantity = count;
        r.description = describe(code, unit, at, count, registers ? (count == 1 ? "register" : "registers")
                                                                  : (count == 1 ? "coil" : "coils"));
        r.item = RequestItem::forLink(AduBuilder::complete(pdu.pdu, options), url,
                                      QStringLiteral("%1 %2 x%3").arg(QString::fromLatin1(functionName(code))).arg(at).arg(count));
        if (registers)
            r.registers = words.mid(at - a, count);
        else
            r.coils = coils.mid(at - a, count);
        out.requests.append(r);
    };
    if (single) {
        for (int i = 0; i < n; ++i) {
            const BuildResult pdu = registers ? RequestBuilder::writeSingleRegister(a + i, words.at(i))
                                              : RequestBuilder::writeSingleCoil(a + i, bool(coils.at(i)));
            if (!built(pdu, registers, error)) {
                if (n > 1)
                    error = QStringLiteral("value %1 of %2: ").arg(i + 1).arg(n) + error;
                appendAddressHint(a, error);
                out.requests.clear();
                return false;
            }
            plan(pdu, registers ? 0x06 : 0x05, a + i, 1);
        }
    } else {
        const BuildResult pdu = registers ? RequestBuilder::writeMultipleRegisters(a, words)
                                          : RequestBuilder::writeMultipleCoils(a, coils);
        if (!built(pdu, registers, error)) {
            appendAddressHint(a, error);
            return false;
        }
        plan(pdu, registers ? 0x10 : 0x0F, a, n);
    }
    out.summary = describeItems(registers ? 0x10 : 0x0F, unit, a, n,
                                registers ? (n == 1 ? "register" : "registers") : (n == 1 ? "coil" : "coils"));
    out.built = true;
    return true;
}

FrameTextResult parseFrameText(const QString &text, bool asciiCharacters)
{
    FrameTextResult result;
    if (asciiCharacters && text.trimmed().startsWith(QLatin1Char(':'))) {
        QByteArray frame = text.trimmed().toLatin1();
        frame.replace("\\r\\n", "\r\n");
        if (!frame.endsWith("\r\n"))
            frame += "\r\n";
        result.bytes = frame;
        result.ok = true;
        return result;
    }
    const HexTextResult parsed = HexText::parse(text);
    if (!parsed.ok) {
        result.error = parsed.error.message;
        const QStringList lines = text.split(QLatin1Char('\n'));
        if (parsed.error.line >= 1 && parsed.error.line <= lines.size()) {
            result.error += QStringLiteral("\n  ") + lines.at(parsed.error.line - 1) + QStringLiteral("\n  ")
                            + QString(qMax(0, parsed.error.column - 1), QLatin1Char(' ')) + QLatin1Char('^');
        }
        return result;
    }
    result.bytes = parsed.bytes;
    result.ok = true;
    return result;
}

QString addressHintFor(const PlannedRequest &request, quint8 exceptionCode, bool exception)
{
    if (!exception || exceptionCode != quint8(ExceptionCode::IllegalDataAddress) || request.functionCode == 0)
        return {};
    return hintWithOption(request.address);
}

} // namespace mbscope::app
