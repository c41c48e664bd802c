#pragma once
// The flags of the sweep job's settings: the command line's one table of names for the
// library's rules (SweepJobFrom), its provenance and the messages of the lower stages.

#include "capsubot/cli/setting_options.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot::cli {

/// The flag of each setting of the sweep job (SweepSettings' fields), of the command's own
/// options and of the fields of the lower stages' messages (the reach search's budgets).
inline const FlagNames kSweepFlags = DashedFlags(
    "grid plot_column plot optimize output threads resume "
    "checkpoint_seconds scan_points harmonics starts hops "
    "global_evaluations rho_max alpha shard A c phi0 sin cos waveform "
    "levels switches T0 e margin margin_stroke stick_margin stability "
    "stable_only bound global_algorithm local_algorithm "
    "from_rest_starts reach_starts reach_evaluations "
    "reach_local_evaluations",
    {{"reach.global_evaluations", "--reach-evaluations"},
     {"reach.local_evaluations", "--reach-local-evaluations"}});

/// The fields the messages of the lower stages are rewritten with: the table but for the
/// settings those messages name by a description ("friction bound T0 = 0 is invalid: ...") or
/// never name. The gait's force_bound keeps its field: a grid axis may set it as well as --bound.
inline const FlagNames kSweepRenamedFields =
    Without(kSweepFlags, {"waveform", "levels", "switches", "T0", "e", "margin", "margin_stroke",
                          "stick_margin", "stability", "stable_only", "bound", "from_rest_starts",
                          "reach_starts", "reach_evaluations", "reach_local_evaluations"});

}  // namespace capsubot::cli
