#include "capsubot/job/design_settings.hpp"

#include <fmt/format.h>

namespace capsubot {

const std::vector<SettingUse>& DesignSettingUses() {
  static const std::vector<SettingUse> uses = {
      {"from_rest_starts", {"from-rest", "drive"}},
      {"reach_starts", {"from-rest", "drive"}},
      {"reach_evaluations", {"from-rest", "drive"}},
      {"reach_local_evaluations", {"from-rest", "drive"}},
      {"reach_seconds", {"from-rest", "drive"}},
      {"threads", {"from-rest", "grid", "drive"}},
      {"force_max", {"drive"}},
      {"harmonics", {"drive"}},
      {"pulse_levels", {"drive"}},
      {"drive_evaluations", {"drive"}},
      {"drive_polishes", {"drive"}},
      {"drive_local_evaluations", {"drive"}},
      {"drive_refine_evaluations", {"drive"}},
      {"drive_screens", {"drive"}},
      {"band_levels", {"", "from-rest"}},
  };
  return uses;
}

void RejectUnusedDriveSettings(const std::string& drive, const std::set<std::string>& given,
                               const SettingNames& names) {
  const std::vector<SettingUse> uses = {
      {"harmonics", {"fourier"}},
      {"pulse_levels", {"pulse"}},
      {"drive_evaluations", {"fourier", "pulse"}},
      {"drive_polishes", {"fourier", "pulse"}},
      {"drive_local_evaluations", {"fourier", "pulse"}},
      {"drive_refine_evaluations", {"fourier", "pulse"}},
      {"drive_screens", {"fourier", "pulse"}},
  };
  RejectUnusedSettings(
      uses, given, drive, [&names](const std::string& d) { return names.Given("drive", d); }, names,
      "is invalid with");
}

std::string DesignRunName(const std::string& run, const SettingNames& names) {
  if (run.empty()) {
    return fmt::format("one design ({}, {})", names.Absent("from_rest"), names.Absent("grid"));
  }
  if (run == "from-rest") return names.Name("from_rest");
  return names.Name(run);
}

}  // namespace capsubot
