#include "capsubot/robot_orbits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/orbit.hpp"
#include "numerics/brent.hpp"

namespace capsubot {
namespace {

constexpr double kPi = 0.5 * kTau;
constexpr int kInitialGrid = 512;    // first partition of the circle
constexpr double kMinWidth = 1e-10;  // phase resolution of the exclusion refinement
constexpr double kSameRoot = 1e-8;   // two candidates closer than this are one root

// Why no root is missed.
//
// psi is linear in alpha (docs/model.md section 4): psi(alpha) = (1-alpha) psi(0) + alpha psi(1), so
// alpha(phi0) = a  <=>  Psi(phi0) := (1-a) psi0(phi0) + a psi1(phi0) = 0 (then psi0 psi1 < 0
// follows for 0 < a < 1 unless both vanish). Psi has no poles, unlike alpha(phi0). Where
// phi1(phi0) is smooth, its derivative follows from the envelope identity d psi1/d phi1 = g(phi1) =
// 0:
//   dPsi/dphi0 = (1-a) tau (F(0) - c) - a (Pi(phi1) - phi1 F(0)),
// and with S = sum_k |(a_k, b_k)| (so |F - c| <= S, |F(s) - F(0)| <= 2S)
//   |dPsi/dphi0| <= L = tau S (1 + a).
// A root in [lo, hi] (width w) therefore needs |Psi(lo)| + |Psi(hi)| <= L w: an interval where
// this fails is excluded rigorously; the others are halved down to kMinWidth, where a sign
// change is located by Newton (bisection safeguard) and a non-crossing (double) root is accepted
// when |Psi| is at the level L*kMinWidth. phi1 is smooth for every phi0 when max|F| < T0 (g
// strictly decreasing). Otherwise the first root of g can jump where g touches zero, and Psi jumps
// with it: then only the one-sided test min(|Psi(lo)|, |Psi(hi)|) > L w is used (valid with one
// jump in the interval), and a "sign change" at a jump is rejected because Psi is not small there.
struct PsiFunction {
  const Forcing* forcing;
  const Params* params;
  double a;
  double operator()(double phi0) const {
    const Orbit o = ComputeOrbit(forcing->WithPhase(phi0), *params);
    return (1.0 - a) * o.psi0 + a * o.psi1;
  }
  // dPsi/dphi0 from the envelope identity above.
  double Derivative(double phi0) const {
    const Orbit o = ComputeOrbit(forcing->WithPhase(phi0), *params);
    const Forcing& f = o.forcing;
    const double F0 = f.F(0.0);
    return (1.0 - a) * kTau * (F0 - f.mean()) - a * (f.Pi(o.phi1) - o.phi1 * F0);
  }
};

}  // namespace

std::vector<Solution> FindRobotOrbits(const Forcing& forcing, const Params& params, double alpha,
                                      bool* complete, std::int64_t max_evaluations) {
  params.Validate();
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw std::invalid_argument(
        fmt::format("mass ratio alpha = {} is invalid: expected 0 < alpha < 1", alpha));
  }
  if (max_evaluations < 1) {
    throw std::invalid_argument(
        fmt::format("max_evaluations = {} is invalid: expected >= 1", max_evaluations));
  }
  if (complete != nullptr) *complete = true;
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

  struct Root {
    double phi0;
    bool crossing;  // a sign change (else a double root: |Psi| at the noise level)
    double residual;
  };
  std::vector<Root> roots;
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
  std::int64_t evaluations = kInitialGrid + 1;
  while (!stack.empty() && evaluations < max_evaluations) {
    const Interval iv = stack.back();
    stack.pop_back();
    const double w = iv.hi - iv.lo, bound = L * w + 2.0 * noise;
    const double alo = std::abs(iv.plo), ahi = std::abs(iv.phi);
    if (smooth ? alo + ahi > bound : std::min(alo, ahi) > bound) continue;  // no root here
    if (w <= kMinWidth) {
      const bool crossing = (iv.plo < 0.0) != (iv.phi < 0.0);
      // Newton with the envelope derivative inside the bracket (bisection fallback). Psi runs
      // detail::Brent for phi1; nesting another Brent here would be safe too (one GSL solver
      // per nesting depth, detail::BrentLease), Newton just converges quadratically.
      const double r = crossing
                           ? detail::SafeNewton(
                                 psi, [&psi](double p) { return psi.Derivative(p); }, iv.lo, iv.hi)
                       : alo <= ahi ? iv.lo
                                    : iv.hi;
      const double residual = std::abs(psi(r));
      if (residual <= accept) roots.push_back({r, crossing, residual});
      continue;
    }
    const double mid = 0.5 * (iv.lo + iv.hi), pmid = psi(mid);
    ++evaluations;
    stack.push_back({mid, iv.hi, pmid, iv.phi});
    stack.push_back({iv.lo, mid, iv.plo, pmid});
  }
  // Undecided intervals left: the work bound stopped the search, roots there are missing.
  if (complete != nullptr) *complete = stack.empty();
  // Candidates within kSameRoot are one root: keep the sign change (the neighbouring
  // intervals of a simple root may pass the |Psi| test too), else the smallest |Psi|.
  std::sort(roots.begin(), roots.end(),
            [](const Root& x, const Root& y) { return x.phi0 < y.phi0; });
  std::vector<double> unique;
  for (std::size_t i = 0; i < roots.size();) {
    std::size_t j = i, pick = i;
    for (; j < roots.size() && roots[j].phi0 - roots[i].phi0 < kSameRoot; ++j) {
      const Root &a = roots[j], &b = roots[pick];
      if ((a.crossing && !b.crossing) || (a.crossing == b.crossing && a.residual < b.residual)) {
        pick = j;
      }
    }
    unique.push_back(roots[pick].phi0);
    i = j;
  }
  for (double r : unique) {
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
