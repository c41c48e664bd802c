#pragma once
// The run of a map of starts shared by the attractors and basins jobs: the whole map
// classified into attractors, or one shard written to its file.

#include <vector>

#include "capsubot/job/attractors_job.hpp"

namespace capsubot::detail {

/// Runs `starts` (the whole map, in its order) with the robot, options and run of `options`;
/// the CSV's second column is u0 when `u0`, else psi; the stage is named after `command`.
/// Validates nothing itself beyond what the library calls check: the jobs validate first.
AttractorsJobResult RunStartMap(const AttractorsJobOptions& options,
                                const std::vector<PhaseState>& starts, bool u0,
                                const char* command);

/// What RunStartMap(options, starts, ...) hands to its backend.
StartMapWork StartMapWorkOf(const AttractorsJobOptions& options,
                            const std::vector<PhaseState>& starts);

}  // namespace capsubot::detail
