// docs/mbscope.1 against the program's own help: every subcommand `mbscope --help` lists has a
// section in the man page, every option its --help lists is mentioned in that section and
// described (with the same value name) in the page, with its short form when it has one ("-a id,
// --unit id"), and no option the page describes for a
// command is unknown to it. So neither can change without the other.
#include "helptext.h"
#include "manpage.h"
#include "processrun.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtTest/QtTest>

using namespace mbscope::testpackaging;

namespace {

const QString kCommands = QStringLiteral("COMMANDS");
// Sections that describe options shared by several commands; each command's section says which
// of them it takes.
const QStringList kSharedOptionSections{QStringLiteral("TARGET OPTIONS"), QStringLiteral("REQUEST OPTIONS"),
                                        QStringLiteral("POLL OPTIONS"), QStringLiteral("PRINT OPTIONS"),
                                        QStringLiteral("RECORD OPTIONS")};

bool isHelpOption(const QString &name)
{
    return name == QLatin1String("help") || name == QLatin1String("help-all") || name == QLatin1String("h");
}

bool mentions(const QString &text, const QString &option)
{
    const QRegularExpression word(QStringLiteral("(?<![\\w-])%1(?![\\w-])").arg(QRegularExpression::escape(option)));
    return word.match(text).hasMatch();
}

// The tag's alternatives ("--cert FILE, --key FILE" gives two) that describe --name.
QStringList definitionsIn(const QStringList &tags, const QString &name)
{
    QStringList found;
    const QString option = QStringLiteral("--") + name;
    for (const QString &tag : tags) {
        for (const QString &alternative : tag.split(QStringLiteral(", "))) {
            const QString a = alternative.trimmed();
            if (a == option || a.startsWith(option + QLatin1Char(' ')))
                found.append(a);
        }
    }
    return found;
}

// The tags that describe --name ("-a id, --unit id" for unit).
QStringList tagsDefining(const QStringList &tags, const QString &name)
{
    QStringList found;
    for (const QString &tag : tags) {
        if (!definitionsIn({tag}, name).isEmpty())
            found.append(tag);
    }
    return found;
}

// "--framing" from the tag "--framing framing"; empty when the tag is no option.
QString optionOfTag(const QString &tag)
{
    static const QRegularExpression option(QStringLiteral(R"(^--([A-Za-z0-9][A-Za-z0-9-]*))"));
    const QRegularExpressionMatch m = option.match(tag.trimmed());
    return m.hasMatch() ? m.captured(1) : QString();
}

} // namespace

class TestManPage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void titleNamesTheVersion();
    void everyCommandHasASection();
    void everyOptionIsDocumented_data();
    void everyOptionIsDocumented();
    void documentedOptionsExist_data();
    void documentedOptionsExist();
    void helpOptionsAreExplained();
    void rendersWithoutWarnings();

private:
    [[nodiscard]] ProcessRun mbscope(const QStringList &arguments) const;
    [[nodiscard]] QList<HelpOption> optionsOf(const QString &command) const { return m_options.value(command); }

    ManPage m_page;
    QStringList m_commands;
    QHash<QString, QList<HelpOption>> m_options;
};

ProcessRun TestManPage::mbscope(const QStringList &arguments) const
{
    return runProcess(QStringLiteral(MBSCOPE_EXECUTABLE), arguments, {}, 60000);
}

void TestManPage::initTestCase()
{
    QFile file(QStringLiteral(MBSCOPE_MAN_PAGE));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(QStringLiteral("cannot read the man page %1").arg(file.fileName())));
    m_page = ManPage::parse(QString::fromUtf8(file.readAll()));
    QVERIFY2(m_page.section(kCommands), "the man page has no COMMANDS section");

    const ProcessRun help = mbscope({QStringLiteral("--help")});
    QVERIFY2(help.succeeded(), help.describe().constData());
    m_commands = helpSubcommands(help.outText());
    QVERIFY2(m_commands.size() >= 7, qPrintable(QStringLiteral("mbscope --help lists only %1").arg(m_commands.join(QLatin1Char(' ')))));
    for (const QString &command : std::as_const(m_commands)) {
        const ProcessRun commandHelp = mbscope({command, QStringLiteral("--help")});
        QVERIFY2(commandHelp.succeeded(), commandHelp.describe().constData());
        const QList<HelpOption> options = helpOptions(commandHelp.outText());
        QVERIFY2(options.size() >= 2, qPrintable(QStringLiteral("mbscope %1 --help lists no options:\n%2")
                                                    .arg(command, commandHelp.outText())));
        m_options.insert(command, options);
    }
}

void TestManPage::titleNamesTheVersion()
{
    const ProcessRun version = mbscope({QStringLiteral("--version")});
    QVERIFY2(version.succeeded(), version.describe().constData());
    const QStringList title = m_page.titleFields();
    QVERIFY2(title.size() >= 4, qPrintable(title.join(QLatin1Char('|'))));
    QCOMPARE(title.at(0), QStringLiteral("MBSCOPE"));
    QCOMPARE(title.at(1), QStringLiteral("1"));
    QCOMPARE(title.at(3), version.outText().trimmed());
}

void TestManPage::everyCommandHasASection()
{
    const QStringList sections = m_page.subsections(kCommands);
    for (const QString &command : std::as_const(m_commands))
        QVERIFY2(sections.contains(command),
                 qPrintable(QStringLiteral("mbscope --help lists '%1' but the man page has no '.SS %1' under COMMANDS").arg(command)));
    for (const QString &section : sections)
        QVERIFY2(m_commands.contains(section),
                 qPrintable(QStringLiteral("the man page describes a command '%1' that mbscope --help does not list").arg(section)));
}

