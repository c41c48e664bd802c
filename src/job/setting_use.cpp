#include "capsubot/job/setting_use.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace capsubot {

bool SettingUse::UsedBy(const std::string& mode) const {
  return std::find(modes.begin(), modes.end(), mode) != modes.end();
}

std::vector<std::string> UnusedSettings(const std::vector<SettingUse>& uses,
                                        const std::string& mode) {
  std::vector<std::string> unused;
  for (const SettingUse& use : uses) {
    if (!use.UsedBy(mode)) unused.push_back(use.setting);
  }
  return unused;
}

std::string ModesOpening(const std::vector<SettingUse>& uses, const std::string& setting,
                         const ModeSet& set) {
  const auto use = std::find_if(uses.begin(), uses.end(),
                                [&setting](const SettingUse& u) { return u.setting == setting; });
  if (use == uses.end()) return "";
  std::string modes;
  for (const std::string& mode : set.modes) {
    if (use->UsedBy(mode)) modes += (modes.empty() ? "" : "|") + mode;
  }
  const bool every_mode = std::all_of(set.modes.begin(), set.modes.end(),
                                      [&use](const std::string& m) { return use->UsedBy(m); });
  std::string runs = use->UsedBy("") ? set.main_job : "";
  if (!modes.empty()) {
    const std::string field = "{" + std::string(set.field) + "}";
    runs += (runs.empty() ? "" : " or ") + (every_mode ? field : field + " " + modes);
  }
  if (use->UsedBy("") && every_mode) return "";
  return "with " + runs + ": ";
}

void RejectUnusedSettings(const std::vector<SettingUse>& uses, const std::set<std::string>& given,
                          const std::string& mode, const ModeName& mode_name,
                          const SettingNames& names, const char* verb) {
  for (const SettingUse& use : uses) {
    if (given.count(use.setting) == 0 || use.UsedBy(mode)) continue;
    std::string expected;
    for (const std::string& m : use.modes) {
      expected += (expected.empty() ? "" : " or ") + mode_name(m);
    }
    const std::string name = names.Name(use.setting);
    throw std::invalid_argument(fmt::format("{} {} {}: expected {} only with {}", name, verb,
                                            mode_name(mode), name, expected));
  }
}

}  // namespace capsubot
