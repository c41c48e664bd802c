#pragma once
// The flags of the design job's settings that only some runs use: the command line's table of
// names for the library's rule (DesignSettingUses) and its provenance.

#include "capsubot/model/setting_names.hpp"

namespace capsubot::app {

/// The flag of each setting of the design job that a run may not use, of the switches that
/// select the runs (--from-rest, --grid, --drive), and of the fields of the lower stages'
/// messages ("levels" of a pulse drive).
inline const FlagNames kDesignFlags = {{"from_rest_starts", "--from-rest-starts"},
                                       {"reach_starts", "--reach-starts"},
                                       {"reach_evaluations", "--reach-evaluations"},
                                       {"reach_local_evaluations", "--reach-local-evaluations"},
                                       {"reach_seconds", "--reach-seconds"},
                                       {"threads", "--threads"},
                                       {"json", "--json"},
                                       {"output", "--output"},
                                       {"force_max", "--force-max"},
                                       {"harmonics", "--harmonics"},
                                       {"pulse_levels", "--pulse-levels"},
                                       {"levels", "--pulse-levels"},
                                       {"drive_evaluations", "--drive-evaluations"},
                                       {"drive_polishes", "--drive-polishes"},
                                       {"drive_local_evaluations", "--drive-local-evaluations"},
                                       {"drive_refine_evaluations", "--drive-refine-evaluations"},
                                       {"drive_screens", "--drive-screens"},
                                       {"shard", "--shard"},
                                       {"resume", "--resume"},
                                       {"band_levels", "--band-levels"},
                                       {"from_rest", "--from-rest"},
                                       {"grid", "--grid"},
                                       {"drive", "--drive"}};

}  // namespace capsubot::app
