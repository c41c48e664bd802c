// capsubot: the command-line program. Parses, runs one subcommand, maps errors to exit codes:
// 0 done, 2 bad input (one line on stderr naming the parameter, its value and the rule),
// 1 a computation that could not be completed (one line saying why: also a failed write, on
// standard output too) or an unexpected failure. SIGINT/SIGTERM remove temporary files. Under
// mpirun with several processes, only the commands that distribute their work run.

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/cli/command.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/cli/suggest.hpp"
#include "capsubot/cluster/ranks.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/model/version.hpp"
#include "commands.hpp"

namespace {

std::string OneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// CLI11 says "Could not convert: --A = abc"; say which rule the value broke. Our number
// validators name the option themselves: "--A: --A = '' is invalid: ..." loses its prefix.
std::string ParseErrorMessage(const CLI::ParseError& e) {
  const std::string text = OneLine(e.what());
  const std::string prefix = "Could not convert: ";
  if (dynamic_cast<const CLI::ConversionError*>(&e) != nullptr && text.rfind(prefix, 0) == 0) {
    return text.substr(prefix.size()) + " is invalid: expected a number";
  }
  const std::size_t colon = text.find(": ");
  if (dynamic_cast<const CLI::ValidationError*>(&e) != nullptr && colon != std::string::npos &&
      text.compare(colon + 2, colon + 1, text.substr(0, colon) + " ") == 0) {
    return text.substr(colon + 2);
  }
  return text;
}

// The arguments CLI11 did not expect, from its message "The following arguments were not
// expected: --t0 1".
std::vector<std::string> UnexpectedArguments(const CLI::ParseError& e) {
  const std::string text = e.what();
  const std::size_t colon = text.find(": ");
  std::vector<std::string> words;
  if (colon == std::string::npos) return words;
  for (const std::string& word : capsubot::SplitText(text.substr(colon + 2), ' ')) {
    if (!word.empty()) words.push_back(word);
  }
  return words;
}

// Prints `who: error: text` and returns `status`. Under mpirun every process parses the same
// command line, so bad input (status 2) is said once, by the process of rank 0; a failure of
// the computation (status 1) is said by the process it happens on, with its rank.
int Fail(const std::string& who, const std::string& text, int status) {
  const int rank = capsubot::LaunchedRank();
  if (status == 2 && rank != 0) return status;
  const std::string where =
      rank > 0 ? fmt::format(" (process of rank {} of an MPI job)", rank) : std::string();
  fmt::print(stderr, "{}: error{}: {}\n", who, where, text);
  return status;
}

// Under mpirun with P > 1 processes, a command that does not distribute its work would run P
// times over: refused (exit 2).
int RefuseOneProcessCommand(const std::string& who, const std::string& name, int processes) {
  return Fail(who,
              fmt::format("mpirun -n {} is invalid for {}: it runs on one process; expected "
                          "mpirun only for sweep, basins, attractors, bifurcation and design "
                          "--grid (docs/cluster.md)",
                          processes, name),
              2);
}

// Output that did not reach standard output (a full disk, /dev/full) is a failed run.
int CheckStdout(const std::string& who, int status) {
  errno = 0;
  if (std::fflush(stdout) == 0 && std::ferror(stdout) == 0) return status;
  const int err = errno != 0 ? errno : EIO;
  return Fail(who, fmt::format("standard output cannot be written: {}", std::strerror(err)), 1);
}

// Says why CLI11 refused the command line (naming the command, if one was recognised) and
// returns exit status 2.
int RefuseCommandLine(const CLI::App& app, const CLI::ParseError& e) {
  const auto subs = app.get_subcommands();
  const std::string who = subs.empty() ? "capsubot" : "capsubot " + subs.front()->get_name();
  if (dynamic_cast<const CLI::ConversionError*>(&e) != nullptr ||
      dynamic_cast<const CLI::ValidationError*>(&e) != nullptr) {
    return Fail(who, ParseErrorMessage(e), 2);
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr && !subs.empty()) {
    if (const auto flag = capsubot::cli::UnknownFlag(*subs.front(), UnexpectedArguments(e))) {
      return Fail(who, *flag, 2);
    }
  }
  return Fail(who, fmt::format("{} (see {} --help)", ParseErrorMessage(e), who), 2);
}

// Runs the command the command line chose and returns its exit status: an error it throws
// is said on one line and mapped to its status (2 bad input, 1 a failed computation).
int RunCommand(const capsubot::cli::Command& command) {
  const std::string who = "capsubot " + command.parser->get_name();
  const int processes = capsubot::LaunchedProcesses();
  if (processes > 1 && !(command.distributed && command.distributed())) {
    return RefuseOneProcessCommand(who, command.parser->get_name(), processes);
  }
  try {
    return CheckStdout(who, command.run());
  } catch (const std::invalid_argument& e) {
    return Fail(who, OneLine(e.what()), 2);
  } catch (const capsubot::WriteError& e) {  // the file could be opened: not bad input
    return Fail(who, OneLine(e.what()), 1);
  } catch (const capsubot::IoError& e) {
    return Fail(who, OneLine(e.what()), 2);
  } catch (const std::runtime_error& e) {  // a computation that could not be completed
    return Fail(who, OneLine(e.what()), 1);
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: internal error: {}\n", who, OneLine(e.what()));
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace capsubot::cli;
  capsubot::InstallTempFileCleanup();
  capsubot::UseLauncherStdout();  // rank 0 under mpirun: a failed write to standard output is seen
  // Past the file size limit (ulimit -f) a write fails with EFBIG and the run says so, keeping
  // what can be resumed, instead of being killed by SIGXFSZ without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "capsubot: one-impact periodic gaits of a vibro-impact capsule robot (A. P. Ivanov, "
      "Vibroimpact Mobile Robot, 2021). All quantities are dimensionless: phases in rad, "
      "positions in units of the inner body's free gap L (walls at x = 0 and 1), velocities in "
      "omega*L, forces in (m1+m2)*omega^2*L.",
      "capsubot"};
  // Before the commands are added: each command takes its parent's formatter.
  app.formatter(std::make_shared<HelpFormatter>(HelpWidth()));
  app.set_version_flag("--version", capsubot::Version(), "Print the version and exit");
  app.require_subcommand(1, 1);
  app.failure_message(CLI::FailureMessage::simple);
  const std::vector<Command> commands = {
      AddSolveCommand(app),     AddSimulateCommand(app),    AddOrbitsCommand(app),
      AddSweepCommand(app),     AddMergeCommand(app),       AddOptimizeCommand(app),
      AddDesignCommand(app),    AddAttractorsCommand(app),  AddPeriodicCommand(app),
      AddBasinsCommand(app),    AddBifurcationCommand(app), AddContinueCommand(app),
      AddCompletionCommand(app)};
  // After the commands are added, which would take it too (and print only their own help).
  app.set_help_all_flag("--help-all", "Print the help of every command and exit");
  UseStrictValues(app);
  // A bare `capsubot` asks what the program does: the help with the list of commands, as
  // --help, exit status 0 (nothing was asked that could be wrong).
  if (argc <= 1) {
    fmt::print("{}", app.help());
    return CheckStdout("capsubot", 0);
  }
  std::vector<std::string> args = ReadHelpCommand(std::vector<std::string>(argv + 1, argv + argc));
  if (!args.empty()) {
    if (const auto unknown = UnknownCommand(app, args.front()))
      return Fail("capsubot", *unknown, 2);
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version: printed by exit()
    return CheckStdout("capsubot", app.exit(e));
  } catch (const CLI::ParseError& e) {
    return RefuseCommandLine(app, e);
  }
  for (const Command& command : commands) {
    if (command.parser->parsed()) return RunCommand(command);
  }
  return 2;
}
