#pragma once
// The flags of the optimize job's settings: the command line's one table of names for the
// library's rules (OptimizeJobFrom) and its provenance.

#include "capsubot/model/setting_names.hpp"

namespace capsubot::app {

/// The flag of each setting of the optimize job (OptimizeSettings' fields), and of the fields of
/// the lower stages' messages ("levels" of a pulse drive).
inline const FlagNames kOptimizeFlags = {{"problem", "--problem"},
                                         {"A", "--A"},
                                         {"c", "--c"},
                                         {"harmonics", "--harmonics"},
                                         {"hops", "--hops"},
                                         {"starts", "--starts"},
                                         {"bound", "--bound"},
                                         {"rho_max", "--rho-max"},
                                         {"max_time", "--max-time"},
                                         {"global_algorithm", "--global-algorithm"},
                                         {"local_algorithm", "--local-algorithm"},
                                         {"global_evaluations", "--global-evaluations"},
                                         {"alpha", "--alpha"},
                                         {"T0_range", "--T0-range"},
                                         {"waveform", "--waveform"},
                                         {"pulse_levels", "--pulse-levels"},
                                         {"from_rest_starts", "--from-rest-starts"},
                                         {"reach_starts", "--reach-starts"},
                                         {"reach_evaluations", "--reach-evaluations"},
                                         {"reach_local_evaluations", "--reach-local-evaluations"},
                                         {"reach_seconds", "--reach-seconds"},
                                         {"drive_evaluations", "--drive-evaluations"},
                                         {"drive_polishes", "--drive-polishes"},
                                         {"drive_local_evaluations", "--drive-local-evaluations"},
                                         {"drive_refine_evaluations", "--drive-refine-evaluations"},
                                         {"drive_screens", "--drive-screens"},
                                         {"band_levels", "--band-levels"},
                                         {"threads", "--threads"},
                                         {"from_rest_csv", "--from-rest-csv"},
                                         {"levels", "--pulse-levels"}};

/// The fields the messages of the lower stages are rewritten with: the table, and the gait's
/// force bound ("force_bound = 2 is invalid: ...") set by --bound.
inline const FlagNames kOptimizeRenamedFields = [] {
  FlagNames names = kOptimizeFlags;
  names.emplace_back("force_bound", "--bound");
  return names;
}();

}  // namespace capsubot::app
