#pragma once
// P3 of docs/model.md section 7: a force given by K harmonics, F = c + sum_k (a_k cos k phi +
// b_k sin k phi) seen from the impact, with mean c > 0 and max |F| <= bound, maximising I.

#include "capsubot/optimize_result.hpp"
#include "capsubot/optimize_search.hpp"
#include "capsubot/params.hpp"

namespace capsubot {

/// P3's options: the shared search options (by default 20 polishes to 1e-9) and K.
struct FourierOptions : SearchOptions {
  FourierOptions() {
    starts = 20;
    rel_tol = 1e-9;
  }
  /// Number of harmonics K; 1 <= K <= kMaxHarmonics.
  int harmonics = 3;

  void Validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// P3: maximise I over K-harmonic forces (impact phase free: the coefficients are relative to
/// the impact, phi0 = 0). Starts from the P2 optimum at the same bound, so its I is never
/// below it; result.baseline_I holds that P2 value. The result's forcing is a Fourier force.
OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options = {});

}  // namespace capsubot
