#include "capsubot/job/design_drive_settings.hpp"

namespace capsubot {

const SettingTable<DesignDriveChoice>& DesignDriveSettings() {
  using D = DesignDriveChoice;
  static const SettingTable<DesignDriveChoice> table = {
      {"drive", &D::drive,
       "instead of the one-impact design, the fastest drive from rest: the force's waveform "
       "(sine: A sin + c; fourier: {harmonics} K; pulse: {pulse_levels} N constant levels), the "
       "motor frequency over {frequency_range} and the inner mass over {m2_range}, under the "
       "motor's peak {force_max}, in each direction (docs/design.md, part (c)); no --force-* "
       "settings"},
      {"force_max", &D::force_max, "with {drive}: the motor's peak force max |F_N| [N], > 0"},
      {"harmonics", &D::harmonics,
       "with {drive} fourier: harmonics K of the drive, 1 <= K <= 16 (the search climbs K = 1, "
       "2, ..., K)"},
      {"pulse_levels", &D::pulse_levels,
       "with {drive} pulse: constant levels N of the drive, 2 <= N <= 16"}};
  return table;
}

}  // namespace capsubot
