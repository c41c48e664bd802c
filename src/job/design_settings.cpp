#include "capsubot/job/design_settings.hpp"

#include <fmt/format.h>

#include <stdexcept>

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

DriveFamily DesignDriveFamily(const std::string& drive, int harmonics, int pulse_levels,
                              const SettingNames& names) {
  if (drive == "sine") return DriveFamily{};
  if (drive == "fourier") return DriveFamily::Fourier(harmonics);
  if (drive == "pulse") return DriveFamily::Pulse(pulse_levels);
  throw std::invalid_argument(fmt::format("{} is invalid: expected {}, {} or {}",
                                          names.Given("drive", drive), names.Value("sine"),
                                          names.Value("fourier"), names.Value("pulse")));
}

void RejectRunsWithDrive(bool from_rest, bool grid, const SettingNames& names) {
  if (!from_rest && !grid) return;
  throw std::invalid_argument(fmt::format(
      "{} is invalid with {}: expected one of them ({} searches the force itself)",
      names.Name(from_rest ? "from_rest" : "grid"), names.Name("drive"), names.Name("drive")));
}

std::string DesignRunChoice::Run() const {
  if (drive) return "drive";
  if (grid) return "grid";
  return from_rest ? "from-rest" : "";
}

void DesignRunChoice::RejectUnused(const std::set<std::string>& given, const SettingNames& names,
                                   const ModeName& run_name,
                                   const std::vector<SettingUse>& more) const {
  if (drive) {
    DesignDriveFamily(*drive, kDesignDriveHarmonics, kDesignDrivePulseLevels, names);
    RejectRunsWithDrive(from_rest, grid, names);
  }
  if (grid && from_rest) {
    throw std::invalid_argument(fmt::format(
        "{} is invalid with {}: expected one of them (a grid writes the one-impact gait of each "
        "point to its CSV file)",
        names.Name("from_rest"), names.Name("grid")));
  }
  RejectUnusedSettings(DesignSettingUses(), given, Run(), run_name, names, "is invalid with");
  RejectUnusedSettings(more, given, Run(), run_name, names, "is invalid with");
  if (drive) RejectUnusedDriveSettings(*drive, given, names);
}

std::string DesignRunName(const std::string& run, const SettingNames& names) {
  if (run.empty()) {
    return fmt::format("one design ({}, {})", names.Absent("from_rest"), names.Absent("grid"));
  }
  if (run == "from-rest") return names.Name("from_rest");
  return names.Name(run);
}

const SettingTable<DesignDriveChoice>& DesignDriveSettings() {
  static const SettingTable<DesignDriveChoice> table = {
      {"drive", &DesignDriveChoice::drive,
       "instead of the one-impact design, the fastest drive from rest: the force's waveform "
       "(sine: A sin + c; fourier: {harmonics} K; pulse: {pulse_levels} N constant levels), the "
       "motor frequency over {frequency_range} and the inner mass over {m2_range}, under the "
       "motor's peak {force_max}, in each direction (docs/design.md, part (c)); no --force-* "
       "settings"},
      {"force_max", &DesignDriveChoice::force_max,
       "with {drive}: the motor's peak force max |F_N| [N], > 0"},
      {"harmonics", &DesignDriveChoice::harmonics,
       "with {drive} fourier: harmonics K of the drive, 1 <= K <= 16 (the search climbs K = 1, "
       "2, ..., K)"},
      {"pulse_levels", &DesignDriveChoice::pulse_levels,
       "with {drive} pulse: constant levels N of the drive, 2 <= N <= 16"}};
  return table;
}

}  // namespace capsubot
