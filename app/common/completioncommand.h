#pragma once

#include "common/cli.h"

#include <QtCore/QStringList>

namespace mbscope::app {

// `mbscope completion bash|zsh`: prints a shell completion script generated from every
// subcommand's --help (the parsers' own text): subcommands, options, which options take a value,
// file and directory values, fixed choices. The dispatcher gives the index of its subcommands, so
// that completion does not depend on the dispatcher that runs it.
int runCompletion(const QStringList &arguments, const CommandLineIndex &index);

} // namespace mbscope::app
