#pragma once
// An event-driven simulation (docs/model.md sections 3 and 10) as JSON: the object of
// `capsubot simulate --json`, as the Python module's simulate returns it (without its tables).

#include <nlohmann/json.hpp>

#include "capsubot/job/simulate_job.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot::json {

/// {"status", "message", "alpha", the final state "phi", "x", "u", "v", "y", "mode", and the
/// figures of the record: "displacement", "v_mean", "impacts_right", "impacts_left", "stops",
/// "breakaways", "sticks", "releases", "events", "energy" {...}}; with options.transient > 0
/// also "transient" {"periods" and the same figures over the transient}; with `orbit` (the
/// analytic orbit the run started from, or null) "orbit" (SolutionJson).
nlohmann::json SimulationJson(const SimResult& result, const SimOptions& options,
                              const Solution* orbit);

/// What `capsubot simulate --json` prints (without provenance): SimulationJson of the run, the
/// simulator's options as run and the orbit it started from (if any), with "force" (ForcingJson).
nlohmann::json SimulateJobJson(const SimulateJobResult& result);

}  // namespace capsubot::json
