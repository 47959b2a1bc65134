#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// `mbscope completion bash|zsh`: prints a shell completion script generated from every
// subcommand's --help (the parsers' own text): subcommands, options, which options take a value,
// file and directory values, fixed choices.
int runCompletion(const QStringList &arguments);

} // namespace mbscope::app
