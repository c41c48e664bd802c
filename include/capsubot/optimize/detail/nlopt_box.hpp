#pragma once
// A bound-constrained NLopt run that maximises a function on a box and remembers the points it
// saw: the search stage of the simulated objectives (the fastest motion from rest, docs/model.md
// section 13), where every evaluation simulates the robot.

#include <functional>
#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize_result.hpp"

namespace capsubot::detail {

/// A point of the box and its score.
struct BoxPoint {
  std::vector<double> y;
  double score = 0.0;
};

/// The i-th point (i >= 1) of the Halton sequence in [0, 1)^dimension (radical inverses in the
/// first `dimension` primes; dimension <= 32).
std::vector<double> HaltonPoint(long long i, int dimension);

/// One NLopt run maximising `objective` (called with `data`) over [lower, upper] from y0
/// (clamped into the box): at most `evaluations` calls and `seconds` of wall-clock time,
/// relative tolerance `rel_tol` on y and on the value, initial step `step_fraction` of each
/// side. Never throws for NLopt's outcomes: they are the status (and `message` for an
/// exception NLopt threw); what `objective` throws (an Interrupt) is thrown again once NLopt
/// stopped.
OptimizeStatus MaximizeOnBox(nlopt::algorithm algorithm, nlopt::func objective, void* data,
                             const std::vector<double>& lower, const std::vector<double>& upper,
                             std::vector<double> y0, int evaluations, double seconds,
                             double rel_tol, double step_fraction, std::string& message);

/// The best distinct points of `seen` whose score is above `floor`, best first, at most
/// `count`: two points are the same when every coordinate differs by at most `same`.
std::vector<BoxPoint> BestDistinctPoints(std::vector<BoxPoint> seen, double floor, int count,
                                         double same);

/// The name of the global stage that scores the points of a Halton sequence of the box (an
/// evenly spread, deterministic random search) instead of running an NLopt algorithm.
inline constexpr const char* kHaltonStage = "HALTON";

/// A search of a box whose objective simulates (the fastest motion from rest, the design's
/// motion from rest): a global stage from `start`, optionally a second global stage from the
/// best point of the first and short local screens from the best distinct points seen, local
/// polishes from the best distinct feasible points the objective has seen by then, then the best
/// distinct candidates, which the caller re-checks with its full settings.
struct BoxSearch {
  nlopt::func objective = nullptr;  ///< maximised; it records every point it scores
  void* data = nullptr;             ///< the objective's data
  /// The points the objective has seen, with their scores (the search ranks them).
  std::function<std::vector<BoxPoint>()> seen;
  /// Wall-clock seconds left for a stage; a stage with none left is skipped.
  std::function<double()> seconds_left;
  /// Told the name of each stage before it runs ("global search", "local polish"); optional.
  std::function<void(const char* stage)> on_stage;
  std::vector<double> lower, upper;  ///< the box
  std::vector<double> start;         ///< first point of the global stage
  nlopt::algorithm global = nlopt::GN_DIRECT_L;
  bool halton = false;  ///< the global stage scores Halton points (`global` unused)
  nlopt::algorithm local = nlopt::LN_SBPLX;
  int global_evaluations = 0;  ///< budget of the global stage (0: skipped)
  int local_evaluations = 0;   ///< budget of each local polish (0: skipped)
  int polish_starts = 1;       ///< polishes, from the best distinct points seen before them
  /// A second global stage after the first, from its best point: an NLopt algorithm and its
  /// budget (0: none). A Halton sample spreads its points evenly; a population search such as
  /// controlled random search then gathers them into the narrow fast regions a sample misses.
  nlopt::algorithm refine = nlopt::GN_CRS2_LM;
  int refine_evaluations = 0;
  /// Short local runs between the global stages and the polishes, from the screen_starts best
  /// distinct points seen, screen_evaluations each (0: none): a landscape of plateaus and cliffs
  /// (a mean over starts) hides where it climbs; many short runs find the starts that lead uphill,
  /// and the polishes then go on from the best ends.
  int screen_starts = 0;
  int screen_evaluations = 0;
  double rel_tol = 0.0;     ///< relative tolerance of both stages (y and value)
  double infeasible = 0.0;  ///< the score of an infeasible point: never a candidate
  double same = 0.0;        ///< two points are one candidate within this (BestDistinctPoints)
  int candidates = 1;       ///< distinct candidates returned, at most
  /// Candidates differ by more than this in some coordinate (at least `same`): apart, they stand
  /// for several regions, so that one that fails the caller's re-check leaves others.
  double candidates_apart = 0.0;
  /// Polishes start from points that differ by more than this in some coordinate.
  double polish_apart = 0.0;

  /// Sets the global stage from its name: kHaltonStage or an NLopt algorithm, one of `allowed`;
  /// throws std::invalid_argument naming `option` otherwise (AlgorithmFromName).
  void SetGlobal(const std::string& name, const std::vector<std::string>& allowed,
                 const char* option);
};

/// What a box search found.
struct BoxSearchResult {
  /// The global stage's status, replaced by the local polish's unless only the global one
  /// stopped at the time limit; kMaxTime when the time limit came before any stage ran.
  OptimizeStatus status = OptimizeStatus::kOk;
  bool max_time = false;             ///< a stage stopped at, or was skipped at, the limit
  std::string message;               ///< NLopt's exceptions, if any
  std::vector<BoxPoint> candidates;  ///< the best distinct feasible points, best first
};

/// Runs the stages of `search` (global; the second global stage; the screens; then a local
/// polish from each of the polish_starts best points at least polish_apart apart, every local
/// run with an initial step of 5 % of each side) and returns the candidates to re-check.
BoxSearchResult SearchBox(const BoxSearch& search);

}  // namespace capsubot::detail
