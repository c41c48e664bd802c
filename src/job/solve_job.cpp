// capsubot solve as one call: the orbit, its energy, and asked its stability and check from rest.

#include "capsubot/job/solve_job.hpp"

#include "capsubot/model/force_spec.hpp"
#include "capsubot/orbit/orbit_energy.hpp"

namespace capsubot {

void SolveJobOptions::Validate() const {
  RefusePulse(forcing, "solve");
  params.Validate();
  margins.Validate();
  if (stability) stability->Validate();
}

SolveJobResult RunSolveJob(const SolveJobOptions& options) {
  options.Validate();
  SolveJobResult result;
  result.options = options;
  if (result.options.stability) result.options.stability->attractor.interrupt = {};
  result.options.on_stage = {};
  TellStage(options.on_stage, options.stability ? "solve: 1/2 the orbit" : "solve: the orbit");
  result.solution = Solve(options.forcing, options.params, options.margins);
  result.energy = OrbitEnergy(result.solution.orbit);
  if (options.stability) {
    TellStage(options.on_stage, "solve: 2/2 its stability and check from rest");
    result.stability = ComputeStability(result.solution.orbit);
    result.from_rest = CheckGaitFromRest(result.solution.orbit, options.params, *options.stability);
  }
  TellStage(options.on_stage, "");
  return result;
}

}  // namespace capsubot
