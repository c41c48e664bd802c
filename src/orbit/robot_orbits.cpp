#include "capsubot/orbit/robot_orbits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "capsubot/numerics/safe_newton.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {
namespace {

constexpr double kPi = 0.5 * kTau;
constexpr int kInitialGrid = 512;    // first partition of the circle
constexpr double kMinWidth = 1e-10;  // phase resolution of the exclusion refinement

// Why no root is missed.
//
// psi is linear in alpha (docs/model.md section 4): psi(alpha) = (1-alpha) psi(0) + alpha psi(1),
// so alpha(phi0) = a  <=>  Psi(phi0) := (1-a) psi0(phi0) + a psi1(phi0) = 0 (then psi0 psi1 < 0
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
  const RobotModel* robot;  // its alpha is a
  double operator()(double phi0) const {
    const Orbit o = ComputeOrbit(robot->forcing.WithPhase(phi0), robot->params);
    const double a = robot->alpha;
    return (1.0 - a) * o.psi0 + a * o.psi1;
  }
  // dPsi/dphi0 from the envelope identity above.
  double Derivative(double phi0) const {
    const Orbit o = ComputeOrbit(robot->forcing.WithPhase(phi0), robot->params);
    const double a = robot->alpha;
    const Forcing& f = o.forcing;
    const double F0 = f.F(0.0);
    return (1.0 - a) * kTau * (F0 - f.mean()) - a * (f.Pi(o.phi1) - o.phi1 * F0);
  }
};

// The terms of the exclusion test above for one robot.
struct PsiBounds {
  double L;       // bound of |dPsi/dphi0|
  double noise;   // rounding allowance in Psi
  double accept;  // |Psi| accepted as a root at width kMinWidth
  bool smooth;    // phi1 is smooth in phi0 (max|F| < T0): the two-sided test holds
};

// A candidate root of Psi, at width kMinWidth.
struct Root {
  double phi0;
  bool crossing;  // a sign change (else a double root: |Psi| at the noise level)
  double residual;
};

// An undecided part [lo, hi] of the circle, with Psi at its ends.
struct Interval {
  double lo, hi, plo, phi;
};

void CheckRobotOrbitsInput(const RobotModel& robot, const Margins& margins,
                           std::int64_t max_evaluations) {
  robot.params.Validate();
  margins.Validate();
  if (!(robot.alpha > 0.0 && robot.alpha < 1.0)) {
    throw std::invalid_argument(
        fmt::format("mass ratio alpha = {} is invalid: expected 0 < alpha < 1", robot.alpha));
  }
  if (max_evaluations < 1) {
    throw std::invalid_argument(
        fmt::format("max_evaluations = {} is invalid: expected >= 1", max_evaluations));
  }
}

// The root of Psi in an interval of width kMinWidth that the exclusion test kept, if |Psi|
// there is small enough to accept.
std::optional<Root> RootIn(const PsiFunction& psi, const PsiBounds& b, const Interval& iv) {
  const double alo = std::abs(iv.plo), ahi = std::abs(iv.phi);
  const bool crossing = (iv.plo < 0.0) != (iv.phi < 0.0);
  // Newton with the envelope derivative inside the bracket (bisection fallback); each
  // evaluation of psi runs its own bracketed Newton iteration for phi1.
  const double r = crossing ? detail::SafeNewton(
                                  psi, [&psi](double p) { return psi.Derivative(p); }, iv.lo, iv.hi)
                   : alo <= ahi ? iv.lo
                                : iv.hi;
  const double residual = std::abs(psi(r));
  if (residual <= b.accept) return Root{r, crossing, residual};
  return std::nullopt;
}

