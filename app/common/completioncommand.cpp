#include "common/completioncommand.h"

#include "common/cli.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QRegularExpression>
#include <QtCore/QTextStream>

#include <algorithm>

namespace mbscope::app {

namespace {

const QStringList kShells{QStringLiteral("bash"), QStringLiteral("zsh")};

// What an option's value (or a positional argument) completes to, from its value name.
enum class ValueKind { None, Word, File, Directory, Choices };

struct Completable {
    QStringList names; // "-h", "--help"
    ValueKind kind = ValueKind::None;
    QString valueName;  // as the help shows it: "FILE", "exception|ignore"
    QStringList choices;
};

struct CommandCompletion {
    QString name;
    QString summary;
    QList<Completable> options;
    bool hasPositional = false;
    Completable positional; // its kind: File, or Choices
};

// FILE, file, PATH and NAME|FILE complete file names; DIR directories; a value name that lists
// lower-case words (exception|ignore) those words; anything else (url, N, max|N) nothing.
void classify(Completable &c, const QString &valueName)
{
    static const QRegularExpression word(QStringLiteral("^[a-z][a-z0-9-]*$"));
    c.valueName = valueName;
    const QStringList alternatives = valueName.split(QLatin1Char('|'));
    for (const QString &a : alternatives) {
        const QString lower = a.toLower();
        if (lower == QLatin1String("file") || lower == QLatin1String("path")) {
            c.kind = ValueKind::File;
            return;
        }
        if (lower == QLatin1String("dir") || lower == QLatin1String("directory")) {
            c.kind = ValueKind::Directory;
            return;
        }
    }
    const bool allWords = alternatives.size() > 1
        && std::all_of(alternatives.cbegin(), alternatives.cend(), [](const QString &a) { return word.match(a).hasMatch(); });
    c.kind = allWords ? ValueKind::Choices : ValueKind::Word;
    if (allWords)
        c.choices = alternatives;
}

// The options QCommandLineParser lists under "Options:" ("  -t, --target <url>   The device...")
// and the positional arguments ("Arguments:"; choices from the usage line's "bash|zsh").
CommandCompletion parseHelp(const SubcommandHelp &help)
{
    static const QRegularExpression optionLine(
        QStringLiteral(R"(^  (-[^\s,<]+(?:, -[^\s,<]+)*)(?: <([^>]+)>)?(?:\s{2,}|$))"));
    CommandCompletion command{help.name, help.summary, {}, false, {}};
    const QStringList lines = help.help.split(QLatin1Char('\n'));
    bool inOptions = false;
    for (const QString &line : lines) {
        if (line == QLatin1String("Options:")) {
            inOptions = true;
            continue;
        }
        if (line == QLatin1String("Arguments:")) {
            command.hasPositional = true;
            inOptions = false;
            continue;
        }
        if (line.isEmpty() || !line.startsWith(QLatin1Char(' '))) {
            inOptions = false;
            continue;
        }
        if (!inOptions)
            continue;
        const QRegularExpressionMatch m = optionLine.match(line);
        if (!m.hasMatch())
            continue;
        Completable option;
        option.names = m.captured(1).split(QStringLiteral(", "));
        if (m.hasCaptured(2) && !m.captured(2).isEmpty())
            classify(option, m.captured(2));
        command.options.append(option);
    }
    command.positional.kind = ValueKind::File;
    const QString usage = lines.value(0);
    const qsizetype afterOptions = usage.indexOf(QLatin1String("[options]"));
    if (command.hasPositional && afterOptions >= 0) {
        const QStringList tokens = usage.mid(afterOptions + 9).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        for (const QString &token : tokens) {
            if (token.contains(QLatin1Char('|')))
                classify(command.positional, token);
        }
    }
    return command;
}

QList<CommandCompletion> commandCompletions(const CommandLineIndex &index)
{
    QList<CommandCompletion> commands;
    for (const SubcommandHelp &help : index.subcommands())
        commands.append(parseHelp(help));
    return commands;
}

QStringList optionNames(const CommandCompletion &command)
{
    QStringList names;
    for (const Completable &o : command.options)
        names += o.names;
    return names;
}

// A case pattern per option of a kind: 'read --record'|'write --record'
QStringList casePatterns(const QList<CommandCompletion> &commands, ValueKind kind, const QStringList &choices = {})
{
    QStringList patterns;
    for (const CommandCompletion &c : commands) {
        for (const Completable &o : c.options) {
            if (o.kind != kind || (kind == ValueKind::Choices && o.choices != choices))
                continue;
            for (const QString &name : o.names)
                patterns.append(QStringLiteral("'%1 %2'").arg(c.name, name));
        }
    }
    return patterns;
}

QString bashScript(const QList<CommandCompletion> &commands, const QStringList &topLevelOptions)
{
    QString s;
    QTextStream out(&s);
    QStringList first;
    for (const CommandCompletion &c : commands)
        first.append(c.name);
    first += topLevelOptions;

    out << "# bash completion for mbscope " << MBSCOPE_VERSION << "                    -*- shell-script -*-\n"
        << "# Generated by `mbscope completion bash` from every subcommand's --help; do not edit.\n"
        << "# Load it in a shell with: source <(mbscope completion bash)\n\n"
        << "_mbscope()\n{\n"
        << "    local cur=${COMP_WORDS[COMP_CWORD]} prev=''\n"
        << "    (( COMP_CWORD > 0 )) && prev=${COMP_WORDS[COMP_CWORD-1]}\n"
        << "    COMPREPLY=()\n"
        << "    # The first word: a subcommand, or one of mbscope's own options.\n"
        << "    if (( COMP_CWORD == 1 )); then\n"
        << "        mapfile -t COMPREPLY < <(compgen -W '" << first.join(QLatin1Char(' ')) << "' -- \"$cur\")\n"
        << "        return 0\n    fi\n\n"
        << "    # The value of the option before the cursor.\n"
        << "    case \"${COMP_WORDS[1]} $prev\" in\n";
    const auto emitCase = [&out](const QStringList &patterns, const QString &body) {
        if (patterns.isEmpty())
            return;
        out << "        " << patterns.join(QStringLiteral(" | \\\n        ")) << ")\n" << body << "            return 0 ;;\n";
    };
    emitCase(casePatterns(commands, ValueKind::File),
             QStringLiteral("            compopt -o filenames 2>/dev/null\n"
                            "            mapfile -t COMPREPLY < <(compgen -f -- \"$cur\")\n"));
    emitCase(casePatterns(commands, ValueKind::Directory),
             QStringLiteral("            compopt -o filenames 2>/dev/null\n"
                            "            mapfile -t COMPREPLY < <(compgen -d -- \"$cur\")\n"));
    QList<QStringList> choiceSets;
    for (const CommandCompletion &c : commands) {
        for (const Completable &o : c.options) {
            if (o.kind == ValueKind::Choices && !choiceSets.contains(o.choices))
                choiceSets.append(o.choices);
        }
    }
    for (const QStringList &choices : std::as_const(choiceSets))
        emitCase(casePatterns(commands, ValueKind::Choices, choices),
                 QStringLiteral("            mapfile -t COMPREPLY < <(compgen -W '%1' -- \"$cur\")\n").arg(choices.join(QLatin1Char(' '))));
    out << "        # Values with nothing to offer (URLs, numbers, durations...).\n";
    emitCase(casePatterns(commands, ValueKind::Word), QString());
    out << "    esac\n\n"
        << "    local options='' choices='' files=''\n"
        << "    case ${COMP_WORDS[1]} in\n";
    for (const CommandCompletion &c : commands) {
        out << "        " << c.name << ")\n            options='" << optionNames(c).join(QLatin1Char(' ')) << "'";
        if (c.hasPositional && c.positional.kind == ValueKind::Choices)
            out << "\n            choices='" << c.positional.choices.join(QLatin1Char(' ')) << "'";
        else if (c.hasPositional)
            out << "\n            files=1";
        out << " ;;\n";
    }
    out << "        *) return 0 ;;\n"
        << "    esac\n"
        << "    if [[ $cur == -* ]]; then\n"
        << "        mapfile -t COMPREPLY < <(compgen -W \"$options\" -- \"$cur\")\n"
        << "    elif [[ -n $choices ]]; then\n"
        << "        mapfile -t COMPREPLY < <(compgen -W \"$choices\" -- \"$cur\")\n"
        << "    elif [[ -n $files ]]; then\n"
        << "        compopt -o filenames 2>/dev/null\n"
        << "        mapfile -t COMPREPLY < <(compgen -f -- \"$cur\")\n"
        << "    else\n"
        << "        mapfile -t COMPREPLY < <(compgen -W \"$options\" -- \"$cur\")\n"
        << "    fi\n"
        << "    return 0\n"
        << "}\n\n"
        << "complete -F _mbscope mbscope\n";
    out.flush();
    return s;
}

// A single-quoted zsh word.
QString zshQuoted(QString text)
{
    text.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    return QLatin1Char('\'') + text + QLatin1Char('\'');
}

QString zshAction(const Completable &c)
{
    switch (c.kind) {
    case ValueKind::File:
        return QStringLiteral("_files");
    case ValueKind::Directory:
        return QStringLiteral("_files -/");
    case ValueKind::Choices:
        return QLatin1Char('(') + c.choices.join(QLatin1Char(' ')) + QLatin1Char(')');
    case ValueKind::None:
    case ValueKind::Word:
        break;
    }
    return QStringLiteral(" ");
}

QString zshScript(const QList<CommandCompletion> &commands, const QStringList &topLevelOptions)
{
    QString s;
    QTextStream out(&s);
    out << "#compdef mbscope\n"
        << "# zsh completion for mbscope " << MBSCOPE_VERSION << "\n"
        << "# Generated by `mbscope completion zsh` from every subcommand's --help; do not edit.\n"
        << "# Install it as _mbscope in a directory of $fpath, or load it with: source <(mbscope completion zsh)\n\n"
        << "_mbscope() {\n"
        << "    local curcontext=$curcontext ret=1\n"
        << "    if (( CURRENT == 2 )); then\n"
        << "        local -a subcommands\n"
        << "        subcommands=(\n";
    for (const CommandCompletion &c : commands)
        out << "            " << zshQuoted(c.name + QLatin1Char(':') + c.summary) << '\n';
    out << "        )\n"
        << "        _describe -t subcommands 'mbscope subcommand' subcommands && ret=0\n"
        << "        if [[ $PREFIX == -* ]]; then\n"
        << "            compadd -- " << topLevelOptions.join(QLatin1Char(' ')) << " && ret=0\n"
        << "        fi\n"
        << "        return ret\n"
        << "    fi\n"
        << "    local subcommand=$words[2]\n"
        << "    shift words\n"
        << "    (( CURRENT-- ))\n"
        << "    curcontext=\"${curcontext%:*:*}:mbscope-$subcommand:\"\n"
        << "    case $subcommand in\n";
    for (const CommandCompletion &c : commands) {
        out << "        " << c.name << ")\n            _arguments -S";
        for (const Completable &o : c.options) {
            for (const QString &name : o.names) {
                // '*' allows an option again (several --hex, --format...).
                QString spec = QLatin1Char('*') + name;
                if (o.kind != ValueKind::None) {
                    QString message = o.valueName;
                    message.replace(QLatin1Char(':'), QLatin1Char('-'));
                    spec += QLatin1Char(':') + message + QLatin1Char(':') + zshAction(o);
                }
                out << " \\\n                " << zshQuoted(spec);
            }
        }
        if (c.hasPositional)
            out << " \\\n                "
                << zshQuoted(c.positional.kind == ValueKind::Choices
                                 ? QStringLiteral("1:%1:%2").arg(c.positional.valueName, zshAction(c.positional))
                                 : QStringLiteral("*:file:_files"));
        out << " && ret=0 ;;\n";
    }
    out << "    esac\n"
        << "    return ret\n"
        << "}\n\n"
        << "if [[ $funcstack[1] == _mbscope ]]; then\n"
        << "    _mbscope \"$@\"\n"
        << "else\n"
        << "    compdef _mbscope mbscope\n"
        << "fi\n";
    out.flush();
    return s;
}

} // namespace

int runCompletion(const QStringList &arguments, const CommandLineIndex &index)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Prints a completion script for bash or zsh, generated from every subcommand's options: "
                       "subcommand names, options, the values of FILE and DIR options as file names, fixed choices.\n"
                       "bash: source <(mbscope completion bash), or save it as "
                       "~/.local/share/bash-completion/completions/mbscope.\n"
                       "zsh: save it as _mbscope in a directory of $fpath (before compinit), or source <(mbscope completion zsh) after compinit.\n"
                       "The package installs both (share/bash-completion/completions/mbscope, share/zsh/vendor-completions/_mbscope).\n"
                       "Example, the bash script saved to a file (to source, or to put where bash-completion looks):\n"
                       "  mbscope completion bash > mbscope.bash\n"
                       "Exit status: 0 ok, 2 usage error."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("shell"), QStringLiteral("bash or zsh."), kShells.join(QLatin1Char('|')));
    if (!parser.parse(arguments)) {
        err << "mbscope completion: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "completion");
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1 || !kShells.contains(positional.constFirst())) {
        err << "mbscope completion: "
            << (positional.isEmpty() ? QStringLiteral("name the shell: bash or zsh")
                                     : QStringLiteral("'%1' is no shell it writes for (bash or zsh)").arg(positional.join(QLatin1Char(' '))))
            << " (see mbscope completion --help)\n";
        return ExitUsage;
    }
    const QList<CommandCompletion> commands = commandCompletions(index);
    out << (positional.constFirst() == QLatin1String("bash") ? bashScript(commands, index.topLevelOptions)
                                                             : zshScript(commands, index.topLevelOptions));
    return ExitOk;
}

} // namespace mbscope::app
