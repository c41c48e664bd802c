#pragma once
// `capsubot attractors` as one call (docs/model.md sections 12 and 13): the long-run motion of
// every start of a grid from rest, simulated exactly and grouped into attractors; the whole map
// (its CSV written when asked) or one shard of it written to its resumable file. The map of
// `basins` is the same run over another plane of starts (basins_job.hpp).

#include <string>
#include <variant>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/parallel/blocks.hpp"
#include "capsubot/sweep/start_map.hpp"

namespace capsubot {

/// The whole map: every start classified, the starts grouped into attractors.
struct WholeStartMap {
  /// The CSV of the map (WriteStartMap: a row per start with its attractor); empty: none. It
  /// is checked to be writable before the run and written atomically after it.
  std::string output;
  std::string comments;  ///< the CSV's first lines, each "# ...\n" (the run's name); "": none
};

/// One shard of the map, the starts s with s % N = K, written to its resumable file
/// (WriteStartShard) with empty attractor cells: a label depends on the whole map, which
/// `capsubot merge` joins from the N files.
struct StartMapShard {
  /// K, N, the file, its comment lines, resume and checkpoint_seconds (StartShardOptions'
  /// rules); its u0 is set by the job (the plane of the starts).
  StartShardOptions file;
};

/// How a map of starts is run.
using StartMapRun = std::variant<WholeStartMap, StartMapShard>;

struct AttractorsJobOptions {
  /// The force F = G(psi + phi0) at the starts' phases psi, T0, e and the mass ratio
  /// m2/(m1+m2), 0 < alpha < 1.
  RobotModel robot;
  StartGrid starts;            ///< n_x starting positions x n_psi starting phases, from rest
  AttractorOptions attractor;  ///< each start's simulation, the grouping, threads, interrupt
  StartMapRun run;             ///< the whole map (default) or one shard
  StartsProgress progress;     ///< told the starts done (of the shard); empty: nobody
  StageCallback on_stage;      ///< told the stage ("attractors: 64 starts"), "" when done
  /// Computes the blocks of starts (this process's threads, or the ranks of an MPI job as
  /// well); null: LocalBlocks().
  const BlockBackend* backend = nullptr;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule: the
  /// grid, params, the attractor options, alpha, the shard.
  void Validate() const;
};

/// What a map job hands to its backend: the starts it computes (those of the shard, for a
/// shard) and how each is classified. The workers of a distributed backend compute the same
/// blocks (Blocks(): MotionBlocks, which refer to this object: it must outlive them).
struct StartMapWork {
  RobotModel robot;
  std::vector<PhaseState> starts;
  AttractorOptions attractor;

  BlockComputeFactory Blocks() const;
};

struct AttractorsJobResult {
  /// The options the job ran with (its callbacks, interrupt and backend cleared).
  AttractorsJobOptions options;
  Attractors attractors;    ///< the whole map: its attractors (none for a shard)
  StartShardSummary shard;  ///< a shard: the starts written to its file, and those resumed
};

/// Runs the map of options.starts from rest (docs/model.md sections 12 and 13): the whole map
/// classified into attractors (its CSV written when options.run asks), or the shard written to
/// its file. Throws std::invalid_argument for bad options (Validate) and IoError for a file
/// that cannot be written (before the long run, where it can be seen then).
AttractorsJobResult RunAttractorsJob(const AttractorsJobOptions& options);

/// The work RunAttractorsJob(options) hands to its backend, for the workers of a distributed
/// backend (which compute it without running the job).
StartMapWork AttractorsJobWork(const AttractorsJobOptions& options);

}  // namespace capsubot
