#pragma once
// A robot designed in SI units (docs/design.md) as JSON: the object of `capsubot design
// --json`, as the Python module's design returns it (the gait's numbers: gait_numbers.hpp).

#include <nlohmann/json.hpp>

#include "capsubot/design/design.hpp"
#include "capsubot/design/design_from_rest.hpp"
#include "capsubot/design/gait_numbers.hpp"
#include "capsubot/job/design_job.hpp"

namespace capsubot::json {

/// The gait: "status", the user's units, "dimensionless" {Dimensionless, cos and sin for a
/// Fourier force, energy when ok}, "orbits", "binding".
nlohmann::json GaitJson(const Gait& gait);

/// The design: {"status", "message", "one_impact" (GaitJson), "robots", "complete"}.
nlohmann::json DesignJson(const DesignResult& result);

/// The `from_rest_best` object: {forward, backward} each with the SI keys of the one-impact
/// gait, dimensionless {T0, A, c, alpha, phi0}, fractions of the starts going each way and the
/// attractors (each with its speed in mm/s), then the cost of the search.
nlohmann::json FromRestBestJson(const DesignInput& input, const DesignFromRestResult& result);

/// One design of the design job: DesignJson, with "robustness" (RobustnessJson of the gait's
/// robustness: "mu", "e", "m2_kg", values in those units; null without a gait) and
/// "from_rest_best" (FromRestBestJson) when part (b) ran. A grid's result has no JSON: its output
/// is its CSV file.
nlohmann::json DesignJobJson(const DesignJobResult& result);

}  // namespace capsubot::json
