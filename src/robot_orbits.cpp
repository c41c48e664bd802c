#include "capsubot/robot_orbits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/orbit.hpp"
#include "detail/brent.hpp"

namespace capsubot {
namespace {

constexpr double kPi = 0.5 * kTau;
constexpr int kInitialGrid = 512;     // first partition of the circle
constexpr double kMinWidth = 1e-10;   // phase resolution of the exclusion refinement
constexpr double kSameRoot = 1e-8;    // two candidates closer than this are one root
constexpr long kMaxEvaluations = 4000000;  // work bound (never reached in practice)

// Why no root is missed.
//
// psi is linear in alpha (MODEL.md section 4): psi(alpha) = (1-alpha) psi(0) + alpha psi(1), so
// alpha(phi0) = a  <=>  Psi(phi0) := (1-a) psi0(phi0) + a psi1(phi0) = 0 (then psi0 psi1 < 0
// follows for 0 < a < 1 unless both vanish). Psi has no poles, unlike alpha(phi0). Where
// phi1(phi0) is smooth, its derivative follows from the envelope identity d psi1/d phi1 = g(phi1) = 0:
//   dPsi/dphi0 = (1-a) tau (F(0) - c) + a (Pi(phi1) - phi1 F(0)),
// and with S = sum_k |(a_k, b_k)| (so |F - c| <= S, |F(s) - F(0)| <= 2S)
//   |dPsi/dphi0| <= L = tau S (1 + a).
// A root in [lo, hi] (width w) therefore needs |Psi(lo)| + |Psi(hi)| <= L w: an interval where
// this fails is excluded rigorously; the others are halved down to kMinWidth, where a sign
// change is located by Brent and a non-crossing (double) root is accepted when |Psi| is at the
// level L*kMinWidth. phi1 is smooth for every phi0 when max|F| < T0 (g strictly decreasing).
// Otherwise the first root of g can jump where g touches zero, and Psi jumps with it: then
// only the one-sided test min(|Psi(lo)|, |Psi(hi)|) > L w is used (valid with one jump in the
// interval), and a "sign change" at a jump is rejected because Psi is not small there.
struct PsiFunction {
  const Forcing* forcing;
  const Params* params;
  double a;
  double operator()(double phi0) const {
    const Orbit o = ComputeOrbit(forcing->WithPhase(phi0), *params);
    return (1.0 - a) * o.psi0 + a * o.psi1;
  }
};

}  // namespace

std::vector<Solution> FindRobotOrbits(const Forcing& forcing, const Params& params,
                                      double alpha) {
  params.Validate();
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw std::invalid_argument(
        fmt::format("mass ratio alpha = {} is invalid: expected 0 < alpha < 1", alpha));
  }
  std::vector<Solution> found;
  double S = 0.0;
  for (int k = 1; k <= forcing.harmonics(); ++k) S += std::hypot(forcing.a(k), forcing.b(k));
  // Without a directed force there is no orbit; a constant force has no phase to choose.
  if (!(forcing.mean() > 0.0) || S == 0.0) return found;

  const PsiFunction psi{&forcing, &params, alpha};
  const double L = kTau * S * (1.0 + alpha);
  const bool smooth = forcing.MaxAbs() < params.T0;
  // Rounding allowance in Psi (its terms are of order tau^2 (S + c + T0)).
  const double noise = 1e-12 * kTau * kTau * (S + forcing.mean() + params.T0);
  const double accept = L * kMinWidth + noise;

  std::vector<double> roots;
  struct Interval {
    double lo, hi, plo, phi;
  };
  std::vector<Interval> stack;
  double prev = psi(-kPi);
  for (int i = 1; i <= kInitialGrid; ++i) {
    const double lo = -kPi + kTau * (i - 1) / kInitialGrid;
    const double hi = i == kInitialGrid ? kPi : -kPi + kTau * i / kInitialGrid;
    const double next = psi(hi);
    stack.push_back({lo, hi, prev, next});
    prev = next;
  }
  long evaluations = kInitialGrid + 1;
  while (!stack.empty() && evaluations < kMaxEvaluations) {
    const Interval iv = stack.back();
    stack.pop_back();
    const double w = iv.hi - iv.lo, bound = L * w + 2.0 * noise;
    const double alo = std::abs(iv.plo), ahi = std::abs(iv.phi);
    if (smooth ? alo + ahi > bound : std::min(alo, ahi) > bound) continue;  // no root here
    if (w <= kMinWidth) {
      double r = alo <= ahi ? iv.lo : iv.hi;
      if ((iv.plo < 0.0) != (iv.phi < 0.0)) r = detail::Brent(psi, iv.lo, iv.hi);
      if (std::abs(psi(r)) <= accept) roots.push_back(r);
      continue;
    }
    const double mid = 0.5 * (iv.lo + iv.hi), pmid = psi(mid);
    ++evaluations;
    stack.push_back({mid, iv.hi, pmid, iv.phi});
    stack.push_back({iv.lo, mid, iv.plo, pmid});
  }
  std::sort(roots.begin(), roots.end());
  double last = -10.0;
  for (double r : roots) {
    if (r - last < kSameRoot) continue;
    last = r;
    const double phi0 = r >= kPi ? r - kTau : r;  // [-pi, pi)
    if (!found.empty() && std::abs(phi0 - found.front().orbit.forcing.phi0()) < kSameRoot) {
      continue;  // pi and -pi are the same phase
    }
    found.push_back(Solve(forcing.WithPhase(phi0), params));
  }
  std::sort(found.begin(), found.end(), [](const Solution& x, const Solution& y) {
    return x.orbit.forcing.phi0() < y.orbit.forcing.phi0();
  });
  return found;
}

}  // namespace capsubot
