#pragma once
// An event-driven simulation as plain text (docs/model.md sections 3, 10 and 11): what
// `capsubot simulate` prints.

#include <string>
#include <vector>

#include "capsubot/job/simulate_job.hpp"

namespace capsubot::text {

/// The force and model, the start, the status and final state, the transient apart, the
/// displacement and mean velocity (beside the analytic orbit's when started from it), the
/// events and the energy budget.
std::string SimulateJobText(const SimulateJobResult& result);

/// What a reader of the run must be told apart from its text or JSON, one note each: that the
/// analytic orbit it started from is not valid ("the analytic orbit is not valid (x_min, ...)"),
/// that the run stopped at its work bound ("stopped early: ..."). Empty when neither.
std::vector<std::string> SimulateJobNotes(const SimulateJobResult& result);

}  // namespace capsubot::text
