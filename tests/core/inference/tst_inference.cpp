// Inference over synthetic samples (issue 28): every type in every order, moving as values of
// that kind move, is found with its type, order, kind and scale; blocks laid out as real devices
// lay them out (floats with a value that stays 0, integers low word first with a value that
// never reaches the high word, SunSpec-style scale-factor registers, a padded serial number,
// status bits) keep their values apart.

#include "inference/blockinferrer.h"
#include "inference/typeinferrer.h"

#include "protocol/registervalue.h"

#include <QtTest/QTest>

#include <cmath>
#include <functional>

using namespace mbscope;

namespace {

constexpr int kSamples = 40;

// One value of a synthetic block: its format and its raw number at sample t.
struct Field {
    QString format;
    std::function<double(int)> raw;
};

BlockSamples makeBlock(const QList<Field> &fields, quint8 function = 4)
{
    BlockSamples block;
    block.function = function;
    block.address = 0;
    for (int t = 0; t < kSamples; ++t) {
        QList<quint16> words;
        for (const Field &f : fields) {
            const RegisterFormat format = RegisterFormat::parse(f.format).format;
            RegisterValueResult r = format.isFloat() ? RegisterValue::fromDouble(f.raw(t), format)
                                   : format.isSigned() ? RegisterValue::fromSigned(qint64(std::llround(f.raw(t))), format)
                                                       : RegisterValue::fromUnsigned(quint64(std::llround(f.raw(t))), format);
            Q_ASSERT(r.ok);
            words += r.value.registers();
        }
        block.samples.append(words);
    }
    block.registerCount = int(block.samples.constFirst().size());
    return block;
}

BlockSamples withText(const QList<Field> &before, const QString &chars, int registers, const QList<Field> &after)
{
    BlockSamples a = makeBlock(before);
    BlockSamples b = makeBlock(after);
    QList<quint16> textWords(registers, 0);
    for (int i = 0; i < chars.size(); ++i)
        textWords[i / 2] |= quint16(chars.at(i).unicode() << (i % 2 == 0 ? 8 : 0));
    BlockSamples out;
    out.function = 3;
    for (int t = 0; t < kSamples; ++t)
        out.samples.append(a.samples.value(t) + textWords + b.samples.value(t));
    out.registerCount = int(out.samples.constFirst().size());
    return out;
}

double sine(int t, double centre, double amplitude) { return centre + amplitude * std::sin(t * 0.37) + 0.013 * t; }

const ValueGuess *at(const QList<ValueGuess> &guesses, int address)
{
    for (const ValueGuess &g : guesses) {
        if (g.address == address)
            return &g;
    }
    return nullptr;
}

} // namespace

