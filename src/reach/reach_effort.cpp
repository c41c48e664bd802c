#include "capsubot/reach/reach_effort.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "capsubot/optimize/detail/nlopt_box.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"

namespace capsubot {
namespace {

// Bounds of the drive budgets (an evaluation simulates a grid of starts: a million of them is
// hours of work).
constexpr long long kMaxDriveEvaluations = 1000000;
constexpr long long kMaxDrivePolishes = 64;
constexpr long long kMaxDriveScreens = 256;
// The relative tolerance of a drive's polishes: far below any change of a mean over starts.
constexpr double kPolishRelTol = 1e-10;
// Each screen of the drive search has this fraction of a polish's budget.
constexpr int kScreenShare = 4;
// The drive search's candidates differ by this much in some coordinate (the coordinates span 1
// or 2).
constexpr double kCandidatesApart = 0.02;

}  // namespace

void ReachEffort::Validate() const {
  detail::Require(
      global_evaluations >= 1,
      fmt::format("reach_evaluations = {} is invalid: expected at least 1", global_evaluations));
  detail::Require(local_evaluations >= 0,
                  fmt::format("reach_local_evaluations = {} is invalid: expected at least 0",
                              local_evaluations));
  detail::Require(max_seconds > 0.0,
                  fmt::format("reach_seconds = {} is invalid: expected a time > 0 (infinity: none)",
                              max_seconds));
  detail::RequireCount("drive_evaluations", drive_evaluations, 1, kMaxDriveEvaluations);
  detail::RequireCount("drive_polishes", drive_polishes, 1, kMaxDrivePolishes);
  detail::RequireCount("drive_local_evaluations", drive_local_evaluations, 0, kMaxDriveEvaluations);
  detail::RequireCount("drive_refine_evaluations", drive_refine_evaluations, 0,
                       kMaxDriveEvaluations);
  detail::RequireCount("drive_screens", drive_screens, 0, kMaxDriveScreens);
}

ReachOptions ReachEffort::Options(double force_bound, double alpha,
                                  const FromRestOptions& check) const {
  ReachOptions r;
  r.force_bound = force_bound;
  r.alpha = alpha;
  r.search.n_x = n_x;
  r.search.n_psi = n_psi;
  r.search.attractor.threads = check.attractor.threads;
  r.search.attractor.interrupt = check.attractor.interrupt;
  r.check = check;
  r.global_evaluations = global_evaluations;
  r.local_evaluations = local_evaluations;
  r.max_seconds = max_seconds;
  return r;
}

ReachOptions ReachEffort::DriveOptions(const DriveFamily& drive, double force_bound, double alpha,
                                       const FromRestOptions& check) const {
  ReachOptions r = Options(force_bound, alpha, check);
  r.drive = drive;
  r.global_algorithm = detail::kHaltonStage;
  r.local_algorithm = "LN_NELDERMEAD";
  r.global_evaluations = drive_evaluations;
  r.polish_starts = drive_polishes;
  r.local_evaluations = drive_local_evaluations;
  // The Halton sample, then controlled random search from its best point, then short screens
  // with 1/kScreenShare of a polish's budget (docs/reach.md, "Drives": the narrow fast regions
  // at a fast motor).
  r.refine_evaluations = drive_refine_evaluations;
  r.screen_starts = drive_screens;
  r.screen_evaluations = drive_local_evaluations / kScreenShare;
  r.candidates = std::max(r.candidates, drive_polishes);
  // The random search gathers many points on the edge of a cliff of the landscape, where a
  // drive can lose its speed under the re-check's other settings (e = 0.999 at e = 1) and its
  // neighbours with it: then twice as many candidates, from several regions.
  if (drive_refine_evaluations > 0) {
    r.candidates = std::max(r.candidates, 2 * drive_polishes);
    r.candidates_apart = kCandidatesApart;
  }
  // A mean over starts is flat between the points where a start changes its motion: a polish
  // stopped by a small relative change would stop on the first plateau; its budget bounds it.
  r.rel_tol = kPolishRelTol;
  return r;
}

}  // namespace capsubot
