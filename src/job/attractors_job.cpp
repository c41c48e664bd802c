// capsubot attractors as one call: the map of starts from rest.

#include "capsubot/job/attractors_job.hpp"

#include "start_map_run.hpp"

namespace capsubot {

void AttractorsJobOptions::Validate() const {
  starts.Validate();
  robot.params.Validate();
  attractor.Validate();
  ValidateStart(robot.alpha, GridStart(0, 0, starts.n_x, starts.n_psi));  // the simulator's alpha
  if (const auto* shard = std::get_if<StartMapShard>(&run)) {
    shard->file.Validate(static_cast<std::size_t>(starts.Starts()));
  }
}

AttractorsJobResult RunAttractorsJob(const AttractorsJobOptions& options) {
  options.Validate();
  return detail::RunStartMap(options, GridStarts(options.starts.n_x, options.starts.n_psi), false,
                             "attractors");
}

StartMapWork AttractorsJobWork(const AttractorsJobOptions& options) {
  return detail::StartMapWorkOf(options, GridStarts(options.starts.n_x, options.starts.n_psi));
}

}  // namespace capsubot