// The candidate roots of Psi over the circle, in the order found: the circle is cut into
// kInitialGrid intervals, each excluded by the test above or halved down to kMinWidth. When
// max_evaluations stops the halving first, *complete (if given) is set to false.
std::vector<Root> CandidateRoots(const PsiFunction& psi, const PsiBounds& b,
                                 std::int64_t max_evaluations, const std::function<void()>& poll,
                                 bool* complete) {
  std::vector<Root> roots;
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
    const double w = iv.hi - iv.lo, bound = b.L * w + 2.0 * b.noise;
    const double alo = std::abs(iv.plo), ahi = std::abs(iv.phi);
    if (b.smooth ? alo + ahi > bound : std::min(alo, ahi) > bound) continue;  // no root here
    if (w <= kMinWidth) {
      if (const std::optional<Root> root = RootIn(psi, b, iv)) roots.push_back(*root);
      continue;
    }
    const double mid = 0.5 * (iv.lo + iv.hi), pmid = psi(mid);
    if (++evaluations % kRobotOrbitsPollEvaluations == 0 && poll) poll();
    stack.push_back({mid, iv.hi, pmid, iv.phi});
    stack.push_back({iv.lo, mid, iv.plo, pmid});
  }
  // Undecided intervals left: the work bound stopped the search, roots there are missing.
  if (complete != nullptr) *complete = stack.empty();
  return roots;
}

// One root per band of candidates, in increasing phi0. Near a fold Psi is flat, so around a
// root |Psi| stays within `accept` over a band accept/|Psi'| wide (sqrt(2 accept/|Psi''|) at a
// double root): many 1e-10 intervals there pass the |Psi| test, and rounding may even flip the
// sign of Psi more than once. Consecutive candidates lie in one band when |Psi| at their
// midpoint is within it (Psi is monotone or convex across a band, so the midpoint is no larger
// than the ends); between two orbits it rises above the band. The circle closes: the last band
// and the first are one when |Psi| is within the band at the midpoint across pi. Roots closer
// than the band (|Psi| between them below the rounding level) are not told apart.
std::vector<Root> OneRootPerBand(const PsiFunction& psi, double accept, std::vector<Root> roots) {
  std::sort(roots.begin(), roots.end(),
            [](const Root& x, const Root& y) { return x.phi0 < y.phi0; });
  const auto same_band = [&](double lo, double hi) {
    return std::abs(psi(0.5 * (lo + hi))) <= accept;
  };
  // Better representative of a band: a sign change, else the smallest |Psi|.
  const auto better = [](const Root& a, const Root& b) {
    return (a.crossing && !b.crossing) || (a.crossing == b.crossing && a.residual < b.residual);
  };
  std::vector<Root> bands;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    if (i > 0 && same_band(roots[i - 1].phi0, roots[i].phi0)) {
      if (better(roots[i], bands.back())) bands.back() = roots[i];
    } else {
      bands.push_back(roots[i]);
    }
  }
  if (bands.size() > 1 && same_band(roots.back().phi0, roots.front().phi0 + kTau)) {
    if (better(bands.back(), bands.front())) bands.front() = bands.back();
    bands.pop_back();
  }
  return bands;
}

}  // namespace

std::vector<Solution> FindRobotOrbits(const RobotModel& robot, const Margins& margins,
                                      bool* complete, std::int64_t max_evaluations,
                                      const std::function<void()>& poll) {
  CheckRobotOrbitsInput(robot, margins, max_evaluations);
  if (complete != nullptr) *complete = true;
  std::vector<Solution> found;
  const Forcing& forcing = robot.forcing;
  const Params& params = robot.params;
  double S = 0.0;
  for (int k = 1; k <= forcing.harmonics(); ++k) S += std::hypot(forcing.a(k), forcing.b(k));
  // Without a directed force there is no orbit; a constant force has no phase to choose.
  if (!(forcing.mean() > 0.0) || S == 0.0) return found;

  const PsiFunction psi{&robot};
  const double L = kTau * S * (1.0 + robot.alpha);
  // Rounding allowance in Psi (its terms are of order tau^2 (S + c + T0)).
  const double noise = 1e-12 * kTau * kTau * (S + forcing.mean() + params.T0);
  const PsiBounds bounds{L, noise, L * kMinWidth + noise, forcing.MaxAbs() < params.T0};
  const std::vector<Root> bands = OneRootPerBand(
      psi, bounds.accept, CandidateRoots(psi, bounds, max_evaluations, poll, complete));
  for (const Root& band : bands) {
    const double phi0 = band.phi0 >= kPi ? band.phi0 - kTau : band.phi0;  // [-pi, pi)
    found.push_back(Solve(forcing.WithPhase(phi0), params, margins));
  }
  std::sort(found.begin(), found.end(), [](const Solution& x, const Solution& y) {
    return x.orbit.forcing.phi0() < y.orbit.forcing.phi0();
  });
  return found;
}

}  // namespace capsubot
