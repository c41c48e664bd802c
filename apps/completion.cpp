// capsubot completion: the bash completion script, written from the commands and flags the
// program itself has, so that the two cannot drift apart. The build writes it to
// capsubot.bash, `cmake --install` puts it in share/bash-completion/completions/capsubot.

#include <fmt/format.h>

#include <memory>
#include <string>

#include "capsubot/cli/command.hpp"
#include "capsubot/cli/completion_script.hpp"
#include "capsubot/cli/help_format.hpp"
#include "commands.hpp"

namespace capsubot::cli {

Command AddCompletionCommand(CLI::App& app) {
  auto shell = std::make_shared<std::string>("bash");
  CLI::App* cmd = app.add_subcommand(
      "completion",
      "Print the completion script of the shell: its commands, their flags and the values of "
      "the flags that have a few or name a file. `cmake --install` installs it for bash "
      "(share/bash-completion/completions/capsubot); without installing, `source "
      "<(capsubot completion bash)` in ~/.bashrc (docs/cli.md).");
  cmd->add_option("SHELL", *shell, "the shell (bash only)")
      ->capture_default_str()
      ->check(CLI::IsMember({"bash"}).description(""))
      ->type_name("bash");
  SetExamples(*cmd, {{"the script for bash: `source capsubot.bash` completes capsubot's commands "
                      "and flags in that shell",
                      "completion bash > capsubot.bash"}});
  return {cmd,
          [&app, shell] {  // `shell` lives as long as the command (its option writes it)
            fmt::print("{}", BashCompletion(app));
            return 0;
          },
          {}};
}

}  // namespace capsubot::cli
