#pragma once
// The flags of the design job's settings that only some runs use: the command line's table of
// names for the library's rule (DesignSettingUses) and its provenance.

#include "capsubot/cli/setting_options.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot::cli {

/// The flag of each setting of the design job that a run may not use, of the switches that
/// select the runs (--from-rest, --grid, --drive), and of the fields of the lower stages'
/// messages ("levels" of a pulse drive).
inline const FlagNames kDesignFlags = DashedFlags(
    "from_rest_starts reach_starts reach_evaluations "
    "reach_local_evaluations reach_seconds threads json output "
    "force_max harmonics pulse_levels drive_evaluations drive_polishes "
    "drive_local_evaluations drive_refine_evaluations drive_screens "
    "shard resume band_levels from_rest grid drive",
    {{"levels", "--pulse-levels"}});

}  // namespace capsubot::cli
