#pragma once
// What a sweep job did, as the line `capsubot sweep` prints on its progress stream.

#include <string>

#include "capsubot/job/sweep_job.hpp"

namespace capsubot::text {

/// "5 points, 5 rows written to f.csv in 0.012 s on 4 threads\n", with " (2 points resumed
/// from the checkpoint)" before the line break when a checkpoint was continued.
std::string SweepJobText(const SweepJobResult& result);

}  // namespace capsubot::text
