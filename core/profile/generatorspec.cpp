#include "generatorspec.h"

namespace mbscope {

namespace {

struct KindName {
    GeneratorSpec::Kind kind;
    const char *name;
};

constexpr KindName kKindNames[] = {
    {GeneratorSpec::Kind::Constant, "constant"},
    {GeneratorSpec::Kind::Counter, "counter"},
    {GeneratorSpec::Kind::RandomWalk, "randomWalk"},
    {GeneratorSpec::Kind::Sine, "sine"},
    {GeneratorSpec::Kind::Poisson, "poisson"},
    {GeneratorSpec::Kind::Copy, "copy"},
};

} // namespace

QString GeneratorSpec::kindName(Kind kind)
{
    for (const KindName &k : kKindNames) {
        if (k.kind == kind)
            return QString::fromLatin1(k.name);
    }
    return QString();
}

std::optional<GeneratorSpec::Kind> GeneratorSpec::kindFromName(QStringView name)
{
    for (const KindName &k : kKindNames) {
        if (name == QLatin1String(k.name))
            return k.kind;
    }
    return std::nullopt;
}

} // namespace mbscope
