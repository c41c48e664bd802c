// P1 of docs/model.md section 7: the impact phase maximising I over valid orbits.
//
// The valid set in phi0 is a union of arcs of the circle and the optimum often sits on an
// arc edge (the orbit grazes a wall). So: scan the circle, bisect every validity flip between
// neighbouring scan points down to phase_tol (keeping the valid side), maximise I by Brent's
// method (GSL) around every local maximum of the scan inside an arc, and return the best.

#include "capsubot/optimize/optimize_phase.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "capsubot/optimize/detail/optimize_common.hpp"
#include "optimize/nlopt_constraints.hpp"

namespace capsubot {
namespace {

using detail::kPi;
using detail::Require;

constexpr int kMaxBrentIterations = 100;
// A point whose constraint violation is at most this is invalid by round-off only (e.g. an
// orbit grazing a wall in the last bit): it does not end a valid arc, yet it is never
// returned, since the result must be valid through Solve.
constexpr double kRoundoffViolation = 1e-12;
// Local minima of the constraint violation searched for arcs narrower than the scan.
constexpr int kMaxHiddenArcs = 16;
// Steps tried around a polished optimum that is invalid by round-off only.
constexpr int kNudges = 8;

bool InArc(const detail::Evaluation& ev) { return ev.valid || ev.violation <= kRoundoffViolation; }

struct GslMinimizerFree {
  void operator()(gsl_min_fminimizer* m) const { gsl_min_fminimizer_free(m); }
};

class PhaseSearch {
 public:
  PhaseSearch(const Forcing& forcing, const detail::ConstraintSetup& setup, double max_time,
              const Interrupt& interrupt)
      : forcing_(forcing), setup_(setup), deadline_(max_time), interrupt_(interrupt) {}

  // The orbit at phi0, reduced into [-pi, pi) first: the search works on unwrapped phases
  // (arcs across -pi), and the evaluated numbers are then exactly the reported ones.
  detail::Evaluation At(double phi0) {
    ++evaluations_;
    return detail::Evaluate(forcing_.WithPhase(detail::ReducePhase(phi0)), setup_);
  }

  // Edge of the valid arc between `in_phase` (in the arc) and `out_phase` by bisection;
  // returns the valid point nearest to the edge (or the arc-side point if none was valid), and
  // its unwrapped phase in `edge_phase`.
  detail::Evaluation Edge(double in_phase, detail::Evaluation in_ev, double out_phase, double tol,
                          double& edge_phase) {
    detail::Evaluation valid_ev = in_ev;
    edge_phase = in_phase;
    while (std::abs(out_phase - in_phase) > tol) {
      const double mid = 0.5 * (in_phase + out_phase);
      if (mid == in_phase || mid == out_phase) break;
      detail::Evaluation ev = At(mid);
      if (InArc(ev)) {
        in_phase = mid;
        if (ev.valid || !valid_ev.valid) {
          valid_ev = std::move(ev);
          edge_phase = mid;
        }
      } else {
        out_phase = mid;
      }
    }
    return valid_ev;
  }

  // Minimum of f on [lo, hi] by GSL's Brent minimiser, started at `mid` where f is below both
  // ends; NaN if that does not hold or GSL fails.
  double BrentMinimum(double (*f)(double, void*), double lo, double mid, double hi, double tol) {
    if (!minimizer_) {
      // Once per process (thread-safe static initialisation): GSL must report, not abort.
      static const bool handler_off = (gsl_set_error_handler_off(), true);
      (void)handler_off;
      minimizer_.reset(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent));
      if (!minimizer_) return NAN;
    }
    gsl_function fn{f, this};
    const double f_lo = f(lo, this), f_mid = f(mid, this), f_hi = f(hi, this);
    if (!(f_mid < f_lo && f_mid < f_hi)) return NAN;  // a plateau or a minimum at an end
    gsl_min_fminimizer* m = minimizer_.get();
    if (gsl_min_fminimizer_set_with_values(m, &fn, mid, f_mid, lo, f_lo, hi, f_hi) != GSL_SUCCESS)
      return NAN;
    for (int it = 0; it < kMaxBrentIterations; ++it) {
      if (gsl_min_fminimizer_iterate(m) != GSL_SUCCESS) break;
      const double a = gsl_min_fminimizer_x_lower(m), b = gsl_min_fminimizer_x_upper(m);
      if (gsl_min_test_interval(a, b, tol, 0.0) == GSL_SUCCESS) break;
    }
    return gsl_min_fminimizer_x_minimum(m);
  }

