#pragma once
// A periodic motion found by Newton shooting as plain text (docs/model.md section 13): what
// `capsubot periodic` prints.

#include <string>

#include "capsubot/job/periodic_job.hpp"

namespace capsubot::text {

/// The force and model, the status of Newton's method, the period and impacts, the mean
/// velocity, the state at the section, the multipliers and the verdict on stability.
std::string PeriodicJobText(const PeriodicJobResult& result);

}  // namespace capsubot::text
