#pragma once
// The whole map of starts of `basins` and `attractors` (without --shard): the long-run motion of
// every start classified into attractors, on the ranks of the MPI job when started by mpirun
// (ranks.hpp), else on this process's threads. Its shards: start_shard.hpp.

#include <optional>
#include <string>
#include <vector>

#include "attract_options.hpp"

namespace capsubot::app {

/// ClassifyStarts of `starts` for `robot` (with `forcing`, its built force), the progress on
/// stderr when shown (progress.hpp). Rank 0 (or a run alone) first checks that `output` can be
/// written (none when empty; the option -o names it), then returns the attractors, the same as on
/// one machine. A worker computes blocks of starts for rank 0 and returns nothing: its command
/// writes and prints nothing and exits 0. Throws as ClassifyStarts (bad options) and AtomicFile
/// (IoError).
std::optional<Attractors> ClassifyWholeMap(const RobotOptions& robot, const Forcing& forcing,
                                           const std::vector<PhaseState>& starts,
                                           const AttractorOptions& attractor,
                                           const std::string& output);

}  // namespace capsubot::app
