#pragma once
// The job of `capsubot orbits` (and the Python module's orbits): every one-impact orbit of a
// robot whose mass ratio is fixed (docs/model.md section 8), none missed, each with its
// validity and stability.

#include <cstdint>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/robot_orbits.hpp"

namespace capsubot {

struct OrbitsJobOptions {
  /// The force's shape (its phi0 is solved for, not used), T0, e and the mass ratio
  /// 0 < alpha < 1.
  RobotModel robot;
  Margins margins;  ///< the margins of the orbits' validity (none: physical validity)
  /// Work bound: evaluations of the orbit equation; 1 <= max_evaluations <= kMaxOrbitEvaluations.
  std::int64_t max_evaluations = kRobotOrbitsMaxEvaluations;
  Interrupt interrupt;  ///< asked about every millisecond of the search

  /// Throws std::invalid_argument naming the first bad field, its value and the rule (alpha is
  /// checked by the search, first).
  void Validate() const;
};

struct OrbitsJobResult {
  OrbitsJobOptions options;      ///< what was searched (the interrupt left out)
  std::vector<Solution> orbits;  ///< sorted by phi0
  bool complete = true;  ///< false: the work bound stopped the search, orbits may be missing
};

/// Runs the job (options.Validate() first).
OrbitsJobResult RunOrbitsJob(const OrbitsJobOptions& options);

}  // namespace capsubot
