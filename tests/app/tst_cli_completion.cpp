// `mbscope completion bash|zsh`: the scripts name every subcommand and every option its --help
// lists, and bash itself, running the function, completes subcommands, options, fixed choices and
// file names; zsh (when installed) parses its script.
#include "clitest.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope::testcli;

namespace {

// The subcommands `mbscope --help` lists under "Subcommands:".
QStringList subcommandsOf(const QString &help)
{
    static const QRegularExpression line(QStringLiteral(R"(^  ([a-z][a-z0-9-]*)\s{2,}\S)"));
    QStringList names;
    bool in = false;
    for (const QString &l : help.split(QLatin1Char('\n'))) {
        if (l == QLatin1String("Subcommands:")) {
            in = true;
            continue;
        }
        if (in && l.isEmpty())
            break;
        const QRegularExpressionMatch m = line.match(l);
        if (in && m.hasMatch())
            names.append(m.captured(1));
    }
    return names;
}

// The long options a subcommand's --help lists.
QStringList longOptionsOf(const QString &help)
{
    static const QRegularExpression option(QStringLiteral(R"(^  (?:-\w, )?(--[A-Za-z0-9][A-Za-z0-9-]*))"));
    QStringList names;
    const QString options = help.section(QStringLiteral("\nOptions:\n"), 1).section(QStringLiteral("\n\n"), 0, 0);
    for (const QString &l : options.split(QLatin1Char('\n'))) {
        const QRegularExpressionMatch m = option.match(l);
        if (m.hasMatch())
            names.append(m.captured(1));
    }
    return names;
}

} // namespace

class TestCliCompletion : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void bashScriptNamesEveryOption();
    void bashCompletes_data();
    void bashCompletes();
    void bashCompletesFileNames();
    void zshScriptParses();
    void unknownShellIsAUsageError();

private:
    // COMPREPLY after _mbscope ran on words with the cursor on the last one.
    [[nodiscard]] QStringList complete(const QStringList &words, const QString &workingDir = {});

    QTemporaryDir m_dir;
    QString m_bashScript;
    QString m_bashPath;
};

void TestCliCompletion::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_bashPath = QStandardPaths::findExecutable(QStringLiteral("bash"));
    QVERIFY2(!m_bashPath.isEmpty(), "bash is not installed");
    const CliResult bash = runMbscope({QStringLiteral("completion"), QStringLiteral("bash")});
    QVERIFY2(bash.finished && bash.exitCode == 0, bash.describe().constData());
    QVERIFY2(bash.err.isEmpty(), bash.describe().constData());
    m_bashScript = bash.outText();
    QFile file(m_dir.filePath(QStringLiteral("mbscope.bash")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bash.out);
}

