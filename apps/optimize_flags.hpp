#pragma once
// The flags of the optimize job's settings: the command line's one table of names for the
// library's rules (OptimizeJobFrom) and its provenance.

#include "capsubot/cli/setting_options.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot::cli {

/// The flag of each setting of the optimize job (OptimizeSettings' fields), and of the fields of
/// the lower stages' messages ("levels" of a pulse drive).
inline const FlagNames kOptimizeFlags = DashedFlags(
    "problem A c harmonics hops starts bound rho_max max_time "
    "global_algorithm local_algorithm global_evaluations alpha T0_range "
    "waveform pulse_levels from_rest_starts reach_starts "
    "reach_evaluations reach_local_evaluations reach_seconds "
    "drive_evaluations drive_polishes drive_local_evaluations "
    "drive_refine_evaluations drive_screens band_levels threads "
    "from_rest_csv",
    {{"levels", "--pulse-levels"}});

/// The fields the messages of the lower stages are rewritten with: the table, and the gait's
/// force bound ("force_bound = 2 is invalid: ...") set by --bound.
inline const FlagNames kOptimizeRenamedFields = [] {
  FlagNames names = kOptimizeFlags;
  names.emplace_back("force_bound", "--bound");
  return names;
}();

}  // namespace capsubot::cli
