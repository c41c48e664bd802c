// The robot of the design job from its settings (capsubot/config/design_config.hpp): the
// order defaults, config file, front end, grid; the messages in each front end's names; the
// settings a provenance lists. The command line's flags and files are tested through the
// program (tests/cli/design_cli_test.cpp), the module's keywords in python/tests/test_design.py.

#include "capsubot/config/design_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "test_utils.hpp"

namespace capsubot {
namespace {

// The two styles of names: a flag given a value and the bare setting (the command line), the
// keyword for both (the Python module).
const DesignConfigNames kFlags{[](const std::string& name) { return "--" + name; },
                               [](const std::string& name) { return name; }, "as flags"};

std::string Keyword(std::string name) {
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}
const DesignConfigNames kKeywords{Keyword, Keyword, "as keyword arguments"};

// A config file with `text` (in the test's temporary folder).
std::string WriteConfig(const std::string& name, const std::string& text) {
  const std::filesystem::path path = testing::TempPath(name);
  std::ofstream(path) << text;
  return path.string();
}

// The example robot (examples/robot.toml).
const char* kRobot =
    "m1 = 0.2\nL = 0.02\nmu = 0.3\ne = 0.7\nforce-amplitude = 0.5\nforce-bias = 0.1\n"
    "frequency = 20\n";

TEST(DesignConfig, TheFrontEndOverridesTheFileAndTheGridOverridesBoth) {
  DesignConfigInput input;
  input.config = WriteConfig("robot.toml", kRobot);
  input.given = {{"mu", "0.25"}, {"frequency-range", "10:30"}};
  input.grid = {ParseDesignGridAxis("e=0.5,0.6")};
  DesignSettingTexts settings;
  const DesignInput in = BuildDesignInput(input, kFlags, &settings);
  EXPECT_EQ(in.m1, 0.2);              // the file
  EXPECT_EQ(in.mu, 0.25);             // the front end over the file
  EXPECT_EQ(in.e, 0.5);               // the grid's first value over the file
  EXPECT_EQ(in.frequency_min, 10.0);  // the front end's range replaces the file's frequency
  EXPECT_EQ(in.frequency_max, 30.0);
  EXPECT_EQ(in.g, DesignInput{}.g);  // the default
  // Every setting the input has, in the table's order, without the grid's e; the frequency's
  // alternative that is used (the range), the default g and scan-points included.
  const DesignSettingTexts expected = {{"m1", "0.2"},
                                       {"L", "0.02"},
                                       {"mu", "0.25"},
                                       {"g", "9.81"},
                                       {"force-amplitude", "0.5"},
                                       {"force-bias", "0.1"},
                                       {"frequency-range", "10:30"},
                                       {"margin", "0"},
                                       {"margin-stroke", "0.02"},
                                       {"stick-margin", "0.02"},
                                       {"rho-max", "0.9"},
                                       {"scan-points", "64"}};
  EXPECT_EQ(settings, expected);
}

TEST(DesignConfig, TheTableNamesEverySettingOnceWithItsHelpAndSyntax) {
  const std::vector<DesignRobotSetting>& table = DesignRobotSettings();
  ASSERT_FALSE(table.empty());
  std::set<std::string> names;
  for (const DesignRobotSetting& s : table) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_NE(std::string(s.help), "") << s.name;
    EXPECT_NE(std::string(s.syntax), "") << s.name;
    // The library names settings bare: each front end writes its own prefix.
    EXPECT_NE(std::string(s.name).rfind("-", 0), 0U) << s.name;
  }
}

TEST(DesignConfig, MessagesNameTheSettingsAsEachFrontEndWritesThem) {
  const auto message = [](const DesignConfigInput& input, const DesignConfigNames& names) {
    return testing::InvalidArgumentMessage([&] { BuildDesignInput(input, names); });
  };
  DesignConfigInput bad_value;
  bad_value.config = WriteConfig("robot_bad_value.toml", kRobot);
  bad_value.given = {{"scan-points", "6.5"}};
  EXPECT_EQ(message(bad_value, kFlags),
            "--scan-points = 6.5 is invalid: expected an integer -2147483648 <= n <= 2147483647");
  EXPECT_EQ(message(bad_value, kKeywords),
            "scan_points = 6.5 is invalid: expected an integer -2147483648 <= n <= 2147483647");

  DesignConfigInput both;
  both.config = WriteConfig("robot_both.toml", kRobot);
  both.given = {{"frequency", "20"}, {"frequency-range", "10:30"}};
  EXPECT_EQ(message(both, kFlags),
            "settings frequency and frequency-range are both given as flags: expected one of them");
  EXPECT_EQ(message(both, kKeywords),
            "settings frequency and frequency_range are both given as keyword arguments: expected "
            "one of them");

  DesignConfigInput missing;
  missing.given = {
      {"m1", "0.2"}, {"mu", "0.3"}, {"e", "0.7"}, {"force-bias", "0.1"}, {"force-sin", "0.5"}};
  EXPECT_EQ(message(missing, kFlags),
            "settings L and frequency or frequency-range are missing: give --L and --frequency "
            "(or L and frequency in the --config file)");
  EXPECT_EQ(message(missing, kKeywords),
            "settings L and frequency or frequency_range are missing: give L and frequency (or L "
            "and frequency in the config file)");

  DesignConfigInput drive;
  drive.config = WriteConfig("robot_drive.toml", kRobot);
  drive.motor_force = false;
  EXPECT_EQ(message(drive, kKeywords),
            "setting force_amplitude is invalid with drive: expected no motor force (the drive "
            "search chooses it; give the motor's peak with force_max)");
  EXPECT_EQ(testing::InvalidArgumentMessage([] { RequireDriveForceMax(kNaN, kKeywords); }),
            "setting force_max is missing: drive needs the motor's peak force, give force_max");
}

TEST(DesignConfig, TheFileIsCheckedAsTheFileWritesIt) {
  DesignConfigInput unknown;
  unknown.config = WriteConfig("robot_unknown.toml", "m1 = 0.2\nmass = 1\n");
  const std::string message =
      testing::InvalidArgumentMessage([&] { BuildDesignInput(unknown, kKeywords); });
  EXPECT_EQ(message.rfind("mass = 1 in " + unknown.config +
                              " is invalid: unknown key, expected one of m1, L, mu, g, e,",
                          0),
            0U)
      << message;

  DesignConfigInput deep;
  deep.config = WriteConfig("robot_deep.toml", "m1 = " + std::string(40, '[') + "\n");
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { BuildDesignInput(deep, kKeywords); }),
            "config file " + deep.config +
                " line 1 is invalid: keys and values nested more than 32 deep: expected at most "
                "32 levels (parts of dotted keys and table headers, nested arrays and inline "
                "tables)");
}

}  // namespace
}  // namespace capsubot
