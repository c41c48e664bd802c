// "Did you mean" (capsubot/cli/suggest.hpp): the nearest name to a mistyped command or flag,
// and `help COMMAND` read as `COMMAND --help`.

#include "capsubot/cli/suggest.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace capsubot::cli {
namespace {

TEST(Suggest, NearestIsTheCaseTwinElseTheClosestWithinAThird) {
  const std::vector<std::string> flags = {"--T0", "--e", "--threads", "--transient"};
  EXPECT_EQ(Nearest("--t0", flags), "--T0");                // case only
  EXPECT_EQ(Nearest("--thread", flags), "--threads");       // one edit
  EXPECT_EQ(Nearest("--transeint", flags), "--transient");  // two edits in eleven characters
  EXPECT_EQ(Nearest("--zzzzzz", flags), std::nullopt);      // nothing that close
  EXPECT_EQ(Nearest("anything", {}), std::nullopt);
}

CLI::App& Program(CLI::App& app) {
  CLI::App* optimize = app.add_subcommand("optimize", "");
  static double bound = 0;
  optimize->add_option("--bound", bound);
  app.add_subcommand("orbits", "");
  return app;
}

TEST(Suggest, AnUnknownCommandOrFlagNamesTheNearest) {
  CLI::App app{"test"};
  Program(app);
  EXPECT_EQ(UnknownCommand(app, "optimize"), std::nullopt);
  EXPECT_EQ(UnknownCommand(app, "--help"), std::nullopt);
  const auto command = UnknownCommand(app, "optimise");
  ASSERT_TRUE(command.has_value());
  EXPECT_NE(command->find("did you mean 'optimize'?"), std::string::npos) << *command;
  const auto flag = UnknownFlag(*app.get_subcommand("optimize"), {"--bond", "1"});
  ASSERT_TRUE(flag.has_value());
  EXPECT_NE(flag->find("--bond"), std::string::npos) << *flag;
  EXPECT_NE(flag->find("did you mean --bound?"), std::string::npos) << *flag;
  EXPECT_EQ(UnknownFlag(*app.get_subcommand("optimize"), {"--zzzzzzzz"}), std::nullopt);
}

TEST(Suggest, HelpCommandIsTheCommandsHelp) {
  EXPECT_EQ(ReadHelpCommand({"help"}), std::vector<std::string>({"--help"}));
  EXPECT_EQ(ReadHelpCommand({"help", "solve"}), std::vector<std::string>({"solve", "--help"}));
  EXPECT_EQ(ReadHelpCommand({"solve", "--A", "1"}),
            std::vector<std::string>({"solve", "--A", "1"}));
}

}  // namespace
}  // namespace capsubot::cli
