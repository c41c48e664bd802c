#pragma once
// The size of an orbit against the friction bound (docs/model.md section 6): multiplying A, c
// (every Fourier coefficient) and T0 by k keeps phi1 and alpha and multiplies u, v+, I and
// 1 - x by k. Only the ratios to T0 shape the orbit; T0 decides whether it fits the walls.

#include "capsubot/orbit/validity.hpp"

namespace capsubot {

/// The largest T0 at which the orbit's shape (the force scaled with T0, e unchanged) keeps the
/// inner body at least `margin` from the left wall: k (1 - x_min) <= 1 - margin, so
/// T0 (1 - margin) / (1 - x_min). NaN when the orbit or its x_min was not computed.
double LargestFittingT0(const Solution& solution, double margin = 0.0);

}  // namespace capsubot
