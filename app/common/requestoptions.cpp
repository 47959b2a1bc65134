#include "common/requestoptions.h"

#include "common/requestnames.h"
#include "common/tabletype.h"
#include "common/targetoptions.h"

#include "protocol/adubuilder.h"
#include "protocol/hextext.h"
#include "protocol/modiconreference.h"
#include "protocol/registervalue.h"
#include "protocol/requestbuilder.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

#include <limits>

namespace mbscope::app {

namespace {

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

// typed: the number the user gave to --address (a PDU address, or counted from 1 with oneBased).
QString hintWithOption(int typed, bool oneBased)
{
    const QString modicon = ModiconReference::addressHint(typed);
    if (!modicon.isEmpty()) {
        const int pdu = ModiconReference::parse(QString::number(typed)).reference.address();
        return oneBased ? modicon + QStringLiteral(": give --address %1 with --one-based").arg(pdu + 1)
                        : modicon + QStringLiteral(": give --address %1").arg(pdu);
    }
    // A block of a manual that numbers registers from 1 starts at 1, 11, 101, 1001...; one past
    // the last PDU address (65536) is the last register counted from 1.
    if (!oneBased && typed >= 1 && typed < 10001 && typed % 10 == 1) {
        return QStringLiteral("%1 looks counted from 1, as mbpoll and many device manuals number registers; counted "
                              "from 0, as on the wire, it is PDU address %2 (0x%3): give --address %2, or --one-based "
                              "to type the manual's numbers")
            .arg(typed)
            .arg(typed - 1)
            .arg(RequestNames::hex4(typed - 1));
    }
    if (!oneBased && typed == 65536)
        return QStringLiteral("65536 is one past the last PDU address (65535) but the last register counted from 1: "
                              "give --address 65535, or --one-based to type the manual's numbers");
    return {};
}

// A refused address of 10001 or more is most often a manual's Modicon reference.
void appendAddressHint(int typed, bool oneBased, QString &error)
{
    const QString hint = hintWithOption(typed, oneBased);
    if (!hint.isEmpty())
        error += QStringLiteral("\n") + hint;
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
    , m_unit(QStringList{QStringLiteral("a"), QStringLiteral("unit")},
             QStringLiteral("Unit (slave) id 0-255 of built and completed requests (default 1; mbpoll's -a)."),
             QStringLiteral("id"), QStringLiteral("1"))
    , m_function(QStringLiteral("function"),
                 QStringLiteral("Read function: 1 coils, 2 discrete inputs, 3 holding registers, 4 input registers "
                                "(default 3)."),
                 QStringLiteral("code"), QStringLiteral("3"))
    , m_address(QStringList{QStringLiteral("r"), QStringLiteral("address")},
                QStringLiteral("First PDU address, 0-based as on the wire: decimal or 0x hex (0x79 is register 40122) "
                               "(default 0); counted from 1 with --one-based, as mbpoll's -r."),
                QStringLiteral("address"), QStringLiteral("0"))
    , m_quantity(QStringList{QStringLiteral("c"), QStringLiteral("quantity")},
                 QStringLiteral("Registers or bits to read (default 1; mbpoll's -c: with -t 3:int, 4:float... the "
                                "32-bit values)."),
                 QStringLiteral("n"),
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
    , m_table(QStringList{QStringLiteral("t"), QStringLiteral("table")},
              QStringLiteral("The table to read, as mbpoll's -t, instead of --function: 0 coils, 1 discrete inputs, 3 input "
                             "registers, 4 holding registers (the first digit of their Modicon references); 3:hex, 4:int "
                             "or 4:float show hex, 32-bit integers or floats, low word first (-B: high word first), and "
                             "then --quantity counts those 32-bit values, as mbpoll's -c does; any --format name may "
                             "follow the colon too (4:u32)."),
              QStringLiteral("type"))
    , m_bigEndian(QStringList{QStringLiteral("B"), QStringLiteral("big-endian")},
                  QStringLiteral("With -t's :int and :float, the high word first (mbpoll's -B)."))
    , m_oneBased(QStringLiteral("one-based"),
                 QStringLiteral("Addresses count registers and bits from 1, as mbpoll and many device manuals do: "
                                "--address 1 is PDU address 0. Every output then says 1-based. The default is 0-based "
                                "PDU addresses, as on the wire."))
    , m_zeroBased(QStringList{QStringLiteral("0"), QStringLiteral("zero-based")},
                  QStringLiteral("Addresses are 0-based PDU addresses (the default; mbpoll's -0)."))
{
}

void RequestOptions::addTo(QCommandLineParser &parser) const
{
    if (m_groups & Hex)
        parser.addOptions({m_hex, m_complete});
    parser.addOption(m_unit);
    if (m_groups & Read)
        parser.addOptions({m_function, m_table, m_quantity});
    if (m_groups & (Read | Write))
        parser.addOptions({m_address, m_format});
    if (m_groups & Read)
        parser.addOption(m_bigEndian);
    if (m_groups & Write)
        parser.addOptions({m_coils, m_registers, m_single});
    if (m_groups & (Read | Write))
        parser.addOptions({m_oneBased, m_zeroBased});
}

bool RequestOptions::read(const QCommandLineParser &parser, const QString &command, const TargetSettings &target,
                          RequestPlan &out, QTextStream &err) const
{
    const bool hex = (m_groups & Hex) && parser.isSet(m_hex);
    const bool write = (m_groups & Write) && (parser.isSet(m_coils) || parser.isSet(m_registers));
    const bool read = (m_groups & Read)
                      && (parser.isSet(m_function) || parser.isSet(m_table) || parser.isSet(m_quantity)
                          || (!write && parser.isSet(m_address)));
    QString error;
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);

    if (int(hex) + int(write) + int(read) > 1) {
        err << prefix << "give one kind of request: --hex, read options (--function, --quantity) or write options "
            << "(--coils, --registers), not several\n";
        return false;
    }
    bool ok = false;
    const bool oneBased = (m_groups & (Read | Write)) && parser.isSet(m_oneBased);
    if (oneBased && parser.isSet(m_zeroBased)) {
        err << prefix << "--one-based and -0/--zero-based say the contrary: give one (0-based is the default)\n";
        return false;
    }
    if (hex && (oneBased || ((m_groups & (Read | Write)) && parser.isSet(m_zeroBased)))) {
        err << prefix << (oneBased ? "--one-based" : "-0/--zero-based") << " says how --address counts, but --hex "
            << "bytes carry their PDU address as they are\n";
        return false;
    }
    out.oneBased = oneBased;
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

bool RequestOptions::readAddress(const QCommandLineParser &parser, bool oneBased, int &address, QString &error) const
{
    constexpr qint64 kIntMax = std::numeric_limits<int>::max();
    const IntegerResult typed = parseInteger(QStringLiteral("--address"), parser.value(m_address), -kIntMax, kIntMax);
    if (!typed.ok) {
        error = typed.error;
        return false;
    }
    if (oneBased && typed.value == 0) {
        error = QStringLiteral("--address 0 with --one-based: counted from 1, the first register or bit is 1 (PDU "
                               "address 0)");
        return false;
    }
    address = int(typed.value - (oneBased ? 1 : 0));
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
    IntegerResult function;
    TableType table;
    if (parser.isSet(m_table)) {
        if (parser.isSet(m_function)) {
            error = QStringLiteral("give -t/--table or --function, not both: -t 0 is --function 1 (coils), -t 1 --function "
                                   "2 (discrete inputs), -t 3 --function 4 (input registers), -t 4 --function 3 (holding "
                                   "registers)");
            return false;
        }
        table = TableType::parse(parser.value(m_table), parser.isSet(m_bigEndian));
        if (!table.ok) {
            error = table.error;
            return false;
        }
        function.value = table.functionCode;
        function.ok = true;
        if (table.format && parser.isSet(m_format)) {
            error = QStringLiteral("-t/--table %1 says how values are shown already: give --format or the suffix, not both")
                        .arg(parser.value(m_table));
            return false;
        }
    } else {
        if (parser.isSet(m_bigEndian)) {
            error = QStringLiteral("-B/--big-endian orders the words of -t's :int and :float (mbpoll's -B): with --function, "
                                   "give a --format with a byte order (f32, f32-cdab...)");
            return false;
        }
        function = parseInteger(QStringLiteral("--function"), parser.value(m_function));
    }
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
    int a = 0;
    if (!readAddress(parser, out.oneBased, a, error))
        return false;
    const IntegerResult quantity = parseInteger(QStringLiteral("--quantity"), parser.value(m_quantity), -kIntMax, kIntMax);
    if (!quantity.ok) {
        error = quantity.error;
        return false;
    }
    const bool registers = function.value >= 3;
    out.formats.clear();
    const QStringList formats = table.format ? QStringList{table.format->name()} : parser.value(m_format).split(QLatin1Char(','));
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

    // mbpoll's -c counts the values of -t 4:int and 4:float, two registers each.
    const int perValue = table.registersPerValue();
    const int q = int(qBound(-kIntMax, quantity.value * perValue, kIntMax)); // refused by the builder when large
    const QString asRegisters = perValue > 1 ? QStringLiteral(" (-c %1 values of -t %2 are %3 registers)")
                                                   .arg(quantity.value)
                                                   .arg(parser.value(m_table))
                                                   .arg(q)
                                             : QString();
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
        error += asRegisters;
        appendAddressHint(a + (out.oneBased ? 1 : 0), out.oneBased, error);
        return false;
    }
    AduOptions options;
    options.framing = url.framing();
    options.unitId = quint8(unit);
    options.transactionId = 1;
    PlannedRequest r;
    r.functionCode = quint8(function.value);
    r.unit = quint8(unit);
    r.address = a;
    r.quantity = q;
    const char *noun = RequestNames::readNoun(r.functionCode, q);
    r.oneBased = out.oneBased;
    r.description = RequestNames::describe(r.functionCode, unit, a, q, noun, out.oneBased);
    r.item = RequestItem::forLink(AduBuilder::complete(pdu.pdu, options), url, RequestNames::itemName(r.functionCode, a, q, out.oneBased));
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
    int a = 0;
    if (!readAddress(parser, out.oneBased, a, error))
        return false;
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

    const int n = int(registers ? words.size() : coils.size());
    const int typed = a + (out.oneBased ? 1 : 0);
    AduOptions options;
    options.framing = url.framing();
    options.unitId = quint8(unit);
    quint16 transactionId = 1;
    const auto plan = [&](const BuildResult &pdu, quint8 code, int at, int count) {
        options.transactionId = transactionId++;
        PlannedRequest r;
        r.functionCode = code;
        r.unit = quint8(unit);
        r.address = at;
        r.quantity = count;
        r.oneBased = out.oneBased;
        r.description = RequestNames::describe(code, unit, at, count, registers ? (count == 1 ? "register" : "registers")
                                                                  : (count == 1 ? "coil" : "coils"),
                                 out.oneBased);
        r.item = RequestItem::forLink(AduBuilder::complete(pdu.pdu, options), url, RequestNames::itemName(code, at, count, out.oneBased));
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
                appendAddressHint(typed, out.oneBased, error);
                out.requests.clear();
                return false;
            }
            plan(pdu, registers ? 0x06 : 0x05, a + i, 1);
        }
    } else {
        const BuildResult pdu = registers ? RequestBuilder::writeMultipleRegisters(a, words)
                                          : RequestBuilder::writeMultipleCoils(a, coils);
        if (!built(pdu, registers, error)) {
            appendAddressHint(typed, out.oneBased, error);
            return false;
        }
        plan(pdu, registers ? 0x10 : 0x0F, a, n);
    }
    out.summary = RequestNames::describeItems(registers ? 0x10 : 0x0F, unit, a, n,
                                registers ? (n == 1 ? "register" : "registers") : (n == 1 ? "coil" : "coils"), out.oneBased);
    out.built = true;
    return true;
}

QString addressHintFor(const PlannedRequest &request, quint8 exceptionCode, bool exception)
{
    if (!exception || exceptionCode != quint8(ExceptionCode::IllegalDataAddress) || request.functionCode == 0)
        return {};
    return hintWithOption(request.address + (request.oneBased ? 1 : 0), request.oneBased);
}

} // namespace mbscope::app
