// libFuzzer target over delimited protocols (issue 15): the pattern table's reader and the
// responder. Byte 0 chooses what the rest is:
//   even: a profile's "delimited" object as JSON text, read by ProfileLoader; when it loads,
//         a few fixed frames go through LineResponder against it (any pattern, any template);
//   odd:  one frame received, answered by the shipped scada-rs485 table (compiled in).
// Nothing may crash or hang; a scada-rs485 answer always runs from '$' to '#', and a frame that
// does not match a rule whole is never answered.
#include "profile/profileloader.h"
#include "sim/lineresponder.h"
#include "sim/profileapplier.h"
#include "sim/simunit.h"

#include <QtCore/QObject>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

LineAnswer answer(const DeviceProfile &profile, const QList<SimUnit *> &units, QByteArrayView frame)
{
    return LineResponder::respond(profile.delimited, frame, [&units](int id) -> SimUnit * {
        for (SimUnit *u : units) {
            if (id < 0 || u->id() == id)
                return u;
        }
        return nullptr;
    });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 1)
        return 0;
    const QByteArray rest(reinterpret_cast<const char *>(data + 1), qsizetype(size - 1));
    QObject owner;
    if (data[0] % 2 == 0) {
        const QByteArray json = R"({"name": "fuzz", "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 8}],
            "coils": [{"address": 0, "count": 8}]}}], "delimited": )" + rest + "}";
        const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("fuzz"));
        if (!r.ok)
            return 0;
        const QList<SimUnit *> units = ProfileApplier::createUnits(r.profile, &owner);
        for (const char *frame : {"$01R#", "$01WB11#", "\x05" "00RSS\x04", "", "{{}}", "#$"})
            (void)answer(r.profile, units, QByteArrayView(frame));
        (void)answer(r.profile, units, rest);
        return 0;
    }
    static const ProfileLoadResult scada = ProfileLoader::load(QStringLiteral("scada-rs485"));
    check(scada.ok);
    const QList<SimUnit *> units = ProfileApplier::createUnits(scada.profile, &owner);
    const LineAnswer a = answer(scada.profile, units, rest);
    if (a.answers) {
        check(a.matched);
        check(a.bytes.startsWith('$') && a.bytes.endsWith('#'));
        check(rest.startsWith('$') && rest.endsWith('#'));
    }
    return 0;
}
