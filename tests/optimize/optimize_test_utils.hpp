#pragma once
// Helpers shared by the optimiser tests (tests/optimize_*_test.cpp).

#include "capsubot/model/params.hpp"
#include "capsubot/orbit/orbit.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot::testing {

/// One period of the event-driven simulator from the orbit's post-impact state (x = 1,
/// u = -e u, v = v+, its alpha): a periodic orbit of the model returns to it.
inline SimResult SimulateOnePeriodFromImpact(const Orbit& o, const Params& params) {
  SimOptions sim;
  sim.alpha = o.alpha;
  sim.x0 = 1.0;
  sim.u0 = -o.e * o.u;
  sim.v0 = o.v_plus;
  return Simulate(o.forcing, params, sim);
}

}  // namespace capsubot::testing
