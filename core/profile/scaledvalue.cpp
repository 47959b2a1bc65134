#include "scaledvalue.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

bool isNumericText(RegisterType type)
{
    return type == RegisterType::Hex16 || type == RegisterType::Binary16 || type == RegisterType::Ascii;
}

} // namespace

std::pair<double, double> ScaledValue::rawRange(RegisterFormat format)
{
    switch (format.type()) {
    case RegisterType::UInt16:
    case RegisterType::Hex16:
    case RegisterType::Binary16:
    case RegisterType::Ascii:
        return {0.0, 65535.0};
    case RegisterType::Int16:
        return {-32768.0, 32767.0};
    case RegisterType::UInt32:
        return {0.0, 4294967295.0};
    case RegisterType::Int32:
        return {-2147483648.0, 2147483647.0};
    case RegisterType::UInt64:
        return {0.0, 18446744073709551615.0};
    case RegisterType::Int64:
        return {-9223372036854775808.0, 9223372036854775807.0};
    case RegisterType::Float32:
        return {-double(FLT_MAX), double(FLT_MAX)};
    case RegisterType::Float64:
        return {-DBL_MAX, DBL_MAX};
    }
    return {0.0, 65535.0};
}

std::pair<double, double> ScaledValue::range() const
{
    const auto [lo, hi] = rawRange(format);
    double a = lo * scale + offset;
    double b = hi * scale + offset;
    if (a > b)
        std::swap(a, b);
    return {a, b};
}

RegisterValueResult ScaledValue::encode(double value, bool clamp) const
{
    const RegisterFormat numeric = isNumericText(format.type())
        ? RegisterFormat(RegisterType::UInt16, format.order())
        : format;
    double raw = (value - offset) / scale;
    if (numeric.isFloat()) {
        if (clamp && std::isfinite(raw)) {
            const auto [lo, hi] = rawRange(numeric);
            raw = std::clamp(raw, lo, hi);
        }
        RegisterValueResult result = RegisterValue::fromDouble(raw, numeric);
        if (result.ok && numeric != format)
            result.value = RegisterValue::fromBits(result.value.bits(), format);
        return result;
    }
    RegisterValueResult result;
    if (!std::isfinite(raw)) {
        if (!clamp) {
            result.error = QStringLiteral("%1 is not a finite number").arg(raw);
            return result;
        }
        raw = std::isnan(raw) ? 0.0 : raw;
    }
    raw = std::round(raw);
    const auto [lo, hi] = rawRange(numeric);
    if (clamp)
        raw = std::clamp(raw, lo, hi);
    if (raw < lo || raw > hi) {
        result.error = QStringLiteral("%1 is out of range for %2 (raw %3 to %4)")
                           .arg(QString::number(value, 'g', 12), format.name(), QString::number(lo, 'g', 20),
                                QString::number(hi, 'g', 20));
        return result;
    }
    // 2^63 and 2^64 are not representable as integers: the largest doubles below them are.
    if (numeric.isSigned())
        result = RegisterValue::fromSigned(raw >= 9223372036854775807.0 ? std::numeric_limits<qint64>::max()
                                                                       : qint64(raw),
                                           numeric);
    else
        result = RegisterValue::fromUnsigned(raw >= 18446744073709551615.0 ? std::numeric_limits<quint64>::max()
                                                                          : quint64(raw),
                                             numeric);
    if (result.ok && numeric != format)
        result.value = RegisterValue::fromBits(result.value.bits(), format);
    return result;
}

double ScaledValue::decode(std::span<const quint16> registers) const
{
    const RegisterValueResult r = RegisterValue::fromRegisters(registers, format);
    if (!r.ok)
        return 0;
    double raw = 0;
    if (isNumericText(format.type()))
        raw = double(r.value.bits());
    else
        raw = r.value.toDouble();
    return raw * scale + offset;
}

} // namespace mbscope
