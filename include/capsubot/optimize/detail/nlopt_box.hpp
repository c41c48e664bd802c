#pragma once
// A bound-constrained NLopt run that maximises a function on a box and remembers the points it
// saw: the search stage of the simulated objectives (the fastest motion from rest, docs/model.md
// section 13), where every evaluation simulates the robot.

#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize_result.hpp"

namespace capsubot::detail {

/// A point of the box and its score.
struct BoxPoint {
  std::vector<double> y;
  double score = 0.0;
};

/// One NLopt run maximising `objective` (called with `data`) over [lower, upper] from y0
/// (clamped into the box): at most `evaluations` calls and `seconds` of wall-clock time,
/// relative tolerance `rel_tol` on y and on the value, initial step `step_fraction` of each
/// side. Never throws for NLopt's outcomes: they are the status (and `message` for an
/// exception NLopt threw); what `objective` throws (an Interrupt) is thrown again once NLopt
/// stopped.
OptimizeStatus MaximizeOnBox(nlopt::algorithm algorithm, nlopt::func objective, void* data,
                             const std::vector<double>& lower, const std::vector<double>& upper,
                             std::vector<double> y0, int evaluations, double seconds,
                             double rel_tol, double step_fraction, std::string& message);

/// The best distinct points of `seen` whose score is above `floor`, best first, at most
/// `count`: two points are the same when every coordinate differs by at most `same`.
std::vector<BoxPoint> BestDistinctPoints(std::vector<BoxPoint> seen, double floor, int count,
                                         double same);

}  // namespace capsubot::detail
