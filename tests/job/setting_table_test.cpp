// The tables of a job's settings (capsubot/job/setting_table.hpp): a help names the other
// settings by their fields, which a front end writes in its names.

#include "capsubot/job/setting_table.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

#include "capsubot/job/motion_settings.hpp"
#include "job/setting_table_checks.hpp"

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

// The checks the tables' tests make fail on a table that binds one value twice, repeats a field
// or names an unknown setting in a help; braces around other text are not names.
TEST(SettingTable, ChecksFindAValueOrFieldSetTwiceAndAnUnknownSetting) {
  const SettingTable<MotionOptions> bad = {
      {"record", &MotionOptions::record, "at least 2 {max_period} as {x, u, v}"},
      {"periods", &MotionOptions::record, "the {recrod}"},
      {"record", &MotionOptions::transient, "before {record}"}};
  const MotionOptions o;
  testing::SettingTablesCheck check;
  check.Add(bad, o);
  const ::testing::AssertionResult once = check.EachFieldAndValueOnce();
  EXPECT_FALSE(once);
  EXPECT_STREQ(once.message(), "set twice (field or value): periods record");
  const ::testing::AssertionResult known = check.HelpsNameKnownSettings({"max_period"});
  EXPECT_FALSE(known);
  EXPECT_STREQ(known.message(), "periods's help names {recrod}; ");
  EXPECT_EQ(check.AllPlaceholders(), (std::vector<std::string>{"max_period", "recrod", "record"}));
}

}  // namespace
}  // namespace capsubot
