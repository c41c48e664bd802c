#pragma once
// The design job's own settings: which runs use which setting (one design (""), one design
// with the fastest motion from rest ("from-rest"), a design grid ("grid"), the fastest drive
// ("drive")), and the drive design's choice as `capsubot design` offers it: the waveform of the
// fastest drive, the motor's peak and the size of a Fourier or pulse waveform. Both front ends
// refuse a setting given to a run that does not use it (RejectUnusedSettings). The robot's
// settings are the config stage's; the search's starts and budgets are the from-rest search's.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "capsubot/job/setting_table.hpp"
#include "capsubot/job/setting_use.hpp"
#include "capsubot/model/setting_names.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/reach/drive_family.hpp"

namespace capsubot {

/// The runs that use each setting of the design job; a setting not listed shapes every run.
const std::vector<SettingUse>& DesignSettingUses();

/// Refuses (std::invalid_argument, in `names`) a setting of the drive design that the waveform
/// `drive` ("sine", "fourier" or "pulse") does not use: harmonics without fourier, pulse_levels
/// without pulse, the budgets of a drive search (drive_*) with the sine, which is searched as the
/// reach problem.
void RejectUnusedDriveSettings(const std::string& drive, const std::set<std::string>& given,
                               const SettingNames& names);

/// The harmonics of the drive design's waveform "fourier" and the levels of "pulse", when not
/// given.
inline constexpr int kDesignDriveHarmonics = 2;
inline constexpr int kDesignDrivePulseLevels = 3;

/// The waveform `drive` of the drive design: "sine", "fourier" with `harmonics` or "pulse" with
/// `pulse_levels`. Throws std::invalid_argument, in `names`, for another name.
DriveFamily DesignDriveFamily(const std::string& drive, int harmonics, int pulse_levels,
                              const SettingNames& names);

/// Refuses (std::invalid_argument, in `names`) the drive design asked together with the motion
/// from rest (`from_rest`) or a grid (`grid`): it searches the force itself. Accepts neither.
void RejectRunsWithDrive(bool from_rest, bool grid, const SettingNames& names);

/// The runs of the design job a front end's settings select, and what each refuses.
struct DesignRunChoice {
  std::optional<std::string> drive;  ///< the drive design's waveform; none: no drive design
  bool grid = false;                 ///< a design grid
  bool from_rest = false;            ///< one design with the fastest motion from rest

  /// "drive", "grid", "from-rest" or "" (one design).
  std::string Run() const;
  /// Refuses (std::invalid_argument, in `names`, the runs named by `run_name`) what the run
  /// cannot take: a drive waveform of another name, the drive design with the motion from rest
  /// or a grid, the motion from rest with a grid, a setting of `given` that the run does not use
  /// (DesignSettingUses, then the front end's own `more`), a drive setting its waveform does not
  /// use (RejectUnusedDriveSettings).
  void RejectUnused(const std::set<std::string>& given, const SettingNames& names,
                    const ModeName& run_name, const std::vector<SettingUse>& more = {}) const;
};

/// The run `run` in `names`: the setting that selects it ("--from-rest", "--grid", "--drive"),
/// or for "" one design without them ("one design (no --from-rest, no --grid)").
std::string DesignRunName(const std::string& run, const SettingNames& names);

/// The drive design asked for (DesignDriveFamily reads drive, harmonics and pulse_levels).
struct DesignDriveChoice {
  std::string drive;                           ///< "sine", "fourier", "pulse"; "": no drive design
  double force_max = kNaN;                     ///< the motor's peak force max |F_N| [N]
  int harmonics = kDesignDriveHarmonics;       ///< the waveform "fourier"'s harmonics K
  int pulse_levels = kDesignDrivePulseLevels;  ///< the waveform "pulse"'s levels N
};

/// drive, force_max, harmonics, pulse_levels. The helps name the robot's ranges of the
/// frequency and the inner mass as {frequency_range} and {m2_range}.
const SettingTable<DesignDriveChoice>& DesignDriveSettings();

}  // namespace capsubot
