#pragma once
// The plain-text report of `capsubot continue` (docs/continuation.md): what the command prints
// without --json.

#include <string>

#include "capsubot/job/continue_job.hpp"

namespace capsubot::text {

/// The branch's summary (Branch::Summary), then the switched branch's (or why there is none)
/// when it was asked, then the curve's: the special point it starts from, its points and range
/// in both parameters, how each direction ended.
std::string ContinueJobText(const ContinueJobResult& result);

}  // namespace capsubot::text