QStringList TestCliCompletion::complete(const QStringList &words, const QString &workingDir)
{
    QProcess bash;
    if (!workingDir.isEmpty())
        bash.setWorkingDirectory(workingDir);
    bash.start(m_bashPath, QStringList{QStringLiteral("-c"),
                                       QStringLiteral("source \"$0\" || exit 9; COMP_WORDS=(\"$@\"); COMP_CWORD=$(($# - 1)); "
                                                      "_mbscope; printf '%s\\n' \"${COMPREPLY[@]}\""),
                                       m_dir.filePath(QStringLiteral("mbscope.bash"))}
                                + words);
    if (!bash.waitForFinished(30000) || bash.exitCode() != 0) {
        qWarning("bash: %s %s", bash.readAllStandardOutput().constData(), bash.readAllStandardError().constData());
        return {QStringLiteral("<bash failed>")};
    }
    const QByteArray err = bash.readAllStandardError();
    if (!err.isEmpty())
        return {QStringLiteral("<bash wrote to stderr: %1>").arg(QString::fromUtf8(err))};
    QStringList reply = QString::fromUtf8(bash.readAllStandardOutput()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    reply.sort();
    return reply;
}

// Every subcommand `mbscope --help` lists, with every long option its --help lists, is in the
// script's table: the script is made from the parsers, no option is left out.
void TestCliCompletion::bashScriptNamesEveryOption()
{
    const CliResult help = runMbscope({QStringLiteral("--help")});
    QVERIFY2(help.exitCode == 0, help.describe().constData());
    const QStringList commands = subcommandsOf(help.outText());
    QVERIFY2(commands.contains(QStringLiteral("read")) && commands.contains(QStringLiteral("completion")), qPrintable(help.outText()));
    for (const QString &command : commands) {
        const QRegularExpression entry(QStringLiteral(R"(\n        %1\)\n            options='([^']*)')").arg(command));
        const QRegularExpressionMatch m = entry.match(m_bashScript);
        QVERIFY2(m.hasMatch(), qPrintable(QStringLiteral("no entry for %1 in the bash script").arg(command)));
        const QStringList scriptOptions = m.captured(1).split(QLatin1Char(' '));
        const CliResult commandHelp = runMbscope({command, QStringLiteral("--help")});
        QVERIFY2(commandHelp.exitCode == 0, commandHelp.describe().constData());
        const QStringList options = longOptionsOf(commandHelp.outText());
        QVERIFY2(options.size() >= 2, qPrintable(commandHelp.outText()));
        for (const QString &option : options)
            QVERIFY2(scriptOptions.contains(option),
                     qPrintable(QStringLiteral("mbscope %1 --help lists %2, the bash completion does not").arg(command, option)));
    }
    QVERIFY(m_bashScript.contains(QLatin1String("complete -F _mbscope mbscope")));
    QVERIFY(m_bashScript.contains(QLatin1String("'read --target'")));
}

void TestCliCompletion::bashCompletes_data()
{
    QTest::addColumn<QStringList>("words");
    QTest::addColumn<QStringList>("expected");
    const auto words = [](const char *line) {
        QStringList w = QString::fromLatin1(line).split(QLatin1Char(' '));
        return w;
    };
    QTest::newRow("subcommand") << words("mbscope re") << QStringList{QStringLiteral("read"), QStringLiteral("replay")};
    QTest::newRow("top-level option") << words("mbscope --vers") << QStringList{QStringLiteral("--version")};
    QTest::newRow("no such subcommand") << words("mbscope record") << QStringList{};
    QTest::newRow("read option") << words("mbscope read --ta")
                                 << QStringList{QStringLiteral("--table"), QStringLiteral("--target")};
    QTest::newRow("after a value") << words("mbscope read --target tcp://127.0.0.1 --qu")
                                   << QStringList{QStringLiteral("--quantity")};
    QTest::newRow("value of --target") << words("mbscope read --target ") << QStringList{};
    QTest::newRow("fixed choices") << words("mbscope replay --unrecorded ")
                                   << QStringList{QStringLiteral("exception"), QStringLiteral("ignore")};
    QTest::newRow("completion's shell") << words("mbscope completion ")
                                        << QStringList{QStringLiteral("bash"), QStringLiteral("zsh")};
    QTest::newRow("unknown subcommand") << words("mbscope sned --ta") << QStringList{};
}

void TestCliCompletion::bashCompletes()
{
    QFETCH(QStringList, words);
    QFETCH(QStringList, expected);
    QCOMPARE(complete(words), expected);
}

// A FILE value (--record) completes file names, DIR (watch --csv) directories, a positional
// argument (analyze's capture) file names.
void TestCliCompletion::bashCompletesFileNames()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    QFile journal(work.filePath(QStringLiteral("bench.mbscope.journal")));
    QVERIFY(journal.open(QIODevice::WriteOnly));
    journal.close();
    QVERIFY(QDir(work.path()).mkdir(QStringLiteral("bench-logs")));
    const QString dir = work.path();
    QCOMPARE(complete({QStringLiteral("mbscope"), QStringLiteral("read"), QStringLiteral("--record"), QStringLiteral("be")}, dir),
             (QStringList{QStringLiteral("bench-logs"), QStringLiteral("bench.mbscope.journal")}));
    QCOMPARE(complete({QStringLiteral("mbscope"), QStringLiteral("watch"), QStringLiteral("--csv"), QStringLiteral("be")}, dir),
             QStringList{QStringLiteral("bench-logs")});
    QCOMPARE(complete({QStringLiteral("mbscope"), QStringLiteral("analyze"), QStringLiteral("bench.")}, dir),
             QStringList{QStringLiteral("bench.mbscope.journal")});
}

void TestCliCompletion::zshScriptParses()
{
    const CliResult zsh = runMbscope({QStringLiteral("completion"), QStringLiteral("zsh")});
    QVERIFY2(zsh.finished && zsh.exitCode == 0 && zsh.err.isEmpty(), zsh.describe().constData());
    QVERIFY(zsh.out.startsWith("#compdef mbscope\n"));
    QVERIFY(zsh.outText().contains(QLatin1String("'*--target:url: '")));
    QVERIFY(zsh.outText().contains(QLatin1String("'*--unrecorded:exception|ignore:(exception ignore)'")));
    QVERIFY(zsh.outText().contains(QLatin1String("'*--record:FILE:_files'")));
    const QString zshPath = QStandardPaths::findExecutable(QStringLiteral("zsh"));
    if (zshPath.isEmpty())
        QSKIP("zsh is not installed (scripts/install-deps.sh --tests installs it): the script's syntax is not checked");
    const QString path = m_dir.filePath(QStringLiteral("_mbscope"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(zsh.out);
    file.close();
    QProcess check;
    check.start(zshPath, {QStringLiteral("-n"), path});
    QVERIFY(check.waitForFinished(30000));
    QVERIFY2(check.exitCode() == 0, check.readAllStandardError().constData());
}

void TestCliCompletion::unknownShellIsAUsageError()
{
    const CliResult fish = runMbscope({QStringLiteral("completion"), QStringLiteral("fish")});
    QCOMPARE(fish.exitCode, 2);
    QVERIFY(fish.out.isEmpty());
    QVERIFY2(fish.errText().contains(QLatin1String("bash or zsh")), fish.describe().constData());
    const CliResult none = runMbscope({QStringLiteral("completion")});
    QCOMPARE(none.exitCode, 2);
}

QTEST_GUILESS_MAIN(TestCliCompletion)
#include "tst_cli_completion.moc"
