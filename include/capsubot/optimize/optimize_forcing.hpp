#pragma once
// P2 of docs/model.md section 7: the harmonic force A sin(phi + phi0) + c (amplitude, mean and
// impact phase) that maximises the step I under the validity conditions, given to NLopt as
// inequality constraints.

#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

/// Largest grid of P2's multistart scan (grid^2 cells of 72 phases each).
inline constexpr int kMaxGrid = 100;
/// Largest number of P1 runs of P2's phase-exact polish.
inline constexpr int kMaxPhaseExactEvaluations = 100000;

/// P2's options: the gait asked for and the shared search (SearchOptions), plus the
/// multistart scan, the restarts and the phase-exact polish.
struct ForcingDesignOptions : SearchOptions {
  /// Grid points per axis of the scan over (A/bound, c/bound) that seeds the multistart;
  /// 2 <= grid <= kMaxGrid.
  int grid = 16;
  /// Basin-hopping restarts after the starts: local polishes from random perturbations of
  /// the best point so far (A and c by about 20 %, phi0 by about 0.2 rad);
  /// 0 <= hops <= kMaxStarts.
  int hops = 20;
  /// Evaluations (P1 runs) of the final phase-exact polish: LN_SBPLX over (A + c, c/(A + c))
  /// of the best valid phase (P1) at each point; 0 switches it off;
  /// 0 <= phase_exact_evaluations <= kMaxPhaseExactEvaluations.
  int phase_exact_evaluations = 600;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
};

/// P2: A, c, phi0 maximising I subject to the conditions of docs/model.md section 5 with the
/// margins of options.gait (clearance max(d, d_s * stroke), stick margin s), A + c <= bound and
/// spectral radius <= rho_max. The returned optimum is re-checked through Solve and is valid
/// whenever status is kOk (kMaxTime: the best point when the time limit was reached).
/// Throws std::invalid_argument for bad params or options.
OptimizeResult OptimizeForcing(const Params& params, const ForcingDesignOptions& options = {});

}  // namespace capsubot
