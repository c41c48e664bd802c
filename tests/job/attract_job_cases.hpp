#pragma once
// What the tests of the long-run jobs (attractors, basins, periodic, simulate, solve) share: the
// robots they run (those of the command-line tests and of docs/attractors.md) and the
// comparison of two maps of attractors.

#include <gtest/gtest.h>

#include <cstring>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"

namespace capsubot::testing {

/// The exact stable P2 optimum at T0 = 1, e = 1 (`capsubot optimize --problem forcing --stable
/// --json`): from rest it settles into 3 right and 1 left impacts per period.
inline RobotModel StableOptimum() {
  return {Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047),
          Params{1.0, 1.0}, 0.6435592358295166};
}

/// A stable valid one-impact orbit with clearance (`capsubot solve --A 0.05 --c 0.02 --phi0
/// -2.842 --T0 0.1 --e 0.5 --stability`: alpha = 0.2792869076315278, spectral radius 0.16);
/// from rest it coexists with a period-12 motion.
inline RobotModel SmallOrbit() {
  return {Forcing::Harmonic(0.05, 0.02, -2.842), Params{0.1, 0.5}, 0.2792869076315278};
}

/// Bit for bit the same double (NaN equals NaN): a job must give exactly what the library calls
/// it makes give.
inline bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The same attractors from the same starts: sizes, labels, every start's motion and every
/// attractor, bit for bit; the first difference is printed.
inline ::testing::AssertionResult SameAttractors(const Attractors& a, const Attractors& b) {
  if (a.starts != b.starts || a.labels != b.labels || a.attractors.size() != b.attractors.size() ||
      a.motions.size() != b.motions.size()) {
    return ::testing::AssertionFailure()
           << "starts " << a.starts << " vs " << b.starts << ", attractors " << a.attractors.size()
           << " vs " << b.attractors.size() << " or the labels differ";
  }
  for (std::size_t i = 0; i < a.motions.size(); ++i) {
    const Motion& m = a.motions[i];
    const Motion& n = b.motions[i];
    if (m.status != n.status || m.period != n.period || m.impacts_right != n.impacts_right ||
        !SameBits(m.mean_velocity, n.mean_velocity)) {
      return ::testing::AssertionFailure()
             << "start " << i << ": mean velocity " << m.mean_velocity << " vs " << n.mean_velocity;
    }
  }
  for (std::size_t k = 0; k < a.attractors.size(); ++k) {
    if (a.attractors[k].starts != b.attractors[k].starts ||
        a.attractors[k].one_impact_orbit != b.attractors[k].one_impact_orbit ||
        !SameBits(a.attractors[k].mean_velocity, b.attractors[k].mean_velocity)) {
      return ::testing::AssertionFailure() << "attractor " << k << " differs";
    }
  }
  if (!SameBits(a.mean_velocity, b.mean_velocity)) {
    return ::testing::AssertionFailure()
           << "mean velocity " << a.mean_velocity << " vs " << b.mean_velocity;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace capsubot::testing
