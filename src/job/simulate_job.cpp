// capsubot simulate as one call: the start resolved, the simulator's options completed, one run.

#include "capsubot/job/simulate_job.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/attract/orbit_start.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot {
namespace {

// `sim` with the start `s` of a given state.
SimOptions WithState(SimOptions sim, const SimulateFromState& s) {
  sim.alpha = s.alpha;
  sim.x0 = s.x0;
  sim.u0 = s.u0;
  sim.v0 = s.v0;
  return sim;
}

}  // namespace

void SimulateJobOptions::Validate() const {
  params.Validate();
  if (samples_per_period < 1 || samples_per_period > kMaxSamplesPerPeriod) {
    throw std::invalid_argument(
        fmt::format("samples_per_period = {} is invalid: expected 1 <= samples_per_period <= {}",
                    samples_per_period, kMaxSamplesPerPeriod));
  }
  if (sim.max_events_per_period > kMaxEventsPerPeriod) {
    throw std::invalid_argument(fmt::format(
        "max_events_per_period = {} is invalid: expected 10 <= max_events_per_period <= {}",
        sim.max_events_per_period, kMaxEventsPerPeriod));
  }
  if (trajectory) {
    // The samples cover the whole run, the transient too.
    RequireTrajectoryRows(sim.transient + sim.periods, static_cast<double>(samples_per_period),
                          "samples_per_period", "transient + periods");
  }
  if (const auto* state = std::get_if<SimulateFromState>(&start)) WithState(sim, *state).Validate();
}

SimulateJobResult RunSimulateJob(const SimulateJobOptions& options) {
  options.Validate();
  SimulateJobResult result;
  result.options = options;
  result.options.observer = nullptr;
  result.options.on_stage = {};
  result.sim = options.sim;
  if (const auto* state = std::get_if<SimulateFromState>(&options.start)) {
    result.sim = WithState(options.sim, *state);
  } else {
    OrbitStart s = StartFromOrbit(options.forcing, options.params);
    result.sim = WithState(options.sim, {s.start.alpha, s.start.x0, s.start.u0, s.start.v0});
    result.orbit = std::move(s.orbit);
  }
  result.sim.energy = true;  // a few hundred nanoseconds per period: nothing for one run
  if (options.trajectory) {
    result.sim.sample_step = kTau / static_cast<double>(options.samples_per_period);
  }
  result.sim.Validate();
  TellStage(options.on_stage,
            fmt::format("simulate: {:g} periods", result.sim.transient + result.sim.periods));
  result.run = Simulate(options.forcing, options.params, result.sim, options.observer);
  TellStage(options.on_stage, "");
  if (result.run.status == SimStatus::kNonFinite) throw std::runtime_error(result.run.message);
  return result;
}

}  // namespace capsubot
