#pragma once
// The bash completion script of a program, written from its own commands and flags, so that
// the two cannot drift apart: the commands, their flags, and the values of the flags that have
// a few (their type name lists them: "phi0|forcing|...") or name a file (type name FILE).

#include <CLI/CLI.hpp>
#include <string>

namespace capsubot::cli {

/// The bash completion script of `app` and its subcommands ("complete -F _capsubot capsubot").
std::string BashCompletion(const CLI::App& app);

}  // namespace capsubot::cli
