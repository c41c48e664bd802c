#pragma once
// The one-impact orbit as plain text (docs/model.md sections 4, 5, 8, 11): the tables that
// `capsubot solve` prints.

#include <string>

#include "capsubot/job/solve_job.hpp"
#include "capsubot/model/energy.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot::text {

/// A readable multi-line summary of a solved orbit, with the margins its validity was checked
/// with.
std::string SolutionTable(const Solution& solution, const Params& params,
                          const Margins& margins = {});

/// Readable lines on the energy budget per period.
std::string EnergyTable(const Energy& energy);

/// Readable lines on the stability (multipliers, spectral radius, verdict).
std::string StabilityTable(const Stability& stability);

/// What `capsubot solve` prints: the orbit, its energy, and with the stability asked the
/// stability and the check from rest.
std::string SolveJobText(const SolveJobResult& result);

}  // namespace capsubot::text
