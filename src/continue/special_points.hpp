#pragma once
// The special points between two consecutive points of a branch (docs/continuation.md): the
// test functions that change sign between them, each located along the arclength.

#include <vector>

#include "continue/branch_system.hpp"

namespace capsubot::detail {

/// Appends to *out the special points between the nodes a and b (b follows a along a's
/// tangent; both at the system's section), located to options.location_tolerance. A change of
/// the impacts or of the event order (grazing, segment change) is looked for first; the smooth
/// test functions (fold, period doubling, Neimark-Sacker, speed extremum) only between points
/// with the same events, where the map is smooth.
void FindSpecialPoints(SmoothSystem& system, const Node& a, const Node& b, double tolerance,
                       std::vector<SpecialPoint>* out);

}  // namespace capsubot::detail
