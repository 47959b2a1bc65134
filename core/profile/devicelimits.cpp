#include "devicelimits.h"

#include <QtCore/QtGlobal>

#include <cmath>

namespace mbscope {

QString DeviceLimits::unknownUnitName(UnknownUnit policy)
{
    switch (policy) {
    case UnknownUnit::FirstUnit: return QStringLiteral("first");
    case UnknownUnit::Exception: return QStringLiteral("exception");
    case UnknownUnit::Silent: return QStringLiteral("silent");
    case UnknownUnit::Auto: break;
    }
    return QStringLiteral("auto");
}

QString DeviceLimits::functionKey(int code)
{
    return QStringLiteral("0x%1").arg(code, 2, 16, QLatin1Char('0')).toUpper().replace(QLatin1String("0X"), QLatin1String("0x"));
}

std::chrono::milliseconds DeviceLimits::clientGap() const
{
    return std::chrono::milliseconds(minGapMs > 0 ? qint64(std::ceil(minGapMs + 1)) : 0);
}

std::chrono::milliseconds DeviceLimits::clientWarmUp() const
{
    return std::chrono::milliseconds(warmUpMs > 0 ? qint64(std::ceil(warmUpMs + qMax(2.0, warmUpMs / 10))) : 0);
}

std::optional<int> DeviceLimits::parseFunctionKey(const QString &key)
{
    bool ok = false;
    const int code = key.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? key.mid(2).toInt(&ok, 16) : key.toInt(&ok, 10);
    return ok ? std::optional<int>(code) : std::nullopt;
}

} // namespace mbscope
