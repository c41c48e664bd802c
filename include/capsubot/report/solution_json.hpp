#pragma once
// The one-impact orbit as JSON (docs/model.md sections 4, 5, 8, 11): the object that
// `capsubot solve --json` prints and the Python module's solve returns. Numbers that do not
// exist (NaN) are written as null.

#include <nlohmann/json.hpp>
#include <vector>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/job/orbits_job.hpp"
#include "capsubot/job/solve_job.hpp"
#include "capsubot/model/energy.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot::json {

/// A solved orbit: its force as ForcingJson describes it (for a Fourier force also "A": null),
/// T0, e, status, phi1, alpha, u, v_plus, I, v_mean, x_min, x_max, stroke, clearance, valid,
/// violations.
nlohmann::json SolutionJson(const Solution& solution);

/// Adds the stability of docs/model.md section 8: "multipliers" (array of {"re", "im"}),
/// "spectral_radius" and "stable" (null, null, false when not computed).
void AddStabilityJson(nlohmann::json& j, const Stability& stability);

/// Adds the energy budget of docs/model.md section 11: "energy" with the keys motor_work,
/// motor_work_positive, friction_loss, impact_loss (dimensionless, per period; null when not
/// computed).
void AddEnergyJson(nlohmann::json& j, const Energy& energy);

/// The object of `capsubot solve --json` (without provenance): SolutionJson with the energy;
/// with the stability asked also the stability and "from_rest" (FromRestJson: the orbit checked
/// from rest).
nlohmann::json SolveJobJson(const SolveJobResult& result);

/// Every orbit of a robot (`capsubot orbits`): one object per orbit, sorted as given, with the
/// keys of SolutionJson, the energy, the stability and "complete" (false: the search hit its
/// work bound and orbits may be missing).
nlohmann::json RobotOrbitsJson(const std::vector<Solution>& orbits, bool complete);

/// The object of `capsubot orbits --json` (without provenance): "orbits", the RobotOrbitsJson
/// of the orbits found.
nlohmann::json OrbitsJobJson(const OrbitsJobResult& result);

}  // namespace capsubot::json
