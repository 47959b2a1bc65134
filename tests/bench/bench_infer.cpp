// How good mbscope infer is (issue 28): each realistic device profile (resources/profiles:
// sdm630-meter, em340-meter, sunspec-inverter, heatpump-controller) is served by `mbscope
// simulate`, `mbscope infer` maps and samples it as a user would (a map scan, then --samples at
// --interval), and its guesses are compared with the profile, value by value:
//   type+order  the guess starts at the value's address, spans its registers and reads the same
//               numbers: the same format, or formats that agree on every value seen (u16 and i16
//               while the sign bit stays clear, u16/hex/bin); strings: ascii of the same length;
//               bits: a bit. "exact" counts only the same type name.
//   scale       numeric register values whose guessed scale is the profile's.
//   const->meas values that never move in the profile (declared constant, or no kind and no
//               generator or a constant one) that the guess calls a measurement.
// Goals: type+order >= 90 %, scale >= 80 %, const->meas 0. --check fails the run when a goal is
// missed. Usage: bench_infer [--samples 40] [--interval 500] [--device NAME] [--check]

#include "benchprocess.h"

#include "profile/profileloader.h"
#include "protocol/registerformat.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QMap>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QTextStream>

#include <cmath>
#include <cstdio>

using namespace mbscope;
using namespace mbscope::bench;

namespace {

struct Device {
    const char *name;
    const char *addresses; // where the map scan searches
    const char *tables;
};

constexpr Device kDevices[] = {
    {"sdm630-meter", "0-99", "3,4"},
    {"em340-meter", "0-99", "3,4"},
    {"sunspec-inverter", "40000-40149", "3"},
    {"heatpump-controller", "0-2599", "2,3,4"},
};

struct Figures {
    int values = 0;
    int typeRight = 0;
    int typeExact = 0;
    int numeric = 0;
    int scaleRight = 0;
    int constants = 0;
    int constantsAsMeasurements = 0;
    QStringList misses;
};

quint8 functionOf(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return 1;
    case SimTable::DiscreteInputs: return 2;
    case SimTable::InputRegisters: return 4;
    case SimTable::HoldingRegisters: return 3;
    }
    return 3;
}

bool sixteenBitUnsignedFamily(RegisterType t)
{
    return t == RegisterType::UInt16 || t == RegisterType::Hex16 || t == RegisterType::Binary16;
}

// Whether the guess reads the same numbers as the truth, given the range the guess saw.
bool sameNumbers(RegisterFormat truth, RegisterFormat guess, double rawMin, double rawMax)
{
    if (truth == guess)
        return true;
    if (truth.registerCount() != guess.registerCount() || truth.order() != guess.order() || truth.isFloat() || guess.isFloat())
        return false;
    const RegisterType a = truth.type();
    const RegisterType b = guess.type();
    if (sixteenBitUnsignedFamily(a) && sixteenBitUnsignedFamily(b))
        return true;
    const double signBit = std::ldexp(1.0, 16 * truth.registerCount() - 1);
    // Signed and unsigned of one width agree while the values stay below the sign bit.
    if (truth.isSigned() != guess.isSigned()) {
        return guess.isSigned() ? rawMin >= 0 : rawMax < signBit;
    }
    return sixteenBitUnsignedFamily(a) == sixteenBitUnsignedFamily(b) && truth.registerCount() == 1;
}

Figures compare(const DeviceProfile &profile, const QJsonObject &inferred)
{
    QMap<QPair<int, int>, QJsonObject> guesses; // (function, address)
    for (const QJsonValue &b : inferred.value(QStringLiteral("blocks")).toArray()) {
        const int function = b.toObject().value(QStringLiteral("function")).toInt();
        for (const QJsonValue &v : b.toObject().value(QStringLiteral("values")).toArray())
            guesses.insert({function, v.toObject().value(QStringLiteral("address")).toInt()}, v.toObject());
    }
    Figures f;
    for (const TableEntry &e : profile.units.constFirst().entries) {
        const int function = functionOf(e.table);
        // Still: declared constant, or neither declared to move nor moved by a generator (a value
        // a unit's script computes says its kind).
        const bool still = e.kind == ValueKind::Constant
            || (e.kind == ValueKind::Unspecified && (!e.generator || e.generator->kind == GeneratorSpec::Kind::Constant));
        const bool bits = isBitTable(e.table);
        const bool text = !bits && e.format.type() == RegisterType::Ascii && e.count > 1;
        const int values = text ? 1 : e.valueCount();
        for (int i = 0; i < values; ++i) {
            const int address = e.address + i * (text ? e.count : e.width());
            const QString where = QStringLiteral("%1 %2 (%3)").arg(function).arg(address).arg(e.name);
            ++f.values;
            const QJsonObject g = guesses.value({function, address});
            const QString type = g.value(QStringLiteral("type")).toString();
            const int registers = g.value(QStringLiteral("registers")).toInt();
            const double scale = g.value(QStringLiteral("scale")).toDouble(1);
            bool typeOk = false;
            bool exact = false;
            if (g.isEmpty()) {
                f.misses.append(where + QStringLiteral(": no guess starts there"));
            } else if (bits) {
                typeOk = exact = type == QLatin1String("bit");
            } else if (text) {
                typeOk = exact = type == QLatin1String("ascii") && registers == e.count;
            } else {
                const RegisterFormat guessed = RegisterFormat::parse(type).format;
                exact = guessed == e.format;
                const double rawMin = g.value(QStringLiteral("minimum")).toDouble() / scale;
                const double rawMax = g.value(QStringLiteral("maximum")).toDouble() / scale;
                typeOk = registers == e.width() && sameNumbers(e.format, guessed, rawMin, rawMax);
            }
            if (!g.isEmpty() && !typeOk)
                f.misses.append(QStringLiteral("%1: %2 guessed %3").arg(where, text ? QStringLiteral("ascii[%1]").arg(e.count) : bits ? QStringLiteral("bit") : e.format.name(), type));
            f.typeRight += typeOk ? 1 : 0;
            f.typeExact += exact ? 1 : 0;
            if (!bits && !text) {
                ++f.numeric;
                const bool scaleOk = !g.isEmpty() && std::fabs(scale - e.scale) <= 1e-9 * std::fabs(e.scale);
                f.scaleRight += scaleOk ? 1 : 0;
                if (!g.isEmpty() && !scaleOk)
                    f.misses.append(QStringLiteral("%1: scale %2 guessed %3").arg(where).arg(e.scale).arg(scale));
            }
            if (still) {
                ++f.constants;
                if (g.value(QStringLiteral("kind")).toString() == QLatin1String("measurement")) {
                    ++f.constantsAsMeasurements;
                    f.misses.append(where + QStringLiteral(": still, guessed a measurement"));
                }
            }
        }
    }
    return f;
}