class TestInference : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void typeAndOrder_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("motion");
        QTest::addColumn<QString>("expected");
        QTest::addColumn<QString>("kind");
        for (const char *order : {"abcd", "cdab", "badc", "dcba"}) {
            const QString o = QString::fromLatin1(order);
            QTest::addRow("f32-%s voltage", order) << QStringLiteral("f32-") + o << "voltage" << QStringLiteral("f32-") + o << "measurement";
            QTest::addRow("f64-%s measurement", order) << QStringLiteral("f64-") + o << "f64" << QStringLiteral("f64-") + o << "measurement";
            QTest::addRow("u32-%s counter with carries", order) << QStringLiteral("u32-") + o << "carry" << QStringLiteral("u32-") + o << "counter";
            QTest::addRow("u32-%s counter above 65535, no carry", order) << QStringLiteral("u32-") + o << "high" << QStringLiteral("u32-") + o << "counter";
            QTest::addRow("i32-%s around zero", order) << QStringLiteral("i32-") + o << "signed" << QStringLiteral("i32-") + o << "measurement";
            QTest::addRow("u64-%s counter past 2^32", order) << QStringLiteral("u64-") + o << "u64" << QStringLiteral("u64-") + o << "counter";
        }
        QTest::addRow("u16 counter") << "u16" << "counter16" << "u16" << "counter";
        QTest::addRow("u16-ba counter") << "u16-ba" << "counter16" << "u16-ba" << "counter";
        QTest::addRow("i16 below zero") << "i16" << "cold" << "i16" << "measurement";
        QTest::addRow("u16 constant") << "u16" << "constant" << "u16" << "constant";
        QTest::addRow("status bits") << "u16" << "status" << "bin" << "status";
    }
    void typeAndOrder()
    {
        QFETCH(QString, format);
        QFETCH(QString, motion);
        QFETCH(QString, expected);
        QFETCH(QString, kind);
        std::function<double(int)> raw;
        if (motion == QLatin1String("voltage"))
            raw = [](int t) { return sine(t, 230.4, 1.2); };
        else if (motion == QLatin1String("f64"))
            raw = [](int t) { return sine(t, 1234.5678, 10); };
        else if (motion == QLatin1String("carry"))
            raw = [](int t) { return 65400.0 + 9 * t; };
        else if (motion == QLatin1String("high"))
            raw = [](int t) { return 300000.0 + 5 * t; };
        else if (motion == QLatin1String("signed"))
            raw = [](int t) { return std::round(sine(t, 0, 1500)); };
        else if (motion == QLatin1String("u64"))
            raw = [](int t) { return 4294967296.0 * 3 + 65500 + 7 * t; };
        else if (motion == QLatin1String("counter16"))
            raw = [](int t) { return 1000.0 + 3 * t; };
        else if (motion == QLatin1String("cold"))
            raw = [](int t) { return std::round(sine(t, -55, 20)); };
        else if (motion == QLatin1String("constant"))
            raw = [](int) { return 1234.0; };
        else if (motion == QLatin1String("status"))
            raw = [](int t) { static const int v[] = {0x0011, 0x0015, 0x0011, 0x0091}; return double(v[(t / 3) % 4]); };
        const QList<ValueGuess> guesses = BlockInferrer::infer(makeBlock({Field{format, raw}}));
        QVERIFY2(!guesses.isEmpty(), "no guess");
        const ValueGuess &g = guesses.constFirst();
        QString all;
        for (const ValueGuess &x : guesses)
            all += QStringLiteral("%1@%2 ").arg(x.typeName()).arg(x.address);
        QVERIFY2(g.typeName() == RegisterFormat::parse(expected).format.name(), qPrintable(all + g.evidence));
        QVERIFY2(guesses.size() == 1, qPrintable(all));
        QCOMPARE(valueKindName(g.kind), kind);
        QVERIFY2(!g.evidence.isEmpty(), "no evidence");
    }

    // Blocks laid out as devices lay them out: each value's type, kind and scale.
    void deviceBlocks_data()
    {
        QTest::addColumn<QString>("device");
        QTest::addColumn<int>("address");
        QTest::addColumn<QString>("type");
        QTest::addColumn<QString>("kind");
        QTest::addColumn<double>("scale");
        QTest::addColumn<QString>("unit");
        // Floats big endian, with a value that stays 0.0 and one that stays 1.0.
        QTest::newRow("floats: voltage") << "floats" << 0 << "f32-abcd" << "measurement" << 1.0 << "V";
        QTest::newRow("floats: current") << "floats" << 2 << "f32-abcd" << "measurement" << 1.0 << "";
        QTest::newRow("floats: export stays 0") << "floats" << 4 << "f32-abcd" << "constant" << 1.0 << "";
        QTest::newRow("floats: frequency") << "floats" << 6 << "f32-abcd" << "measurement" << 1.0 << "Hz";
        QTest::newRow("floats: energy") << "floats" << 8 << "f32-abcd" << "counter" << 1.0 << "";
        // 32-bit integers low word first, tenths of volts, an energy counter above 65535.
        QTest::newRow("ints: voltage x0.1") << "ints" << 0 << "u32-cdab" << "measurement" << 0.1 << "V";
        QTest::newRow("ints: frequency x0.1") << "ints" << 2 << "u32-cdab" << "measurement" << 0.1 << "Hz";
        QTest::newRow("ints: power negative") << "ints" << 4 << "i32-cdab" << "measurement" << 1.0 << "";
        QTest::newRow("ints: energy") << "ints" << 6 << "u32-cdab" << "counter" << 1.0 << "";
        // SunSpec style: values then their scale-factor register.
        QTest::newRow("sunspec: current") << "sunspec" << 0 << "u16" << "measurement" << 0.01 << "";
        QTest::newRow("sunspec: current sf") << "sunspec" << 2 << "i16" << "constant" << 1.0 << "";
        QTest::newRow("sunspec: voltage") << "sunspec" << 3 << "u16" << "measurement" << 0.1 << "V";
        QTest::newRow("sunspec: voltage sf") << "sunspec" << 4 << "i16" << "constant" << 1.0 << "";
        QTest::newRow("sunspec: power") << "sunspec" << 5 << "u16" << "measurement" << 1.0 << "";
        QTest::newRow("sunspec: frequency") << "sunspec" << 7 << "u16" << "measurement" << 0.01 << "Hz";
        // A controller: temperatures in tenths, status bits, a serial number.
        QTest::newRow("controller: temperature") << "controller" << 0 << "i16" << "measurement" << 0.1 << "degC";
        QTest::newRow("controller: outdoor below 0") << "controller" << 1 << "i16" << "measurement" << 0.1 << "degC";
        QTest::newRow("controller: status") << "controller" << 2 << "bin" << "status" << 1.0 << "";
        QTest::newRow("controller: serial") << "controller" << 3 << "ascii[8]" << "constant" << 1.0 << "";
        QTest::newRow("controller: setpoint") << "controller" << 11 << "u16" << "constant" << 1.0 << "";
        // Still small integers side by side: no float read with its bytes swapped.
        QTest::newRow("settings: small integers") << "settings" << 0 << "u16" << "constant" << 1.0 << "";
        QTest::newRow("settings: next") << "settings" << 1 << "u16" << "constant" << 1.0 << "";
        QTest::newRow("settings: round float") << "settings" << 3 << "f32-abcd" << "constant" << 1.0 << "";
    }
    void deviceBlocks()
    {
        QFETCH(QString, device);
        QFETCH(int, address);
        QFETCH(QString, type);
        QFETCH(QString, kind);
        QFETCH(double, scale);
        QFETCH(QString, unit);
        BlockSamples block;
        if (device == QLatin1String("floats")) {
            block = makeBlock({{QStringLiteral("f32"), [](int t) { return sine(t, 231.2, 0.8); }},
                               {QStringLiteral("f32"), [](int t) { return sine(t, 4.7, 0.3); }},
                               {QStringLiteral("f32"), [](int) { return 0.0; }},
                               {QStringLiteral("f32"), [](int t) { return 50.0 + 0.02 * std::sin(t * 0.9); }},
                               {QStringLiteral("f32"), [](int t) { return 1523.25 + 0.01 * t; }}});
        } else if (device == QLatin1String("ints")) {
            block = makeBlock({{QStringLiteral("u32-cdab"), [](int t) { return std::round(sine(t, 2305, 12)); }},
                               {QStringLiteral("u32-cdab"), [](int t) { return std::round(sine(t, 500, 1)); }},
                               {QStringLiteral("i32-cdab"), [](int t) { return std::round(sine(t, 20, 900)); }},
                               {QStringLiteral("u32-cdab"), [](int t) { return 123456.0 + 2 * t; }}});
        } else if (device == QLatin1String("sunspec")) {
            block = makeBlock({{QStringLiteral("u16"), [](int t) { return std::round(sine(t, 1520, 40)); }},
                               {QStringLiteral("u16"), [](int t) { return std::round(sine(t, 1490, 40)); }},
                               {QStringLiteral("i16"), [](int) { return -2.0; }},
                               {QStringLiteral("u16"), [](int t) { return std::round(sine(t, 2312, 10)); }},
                               {QStringLiteral("i16"), [](int) { return -1.0; }},
                               {QStringLiteral("u16"), [](int t) { return std::round(sine(t, 3400, 300)); }},
                               {QStringLiteral("i16"), [](int) { return 0.0; }},
                               {QStringLiteral("u16"), [](int t) { return std::round(sine(t, 5000, 3)); }},
                               {QStringLiteral("i16"), [](int) { return -2.0; }}});
        } else if (device == QLatin1String("settings")) {
            block = makeBlock({{QStringLiteral("u16"), [](int) { return 190.0; }},
                               {QStringLiteral("u16"), [](int) { return 60.0; }},
                               {QStringLiteral("u16"), [](int) { return 3.0; }},
                               {QStringLiteral("f32"), [](int) { return 60.0; }}});
        } else {
            block = withText({{QStringLiteral("i16"), [](int t) { return std::round(sine(t, 215, 8)); }},
                              {QStringLiteral("i16"), [](int t) { return std::round(sine(t, -32, 15)); }},
                              {QStringLiteral("u16"), [](int t) { static const int v[] = {0x0011, 0x0015, 0x0011, 0x0091}; return double(v[(t / 3) % 4]); }}},
                             QStringLiteral("CT-20481"), 8,
                             {{QStringLiteral("u16"), [](int) { return 210.0; }}});
        }
        const QList<ValueGuess> guesses = BlockInferrer::infer(block);
        QString all;
        for (const ValueGuess &x : guesses)
            all += QStringLiteral("%1@%2 %3 x%4; ").arg(x.typeName()).arg(x.address).arg(valueKindName(x.kind)).arg(x.scale);
        const ValueGuess *g = at(guesses, address);
        QVERIFY2(g, qPrintable(QStringLiteral("nothing starts at %1: %2").arg(address).arg(all)));
        QVERIFY2(g->typeName() == type, qPrintable(all));
        QVERIFY2(valueKindName(g->kind) == kind, qPrintable(all));
        QVERIFY2(qFuzzyCompare(g->scale, scale), qPrintable(all));
        QCOMPARE(g->unit, unit);
    }

    // A three-phase meter of 32-bit integers low word first whose powers follow from its voltages
    // (x0.1), currents (x0.001) and power factors (x0.001) as a meter computes them: the currents
    // and powers get their scales from the relations between registers (PowerRelations). When
    // the powers move on their own, nothing relates them and they keep scale 1.
    void powerRelations_data()
    {
        QTest::addColumn<bool>("related");
        QTest::addColumn<int>("address");
        QTest::addColumn<double>("scale");
        QTest::addColumn<QString>("unit");
        QTest::addColumn<QString>("evidence");
        QTest::newRow("current L1") << true << 6 << 0.001 << "A" << "V(0) x A(6)";
        QTest::newRow("current L3") << true << 10 << 0.001 << "A" << "x A(10)";
        QTest::newRow("active power L1") << true << 12 << 0.1 << "W" << "x PF(36)";
        QTest::newRow("apparent power L2") << true << 20 << 0.1 << "VA" << "= V(2) x A(8) over";
        QTest::newRow("reactive power L1") << true << 24 << 0.1 << "var" << "sqrt(VA(18)^2 - W(12)^2)";
        QTest::newRow("reactive power L3, negative") << true << 28 << 0.1 << "var" << "sqrt(VA(22)^2 - W(16)^2)";
        QTest::newRow("total active power") << true << 30 << 0.1 << "W" << "30 = 12 + 14 + 16";
        QTest::newRow("total reactive power") << true << 34 << 0.1 << "var" << "34 = 24 + 26 + 28";
        QTest::newRow("voltage still recognised") << true << 0 << 0.1 << "V" << "reads as voltage";
        QTest::newRow("unrelated: current") << false << 6 << 1.0 << "" << "";
        QTest::newRow("unrelated: apparent power") << false << 18 << 1.0 << "" << "";
    }
    void powerRelations()
    {
        QFETCH(bool, related);
        QFETCH(int, address);
        QFETCH(double, scale);
        QFETCH(QString, unit);
        QFETCH(QString, evidence);
        auto volts = [](int p, int t) { return std::round(10 * (230 + 0.5 * p + 0.8 * std::sin(0.37 * t + p))) / 10; };
        auto amps = [](int p, int t) { return std::round(1000 * (5 + p + 1.5 * std::sin(0.23 * t + p))) / 1000; };
        auto factor = [](int p, int t) { return std::round(1000 * (0.92 + 0.04 * std::sin(0.51 * t + p))) / 1000; };
        auto va = [&](int p, int t) { return related ? volts(p, t) * amps(p, t) : sine(t + 7 * p, 1200, 300); };
        auto w = [&](int p, int t) { return va(p, t) * factor(p, t); };
        auto var = [&](int p, int t) { return (p == 2 ? -1 : 1) * std::sqrt(std::max(0.0, va(p, t) * va(p, t) - w(p, t) * w(p, t))); };
        QList<Field> fields;
        auto add = [&](const QString &format, std::function<double(int)> raw) { fields.append({format, std::move(raw)}); };
        for (int p = 0; p < 3; ++p)
            add(QStringLiteral("u32-cdab"), [=](int t) { return std::round(10 * volts(p, t)); });
        for (int p = 0; p < 3; ++p)
            add(QStringLiteral("u32-cdab"), [=](int t) { return std::round(1000 * amps(p, t)); });
        for (const auto &quantity : {std::function<double(int, int)>(w), std::function<double(int, int)>(va),
                                     std::function<double(int, int)>(var)}) {
            for (int p = 0; p < 3; ++p)
                add(QStringLiteral("i32-cdab"), [=](int t) { return std::round(10 * quantity(p, t)); });
        }
        for (const auto &quantity : {std::function<double(int, int)>(w), std::function<double(int, int)>(va),
                                     std::function<double(int, int)>(var)}) {
            add(QStringLiteral("i32-cdab"), [=](int t) {
                double sum = 0;
                for (int p = 0; p < 3; ++p)
                    sum += std::round(10 * quantity(p, t)) / 10;
                return std::round(10 * sum);
            });
        }
        for (int p = 0; p < 3; ++p)
            add(QStringLiteral("i16"), [=](int t) { return std::round(1000 * factor(p, t)); });
        const BlockSamples block = makeBlock(fields, 3);
        const QList<ValueGuess> guesses = BlockInferrer::infer(block);
        QString all;
        for (const ValueGuess &x : guesses)
            all += QStringLiteral("%1@%2 x%3 %4; ").arg(x.typeName()).arg(x.address).arg(x.scale).arg(x.unit);
        const ValueGuess *g = at(guesses, address);
        QVERIFY2(g, qPrintable(all));
        QVERIFY2(qFuzzyCompare(g->scale, scale), qPrintable(g->scaleEvidence + QStringLiteral(" | ") + all));
        QCOMPARE(g->unit, unit);
        QVERIFY2(g->scaleEvidence.contains(evidence), qPrintable(g->scaleEvidence));
        if (related && unit != QLatin1String("V"))
            QVERIFY(g->scaleConfidence >= 0.5 && g->scaleConfidence < 0.8); // a relation, not a reading of the value
    }

    void bitsAreConstantOrStatus()
    {
        BlockSamples block;
        block.function = 2;
        block.registerCount = 3;
        for (int t = 0; t < kSamples; ++t)
            block.samples.append({1, quint16(t % 7 == 0 ? 1 : 0), 0});
        const QList<ValueGuess> guesses = BlockInferrer::infer(block);
        QCOMPARE(guesses.size(), 3);
        QCOMPARE(guesses.at(0).kind, ValueKind::Constant);
        QCOMPARE(guesses.at(1).kind, ValueKind::Status);
        QVERIFY(guesses.at(1).bit);
    }

    void plausibleFloats_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<bool>("plausible");
        QTest::newRow("zero") << 0.0 << true;
        QTest::newRow("mains") << 230.1 << true;
        QTest::newRow("denormal") << 9.2e-41 << false;
        QTest::newRow("huge") << 2.3e23 << false;
        QTest::newRow("nan") << std::nan("") << false;
        QTest::newRow("inf") << HUGE_VAL << false;
    }
    void plausibleFloats()
    {
        QFETCH(double, value);
        QFETCH(bool, plausible);
        QCOMPARE(TypeInferrer::plausibleFloat(value), plausible);
    }
};

QTEST_GUILESS_MAIN(TestInference)
#include "tst_inference.moc"
