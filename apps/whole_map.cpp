// The whole map of starts of `basins` and `attractors`, classified on the ranks.

#include "whole_map.hpp"

#include "capsubot/io/io.hpp"
#include "ranks.hpp"

namespace capsubot::app {

std::optional<Attractors> ClassifyWholeMap(const RobotOptions& robot, const Forcing& forcing,
                                           const std::vector<PhaseState>& starts,
                                           const AttractorOptions& attractor,
                                           const std::string& output) {
  Ranks ranks;  // under mpirun: rank 0 runs the command, the others compute blocks of starts
  if (ranks.worker()) {
    ranks.Serve(MotionBlocks(forcing, robot.params, robot.alpha, starts, attractor),
                attractor.threads);
    return std::nullopt;
  }
  if (!output.empty()) CheckWritable(output, "-o");  // before the long run
  return ClassifyStarts(forcing, robot.params, robot.alpha, starts, attractor,
                        CountProgress("starts"), ranks.backend());
}

}  // namespace capsubot::app
