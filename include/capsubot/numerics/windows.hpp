#pragma once
// Bounded 1-D maximisation over a feasible set made of windows, some of them far narrower than
// the spacing of a scan: the windows are bracketed first, with a feasibility measure that is
// continuous between the points where the number of solution branches changes, then the
// objective is maximised inside each window (GoldenRefine from each local maximum of its
// samples) and the best is kept.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "capsubot/numerics/golden.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::detail {

/// What one evaluation tells about a point x.
struct Probe {
  bool feasible = false;
  /// Feasibility measure: >= 0 where feasible, <= 0 where not, continuous in x between the
  /// points where `branches` changes; -infinity where nothing is measured (no branch).
  double slack = -std::numeric_limits<double>::infinity();
  /// Number of solution branches at x (the orbits of a robot): a change between two points
  /// means a fold, or another switch, between them.
  int branches = 0;
  /// The objective at x where feasible (NaN elsewhere).
  double value = kNaN;
};

struct WindowSample {
  double x = kNaN;
  Probe probe;
};

/// The consecutive feasible samples first..last of a search; the samples next to them (if any)
/// are infeasible, so the window's edges lie within them.
struct Window {
  int first = 0;
  int last = 0;
};

struct WindowSearch {
  std::vector<WindowSample> samples;  ///< every point of the scan and of the bracketing, by x
  std::vector<Window> windows;        ///< the feasible windows among them, by x
  /// The best objective over the windows (x and f; its index and evaluations are unused).
  ScanMax best;
  int evaluations = 0;  ///< calls of the probe
  int maxima = 0;       ///< local maxima of the objective refined in the windows
  /// The refinement budget ran out while some gap still had to be refined: a window narrower
  /// than the scan's spacing may be missing.
  bool exhausted = false;
  bool halted = false;  ///< the caller's halt() stopped the search
};

/// How finely MaximiseOverWindows looks (all lengths in x).
struct WindowOptions {
  int scan_points = 64;  ///< uniform samples of [lo, hi], both ends exact, >= 2
  /// A gap that may hide a window is refined until it is narrower than this.
  double resolution = 1e-6;
  /// ... except a gap across which the number of branches changes (a fold): there the solutions
  /// merge and become costly to resolve, so it is refined only to this (>= resolution).
  double fold_resolution = 1e-4;
  int max_refinements = 512;  ///< budget of probes for the refinement of gaps
  double tol = 1e-9;          ///< bracket width at which GoldenRefine stops in a window
};

namespace windows_internal {

constexpr double kGolden = 0.38196601125010515;  // (3 - sqrt 5)/2, as in GoldenRefine

// Whether an infeasible sample's measure is a local maximum of the samples (its infeasible
// neighbours not above it, strictly below on one side or a range end), so that the measure
// may rise above zero between them.
inline bool LocalMaximum(const std::vector<WindowSample>& s, std::size_t i) {
  const Probe& p = s[i].probe;
  if (p.feasible || !std::isfinite(p.slack)) return false;
  const auto below = [&](std::size_t j, bool strict) {
    const Probe& q = s[j].probe;
    return !q.feasible && (strict ? q.slack < p.slack : q.slack <= p.slack);
  };
  const bool has_left = i > 0, has_right = i + 1 < s.size();
  if (!has_left || !has_right) {
    return has_left ? below(i - 1, true) : has_right ? below(i + 1, true) : false;
  }
  return (below(i - 1, true) && below(i + 1, false)) || (below(i - 1, false) && below(i + 1, true));
}

// The width of the gap after sample i if it is still to be refined, else 0.
inline double OpenWidth(const std::vector<WindowSample>& s, std::size_t i, const WindowOptions& o) {
  if (i + 1 >= s.size()) return 0.0;
  const double width = s[i + 1].x - s[i].x;
  const bool fold = s[i].probe.branches != s[i + 1].probe.branches;
  return width > (fold ? o.fold_resolution : o.resolution) ? width : 0.0;
}

// The next point to evaluate, or NaN when no gap needs it. Three kinds of gap may hide a
// window: where the number of branches changes (a fold: bisected), where feasibility changes
// (a window's edge: bisected) and beside an infeasible local maximum of the measure (refined
// by golden-section steps on the measure, into the larger side still open). The most
// promising goes first: the local maxima and branch changes by their measure (nearest to
// feasible first), then the edges, the leftmost on ties.
inline double NextTrial(const std::vector<WindowSample>& s, const WindowOptions& o) {
  double trial = kNaN;
  int best_kind = -1;  // 2: local maximum or branch change; 1: edge
  double best_rank = -std::numeric_limits<double>::infinity();
  const auto offer = [&](int kind, double rank, double x) {
    if (kind > best_kind || (kind == best_kind && rank > best_rank)) {
      best_kind = kind;
      best_rank = rank;
      trial = x;
    }
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Probe& p = s[i].probe;
    if (OpenWidth(s, i, o) > 0.0) {
      const Probe& q = s[i + 1].probe;
      const double mid = 0.5 * (s[i].x + s[i + 1].x);
      if (p.branches != q.branches) {
        offer(2, std::max(p.slack, q.slack), mid);
      } else if (p.feasible != q.feasible) {
        offer(1, 0.0, mid);
      }
    }
    if (LocalMaximum(s, i)) {
      const double left = i > 0 ? OpenWidth(s, i - 1, o) : 0.0, right = OpenWidth(s, i, o);
      if (left > 0.0 || right > 0.0) {
        const double b = s[i].x;
        offer(2, p.slack, right >= left ? b + kGolden * right : b - kGolden * left);
      }
    }
  }
  return trial;
}

}  // namespace windows_internal