  // The point at x, or a valid one within a few tol of it if x is invalid by round-off only;
  // its unwrapped phase in `at`.
  detail::Evaluation ValidNear(double x, double tol, double& at) {
    at = x;
    detail::Evaluation ev = At(x);
    for (int k = 1; k <= kNudges && !ev.valid && InArc(ev); ++k) {
      at = x + (k % 2 == 0 ? 1.0 : -1.0) * ((k + 1) / 2) * tol;
      ev = At(at);
    }
    return ev;
  }

  // Maximises I on [lo, hi] around `mid` (I(mid) above I at both ends); replaces `best` if
  // the polished point is valid and better.
  bool Polish(double lo, double mid, double hi, double tol, detail::Evaluation& best) {
    auto minus_I = [](double phi0, void* self) {
      const detail::Evaluation ev = static_cast<PhaseSearch*>(self)->At(phi0);
      // Where no orbit exists, -I is undefined: a large value keeps Brent away from it.
      return ev.solution.orbit.ok() ? -ev.I : 1e300;
    };
    const double x = BrentMinimum(minus_I, lo, mid, hi, tol);
    if (std::isnan(x)) return false;
    double at = x;
    detail::Evaluation ev = ValidNear(x, tol, at);
    if (ev.valid && ev.I > best.I) {
      best = std::move(ev);
      return true;
    }
    return false;
  }

  // Looks for a valid arc narrower than the scan between lo and hi, around `mid` where the
  // constraint violation has a local minimum: minimises the violation (Brent); if that
  // reaches a valid point, bisects the arc's two edges. Offers every valid point to `best`.
  void HiddenArc(double lo, double mid, double hi, double tol, detail::Evaluation& best) {
    auto violation = [](double phi0, void* self) {
      return static_cast<PhaseSearch*>(self)->At(phi0).violation;
    };
    const double x = BrentMinimum(violation, lo, mid, hi, tol);
    if (std::isnan(x)) return;
    double in = x;
    detail::Evaluation inside = ValidNear(x, tol, in);
    if (!InArc(inside)) {
      // No arc (or one narrower than the tolerance): still the point nearest to validity.
      if (detail::Better(inside, best)) best = std::move(inside);
      return;
    }
    for (double out : {lo, hi}) {
      double edge_phase = in;
      detail::Evaluation edge = Edge(in, inside, out, tol, edge_phase);
      if (detail::Better(edge, best)) best = std::move(edge);
    }
    if (detail::Better(inside, best)) best = std::move(inside);
  }

  int evaluations() const { return evaluations_; }
  /// True once the time limit has passed (every stage then stops at its next step).
  bool Expired() { return deadline_.Expired(); }
  /// Asks the interrupt (which throws to abandon the search), then Expired(): before every
  /// scan point and every edge or polish, each a bounded number of evaluations.
  bool StopNow() {
    Poll(interrupt_);
    return Expired();
  }

 private:
  Forcing forcing_;
  detail::ConstraintSetup setup_;
  detail::Deadline deadline_;
  const Interrupt& interrupt_;
  int evaluations_ = 0;
  std::unique_ptr<gsl_min_fminimizer, GslMinimizerFree> minimizer_;
};

// The scan of the circle: n phases -pi + h i, h = tau / n, their orbits, and which lie
// inside a valid arc.
struct CircleScan {
  std::vector<double> phase;
  std::vector<detail::Evaluation> at;
  std::vector<char> arc;  // inside a valid arc (valid, or invalid by round-off only)
  int best = 0;           // the best point scanned (detail::Better)
  int valid_count = 0;

