#include "valuekind.h"

#include <QtCore/QStringList>

namespace mbscope {

namespace {

struct KindName {
    ValueKind kind;
    const char *name;
};

constexpr KindName kKindNames[] = {
    {ValueKind::Measurement, "measurement"}, {ValueKind::Counter, "counter"},
    {ValueKind::Setting, "setting"},         {ValueKind::Status, "status"},
    {ValueKind::Enumeration, "enumeration"}, {ValueKind::Constant, "constant"},
    {ValueKind::Reserved, "reserved"},
};

} // namespace

QString valueKindName(ValueKind kind)
{
    for (const KindName &k : kKindNames) {
        if (k.kind == kind)
            return QString::fromLatin1(k.name);
    }
    return QString();
}

std::optional<ValueKind> valueKindFromName(QStringView name)
{
    for (const KindName &k : kKindNames) {
        if (name == QLatin1String(k.name))
            return k.kind;
    }
    return std::nullopt;
}

QString valueKindNames()
{
    QStringList names;
    for (const KindName &k : kKindNames)
        names.append(QString::fromLatin1(k.name));
    const QString last = names.takeLast();
    return names.join(QStringLiteral(", ")) + QStringLiteral(" or ") + last;
}

} // namespace mbscope
