#pragma once
// P3 of docs/model.md section 7: a force given by K harmonics, F = c + sum_k (a_k cos k phi +
// b_k sin k phi) seen from the impact, with mean c > 0 and max |F| <= bound, maximising I.

#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

/// P3's options: the gait asked for, given once for P3 and the P2 optimum it starts from,
/// and P3's own search.
struct FourierOptions {
  /// The gait asked for (force_bound, rho_max, max_time, local_algorithm, seed, active_tol),
  /// which P3 asks too, and P2's search for the harmonic optimum: the baseline and first start.
  ForcingDesignOptions harmonic;
  /// P3's own search: by default 20 polishes to a relative tolerance of 1e-9.
  SearchEffort search{kMultistart, 20, 1e-9, 20000, 5000};
  /// Number of harmonics K; 1 <= K <= kMaxHarmonics.
  int harmonics = 3;

  void Validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// P3: maximise I over K-harmonic forces (impact phase free: the coefficients are relative to
/// the impact, phi0 = 0) under the same conditions as P2, with max |F| <= bound. Starts from
/// the P2 optimum (options.harmonic), so its I is never below it; result.baseline_I holds
/// that P2 value. The result's forcing is a Fourier force. The time limit covers both.
OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options = {});

}  // namespace capsubot
