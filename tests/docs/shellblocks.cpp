#include "shellblocks.h"

#include <QtCore/QRegularExpression>

namespace mbscope::testdocs {

namespace {

const QStringList kShellLanguages = {QStringLiteral("sh"), QStringLiteral("shell"), QStringLiteral("bash"), QStringLiteral("console")};

void applyDirective(const QString &directive, ShellBlock &block)
{
    static const QRegularExpression skip(QStringLiteral(R"(^skip\s*\((.+)\)$)"));
    static const QRegularExpression exit(QStringLiteral(R"(^exit\s+(\d+)$)"));
    static const QRegularExpression setup(QStringLiteral(R"(^setup\s+(.+)$)"));
    static const QRegularExpression sub(QStringLiteral(R"(^sub\s+(.+?)\s+=>\s+(.+)$)"));
    static const QRegularExpression stop(QStringLiteral(R"(^stop after\s+(\d+)\s*s$)"));
    static const QRegularExpression timeout(QStringLiteral(R"(^timeout\s+(\d+)\s*s$)"));
    QRegularExpressionMatch m;
    if ((m = skip.match(directive)).hasMatch())
        block.skip = m.captured(1);
    else if ((m = exit.match(directive)).hasMatch())
        block.exitStatus = m.captured(1).toInt();
    else if ((m = setup.match(directive)).hasMatch())
        block.setup.append(m.captured(1));
    else if ((m = sub.match(directive)).hasMatch())
        block.substitutions.append({m.captured(1), m.captured(2)});
    else if ((m = stop.match(directive)).hasMatch())
        block.stopAfterSeconds = m.captured(1).toInt();
    else if ((m = timeout.match(directive)).hasMatch())
        block.timeoutSeconds = m.captured(1).toInt();
    else
        block.problems.append(QStringLiteral("unknown directive 'docs-test: %1'").arg(directive));
}

// The docs-test comments on the lines before the fence at index fence (blank lines between
// them allowed).
void readDirectives(const QStringList &lines, int fence, ShellBlock &block)
{
    static const QRegularExpression comment(QStringLiteral(R"(^<!--\s*docs-test:\s*(.*?)\s*-->$)"));
    QStringList found;
    for (int i = fence - 1; i >= 0; --i) {
        const QString line = lines.at(i).trimmed();
        if (line.isEmpty())
            continue;
        const QRegularExpressionMatch m = comment.match(line);
        if (!m.hasMatch())
            break;
        found.prepend(m.captured(1));
    }
    for (const QString &directive : std::as_const(found))
        applyDirective(directive, block);
}

QString consoleCommands(const QStringList &body)
{
    QStringList commands;
    bool continued = false;
    for (const QString &line : body) {
        if (continued) {
            commands.append(line);
        } else if (line.startsWith(QLatin1String("$ "))) {
            commands.append(line.mid(2));
        } else {
            continue;
        }
        continued = line.endsWith(QLatin1Char('\\'));
    }
    return commands.join(QLatin1Char('\n'));
}

} // namespace

QList<ShellBlock> shellBlocks(const QString &markdown)
{
    const QStringList lines = markdown.split(QLatin1Char('\n'));
    QList<ShellBlock> blocks;
    for (int i = 0; i < lines.size(); ++i) {
        const QString fence = lines.at(i).trimmed();
        if (!fence.startsWith(QLatin1String("```")))
            continue;
        const QString language = fence.mid(3).trimmed();
        int end = i + 1;
        while (end < lines.size() && !lines.at(end).trimmed().startsWith(QLatin1String("```")))
            ++end;
        const QStringList body = lines.mid(i + 1, end - i - 1);
        ShellBlock block;
        block.line = i + 1;
        block.language = language;
        if (kShellLanguages.contains(language)) {
            block.script = language == QLatin1String("console") ? consoleCommands(body) : body.join(QLatin1Char('\n'));
            readDirectives(lines, i, block);
            blocks.append(block);
        } else if (language.isEmpty() && !body.isEmpty()
                   && (body.first().startsWith(QLatin1String("$ ")) || body.first().startsWith(QLatin1String("mbscope ")))) {
            block.problems.append(QStringLiteral("a block of commands with no language: tag it ```sh (a script) or ```console "
                                                 "(commands after \"$ \", their output below) so that it is run"));
            blocks.append(block);
        }
        i = end;
    }
    return blocks;
}

QList<ShellBlock> helpBlocks(const QString &help, const QString &command)
{
    static const QRegularExpression opening(QStringLiteral(R"(^Examples?\b.*:$)"));
    static const QRegularExpression simulator(QStringLiteral(R"(\(with (mbscope simulate [^);]+?) running[;)])"));
    static const QRegularExpression notRun(QStringLiteral(R"(\(not run by the tests: ([^)]+)\))"));
    const QStringList lines = help.split(QLatin1Char('\n'));
    const QString own = QStringLiteral("mbscope %1 ").arg(command);
    QList<ShellBlock> blocks;
    bool ownExample = false;
    for (int i = 0; i < lines.size(); ++i) {
        const QString &line = lines.at(i);
        if (!line.startsWith(QLatin1String("Example")))
            continue;
        ShellBlock block;
        block.line = i + 1;
        block.language = QStringLiteral("help");
        if (!opening.match(line).hasMatch()) {
            block.problems.append(QStringLiteral("'%1': an example's commands go on the lines after \"Example...:\", each "
                                                 "indented by two spaces").arg(line));
            blocks.append(block);
            continue;
        }
        if (const QRegularExpressionMatch m = notRun.match(line); m.hasMatch())
            block.skip = m.captured(1);
        const QRegularExpressionMatch sim = simulator.match(line);
        if (sim.hasMatch()) {
            block.setup.append(sim.captured(1) + QStringLiteral(" --quiet --ready-file sim%1.ready &").arg(i));
            block.setup.append(QStringLiteral("until [ -e sim%1.ready ]; do sleep 0.1; done").arg(i));
        }
        QStringList commands;
        while (i + 1 < lines.size() && lines.at(i + 1).startsWith(QLatin1String("  mbscope ")))
            commands.append(lines.at(++i).mid(2));
        if (commands.isEmpty())
            block.problems.append(QStringLiteral("'%1' is followed by no command (\"  mbscope ...\")").arg(line));
        for (const QString &c : std::as_const(commands))
            ownExample = ownExample || (c + QLatin1Char(' ')).startsWith(own);
        block.script = commands.join(QLatin1Char('\n'));
        blocks.append(block);
    }
    if (!ownExample) {
        ShellBlock missing;
        missing.language = QStringLiteral("help");
        missing.problems.append(QStringLiteral("mbscope %1 --help has no example of mbscope %1 (\"Example:\", then the command "
                                               "on the next line, indented by two spaces)").arg(command));
        blocks.append(missing);
    }
    return blocks;
}

} // namespace mbscope::testdocs
