#pragma once
// The keywords of the optimize job's settings: each keyword is its setting's field name
// (OptimizeSettings), but for the fields of the lower stages' messages named otherwise.

#include "capsubot/model/setting_names.hpp"

namespace capsubot::python {

/// The keyword of each field whose keyword is not the field's own name ("levels" of a pulse
/// drive, set by pulse_levels; the gait's force_bound, set by bound).
inline const FlagNames kOptimizeKeywords = {{"levels", "pulse_levels"}, {"force_bound", "bound"}};

}  // namespace capsubot::python
