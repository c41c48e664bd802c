#pragma once
// Which runs of the design job use which setting: one design (""), one design with the
// fastest motion from rest ("from-rest"), a design grid ("grid"), the fastest drive ("drive").
// Both front ends refuse a setting given to a run that does not use it (RejectUnusedSettings).

#include <string>
#include <vector>

#include "capsubot/job/setting_names.hpp"
#include "capsubot/job/setting_use.hpp"

namespace capsubot {

/// The runs that use each setting of the design job; a setting not listed shapes every run.
const std::vector<SettingUse>& DesignSettingUses();

/// The run `run` in `names`: the setting that selects it ("--from-rest", "--grid", "--drive"),
/// or for "" one design without them ("one design (no --from-rest, no --grid)").
std::string DesignRunName(const std::string& run, const SettingNames& names);

}  // namespace capsubot
