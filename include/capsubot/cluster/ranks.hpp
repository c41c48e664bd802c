#pragma once
// The processes of a run started by `mpirun -n P capsubot <command> ...` (or srun): rank 0
// runs the command and hands blocks of work to the other ranks, which compute them with
// their threads and send the bytes back (master-worker, dynamic: a rank gets its next block
// when it returns one). Started without mpirun, or with one rank, the command runs alone in
// this process exactly as without MPI. The MPI code lives in src/cluster/mpi.cpp, built with
// the CMake option CAPSUBOT_MPI; src/cluster/alone.cpp replaces it otherwise. See
// docs/cluster.md.

#include <memory>

#include "capsubot/parallel/blocks.hpp"

namespace capsubot {

/// Processes of the job this process was started in, as its launcher says (mpirun, srun:
/// OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_SIZE); 1 when started alone.
int LaunchedProcesses();
/// Rank of this process in that job, as its launcher says (OMPI_COMM_WORLD_RANK, PMI_RANK or
/// PMIX_RANK), known before MPI is started; 0 when started alone.
int LaunchedRank();

/// Under mpirun, rank 0's standard output is a terminal or pipe that mpirun copies to its own
/// standard output, ignoring a write that fails there (a full disk, /dev/full): the run would
/// say nothing and exit 0. On rank 0 of a job started by mpirun on this machine, this makes
/// standard output mpirun's own (opened again through /proc), so that a failed write fails the
/// run (exit 1) as it does without mpirun. Elsewhere (no launcher, another rank, a launcher that
/// is not the parent, a standard output that is already a file) it changes nothing.
void UseLauncherStdout();

class Ranks {
 public:
  /// Joins the MPI job when this process was started by mpirun (srun) with more than one
  /// process; otherwise (and with one process) the run is alone. Throws std::invalid_argument
  /// when started with several processes by a capsubot built without MPI.
  Ranks();
  /// Rank 0: tells the workers to stop (also after an error); then leaves the MPI job.
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  /// A worker: rank > 0 (it serves blocks, writes nothing).
  bool worker() const;
  /// The backend of rank 0 or of a run alone: its own threads plus the workers'.
  const BlockBackend& backend() const;
  /// On a worker: computes the blocks rank 0 sends, with computers made by `make` on
  /// `threads` threads (0: all cores), until rank 0 says stop. A block that fails is reported to
  /// rank 0 (its message) and fails the run there. Returns the exit status (0).
  int Serve(const BlockComputeFactory& make, int threads);

  struct Job;

 private:
  std::unique_ptr<Job> job_;
};

}  // namespace capsubot
