#pragma once
// The settings a user gives a search of the fastest gait (docs/model.md sections 7 and 12): the
// force bound, the stability requirement, the time limit and how hard to search. Every front end
// (the optimize and sweep commands, the Python module) fills one request and builds each
// problem's options from it here, so the same settings search the same way everywhere.

#include <limits>
#include <optional>
#include <string>

#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_fourier.hpp"
#include "capsubot/optimize/optimize_phase.hpp"

namespace capsubot {

struct SearchRequest {
  /// The gait asked for: the force bound (NaN: T0), rho_max (infinity: no stability
  /// requirement) and the margins d, d_s, s of every orbit.
  GaitRequirements gait;
  /// Wall-clock limit of one optimisation [s].
  double max_time = OptimizeOptions{}.max_time;
  /// Global stage of P2 and P3 ("multistart" or an NLopt global algorithm).
  std::string global_algorithm = kMultistart;
  /// Local polish of P2 and P3 (an NLopt local algorithm).
  std::string local_algorithm = SearchOptions{}.local_algorithm;
  /// Local polishes of P2 and P3; none: each problem's own default (SearchEffort::starts).
  std::optional<int> starts;
  /// Evaluation budget of an NLopt global stage of P2 and P3.
  int global_evaluations = SearchEffort{}.global_evaluations;
  /// P2's basin-hopping restarts.
  int hops = ForcingDesignOptions{}.hops;
  /// Harmonics K of P3's force.
  int harmonics = FourierOptions{}.harmonics;
  /// Asked by every problem built from the request (OptimizeOptions::interrupt).
  Interrupt interrupt;

  /// The same request for an exact optimum: no margins, and the stability requirement
  /// `rho_max` (inf, or 1).
  SearchRequest Exact(double rho_max) const {
    SearchRequest r = *this;
    r.gait.margins = {};
    r.gait.rho_max = rho_max;
    return r;
  }
};

/// P1's options: the stability requirement and the time limit.
PhaseOptions PhaseOptionsFor(const SearchRequest& request);
/// P2's options: the gait asked for, searched as the request says.
ForcingDesignOptions ForcingOptionsFor(const SearchRequest& request);
/// P3's options: the gait asked for (its harmonic seed searched with P2's default effort) and
/// P3's own search as the request says.
FourierOptions FourierOptionsFor(const SearchRequest& request);

}  // namespace capsubot
