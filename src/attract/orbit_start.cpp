#include "capsubot/attract/orbit_start.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/model/force_spec.hpp"

namespace capsubot {

SimOptions StartAfterImpact(const Orbit& orbit, double periods) {
  if (!orbit.ok()) {
    throw std::invalid_argument(
        fmt::format("orbit status = {} is invalid: expected an orbit that exists (status ok)",
                    StatusName(orbit.status)));
  }
  // Right after the impact (docs/model.md section 4): x = 1, x' = -e u, v = v+.
  SimOptions opt;
  opt.alpha = orbit.alpha;
  opt.x0 = 1.0;
  opt.u0 = -orbit.e * orbit.u;
  opt.v0 = orbit.v_plus;
  opt.periods = periods;
  return opt;
}

OrbitStart StartFromOrbit(const Forcing& forcing, const Params& params) {
  RefusePulse(forcing, "from_orbit (a start on the analytic one-impact orbit)");
  OrbitStart s;
  s.orbit = Solve(forcing, params);
  if (!s.orbit.orbit.ok()) {
    throw std::invalid_argument(
        fmt::format("from_orbit: no one-impact orbit exists for this force, T0 and e ({})",
                    StatusName(s.orbit.orbit.status)));
  }
  s.start = StartAfterImpact(s.orbit.orbit);
  return s;
}

}  // namespace capsubot
