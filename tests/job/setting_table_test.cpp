// The tables of a job's settings (capsubot/job/setting_table.hpp): a help names the other
// settings by their fields, which a front end writes in its names.

#include "capsubot/job/setting_table.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

#include "capsubot/job/motion_settings.hpp"

namespace capsubot {
namespace {

TEST(SettingTable, AHelpNamesTheSettingsInTheFrontEndsNames) {
  const FlagNames flags = {{"max_period", "--max-period"}, {"record", "--record"}};
  EXPECT_EQ(HelpIn("at least 2 {max_period}, as {record} and {max_period}", flags),
            "at least 2 --max-period, as --record and --max-period");
  // Braces that are not a named field are text: a list of keys, an unknown field.
  EXPECT_EQ(HelpIn("state {x, u, v}; {psi}", flags), "state {x, u, v}; {psi}");
  EXPECT_EQ(HelpIn("{record}", {{"record", "record"}}), "record");
}

// Each row of the motion table sets a field of its own, with a help, and a range only where one
// is given: two rows on one member would bind two flags to one value.
TEST(SettingTable, EveryMotionSettingSetsAFieldOfItsOwn) {
  const SettingTable<MotionOptions>& table = MotionSettings();
  ASSERT_FALSE(table.empty());
  std::set<std::string> fields;
  MotionOptions o;
  std::set<const void*> members;
  for (const auto& row : table) {
    EXPECT_TRUE(fields.insert(row.field).second) << row.field;
    EXPECT_GT(std::string(row.help).size(), 10u) << row.field;
    EXPECT_LE(row.lo, row.hi) << row.field;
    std::visit([&](auto m) { EXPECT_TRUE(members.insert(&(o.*m)).second) << row.field; },
               row.member);
  }
}

}  // namespace
}  // namespace capsubot
