// The bash completion script (capsubot/cli/completion_script.hpp), written from a program's own
// commands and flags: each command's branch proposes its flags, the choices of a flag whose type
// name lists them, file names after a FILE, and nothing after a value to type.

#include "capsubot/cli/completion_script.hpp"

#include <gtest/gtest.h>

#include <string>

namespace capsubot::cli {
namespace {

TEST(CompletionScript, EachCommandHasItsFlagsAndTheirValues) {
  CLI::App app{"test", "capsubot"};
  CLI::App* run = app.add_subcommand("run", "");
  std::string mode, output;
  double x = 0;
  run->add_option("--mode", mode)->type_name("phi0|forcing|FLOAT");
  run->add_option("-o,--output", output)->type_name("FILE");
  run->add_option("--x", x);
  app.add_subcommand("other", "");
  const std::string script = BashCompletion(app);
  EXPECT_NE(script.find("\"\") _capsubot_words \"run other"), std::string::npos) << script;
  EXPECT_NE(script.find("    run)\n"), std::string::npos) << script;
  EXPECT_NE(script.find("--mode) _capsubot_words \"phi0 forcing\"; return ;;"),
            std::string::npos)
      << script;  // the choices, not the type to type (FLOAT)
  EXPECT_NE(script.find("-o|--output) _capsubot_files; return ;;"), std::string::npos) << script;
  EXPECT_NE(script.find("--x) return ;;"), std::string::npos) << script;
  EXPECT_NE(script.find("flags=\"-h --help --mode -o --output --x\""), std::string::npos) << script;
  EXPECT_NE(script.find("    other)\n"), std::string::npos) << script;
  EXPECT_NE(script.find("complete -F _capsubot capsubot"), std::string::npos);
}

}  // namespace
}  // namespace capsubot::cli