void TestManPage::everyOptionIsDocumented_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("valueName");
    QTest::addColumn<QString>("shortName");
    for (const QString &command : std::as_const(m_commands)) {
        for (const HelpOption &o : optionsOf(command)) {
            if (!isHelpOption(o.name))
                QTest::addRow("%s --%s", qPrintable(command), qPrintable(o.name)) << command << o.name << o.valueName
                                                                                  << o.shortName;
        }
    }
}

// The command's section names the option, and a .TP item describes it with the value name the
// help shows: in the command's own section, else in one of the shared option sections.
void TestManPage::everyOptionIsDocumented()
{
    QFETCH(QString, command);
    QFETCH(QString, option);
    QFETCH(QString, valueName);
    QFETCH(QString, shortName);
    const ManPage::Section *own = m_page.section(kCommands, command);
    QVERIFY2(own, qPrintable(QStringLiteral("no section for %1").arg(command)));
    QVERIFY2(mentions(own->text, QStringLiteral("--") + option),
             qPrintable(QStringLiteral("mbscope %1 --help lists --%2, but its man page section never mentions it")
                            .arg(command, option)));

    QStringList definitions = definitionsIn(own->tags, option);
    QStringList tags = tagsDefining(own->tags, option);
    if (definitions.isEmpty()) {
        for (const QString &heading : kSharedOptionSections) {
            if (const ManPage::Section *shared = m_page.section(heading)) {
                definitions += definitionsIn(shared->tags, option);
                tags += tagsDefining(shared->tags, option);
            }
        }
    }
    QVERIFY2(!definitions.isEmpty(),
             qPrintable(QStringLiteral("--%1 (mbscope %2) is described by no .TP item, neither in the %2 section nor in %3")
                            .arg(option, command, kSharedOptionSections.join(QStringLiteral(", ")))));
    const QString expected = valueName.isEmpty() ? QStringLiteral("--") + option
                                                 : QStringLiteral("--%1 %2").arg(option, valueName);
    QVERIFY2(definitions.contains(expected),
             qPrintable(QStringLiteral("mbscope %1 --help shows '%2', the man page '%3'")
                            .arg(command, expected, definitions.join(QStringLiteral("' and '")))));
    if (shortName.isEmpty())
        return;
    const QString shortForm = QStringLiteral("-") + shortName;
    const bool listed = std::any_of(tags.cbegin(), tags.cend(), [&](const QString &tag) {
        const QStringList alternatives = tag.split(QStringLiteral(", "));
        return std::any_of(alternatives.cbegin(), alternatives.cend(), [&](const QString &a) {
            return a.trimmed() == shortForm || a.trimmed().startsWith(shortForm + QLatin1Char(' '));
        });
    });
    QVERIFY2(listed, qPrintable(QStringLiteral("mbscope %1 --help gives --%2 the short form %3, but the man page's item '%4' "
                                               "does not list it")
                                    .arg(command, option, shortForm, tags.join(QStringLiteral("' and '")))));
}

void TestManPage::documentedOptionsExist_data()
{
    QTest::addColumn<QStringList>("commands");
    QTest::addColumn<QString>("option");
    for (const QString &command : std::as_const(m_commands)) {
        if (const ManPage::Section *own = m_page.section(kCommands, command)) {
            for (const QString &tag : own->tags) {
                const QString option = optionOfTag(tag);
                if (!option.isEmpty())
                    QTest::addRow("%s: %s", qPrintable(command), qPrintable(tag)) << QStringList{command} << option;
            }
        }
    }
    for (const QString &heading : kSharedOptionSections) {
        const ManPage::Section *shared = m_page.section(heading);
        if (!shared)
            continue;
        for (const QString &tag : shared->tags) {
            const QString option = optionOfTag(tag);
            if (!option.isEmpty())
                QTest::addRow("%s: %s", qPrintable(heading), qPrintable(tag)) << m_commands << option;
        }
    }
}

// An option the page describes is one that the command (or, in a shared section, at least one
// command) still has.
void TestManPage::documentedOptionsExist()
{
    QFETCH(QStringList, commands);
    QFETCH(QString, option);
    for (const QString &command : std::as_const(commands)) {
        for (const HelpOption &o : optionsOf(command)) {
            if (o.name == option)
                return;
        }
    }
    QFAIL(qPrintable(QStringLiteral("the man page describes --%1, but the --help of %2 does not list it")
                         .arg(option, commands.join(QStringLiteral(", ")))));
}

void TestManPage::helpOptionsAreExplained()
{
    const QString text = m_page.plainText();
    for (const char *option : {"--help", "--help-all", "--version"})
        QVERIFY2(mentions(text, QLatin1String(option)), option);
}

void TestManPage::rendersWithoutWarnings()
{
    const QString groff = findProgram(QStringLiteral("groff"));
    if (groff.isEmpty())
        QSKIP("groff is not installed (Debian: groff-base)");
    const ProcessRun run = runProcess(groff, {QStringLiteral("-man"), QStringLiteral("-ww"), QStringLiteral("-z"),
                                              QStringLiteral(MBSCOPE_MAN_PAGE)});
    QVERIFY2(run.succeeded(), run.describe().constData());
    QVERIFY2(run.err.isEmpty(), run.describe().constData());
}

QTEST_GUILESS_MAIN(TestManPage)
#include "tst_manpage.moc"
