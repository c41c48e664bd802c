// A capsubot built without MPI (CMake option CAPSUBOT_MPI off): every run is alone; started
// by mpirun with several processes, a command that distributes its work says so and stops.

#include <stdexcept>

#include "capsubot/cluster/ranks.hpp"

namespace capsubot {

struct Ranks::Job {};

Ranks::Ranks() {
  if (LaunchedProcesses() > 1) {
    throw std::invalid_argument(
        "mpirun -n P with P > 1 is invalid for this capsubot: it was built without MPI "
        "(CMake option CAPSUBOT_MPI=OFF): expected one process, or `--shard K/N` per process");
  }
}

Ranks::~Ranks() = default;

bool Ranks::worker() const { return false; }

const BlockBackend& Ranks::backend() const { return LocalBlocks(); }

int Ranks::Serve(const BlockComputeFactory&, int) { return 0; }

}  // namespace capsubot