  int size() const { return static_cast<int>(phase.size()); }
  int Next(int i) const { return (i + 1) % size(); }
  int Prev(int i) const { return (i + size() - 1) % size(); }
  // The phase of scan point j seen from scan point i as a neighbour (unwrapped by one turn).
  double Beside(int i, int j) const {
    const double d = phase[j] - phase[i];
    return d > kPi ? phase[j] - kTau : d < -kPi ? phase[j] + kTau : phase[j];
  }
};

// The circle scanned at n phases; once the search must stop, the points left are not
// evaluated (outside every arc).
CircleScan ScanCircle(PhaseSearch& search, int n) {
  const double h = kTau / n;
  CircleScan scan;
  scan.phase.resize(n);
  scan.at.resize(n);
  scan.arc.resize(n);
  for (int i = 0; i < n; ++i) {
    scan.phase[i] = -kPi + h * i;
    if (search.StopNow()) {  // not scanned: outside every arc
      scan.at[i].violation = HUGE_VAL;
      continue;
    }
    scan.at[i] = search.At(scan.phase[i]);
    if (scan.at[i].valid) ++scan.valid_count;
    scan.arc[i] = InArc(scan.at[i]);
    if (detail::Better(scan.at[i], scan.at[scan.best])) scan.best = i;
  }
  return scan;
}

// Arcs narrower than the scan: among invalid points between invalid neighbours, the local
// minima of the violation with an orbit are candidates; the smallest few are searched.
void SearchHiddenArcs(PhaseSearch& search, const CircleScan& scan, double tol,
                      detail::Evaluation& winner) {
  std::vector<int> dips;
  for (int i = 0; i < scan.size(); ++i) {
    const int a = scan.Prev(i), b = scan.Next(i);
    if (scan.arc[i] || scan.arc[a] || scan.arc[b] || !scan.at[i].solution.orbit.ok()) continue;
    if (scan.at[i].violation < scan.at[a].violation &&
        scan.at[i].violation < scan.at[b].violation) {
      dips.push_back(i);
    }
  }
  const auto by_violation = [&](int i, int j) {
    return scan.at[i].violation < scan.at[j].violation;
  };
  if (dips.size() > static_cast<std::size_t>(kMaxHiddenArcs)) {
    std::partial_sort(dips.begin(), dips.begin() + kMaxHiddenArcs, dips.end(), by_violation);
    dips.resize(kMaxHiddenArcs);
  }
  for (int i : dips) {
    if (search.StopNow()) break;
    search.HiddenArc(scan.Beside(i, scan.Prev(i)), scan.phase[i], scan.Beside(i, scan.Next(i)), tol,
                     winner);
  }
}

// The extent [lo[i], hi[i]] of the valid arc around each scan point i.
struct ArcExtents {
  std::vector<double> lo, hi;
};

// Arc edges: bisects every validity flip between neighbours, keeping the valid side; offers
// every edge to `winner` and returns the arcs' extents.
ArcExtents BisectArcEdges(PhaseSearch& search, const CircleScan& scan, double tol,
                          detail::Evaluation& winner) {
  const int n = scan.size();
  ArcExtents extent{std::vector<double>(n), std::vector<double>(n)};
  for (int i = 0; i < n; ++i) {
    extent.lo[i] = scan.Beside(i, scan.Prev(i));
    extent.hi[i] = scan.Beside(i, scan.Next(i));
  }
  for (int i = 0; i < n; ++i) {
    const int j = scan.Next(i);
    if (scan.arc[i] == scan.arc[j] || search.StopNow()) continue;
    const int v = scan.arc[i] ? i : j, w = scan.arc[i] ? j : i;
    double edge_phase = scan.phase[v];
    detail::Evaluation edge =
        search.Edge(scan.phase[v], scan.at[v], scan.Beside(v, w), tol, edge_phase);
    (v == i ? extent.hi[v] : extent.lo[v]) = edge_phase;
    if (detail::Better(edge, winner)) winner = std::move(edge);
  }
  return extent;
}

// Polishes I around every local maximum of I among the scan points inside an arc.
void PolishLocalMaxima(PhaseSearch& search, const CircleScan& scan, const ArcExtents& extent,
                       double tol, detail::Evaluation& winner) {
  for (int i = 0; i < scan.size(); ++i) {
    if (!scan.arc[i] || search.StopNow()) continue;
    const int a = scan.Prev(i), b = scan.Next(i);
    if ((scan.arc[a] && scan.at[a].I > scan.at[i].I) ||
        (scan.arc[b] && scan.at[b].I > scan.at[i].I)) {
      continue;
    }
    search.Polish(extent.lo[i], scan.phase[i], extent.hi[i], tol, winner);
  }
}

// The result for the best point found, `winner`.
OptimizeResult PhaseResult(const detail::Evaluation& winner, const detail::ConstraintSetup& setup,
                           const PhaseOptions& options, PhaseSearch& search,
                           const CircleScan& scan) {
  const int n = scan.size();
  OptimizeResult result;
  result.algorithm = fmt::format("scan{}+bisection+brent", n);
  // Every point was evaluated at its phase reduced into [-pi, pi): report it as it is.
  const double phi0 = winner.solution.orbit.forcing.phi0();
  result.evaluations = search.evaluations();
  result.solution = winner.solution;
  result.spectral_radius = detail::SpectralRadius(winner);
  const std::string gait = "orbit" + detail::RequirementWords(setup);
  if (winner.valid) {
    result.status = OptimizeStatus::kOk;
    result.active_constraints = detail::ActiveConstraints(winner, setup, options.active_tol);
    result.binding = detail::BindingMargins(winner, setup, options.active_tol);
    result.message = fmt::format(
        "best valid {} over phi0: I = {:.10g} at phi0 = {:.10g} ({} of {} scanned phases valid)",
        gait, winner.I, phi0, scan.valid_count, n);
  } else {
    result.status = OptimizeStatus::kNoValidOrbit;
    result.message = fmt::format(
        "no phase phi0 gives a valid {} ({} phases scanned); nearest to valid: phi0 = "
        "{:.10g}, which violates {}",
        gait, n, phi0, detail::DescribeViolations(winner, setup));
  }
  if (search.Expired()) {
    result.status = OptimizeStatus::kMaxTime;
    result.message +=
        fmt::format(" (time limit of {:g} s reached: the search is incomplete)", options.max_time);
  }
  return result;
}

}  // namespace