double percent(int part, int whole)
{
    return whole == 0 ? 100.0 : 100.0 * part / whole;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    QTextStream err(stderr);
    int samples = 40;
    int intervalMs = 500;
    bool check = false;
    QString only;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (a == QLatin1String("--samples") && i + 1 < args.size())
            samples = args.at(++i).toInt();
        else if (a == QLatin1String("--interval") && i + 1 < args.size())
            intervalMs = args.at(++i).toInt();
        else if (a == QLatin1String("--device") && i + 1 < args.size())
            only = args.at(++i);
        else if (a == QLatin1String("--check"))
            check = true;
        else {
            err << "usage: bench_infer [--samples N] [--interval MS] [--device NAME] [--check]\n";
            return 2;
        }
    }
    const QString mbscope = QStringLiteral(MBSCOPE_EXECUTABLE);
    out << "mbscope infer against the realistic devices: " << samples << " samples every " << intervalMs << " ms\n";
    out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
               .arg(QStringLiteral("device"), -20)
               .arg(QStringLiteral("values"), 6)
               .arg(QStringLiteral("type+order"), 16)
               .arg(QStringLiteral("(exact)"), 9)
               .arg(QStringLiteral("scale"), 16)
               .arg(QStringLiteral("const->meas"), 12);
    bool goals = true;
    bool ran = false;
    for (const Device &d : kDevices) {
        const QString name = QString::fromLatin1(d.name);
        if (!only.isEmpty() && only != name)
            continue;
        ran = true;
        const ProfileLoadResult truth = ProfileLoader::loadFile(QStringLiteral(MBSCOPE_PROFILES_DIR "/") + name + QStringLiteral(".json"));
        if (!truth.ok) {
            err << name << ": " << truth.errorText() << '\n';
            return 1;
        }
        BenchServer server;
        server.name = name;
        if (!server.start(mbscope, {QStringLiteral("simulate"), QStringLiteral("--profile"), name, QStringLiteral("--listen"),
                                    QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                          QRegularExpression(QStringLiteral("listening tcp://127\\.0\\.0\\.1:(\\d+)")), false, 0))
            return 1;
        QProcess infer;
        infer.start(mbscope, {QStringLiteral("infer"), QStringLiteral("tcp://127.0.0.1:%1").arg(server.port),
                              QStringLiteral("--addresses"), QString::fromLatin1(d.addresses), QStringLiteral("--tables"),
                              QString::fromLatin1(d.tables), QStringLiteral("--samples"), QString::number(samples),
                              QStringLiteral("--interval"), QStringLiteral("%1ms").arg(intervalMs), QStringLiteral("--json")});
        if (!infer.waitForFinished(600000) || infer.exitCode() != 0) {
            err << name << ": mbscope infer failed: " << infer.readAllStandardError() << '\n';
            server.stop();
            return 1;
        }
        server.stop();
        const QJsonObject inferred = QJsonDocument::fromJson(infer.readAllStandardOutput()).object();
        const Figures f = compare(truth.profile, inferred);
        const double type = percent(f.typeRight, f.values);
        const double scale = percent(f.scaleRight, f.numeric);
        out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
                   .arg(name, -20)
                   .arg(f.values, 6)
                   .arg(QStringLiteral("%1/%2 %3%").arg(f.typeRight).arg(f.values).arg(type, 5, 'f', 1), 16)
                   .arg(QStringLiteral("%1%").arg(percent(f.typeExact, f.values), 0, 'f', 1), 9)
                   .arg(QStringLiteral("%1/%2 %3%").arg(f.scaleRight).arg(f.numeric).arg(scale, 5, 'f', 1), 16)
                   .arg(QStringLiteral("%1/%2").arg(f.constantsAsMeasurements).arg(f.constants), 12);
        for (const QString &m : f.misses)
            out << "    miss: " << m << '\n';
        out.flush();
        goals = goals && type >= 90 && scale >= 80 && f.constantsAsMeasurements == 0;
    }
    if (!ran) {
        err << "bench_infer: no device named " << only << '\n';
        return 2;
    }
    out << "goals (type+order >= 90 %, scale >= 80 %, no still value called a measurement) met on every device: "
        << (goals ? "yes" : "no") << '\n';
    return check && !goals ? 1 : 0;
}
