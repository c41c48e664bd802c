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
