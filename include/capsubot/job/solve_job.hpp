#pragma once
// `capsubot solve` as one call: the one-impact orbit of a force (docs/model.md section 4) with
// every validity condition (section 5) and its energy budget (section 11); asked, also its
// stability (section 8) and its check from rest (section 12).

#include <optional>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/energy.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot {

struct SolveJobOptions {
  Forcing forcing;  ///< the force F(phi) = G(phi + phi0), phi = 0 at the impact
  Params params;    ///< T0, e
  Margins margins;  ///< the margins of the validity conditions (none: physical validity)
  /// Also the stability of the orbit and its check from rest on this grid of starts (with
  /// its threads and interrupt); none: the orbit alone.
  std::optional<FromRestOptions> stability;
  /// Told the stage ("solve: 1/2 the orbit", "solve: 2/2 its check from rest"), "" when done.
  StageCallback on_stage;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule (params,
  /// margins, the grid and options of the check from rest).
  void Validate() const;
};

struct SolveJobResult {
  SolveJobOptions options;  ///< the options it ran with (the interrupt and callback cleared)
  Solution solution;        ///< the orbit and its validity
  Energy energy;            ///< the energy budget per period of the orbit (OrbitEnergy)
  Stability stability;      ///< with options.stability: the multipliers (else not computed)
  GaitFromRest from_rest;   ///< with options.stability: the orbit checked from rest
};

/// Solves the orbit, and with options.stability its stability and check from rest. Throws
/// std::invalid_argument for bad options; an orbit that does not exist or is not valid is a
/// status of the solution.
SolveJobResult RunSolveJob(const SolveJobOptions& options);

}  // namespace capsubot
