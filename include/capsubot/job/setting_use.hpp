#pragma once
// Which modes of a job use a setting. A mode is what a job's mode setting selects (`optimize`'s
// problem, "" for the main job); a setting given to a mode that does not use it would be
// silently ignored, so the job refuses it; a setting left to its default that a mode does not
// use does not shape the mode's output (a front end leaves it out of the provenance).

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "capsubot/model/setting_names.hpp"

namespace capsubot {

struct SettingUse {
  std::string setting;             ///< the field, "hops"
  std::vector<std::string> modes;  ///< the modes that use it ("": the main job)
  bool UsedBy(const std::string& mode) const;
};

/// The settings of `uses` that `mode` does not use, in the table's order.
std::vector<std::string> UnusedSettings(const std::vector<SettingUse>& uses,
                                        const std::string& mode);

/// A mode as a job's messages name it, in a front end's names ("--problem forcing").
using ModeName = std::function<std::string(const std::string& mode)>;

/// Throws std::invalid_argument for the first setting of `uses` in `given` that `mode` does not
/// use: "<setting> <verb> <mode>: expected <setting> only with <mode> or <mode>", in `names`
/// ("--alpha conflicts with the main job (no --problem): expected --alpha only with --problem
/// reach").
void RejectUnusedSettings(const std::vector<SettingUse>& uses, const std::set<std::string>& given,
                          const std::string& mode, const ModeName& mode_name,
                          const SettingNames& names, const char* verb = "conflicts with");

}  // namespace capsubot
