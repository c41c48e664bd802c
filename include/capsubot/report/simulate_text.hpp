#pragma once
// An event-driven simulation as plain text (docs/model.md sections 3, 10 and 11): what
// `capsubot simulate` prints.

#include <string>

#include "capsubot/job/simulate_job.hpp"

namespace capsubot::text {

/// The force and model, the start, the status and final state, the transient apart, the
/// displacement and mean velocity (beside the analytic orbit's when started from it), the
/// events and the energy budget.
std::string SimulateJobText(const SimulateJobResult& result);

}  // namespace capsubot::text
