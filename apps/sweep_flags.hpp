#pragma once
// The flags of the sweep job's settings: the command line's one table of names for the
// library's rules (SweepJobFrom), its provenance and the messages of the lower stages.

#include "capsubot/model/setting_names.hpp"

namespace capsubot::app {

/// The flag of each setting of the sweep job (SweepSettings' fields), of the command's own
/// options and of the fields of the lower stages' messages (the reach search's budgets).
inline const FlagNames kSweepFlags = {{"grid", "--grid"},
                                      {"plot_column", "--plot-column"},
                                      {"plot", "--plot"},
                                      {"optimize", "--optimize"},
                                      {"output", "--output"},
                                      {"threads", "--threads"},
                                      {"resume", "--resume"},
                                      {"checkpoint_seconds", "--checkpoint-seconds"},
                                      {"scan_points", "--scan-points"},
                                      {"harmonics", "--harmonics"},
                                      {"starts", "--starts"},
                                      {"hops", "--hops"},
                                      {"global_evaluations", "--global-evaluations"},
                                      {"rho_max", "--rho-max"},
                                      {"alpha", "--alpha"},
                                      {"shard", "--shard"},
                                      {"A", "--A"},
                                      {"c", "--c"},
                                      {"phi0", "--phi0"},
                                      {"sin", "--sin"},
                                      {"cos", "--cos"},
                                      {"reach.global_evaluations", "--reach-evaluations"},
                                      {"reach.local_evaluations", "--reach-local-evaluations"},
                                      {"waveform", "--waveform"},
                                      {"levels", "--levels"},
                                      {"switches", "--switches"},
                                      {"T0", "--T0"},
                                      {"e", "--e"},
                                      {"margin", "--margin"},
                                      {"margin_stroke", "--margin-stroke"},
                                      {"stick_margin", "--stick-margin"},
                                      {"stability", "--stability"},
                                      {"stable_only", "--stable-only"},
                                      {"bound", "--bound"},
                                      {"global_algorithm", "--global-algorithm"},
                                      {"local_algorithm", "--local-algorithm"},
                                      {"from_rest_starts", "--from-rest-starts"},
                                      {"reach_starts", "--reach-starts"},
                                      {"reach_evaluations", "--reach-evaluations"},
                                      {"reach_local_evaluations", "--reach-local-evaluations"}};

/// The fields the messages of the lower stages are rewritten with: the table but for the
/// settings those messages name by a description ("friction bound T0 = 0 is invalid: ...") or
/// never name, and the gait's force bound ("force_bound = 2 is invalid: ...") set by --bound.
inline const FlagNames kSweepRenamedFields = [] {
  FlagNames names =
      Without(kSweepFlags, {"waveform", "levels", "switches", "T0", "e", "margin", "margin_stroke",
                            "stick_margin", "stability", "stable_only", "bound", "from_rest_starts",
                            "reach_starts", "reach_evaluations", "reach_local_evaluations"});
  names.emplace_back("force_bound", "--bound");
  return names;
}();

}  // namespace capsubot::app
