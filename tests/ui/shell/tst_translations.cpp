// The Indonesian translation is complete: lupdate, run over the sources the window shows text
// from (as the update_translations target does), finds no string that mbscope_id.ts lacks or
// leaves unfinished, and no translation loses a placeholder (%1, %n), an HTML tag or its
// &-accelerator. Each failure names the string and where it is in the sources.
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QHash>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTranslator>
#include <QtCore/QXmlStreamReader>
#include <QtTest/QTest>

#include "protocol/dissector.h"
#include "protocol/functioncode.h"
#include "protocol/modiconreference.h"
#include "protocol/registerformat.h"
#include "protocol/streamframe.h"

using namespace mbscope;

#include <algorithm>
#include <cstring>

namespace {

struct TsMessage {
    QString context;
    QString source;
    QString comment;
    QString file; // lupdate's location (absolute when asked with -locations absolute)
    int line = 0;
    bool numerus = false;
    bool unfinished = true;
    QStringList translations; // one, or the numerus forms
};

QString keyOf(const TsMessage &m)
{
    return m.context + QLatin1Char('\x1f') + m.source + QLatin1Char('\x1f') + m.comment;
}

// Reads a Qt Linguist .ts file; *error says where it is not one.
QList<TsMessage> readTs(const QString &path, QString *error)
{
    QList<TsMessage> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage current;
    QString lastFile;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const QStringView name = xml.name();
        if (name == u"name") {
            context = xml.readElementText();
        } else if (name == u"message") {
            current = TsMessage{};
            current.context = context;
            current.numerus = xml.attributes().value(QLatin1String("numerus")) == u"yes";
        } else if (name == u"location") {
            const QXmlStreamAttributes a = xml.attributes();
            // lupdate names files relative to the .ts file's folder.
            if (a.hasAttribute(QLatin1String("filename")))
                lastFile = QFileInfo(path).dir().absoluteFilePath(a.value(QLatin1String("filename")).toString());
            if (current.file.isEmpty()) {
                current.file = lastFile;
                current.line = a.value(QLatin1String("line")).toInt();
            }
        } else if (name == u"source") {
            current.source = xml.readElementText();
        } else if (name == u"comment") {
            current.comment = xml.readElementText();
        } else if (name == u"translation") {
            const QStringView type = xml.attributes().value(QLatin1String("type"));
            current.unfinished = type == u"unfinished" || type == u"vanished" || type == u"obsolete";
            if (current.numerus) {
                while (xml.readNextStartElement()) {
                    if (xml.name() == u"numerusform")
                        current.translations << xml.readElementText();
                    else
                        xml.skipCurrentElement();
                }
            } else {
                current.translations << xml.readElementText();
            }
            messages << current;
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

QStringList sorted(QStringList list)
{
    std::sort(list.begin(), list.end());
    return list;
}

QStringList matches(const QRegularExpression &re, const QString &text, int group = 0)
{
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured(group);
    return found;
}

// The accelerators of a text: '&' before a character, not "&&" (a literal ampersand).
int acceleratorCount(QString text)
{
    text.remove(QStringLiteral("&&"));
    static const QRegularExpression accelerator(QStringLiteral("&[^\\s&]"));
    return int(matches(accelerator, text).size());
}

// What is wrong with one translation of source; empty when it is fine.
QStringList translationProblems(const QString &source, const QString &translation, bool numerus)
{
    QStringList problems;
    if (translation.trimmed().isEmpty() && !source.trimmed().isEmpty())
        return {QStringLiteral("the translation is empty")};
    static const QRegularExpression placeholder(QStringLiteral("%L?\\d+|%n"));
    QStringList wanted = matches(placeholder, source);
    QStringList have = matches(placeholder, translation);
    if (numerus) {
        // A numerus form may leave %n out ("one register"); every other placeholder stays.
        wanted.removeAll(QStringLiteral("%n"));
        have.removeAll(QStringLiteral("%n"));
    }
    if (sorted(wanted) != sorted(have))
        problems << QStringLiteral("placeholders %1 in the source, %2 in the translation")
                        .arg(sorted(wanted).join(QLatin1Char(' ')), sorted(have).join(QLatin1Char(' ')));
    static const QRegularExpression tag(QStringLiteral("</?([A-Za-z][A-Za-z0-9]*)"));
    if (sorted(matches(tag, source, 0)) != sorted(matches(tag, translation, 0)))
        problems << QStringLiteral("HTML tags %1 in the source, %2 in the translation")
                        .arg(sorted(matches(tag, source)).join(QLatin1Char(' ')),
                             sorted(matches(tag, translation)).join(QLatin1Char(' ')));
    if (acceleratorCount(source) != acceleratorCount(translation))
        problems << QStringLiteral("%1 &-accelerator(s) in the source, %2 in the translation")
                        .arg(acceleratorCount(source))
                        .arg(acceleratorCount(translation));
    return problems;
}

// The problems of one message lupdate found, against the committed translation (null: missing).
QStringList messageProblems(const TsMessage &found, const TsMessage *committed)
{
    if (!committed)
        return {QStringLiteral("missing from mbscope_id.ts (run the update_translations target, then translate it)")};
    if (committed->unfinished)
        return {QStringLiteral("unfinished in mbscope_id.ts")};
    if (committed->translations.isEmpty())
        return {QStringLiteral("has no translation")};
    QStringList problems;
    for (const QString &t : committed->translations)
        problems << translationProblems(found.source, t, found.numerus);
    return problems;
}

QString describe(const TsMessage &m, const QStringList &problems)
{
    return QStringLiteral("%1:%2: [%3] \"%4\": %5")
        .arg(QDir(QStringLiteral(MBSCOPE_SOURCE_DIR)).relativeFilePath(m.file))
        .arg(m.line)
        .arg(m.context, m.source, problems.join(QStringLiteral("; ")));
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void checkerFindsProblems_data();
    void checkerFindsProblems();
    void everyStringTranslated_data();
    void everyStringTranslated();
    void noStaleEntries();
    void coreTextsAreMarked();

private:
    QTemporaryDir m_dir;
    QList<TsMessage> m_found;                // what lupdate finds in the sources now
    QHash<QString, TsMessage> m_committed;   // resources/translations/mbscope_id.ts
};

void TestTranslations::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString lupdate = QStringLiteral(MBSCOPE_LUPDATE);
    if (!QFileInfo::exists(lupdate))
        QSKIP("lupdate is not installed (Debian: qt6-l10n-tools)");
    const QString src = QStringLiteral(MBSCOPE_SOURCE_DIR);
    const QString fresh = m_dir.filePath(QStringLiteral("fresh_id.ts"));
    QProcess run;
    run.start(lupdate, {QStringLiteral("-silent"), QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                        QStringLiteral("absolute"), QStringLiteral("-target-language"), QStringLiteral("id_ID"),
                        src + QStringLiteral("/core"), src + QStringLiteral("/ui"), src + QStringLiteral("/app/gui.cpp"),
                        QStringLiteral("-ts"), fresh});
    QVERIFY2(run.waitForFinished(120000), qPrintable(run.errorString()));
    QVERIFY2(run.exitCode() == 0, run.readAllStandardError().constData());

    QString error;
    m_found = readTs(fresh, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(m_found.size() > 300, qPrintable(QStringLiteral("lupdate found only %1 strings").arg(m_found.size())));
    const QList<TsMessage> committed = readTs(QStringLiteral(MBSCOPE_TS_FILE), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    for (const TsMessage &m : committed)
        m_committed.insert(keyOf(m), m);
}

// The checks themselves, on made-up strings: each wrong translation is caught, a right one is not.
void TestTranslations::checkerFindsProblems_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("translation");
    QTest::addColumn<bool>("numerus");
    QTest::addColumn<QString>("problem"); // a word of the expected problem; empty: none

    QTest::newRow("fine") << QStringLiteral("Sent: %1") << QStringLiteral("Terkirim: %1") << false << QString();
    QTest::newRow("placeholder lost") << QStringLiteral("%1 of %2 registers") << QStringLiteral("%1 register")
                                      << false << QStringLiteral("placeholders");
    QTest::newRow("placeholder renamed") << QStringLiteral("unit %1") << QStringLiteral("unit %2") << false
                                         << QStringLiteral("placeholders");
    QTest::newRow("tag lost") << QStringLiteral("press <b>Send</b>") << QStringLiteral("tekan Kirim") << false
                              << QStringLiteral("HTML");
    QTest::newRow("accelerator lost") << QStringLiteral("&File") << QStringLiteral("Berkas") << false
                                      << QStringLiteral("accelerator");
    QTest::newRow("ampersand is no accelerator") << QStringLiteral("Read && write") << QStringLiteral("Baca && tulis")
                                                 << false << QString();
    QTest::newRow("numerus without %n") << QStringLiteral("%n registers") << QStringLiteral("register") << true
                                        << QString();
    QTest::newRow("empty") << QStringLiteral("Ready") << QString() << false << QStringLiteral("empty");
}

void TestTranslations::checkerFindsProblems()
{
    QFETCH(QString, source);
    QFETCH(QString, translation);
    QFETCH(bool, numerus);
    QFETCH(QString, problem);
    const QStringList problems = translationProblems(source, translation, numerus);
    if (problem.isEmpty())
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
    else
        QVERIFY2(problems.join(QLatin1Char(' ')).contains(problem), qPrintable(problems.join(QStringLiteral("; "))));

    // A missing or unfinished message is a problem whatever its translation.
    TsMessage m;
    m.source = source;
    QVERIFY(!messageProblems(m, nullptr).isEmpty());
    m.translations = {translation};
    m.unfinished = true;
    QVERIFY(!messageProblems(m, &m).isEmpty());
}

// One row per translation context, so a failure says which class's strings are missing.
void TestTranslations::everyStringTranslated_data()
{
    QTest::addColumn<QString>("context");
    QStringList contexts;
    for (const TsMessage &m : std::as_const(m_found)) {
        if (!contexts.contains(m.context))
            contexts << m.context;
    }
    for (const QString &c : std::as_const(contexts))
        QTest::newRow(qPrintable(c)) << c;
}

void TestTranslations::everyStringTranslated()
{
    QFETCH(QString, context);
    QStringList failures;
    for (const TsMessage &m : std::as_const(m_found)) {
        if (m.context != context)
            continue;
        const auto it = m_committed.constFind(keyOf(m));
        const QStringList problems = messageProblems(m, it == m_committed.constEnd() ? nullptr : &*it);
        if (!problems.isEmpty())
            failures << describe(m, problems);
    }
    // Each on its own line: QTest cuts a long failure message short.
    for (const QString &failure : std::as_const(failures))
        qWarning("%s", qPrintable(failure));
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 string(s) of %2 not (properly) translated, listed above; "
                                                           "the first: %3")
                                                .arg(failures.size())
                                                .arg(context, failures.value(0))));
}

