#pragma once
// The fastest Fourier drive from rest, climbing in the number of harmonics (docs/reach.md,
// "Drives"): the sine's reach search (seeded with the robust one-impact gait), then K = 2, 3,
// ..., each seeded with the winners of the smaller K. A smaller K's winner belongs to every
// larger K (its other coefficients 0), so each step is at least as fast as the one below it.

#include <vector>

#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot {

/// The winners of the steps: steps[k - 1] is the fastest drive of K = k harmonics found (k = 1:
/// the sine, today's reach problem).
struct DriveLadder {
  std::vector<ReachResult> steps;
  /// The last step's winner (the requested K).
  const ReachResult& best() const { return steps.back(); }
};

/// The ladder up to options.drive (a Fourier family of K >= 1 harmonics) from `sine`, the sine's
/// reach result (OptimizeReach with the sine family, seeded with `seed`): each step k >= 2 is
/// OptimizeReach(params, seed, options) with the drive K = k and options.seeds replaced by the
/// winners below it (each step has its own options.max_seconds). Throws std::invalid_argument
/// for bad params or options.
DriveLadder ClimbDriveLadder(const Params& params, const OptimizeResult& seed,
                             const ReachResult& sine, const ReachOptions& options);

}  // namespace capsubot