/// Maximum of an objective over the feasible points of [lo, hi]. probe(x) returns a Probe.
/// First options.scan_points uniform samples lo, ..., hi (both ends exact). Then the gaps that
/// may hide a window are refined (windows_internal::NextTrial) until each is narrower than
/// its resolution or options.max_refinements probes have been spent (`exhausted`). Then in
/// each window, from each local maximum of the objective among its samples and between that
/// sample's neighbours, GoldenRefine maximises the objective to options.tol, and the best is
/// kept. halt() is asked before each probe; once it says true the search ends with what it
/// has. At most scan_points + max_refinements + kGoldenMaxSteps * M probes, M the local maxima
/// of the objective among the samples of the windows.
template <class ProbeFn, class HaltFn>
WindowSearch MaximiseOverWindows(const ProbeFn& probe, const HaltFn& halt, double lo, double hi,
                                 const WindowOptions& options) {
  WindowSearch r;
  const auto evaluate = [&](double x) {
    ++r.evaluations;
    return probe(x);
  };
  const int n = options.scan_points;
  for (int i = 0; i < n && !(r.halted = halt()); ++i) {
    const double x = i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1);
    r.samples.push_back({x, evaluate(x)});
  }
  for (int spent = 0; !r.halted; ++spent) {
    const double x = windows_internal::NextTrial(r.samples, options);
    if (std::isnan(x)) break;
    if (spent == options.max_refinements) {
      r.exhausted = true;
      break;
    }
    if ((r.halted = halt())) break;
    const auto at = std::upper_bound(r.samples.begin(), r.samples.end(), x,
                                     [](double v, const WindowSample& s) { return v < s.x; });
    r.samples.insert(at, {x, evaluate(x)});
  }
  const std::vector<WindowSample>& s = r.samples;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].probe.feasible) continue;
    if (i == 0 || !s[i - 1].probe.feasible) r.windows.push_back({static_cast<int>(i), 0});
    r.windows.back().last = static_cast<int>(i);
  }
  const auto objective = [&](double x) {
    if (halt()) return kNaN;
    const Probe p = evaluate(x);
    return p.feasible ? p.value : kNaN;
  };
  for (const Window& w : r.windows) {
    for (int j = w.first; j <= w.last; ++j) {
      // Every local maximum of the objective among the window's samples (its ends compared
      // with their neighbour inside only): the objective may have several in one window (where
      // the fastest solution changes), and the best sample need not be next to the best one.
      const double v = s[j].probe.value;
      const bool left_lower = j == w.first || s[j - 1].probe.value < v;
      const bool right_lower = j == w.last || s[j + 1].probe.value < v;
      const bool left_not_higher = j == w.first || s[j - 1].probe.value <= v;
      const bool right_not_higher = j == w.last || s[j + 1].probe.value <= v;
      if (!((left_lower && right_not_higher) || (left_not_higher && right_lower))) continue;
      ScanMax start;
      start.x = s[j].x;
      start.f = v;
      const double a = s[j > 0 ? j - 1 : j].x;
      const double c = s[j + 1 < static_cast<int>(s.size()) ? j + 1 : j].x;
      ++r.maxima;
      const ScanMax m = GoldenRefine(objective, a, c, options.tol, start);
      if (m.f > r.best.f) r.best = m;
    }
  }
  r.halted = r.halted || halt();
  return r;
}

}  // namespace capsubot::detail
