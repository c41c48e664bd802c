#include "capsubot/orbit/scaling.hpp"

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

double LargestFittingT0(const Solution& solution, double margin) {
  if (!solution.orbit.ok()) return kNaN;
  return solution.orbit.T0 * (1.0 - margin) / (1.0 - solution.validity.x_min);
}

}  // namespace capsubot
