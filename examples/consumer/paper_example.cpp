// Solves the paper's worked example (c = A = T0/2, T0 = 1, e = 1, phi0 = -2.944899971002)
// through the installed library and prints the stop phase, the mass ratio and the
// displacement per period.
#include <cstdio>

#include "capsubot/orbit/validity.hpp"
#include "capsubot/model/version.hpp"

int main() {
  const capsubot::Forcing force = capsubot::Forcing::Harmonic(0.5, 0.5, -2.944899971002);
  const capsubot::Solution s = capsubot::Solve(force, capsubot::Params{});
  std::printf("capsubot %s: phi1 = %.12f alpha = %.12f I = %.12f valid = %d\n", capsubot::Version(),
              s.orbit.phi1, s.orbit.alpha, s.orbit.I, s.validity.valid() ? 1 : 0);
  return s.orbit.ok() ? 0 : 1;
}
