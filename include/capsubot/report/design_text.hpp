#pragma once
// The design job's result as the text `capsubot design` prints (docs/design.md).

#include <string>

#include "capsubot/job/design_job.hpp"

namespace capsubot::text {

/// One design: the robot, what was searched, the fastest robust one-impact gait (its numbers in
/// the user's units and dimensionless, the `capsubot solve` command of its orbit) and, when part
/// (b) ran, the fastest motion from rest in each direction with its attractors. A grid: the line
/// "N points written to FILE in S s on T threads".
std::string DesignJobText(const DesignJobResult& result);

}  // namespace capsubot::text