// Entries the sources no longer have are only noise for translators: lupdate -no-obsolete drops
// them. Reported, not failed: a string removed today is no reason to stop a build.
void TestTranslations::noStaleEntries()
{
    QSet<QString> live;
    for (const TsMessage &m : std::as_const(m_found))
        live.insert(keyOf(m));
    int stale = 0;
    for (auto it = m_committed.cbegin(); it != m_committed.cend(); ++it) {
        if (!live.contains(it.key()) && !it->unfinished) {
            ++stale;
            qInfo("stale entry (no longer in the sources): [%s] \"%s\"", qPrintable(it->context), qPrintable(it->source));
        }
    }
    qInfo("%lld strings found in the sources, %lld entries in mbscope_id.ts, %d stale", qlonglong(m_found.size()),
          qlonglong(m_committed.size()), stale);
}

// The core's static strings reach the window only through QT_TRANSLATE_NOOP("mbscope::Field"):
// one written without the marker is in no .ts and stays English. Every field name and meaning of
// frames of every function code (requests and responses, whole and cut short, with patterned
// data) and every name the core hands out must be in the compiled translation.
void TestTranslations::coreTextsAreMarked()
{
    QTranslator translator;
    QVERIFY2(translator.load(QStringLiteral(":/translations/mbscope_id.qm")), "no :/translations/mbscope_id.qm");
    QMap<QString, QString> unmarked; // text -> where it was seen
    // ASCII control character names (NUL, STX, DC2) are the same in every language.
    static const QRegularExpression mnemonic(QStringLiteral("^[A-Z]{2,3}[0-9]?$"));
    const auto check = [&](const char *text, const QString &where) {
        if (text && *text && translator.translate("mbscope::Field", text).isEmpty() && !unmarked.contains(QLatin1String(text))
            && !mnemonic.match(QLatin1String(text)).hasMatch())
            unmarked.insert(QLatin1String(text), where);
    };
    int fields = 0;
    for (int code = 0; code < 256; ++code) {
        for (int length = 0; length <= 12; ++length) {
            for (const char fill : {'\x00', '\x01', '\x04', '\xFF'}) {
                QByteArray pdu(1 + length, fill);
                pdu[0] = char(code);
                if (length > 0)
                    pdu[1] = char(length - 1); // a byte count that fits
                for (const Direction direction : {Direction::Request, Direction::Response}) {
                    DissectOptions options;
                    options.framing = Framing::Pdu;
                    options.direction = direction;
                    const Dissection d = Dissector::dissect(pdu, options);
                    for (const Field &f : d.fields.fields()) {
                        ++fields;
                        const QString where = QStringLiteral("field %1 of PDU %2").arg(QLatin1String(f.key),
                                                                                   QString::fromLatin1(pdu.toHex(' ')));
                        check(f.name, where);
                        // The comm event log's texts are put together from flags at compile time
                        // (pducommevents.cpp): no one string to mark; they stay English.
                        if (std::strcmp(f.key, "modbus.event") != 0)
                            check(f.meaning, where);
                    }
                }
            }
        }
    }
    // Diagnostics (08): every sub-function, asked and answered.
    for (int sub = 0; sub <= 0x16; ++sub) {
        for (const Direction direction : {Direction::Request, Direction::Response}) {
            DissectOptions options;
            options.framing = Framing::Pdu;
            options.direction = direction;
            const QByteArray pdu = QByteArray::fromHex("0800") + char(sub) + QByteArray::fromHex("0000");
            const Dissection d = Dissector::dissect(pdu, options);
            for (const Field &f : d.fields.fields()) {
                check(f.name, QStringLiteral("field %1 of diagnostics %2").arg(QLatin1String(f.key)).arg(sub));
                check(f.meaning, QStringLiteral("field %1 of diagnostics %2").arg(QLatin1String(f.key)).arg(sub));
            }
        }
    }
    for (const QByteArray &hex : {QByteArrayLiteral("01030000000AC5CD"), QByteArrayLiteral("0103000000"),
                                  QByteArrayLiteral("000100000006010300000001"), QByteArrayLiteral("F7830215")}) {
        for (const Framing framing : {Framing::Rtu, Framing::Tcp, Framing::Ascii, Framing::Auto}) {
            DissectOptions options;
            options.framing = framing;
            const Dissection d = Dissector::dissect(QByteArray::fromHex(hex), options);
            for (const Field &f : d.fields.fields()) {
                check(f.name, QStringLiteral("field %1 of %2").arg(QLatin1String(f.key), QLatin1String(hex)));
                check(f.meaning, QStringLiteral("field %1 of %2").arg(QLatin1String(f.key), QLatin1String(hex)));
            }
        }
    }
    for (int code = 0; code < 256; ++code) {
        check(functionName(quint8(code)), QStringLiteral("functionName(%1)").arg(code));
        check(exceptionName(quint8(code)), QStringLiteral("exceptionName(%1)").arg(code));
        check(exceptionMeaning(quint8(code)), QStringLiteral("exceptionMeaning(%1)").arg(code));
    }
    for (const ModbusTable table : {ModbusTable::Coils, ModbusTable::DiscreteInputs, ModbusTable::InputRegisters,
                                    ModbusTable::HoldingRegisters})
        check(ModiconReference::tableName(table), QStringLiteral("ModiconReference::tableName"));
    for (int type = 0; type <= int(RegisterType::Float64); ++type) {
        for (const RegisterOrder order : {RegisterOrder::ABCD, RegisterOrder::CDAB, RegisterOrder::BADC, RegisterOrder::DCBA}) {
            const RegisterFormat format(RegisterType(type), order);
            check(format.typeDescription(), QStringLiteral("RegisterFormat::typeDescription"));
            check(format.orderWords(), QStringLiteral("RegisterFormat::orderWords"));
        }
    }
    for (int reason = 0; reason <= int(SkipReason::Incomplete); ++reason)
        check(skipReasonName(SkipReason(reason)), QStringLiteral("skipReasonName(%1)").arg(reason));

    QStringList failures;
    for (auto it = unmarked.cbegin(); it != unmarked.cend(); ++it)
        failures << QStringLiteral("\"%1\" (%2)").arg(it.key(), it.value());
    for (const QString &failure : std::as_const(failures))
        qWarning("not marked with QT_TRANSLATE_NOOP(\"mbscope::Field\", ...) or not translated: %s", qPrintable(failure));
    QVERIFY2(fields > 10000, qPrintable(QStringLiteral("only %1 fields dissected").arg(fields)));
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 core text(s) the window cannot translate, listed above; the first: %2")
                                                .arg(failures.size())
                                                .arg(failures.value(0))));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
