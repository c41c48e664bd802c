#pragma once
// `capsubot bifurcation` as one call: a brute-force bifurcation diagram (docs/model.md section
// 13; capsubot/attract/bifurcation.hpp), or one shard of a two-parameter study, written to its
// CSV files (capsubot/sweep/bifurcation_csv.hpp). The job decides what the parts of a user's
// request mean together: the robot's mass ratio when alpha is the parameter stepped, the
// analytic orbits only with a summary file, a shard's files or the whole study's.

#include <cstdint>
#include <string>

#include "capsubot/attract/bifurcation.hpp"
#include "capsubot/model/model_parameter.hpp"
#include "capsubot/sweep/bifurcation_csv.hpp"

namespace capsubot {

struct BifurcationJobOptions {
  /// The robot: its force, T0 and e and its mass ratio alpha, 0 < alpha < 1; alpha may be NaN when
  /// the diagram steps alpha or the study's second parameter is alpha (their first value is then
  /// the robot's).
  RobotModel robot;
  /// The diagram: the parameter, its range (from != to) and steps, the directions, the motion,
  /// the start, the second parameter's values, the shard, the threads. Its analytic orbits go
  /// to the summary file: without one they are not computed.
  BifurcationOptions diagram;
  /// The files: impacts (required) and summary (empty: none), the comment lines that start
  /// both (each "# ...\n": provenance); resume and checkpoint_seconds apply to a shard of
  /// the study (diagram.shards >= 2), whose files are checkpointed, not to the whole study.
  BifurcationShardFiles files;
  /// Told the parameter values simulated so far of their total (bifurcation.hpp); empty: nobody.
  StartsProgress progress;

  /// Throws std::invalid_argument naming the first bad option, its value and the rule (alpha
  /// missing, from = to, two outputs that are one file, resume of a whole study, and every
  /// rule of ValidateBifurcation and BifurcationShardFiles::Validate).
  void Validate() const;
};

/// The directions called `name`: "up", "down" or "both" (up, then down), into options.up and
/// options.down. Throws std::invalid_argument "direction = ... is invalid" for another name.
void SetBifurcationDirection(const std::string& name, BifurcationOptions& options);

/// The second parameter of a study and its values from `spec`, NAME=lo:hi:n, NAME=lo:hi:n:log
/// or NAME=v1,v2,... (the syntax of a sweep's grid axis, NAME a robot parameter), into
/// options.over, over_harmonic and over_values. Throws std::invalid_argument for a bad spec and
/// for more than kMaxOverValues values ("over = ... is invalid", checked before they are held).
void SetBifurcationOver(const std::string& spec, BifurcationOptions& options);

/// The diagram a job computes: its options checked, the robot's alpha and the diagram's
/// options as they run. The blocks a distributed run's workers compute are
/// BifurcationBlocks(robot.forcing, robot.params, robot.alpha, diagram).
struct BifurcationJobPlan {
  RobotModel robot;
  BifurcationOptions diagram;
};

/// Throws what BifurcationJobOptions::Validate throws.
BifurcationJobPlan PlanBifurcationJob(const BifurcationJobOptions& options);

/// What a bifurcation job wrote.
struct BifurcationJobResult {
  BifurcationOptions diagram;     ///< the diagram's options as run (the analytic orbits or not)
  std::string impacts;            ///< the impacts file written
  std::string summary;            ///< the summary file written; empty: none
  std::int64_t impact_rows = 0;   ///< impacts written (a resumed shard: with those resumed)
  std::int64_t summary_rows = 0;  ///< summary rows written
  int parts = 0;                  ///< a shard: its parts (0: the whole study)
  int parts_resumed = 0;          ///< a shard: its parts taken over from the checkpoints
  /// The whole study's diagram, as written; empty for a shard (its parts went to its files).
  BifurcationDiagram rows;
};

/// Computes the diagram of PlanBifurcationJob(options) (its parts by `backend`: this process's
/// threads by default) and writes its files: the whole study's (atomically, once computed;
/// the impacts path is checked writable first) or a shard's (WriteBifurcationShard: part
/// after part, checkpointed, resumable). Throws std::invalid_argument for bad options (before
/// any file is touched), IoError for a file that cannot be used.
BifurcationJobResult RunBifurcationJob(const BifurcationJobOptions& options,
                                       const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
