#pragma once
// A subcommand of the program: its parser, what it runs, whether it distributes its work over
// the ranks of an MPI job; and its messages in the flags' names.

#include <CLI/CLI.hpp>
#include <functional>

#include "capsubot/model/setting_names.hpp"

namespace capsubot::cli {

/// A subcommand: its parser and what to run once the command line is parsed. `run` returns
/// the exit status; it throws std::invalid_argument or IoError for bad input (exit status 2).
struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;
  /// Whether the command as parsed distributes its work over the ranks of an MPI job
  /// (capsubot/cluster/ranks.hpp); empty: it never does, and main refuses it under mpirun with P
  /// > 1.
  std::function<bool()> distributed;
};

/// Runs `run`; a std::invalid_argument, WriteError or IoError it throws is thrown again (the
/// same type) WithFlagNames(names): the library's field names as the flags that set them.
int RunNamingFlags(const FlagNames& names, const std::function<int()>& run);

}  // namespace capsubot::cli
