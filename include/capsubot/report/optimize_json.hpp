#pragma once
// The optimisers' results as JSON (docs/model.md sections 7, 12 and 13): the objects that
// `capsubot optimize --json` prints, for one problem, for the reach problem and for the main
// job, as the Python module's optimize returns them.

#include <nlohmann/json.hpp>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/job/optimize_job.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot::json {

/// One optimisation result: the optimum's orbit as SolutionJson shows it, with the optimiser's
/// status in place of the orbit's, "problem", "message", "active_constraints", "binding",
/// "evaluations", "algorithm", "spectral_radius" and "stable" (when the orbit exists) and
/// "coefficients" {c, cos, sin} for a Fourier force.
nlohmann::json OptimizeResultJson(const OptimizeResult& result, const char* problem);

/// Adds the model and the requirements every result of a run shares: "T0", "e", "margin",
/// "margin_stroke", "stick_margin", "rho_max" (null: infinity, no requirement).
void AddRequirementsJson(nlohmann::json& j, const Params& params, double rho_max);

/// The `reach` object: A, c, phi0, alpha, mean_velocity, status, message, attractors,
/// summary, spread {chatter_small, chatter_large, e_0999, max_relative_deviation,
/// event_limit_starts}, seed_won, robust_to_settings, evaluations, rejected_evaluations,
/// algorithm (no wall-clock time: the JSON of a run is the same on every run), seed {A, c, phi0,
/// alpha, I, v_mean, mean_velocity_from_rest, reached} (null without a checked seed).
nlohmann::json ReachJson(const ReachResult& reach);

/// The object of the job's result. One problem (phase, forcing, fourier): OptimizeResultJson,
/// the requirements, "from_rest" (FromRestJson of the optimum checked from rest) and, for
/// fourier, "baseline_I" and "gain" (I / baseline_I - 1, null without a valid gait). The reach
/// problem: ReachJson with the requirements of its seed (the robust gait). The main job: the
/// requirements, "force_bound" and the results "paper" (P1 at c = A = T0/2 without margins),
/// "robust" (P2 with the margins, with "from_rest": the reach seed's check), "reach" (with
/// "robustness": its most common motion from rest continued, null unless it is periodic),
/// "fastest" and "fastest_stable" (P2 without margins), each with a "note", and "robustness":
/// the robust gait's motion continued in T0, e and alpha (RobustnessJson; null without a
/// robust gait).
nlohmann::json OptimizeJobJson(const OptimizeJobResult& result);

}  // namespace capsubot::json
