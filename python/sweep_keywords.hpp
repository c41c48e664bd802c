#pragma once
// The keywords of the sweep job's settings: each keyword is its setting's field name
// (SweepSettings), but for the fields of the lower stages' messages named otherwise.

#include "capsubot/model/setting_names.hpp"

namespace capsubot::python {

/// The keyword of each field whose keyword is not the field's own name (the reach search's
/// budgets, named by their place in the job's options). The gait's force_bound keeps its field:
/// a grid axis may set it as well as bound.
inline const FlagNames kSweepKeywords = {{"reach.global_evaluations", "reach_evaluations"},
                                         {"reach.local_evaluations", "reach_local_evaluations"}};

}  // namespace capsubot::python
