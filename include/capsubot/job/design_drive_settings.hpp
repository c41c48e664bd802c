#pragma once
// The drive design's own settings as `capsubot design` offers them: the waveform of the
// fastest drive, the motor's peak and the size of a Fourier or pulse waveform. The robot's
// settings are the config stage's; the search's starts and budgets are the from-rest search's.

#include <string>

#include "capsubot/job/design_settings.hpp"
#include "capsubot/job/setting_table.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

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