void PhaseOptions::Validate() const {
  detail::RequireCount("scan_points", scan_points, kMinScanPoints, kMaxScanPoints);
  Require(std::isfinite(phase_tol) && phase_tol > 0.0,
          fmt::format("phase_tol = {} is invalid: expected a finite phase_tol > 0", phase_tol));
  OptimizeOptions::Validate();
}

OptimizeResult OptimizePhase(const Forcing& forcing, const Params& params,
                             const PhaseOptions& options) {
  params.Validate();
  options.Validate();
  // No force bound: the force is given, and validity bounds max |F| by T0 (up to rounding).
  const detail::ConstraintSetup setup{params, HUGE_VAL, options.gait.rho_max, 0.0,
                                      options.gait.margins};
  PhaseSearch search(forcing, setup, options.max_time, options.interrupt);
  const CircleScan scan = ScanCircle(search, options.scan_points);
  detail::Evaluation winner = scan.at[scan.best];
  SearchHiddenArcs(search, scan, options.phase_tol, winner);
  if (scan.valid_count > 0) {
    const ArcExtents extent = BisectArcEdges(search, scan, options.phase_tol, winner);
    PolishLocalMaxima(search, scan, extent, options.phase_tol, winner);
  }
  return PhaseResult(winner, setup, options, search, scan);
}

}  // namespace capsubot
