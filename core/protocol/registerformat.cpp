#include "registerformat.h"

namespace mbscope {

namespace {

struct TypeInfo {
    RegisterType type;
    const char *name;        // canonical short name
    const char *description; // for description()
};

constexpr TypeInfo kTypes[] = {
    {RegisterType::UInt16, "u16", QT_TRANSLATE_NOOP("mbscope::Field", "unsigned 16-bit")},
    {RegisterType::Int16, "i16", QT_TRANSLATE_NOOP("mbscope::Field", "signed 16-bit")},
    {RegisterType::Hex16, "hex", QT_TRANSLATE_NOOP("mbscope::Field", "16-bit hex")},
    {RegisterType::Binary16, "bin", QT_TRANSLATE_NOOP("mbscope::Field", "16-bit binary")},
    {RegisterType::Ascii, "ascii", QT_TRANSLATE_NOOP("mbscope::Field", "ASCII, two characters per register")},
    {RegisterType::UInt32, "u32", QT_TRANSLATE_NOOP("mbscope::Field", "unsigned 32-bit")},
    {RegisterType::Int32, "i32", QT_TRANSLATE_NOOP("mbscope::Field", "signed 32-bit")},
    {RegisterType::UInt64, "u64", QT_TRANSLATE_NOOP("mbscope::Field", "unsigned 64-bit")},
    {RegisterType::Int64, "i64", QT_TRANSLATE_NOOP("mbscope::Field", "signed 64-bit")},
    {RegisterType::Float32, "f32", QT_TRANSLATE_NOOP("mbscope::Field", "float32 (IEEE 754 single)")},
    {RegisterType::Float64, "f64", QT_TRANSLATE_NOOP("mbscope::Field", "float64 (IEEE 754 double)")},
};

struct Alias {
    const char *name;
    RegisterType type;
};

constexpr Alias kAliases[] = {
    {"uint16", RegisterType::UInt16}, {"int16", RegisterType::Int16},
    {"hex16", RegisterType::Hex16},   {"binary", RegisterType::Binary16},
    {"uint32", RegisterType::UInt32}, {"int32", RegisterType::Int32},
    {"uint64", RegisterType::UInt64}, {"int64", RegisterType::Int64},
    {"float32", RegisterType::Float32}, {"float", RegisterType::Float32},
    {"float64", RegisterType::Float64}, {"double", RegisterType::Float64},
};

constexpr RegisterOrder kOrders[] = {RegisterOrder::ABCD, RegisterOrder::CDAB, RegisterOrder::BADC,
                                     RegisterOrder::DCBA};

const TypeInfo &info(RegisterType type)
{
    for (const TypeInfo &t : kTypes) {
        if (t.type == type)
            return t;
    }
    return kTypes[0];
}

// Order spellings by width; index matches kOrders.
constexpr const char *kOrderNames16[] = {"AB", "AB", "BA", "BA"};
constexpr const char *kOrderNames32[] = {"ABCD", "CDAB", "BADC", "DCBA"};
constexpr const char *kOrderNames64[] = {"ABCDEFGH", "GHEFCDAB", "BADCFEHG", "HGFEDCBA"};
constexpr const char *kOrderWords[] = {QT_TRANSLATE_NOOP("mbscope::Field", "big endian"), QT_TRANSLATE_NOOP("mbscope::Field", "word swap"), QT_TRANSLATE_NOOP("mbscope::Field", "byte swap"),
                                       QT_TRANSLATE_NOOP("mbscope::Field", "little endian")};

const char *orderSpelling(int registers, RegisterOrder order)
{
    const auto i = size_t(order);
    if (registers == 1)
        return kOrderNames16[i];
    if (registers == 2)
        return kOrderNames32[i];
    return kOrderNames64[i];
}

QString expectedTypes()
{
    return QStringLiteral("u16, i16, hex, bin, ascii, u32, i32, u64, i64, f32 or f64, optionally followed by "
                          "an order as in f32-cdab");
}

QString expectedOrders(RegisterType type)
{
    switch (RegisterFormat::registerCount(type)) {
    case 1:
        return QStringLiteral("ab or ba");
    case 2:
        return QStringLiteral("abcd, cdab, badc or dcba");
    default:
        return QStringLiteral("abcdefgh, ghefcdab, badcfehg or hgfedcba (or abcd, cdab, badc, dcba)");
    }
}

bool matchType(QStringView token, RegisterType *type)
{
    for (const TypeInfo &t : kTypes) {
        if (token == QLatin1String(t.name)) {
            *type = t.type;
            return true;
        }
    }
    for (const Alias &a : kAliases) {
        if (token == QLatin1String(a.name)) {
            *type = a.type;
            return true;
        }
    }
    return false;
}

bool matchOrder(QStringView token, RegisterType type, RegisterOrder *order)
{
    const int registers = RegisterFormat::registerCount(type);
    for (size_t i = 0; i < std::size(kOrders); ++i) {
        bool match = false;
        if (registers == 1)
            match = token.compare(QLatin1String(kOrderNames16[i]), Qt::CaseInsensitive) == 0;
        else if (registers == 2)
            match = token.compare(QLatin1String(kOrderNames32[i]), Qt::CaseInsensitive) == 0;
        else
            match = token.compare(QLatin1String(kOrderNames64[i]), Qt::CaseInsensitive) == 0
                || token.compare(QLatin1String(kOrderNames32[i]), Qt::CaseInsensitive) == 0;
        if (match) {
            *order = kOrders[i];
            return true;
        }
    }
    return false;
}

RegisterFormatResult failed(QString why)
{
    RegisterFormatResult result;
    result.error = std::move(why);
    return result;
}

} // namespace

QString RegisterFormat::typeName() const
{
    return QLatin1String(info(m_type).name);
}

QString RegisterFormat::orderName() const
{
    return QLatin1String(orderSpelling(registerCount(), m_order));
}

QString RegisterFormat::name() const
{
    if (registerCount() == 1)
        return m_order == RegisterOrder::ABCD ? typeName() : typeName() + QLatin1String("-ba");
    return typeName() + QLatin1Char('-') + orderName().toLower();
}

const char *RegisterFormat::typeDescription() const
{
    return info(m_type).description;
}

const char *RegisterFormat::orderWords() const
{
    if (registerCount() == 1)
        return m_order == RegisterOrder::ABCD ? QT_TRANSLATE_NOOP("mbscope::Field", "high byte first") : QT_TRANSLATE_NOOP("mbscope::Field", "byte swap");
    return kOrderWords[size_t(m_order)];
}

QString RegisterFormat::description() const
{
    const QString order = registerCount() == 1
        ? (m_order == RegisterOrder::ABCD ? QStringLiteral("high byte first (AB)")
                                          : QStringLiteral("byte swap (BA)"))
        : QLatin1String(kOrderWords[size_t(m_order)]) + QLatin1String(" (") + orderName() + QLatin1Char(')');
    return QLatin1String(info(m_type).description) + QLatin1String(", ") + order;
}

RegisterFormatResult RegisterFormat::parse(QStringView name)
{
    const QString text = name.trimmed().toString().toLower();
    if (text.isEmpty())
        return failed(QStringLiteral("the register format is empty: expected ") + expectedTypes());

    const qsizetype dash = text.indexOf(QLatin1Char('-'));
    const QStringView typeToken = dash < 0 ? QStringView(text) : QStringView(text).first(dash);
    RegisterType type = RegisterType::UInt16;
    if (!matchType(typeToken, &type)) {
        QString why = QLatin1Char('\'') + name.trimmed().toString() + QLatin1String("' is not a register format: ");
        if (dash >= 0)
            why += QLatin1Char('\'') + typeToken.toString() + QLatin1String("' is not a type; ");
        return failed(why + QLatin1String("expected ") + expectedTypes());
    }

    RegisterOrder order = RegisterOrder::ABCD;
    if (dash >= 0) {
        const QStringView orderToken = QStringView(text).sliced(dash + 1);
        if (!matchOrder(orderToken, type, &order)) {
            return failed(QLatin1Char('\'') + name.trimmed().toString() + QLatin1String("' is not a register format: ")
                          + QLatin1String(info(type).name) + QLatin1String(" takes the order ")
                          + expectedOrders(type) + QLatin1String(", not '") + orderToken.toString()
                          + QLatin1Char('\''));
        }
    }

    RegisterFormatResult result;
    result.format = RegisterFormat(type, order);
    result.ok = true;
    return result;
}

QList<RegisterFormat> RegisterFormat::all()
{
    QList<RegisterFormat> formats;
    formats.reserve(34);
    for (const TypeInfo &t : kTypes) {
        if (registerCount(t.type) == 1) {
            formats.append(RegisterFormat(t.type, RegisterOrder::ABCD));
            formats.append(RegisterFormat(t.type, RegisterOrder::BADC));
        } else {
            for (RegisterOrder order : kOrders)
                formats.append(RegisterFormat(t.type, order));
        }
    }
    return formats;
}

} // namespace mbscope
