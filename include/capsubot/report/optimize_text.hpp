#pragma once
// The text report of the optimize job, as `capsubot optimize` prints it: the main job in five
// numbered parts and which gait to build, one problem with its optimum checked from rest, or
// the fastest motion from rest.

#include <string>

#include "capsubot/job/optimize_job.hpp"

namespace capsubot::text {

/// The plain-text report of `result`, lines ending in '\n'.
std::string OptimizeJobText(const OptimizeJobResult& result);

}  // namespace capsubot::text
