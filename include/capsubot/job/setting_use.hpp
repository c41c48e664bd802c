#pragma once
// Which modes of a job use a setting. A mode is what a job's mode setting selects (`optimize`'s
// problem, "" for the main job); a setting given to a mode that does not use it would be
// silently ignored, so the job refuses it; a setting left to its default that a mode does not
// use does not shape the mode's output (a front end leaves it out of the provenance).

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "capsubot/job/setting_table.hpp"
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

/// The modes of a job as the helps of its settings name them.
struct ModeSet {
  const char* field;               ///< the setting that selects the mode: "problem", "optimize"
  std::vector<std::string> modes;  ///< every mode but the main job: "phase", "forcing", ...
  const char* main_job;            ///< the run without a mode: "the main job", "no {optimize}"
};

/// The runs of `set` that use `setting` (by `uses`; a setting not listed: every run) as the
/// opening of its help, in the help's brace syntax: "with {problem} forcing|reach: ", "with the
/// main job or {problem} reach: ", "with {optimize}: " (every mode but the main job); "" when
/// every run uses it.
std::string ModesOpening(const std::vector<SettingUse>& uses, const std::string& setting,
                         const ModeSet& set);

/// `table` with the help of each row opened by the runs that use its setting (ModesOpening):
/// one meaning of a setting, written once, in the words of each job's modes.
template <class Options>
SettingTable<Options> WithModes(SettingTable<Options> table, const std::vector<SettingUse>& uses,
                                const ModeSet& set) {
  for (SettingRow<Options>& row : table) {
    row.help = KeptText(ModesOpening(uses, row.field, set) + row.help);
  }
  return table;
}

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
